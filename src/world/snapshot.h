// Internal: what the tests and the fuzz harness need of the snapshot format (snapshot.c describes
// it): the header's size and the checksum that guards the bytes after it.
#pragma once

#include <stdint.h>

/// Bytes of a snapshot image's header; the checksum covers the image from byte 24 (the world's
/// identity at 24..31 included) to its end.
#define TB_SNAPSHOT_HEADER_SIZE 32

/// The checksum of an image of `size` bytes, as its header holds it (bytes 16..23).
uint64_t tbSnapshotChecksum(const uint8_t* image, int size);

/// Write the checksum of an image into its header: for tests and the fuzz harness, which change
/// bytes behind the checksum to reach the checks that come after it. Nothing for a NULL image or
/// one shorter than the header.
void tbSnapshotSeal(uint8_t* image, int size);
