// Internal: what the tests and the fuzz harness need of the snapshot format (snapshot.c describes
// it): the header's size and the checksum that guards the image.
#pragma once

#include <stdint.h>

/// Bytes of a snapshot image's header; the checksum (bytes 16..23) covers every other byte of the
/// image: the header's first 16 bytes and everything from byte 24 to the end.
#define TB_SNAPSHOT_HEADER_SIZE 32

/// The checksum of an image of `size` bytes (at least the header), as its header holds it.
uint64_t tbSnapshotChecksum(const uint8_t* image, int size);

/// Write the checksum of an image into its header: for tests and the fuzz harness, which change
/// bytes behind the checksum to reach the checks that come after it. Nothing for a NULL image or
/// one shorter than the header.
void tbSnapshotSeal(uint8_t* image, int size);
