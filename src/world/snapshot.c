// Snapshots (Box2D v3.2's snapshot group: b2World_Snapshot, b2World_Restore,
// b2CreateWorldFromSnapshot): the whole simulation state of a world as one byte image, restored in
// place or into a new world, after which the world steps on bit for bit as if it had never left
// the instant of the snapshot.
//
// What an image holds is what the next steps read and cannot recompute exactly: every body, shape,
// chain, contact (manifold, warm-start impulses, recycling base, simplex cache, touching-step count),
// joint (parameters and impulses) and their id pools (free lists in order, every slot's generation),
// each body's shape, contact and joint lists in their order (the island stage wakes bodies in the
// order of those lists), the awake list in its order, the broad phase (method, proxy table with its
// free chain, move buffer, both trees node for node: the shape of a tree decides the order in which
// queries report proxies, continuous collision's included; the spatial hash's cell size and update
// count), the automatic broad phase's vote, the world's settings and step index, and the end events
// waiting for the next step. Host wiring (task system, worker count, user data, callbacks) is not
// state and is not stored: an in-place restore keeps the world's, a new world gets the defaults;
// body, shape and joint user data read back NULL, as in Box2D v3.2.
//
// What it leaves out is recomputed bit for bit on restore, or provably unread before the step
// rewrites it:
// - derived values, each stored only when recomputing it would not give the same bits (a flag says
//   which, so a prediction that misses costs bytes, never correctness): a body's mass properties
//   (tbComputeBodyMass), origin (from its centre of mass), extents and speculative reach; a shape's
//   tight box and, when the last finalize re-made it, its fat box; a polygon's normals and centroid
//   (tbMakePolygon on its vertices); a contact's mixed materials (the default mixing), its anchors
//   and recycling base, or for a recycled manifold its points and separations (what the narrow
//   phase made of them at the bodies' start-of-step poses, which the image keeps); a tree
//   node's box, category bits and height (from its children); a proxy's box, bits and shape;
// - lists rebuilt from what is stored: the pair set, each contact's bodies, the counts of kinematic
//   and static bodies, static proxies, linear locks and contacts wanting hit events;
// - the step cache (step_cache.h): every stage either rebuilds its lists or keeps the last step's,
//   and keeping is allowed only when the rebuild would give the same lists, so a restored world
//   starts with the cache invalidated (versions that match no stamp) and rebuilds;
// - per-step scratch: a contact's gather stamp (set to one no coming step uses), a joint's solver view (written by its
//   preparation), the step arena, the last step's events.
//
// Format (little-endian). A 32-byte header: "TBSN", version (2 bytes), precision (1: the build's
// tbPos in doubles), header size, image size (4), length units per metre (float), a checksum (8),
// the step index and the live body count (4 each, for tools). The checksum (64-bit, MurmurHash3's
// mixing, Appleby) covers every byte but its own. Then the sections in the order written below, in
// varints (LEB128; signed values zigzag-coded; ids as differences from the id written before) and
// raw floats; groups of floats that are mostly their defaults (velocities, forces, impulses,
// parameters) are written as a mask of the ones that differ, then those; shapes name their
// geometry and their material from dictionaries, each entry written once. Nothing in the image is
// trusted: a restore decodes it into a separate world, checks every count against the bytes left,
// every index, list and tree for range, uniqueness and cycles, and every value as the API would
// (finite, in range, valid geometry), and only then replaces the world's contents; a refused image
// leaves the world as it was.
#include "snapshot.h"

#include "body.h"
#include "chain.h"
#include "contact.h"
#include "shape.h"
#include "world.h"

#include "broad_phase/broad_phase.h"
#include "collision/dynamic_tree_node.h"
#include "core/array.h"
#include "joints/joint.h"
#include "solver/constraint_graph.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define TB_SNAPSHOT_MAGIC 0x4E534254u // "TBSN" as bytes
// Version 2: manifold points carry baseSeparation, waiting end events their contact id, bodies
// allowFastRotation, the settings contact softening (Box2D v3.2's fields); a version 1 image is
// refused by name rather than misread.
#define TB_SNAPSHOT_VERSION 2u

#if defined(TUMBLE_DOUBLE_PRECISION)
#define TB_SNAPSHOT_PRECISION 1u
#else
#define TB_SNAPSHOT_PRECISION 0u
#endif

// --------------------------------------------------------------------------------------------
// Checksum: 64-bit words mixed as MurmurHash3's x64 body mixes its blocks (Appleby), each word
// through the fmix64 finaliser first. Each step is a bijection of the running hash for a fixed
// word and of the word for a fixed hash, so an image that differs from a sealed one in a single
// word always fails; other damage fails but for one chance in 2^64.

static uint64_t tbFinalMix(uint64_t x)
{
	x ^= x >> 33;
	x *= 0xFF51AFD7ED558CCDull;
	x ^= x >> 33;
	x *= 0xC4CEB9FE1A85EC53ull;
	x ^= x >> 33;
	return x;
}

static uint64_t tbChecksumBytes(uint64_t h, const uint8_t* bytes, int count)
{
	int i = 0;
	for (; i + 8 <= count; i += 8)
	{
		uint64_t word = 0;
		for (int k = 0; k < 8; ++k)
		{
			word |= (uint64_t)bytes[i + k] << (8 * k);
		}
		h ^= tbFinalMix(word);
		h = ((h << 27) | (h >> 37)) * 5u + 0x52DCE729u;
	}
	uint64_t tail = 0;
	for (int k = 0; i + k < count; ++k)
	{
		tail |= (uint64_t)bytes[i + k] << (8 * k);
	}
	h ^= tbFinalMix(tail ^ ((uint64_t)(count - i) << 56));
	return ((h << 27) | (h >> 37)) * 5u + 0x52DCE729u;
}

uint64_t tbSnapshotChecksum(const uint8_t* image, int size)
{
	uint64_t h = 0x243F6A8885A308D3ull ^ (uint64_t)(uint32_t)size;
	h = tbChecksumBytes(h, image, 16);
	h = tbChecksumBytes(h, image + TB_SNAPSHOT_HEADER_SIZE - 8, size - (TB_SNAPSHOT_HEADER_SIZE - 8));
	return tbFinalMix(h);
}

static void tbStoreU16(uint8_t* p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
}

static void tbStoreU32(uint8_t* p, uint32_t v)
{
	for (int k = 0; k < 4; ++k)
	{
		p[k] = (uint8_t)(v >> (8 * k));
	}
}

static uint32_t tbLoadU32(const uint8_t* p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint64_t tbLoadU64(const uint8_t* p)
{
	return (uint64_t)tbLoadU32(p) | (uint64_t)tbLoadU32(p + 4) << 32;
}

void tbSnapshotSeal(uint8_t* image, int size)
{
	if (image == NULL || size < TB_SNAPSHOT_HEADER_SIZE)
	{
		return;
	}
	uint64_t sum = tbSnapshotChecksum(image, size);
	tbStoreU32(image + 16, (uint32_t)sum);
	tbStoreU32(image + 20, (uint32_t)(sum >> 32));
}

// --------------------------------------------------------------------------------------------
// Writing: counting only (data NULL: the size query), or into a buffer that grows, copied into the
// caller's when it fits (one pass, and nothing written into a buffer that is too small).

typedef struct tbWriter
{
	uint8_t* data;
	int64_t size;
	int64_t capacity;
} tbWriter;

static void tbPutBytes(tbWriter* w, const void* bytes, int count)
{
	int64_t needed = w->size + count;
	if (w->data != NULL && needed > w->capacity && needed <= INT32_MAX)
	{
		int64_t grown = 2 * w->capacity < needed ? needed : 2 * w->capacity;
		grown = grown > INT32_MAX ? INT32_MAX : grown;
		w->data = tbGrowAlloc(w->data, (int)w->capacity, (int)grown);
		w->capacity = grown;
	}
	if (w->data != NULL && needed <= w->capacity)
	{
		memcpy(w->data + w->size, bytes, (size_t)count); // beyond an int of bytes: counted only
	}
	w->size += count;
}

static void tbPutU8(tbWriter* w, uint32_t value)
{
	uint8_t b = (uint8_t)value;
	tbPutBytes(w, &b, 1);
}

static void tbPutU64(tbWriter* w, uint64_t value)
{
	if (value < 0x80u && w->data != NULL && w->size < w->capacity)
	{
		w->data[w->size++] = (uint8_t)value; // most numbers fit a byte
		return;
	}
	uint8_t bytes[10];
	int n = 0;
	do
	{
		uint8_t b = (uint8_t)(value & 0x7Fu);
		value >>= 7;
		bytes[n++] = (uint8_t)(b | (value != 0 ? 0x80u : 0u));
	} while (value != 0);
	tbPutBytes(w, bytes, n);
}

static void tbPutUInt(tbWriter* w, uint32_t value)
{
	tbPutU64(w, value);
}

static void tbPutInt(tbWriter* w, int value)
{
	uint32_t zigzag = value < 0 ? ((~(uint32_t)value) << 1) | 1u : (uint32_t)value << 1;
	tbPutU64(w, zigzag);
}

/// An id as its difference from a nearby one (the last id of its kind written): ids written in
/// order are close, and their differences fit a byte.
static void tbPutDelta(tbWriter* w, int64_t value, int64_t previous)
{
	int64_t d = value - previous;
	tbPutU64(w, d < 0 ? ((~(uint64_t)d) << 1) | 1u : (uint64_t)d << 1);
}

static void tbPutFloat(tbWriter* w, float value)
{
	uint32_t bits;
	memcpy(&bits, &value, sizeof(bits));
	uint8_t bytes[4];
	tbStoreU32(bytes, bits);
	tbPutBytes(w, bytes, 4);
}

static void tbPutVec2(tbWriter* w, tbVec2 v)
{
	tbPutFloat(w, v.x);
	tbPutFloat(w, v.y);
}

static void tbPutRot(tbWriter* w, tbRot q)
{
	tbPutFloat(w, q.c);
	tbPutFloat(w, q.s);
}

static void tbPutAABB(tbWriter* w, tbAABB box)
{
	tbPutVec2(w, box.lowerBound);
	tbPutVec2(w, box.upperBound);
}

static void tbPutCoordinate(tbWriter* w, const void* value, size_t size)
{
	uint8_t bytes[8];
	uint64_t bits = 0;
	if (size == 8)
	{
		memcpy(&bits, value, 8);
	}
	else
	{
		uint32_t b32;
		memcpy(&b32, value, 4);
		bits = b32;
	}
	for (size_t k = 0; k < size; ++k)
	{
		bytes[k] = (uint8_t)(bits >> (8 * k));
	}
	tbPutBytes(w, bytes, (int)size);
}

/// A world position: floats, or doubles in the large-world build (the header says which).
static void tbPutPos(tbWriter* w, tbPos p)
{
	tbPutCoordinate(w, &p.x, sizeof(p.x));
	tbPutCoordinate(w, &p.y, sizeof(p.y));
}

static bool tbSameFloat(float a, float b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

static bool tbSameVec2(tbVec2 a, tbVec2 b)
{
	return tbSameFloat(a.x, b.x) && tbSameFloat(a.y, b.y);
}

/// Up to 64 floats as a mask of those whose bits differ from `defaults`, then those.
static void tbPutFloatsOver(tbWriter* w, const float* values, const float* defaults, int count)
{
	uint64_t mask = 0;
	for (int i = 0; i < count; ++i)
	{
		mask |= tbSameFloat(values[i], defaults != NULL ? defaults[i] : 0.0f) ? 0u : (uint64_t)1 << i;
	}
	tbPutU64(w, mask);
	for (int i = 0; i < count; ++i)
	{
		if (mask & ((uint64_t)1 << i))
		{
			tbPutFloat(w, values[i]);
		}
	}
}

// --------------------------------------------------------------------------------------------
// Reading: bounds-checked; the first problem is kept as the message the caller reports, and every
// read after it returns zero.

typedef struct tbReader
{
	const uint8_t* data;
	int size;
	int offset;
	const char* section; ///< what is being read (named in the message when the image ends early)
	bool failed;
	char message[256];
} tbReader;

static bool tbFail(tbReader* r, const char* format, ...) TB_PRINTF_FORMAT(2, 3);

static bool tbFail(tbReader* r, const char* format, ...)
{
	if (r->failed == false)
	{
		r->failed = true;
		va_list args;
		va_start(args, format);
		vsnprintf(r->message, sizeof(r->message), format, args);
		va_end(args);
	}
	return false;
}

static int tbRemaining(const tbReader* r)
{
	return r->size - r->offset;
}

static bool tbGetBytes(tbReader* r, void* out, int count)
{
	if (r->failed || count > tbRemaining(r))
	{
		memset(out, 0, (size_t)count);
		if (r->failed == false)
		{
			tbFail(r, "the image is truncated: it ends inside its %s (byte %d of %d)", r->section, r->offset, r->size);
		}
		return false;
	}
	memcpy(out, r->data + r->offset, (size_t)count);
	r->offset += count;
	return true;
}

static uint32_t tbGetU8(tbReader* r)
{
	uint8_t b = 0;
	tbGetBytes(r, &b, 1);
	return b;
}

static uint64_t tbGetU64(tbReader* r)
{
	if (r->failed == false && r->offset < r->size && r->data[r->offset] < 0x80u)
	{
		return r->data[r->offset++]; // most numbers fit a byte
	}
	uint64_t value = 0;
	for (int shift = 0; shift < 64; shift += 7)
	{
		uint32_t b = tbGetU8(r);
		if (r->failed)
		{
			return 0;
		}
		if (shift == 63 && b > 1u)
		{
			tbFail(r, "a number in its %s (byte %d) is longer than 64 bits", r->section, r->offset - 1);
			return 0;
		}
		value |= (uint64_t)(b & 0x7Fu) << shift;
		if ((b & 0x80u) == 0)
		{
			return value;
		}
	}
	tbFail(r, "a number in its %s (byte %d) is longer than 64 bits", r->section, r->offset - 1);
	return 0;
}

static uint32_t tbGetUInt(tbReader* r)
{
	uint64_t value = tbGetU64(r);
	if (value > UINT32_MAX)
	{
		tbFail(r, "a number in its %s (byte %d) is larger than 32 bits", r->section, r->offset - 1);
		return 0;
	}
	return (uint32_t)value;
}

static int tbGetInt(tbReader* r)
{
	uint32_t zigzag = tbGetUInt(r);
	uint32_t half = zigzag >> 1;
	return (zigzag & 1u) != 0 ? -(int)half - 1 : (int)half;
}

/// tbPutDelta's id: in [lower, limit), or fails naming `what`.
static int tbGetDelta(tbReader* r, int64_t previous, int lower, int limit, const char* what)
{
	uint64_t zigzag = tbGetU64(r);
	uint64_t half = zigzag >> 1;
	if (r->failed || half > ((uint64_t)1 << 40))
	{
		return r->failed ? lower : (tbFail(r, "%s is out of range", what), lower);
	}
	int64_t value = previous + ((zigzag & 1u) != 0 ? -(int64_t)half - 1 : (int64_t)half);
	if (value < lower || value >= limit)
	{
		tbFail(r, "%s is %lld, out of range (%d to %d)", what, (long long)value, lower, limit - 1);
		return lower;
	}
	return (int)value;
}

/// A non-negative int below `limit`, or fails naming `what`.
static int tbGetIndex(tbReader* r, int limit, const char* what)
{
	uint32_t value = tbGetUInt(r);
	if (r->failed == false && value >= (uint32_t)limit)
	{
		tbFail(r, "%s is %u, out of range (0 to %d)", what, value, limit - 1);
		return 0;
	}
	return r->failed ? 0 : (int)value;
}

/// A count of items that take at least `bytesEach` bytes in the rest of the image: bounds what a
/// corrupt count could make the reader allocate by the image's own size.
static int tbGetCount(tbReader* r, int bytesEach, const char* what)
{
	uint32_t value = tbGetUInt(r);
	if (r->failed == false && (uint64_t)value * (uint64_t)bytesEach > (uint64_t)tbRemaining(r))
	{
		tbFail(r, "%s is %u, more than the %d bytes left could hold", what, value, tbRemaining(r));
		return 0;
	}
	return r->failed ? 0 : (int)value;
}

static float tbGetRawFloat(tbReader* r)
{
	uint8_t bytes[4] = {0, 0, 0, 0};
	if (r->failed == false && tbRemaining(r) >= 4)
	{
		memcpy(bytes, r->data + r->offset, 4);
		r->offset += 4;
	}
	else
	{
		tbGetBytes(r, bytes, 4);
	}
	uint32_t bits = tbLoadU32(bytes);
	float value;
	memcpy(&value, &bits, sizeof(value));
	return value;
}

/// A finite float, or fails naming `what`.
static float tbGetFloat(tbReader* r, const char* what)
{
	float value = tbGetRawFloat(r);
	if (r->failed == false && tbIsValidFloat(value) == false)
	{
		tbFail(r, "%s is not finite (byte %d)", what, r->offset - 4);
		return 0.0f;
	}
	return value;
}

static tbVec2 tbGetVec2(tbReader* r, const char* what)
{
	tbVec2 v;
	v.x = tbGetFloat(r, what);
	v.y = tbGetFloat(r, what);
	return v;
}

static tbRot tbGetRot(tbReader* r, const char* what)
{
	tbRot q;
	q.c = tbGetFloat(r, what);
	q.s = tbGetFloat(r, what);
	if (r->failed == false && tbIsValidRotation(q) == false)
	{
		tbFail(r, "%s is (%g, %g), not a unit rotation", what, (double)q.c, (double)q.s);
	}
	return q;
}

static tbAABB tbGetAABB(tbReader* r, const char* what)
{
	tbAABB box;
	box.lowerBound = tbGetVec2(r, what);
	box.upperBound = tbGetVec2(r, what);
	if (r->failed == false && (box.lowerBound.x > box.upperBound.x || box.lowerBound.y > box.upperBound.y))
	{
		tbFail(r, "%s is inverted (its lower corner is above its upper corner)", what);
	}
	return box;
}

static void tbGetCoordinate(tbReader* r, void* out, size_t size)
{
	uint8_t bytes[8];
	tbGetBytes(r, bytes, (int)size);
	uint64_t bits = 0;
	for (size_t k = 0; k < size; ++k)
	{
		bits |= (uint64_t)bytes[k] << (8 * k);
	}
	if (size == 8)
	{
		memcpy(out, &bits, 8);
	}
	else
	{
		uint32_t b32 = (uint32_t)bits;
		memcpy(out, &b32, 4);
	}
}

/// A world position, finite (bounded by the caller where the world bounds it).
static tbPos tbGetPos(tbReader* r, const char* what)
{
	tbPos p;
	tbGetCoordinate(r, &p.x, sizeof(p.x));
	tbGetCoordinate(r, &p.y, sizeof(p.y));
	if (r->failed == false && (isfinite(p.x) == false || isfinite(p.y) == false))
	{
		tbFail(r, "%s is not finite", what);
		p.x = 0;
		p.y = 0;
	}
	return p;
}

/// tbPutFloatsOver's counterpart: each float finite.
static void tbGetFloatsOver(tbReader* r, float* values, const float* defaults, int count, const char* what)
{
	uint64_t mask = tbGetU64(r);
	if (r->failed == false && count < 64 && (mask >> count) != 0)
	{
		tbFail(r, "%s: a mask names fields that do not exist", what);
	}
	for (int i = 0; i < count; ++i)
	{
		bool stored = r->failed == false && (mask & ((uint64_t)1 << i)) != 0;
		values[i] = stored ? tbGetFloat(r, what) : (defaults != NULL ? defaults[i] : 0.0f);
	}
}

static bool tbIsNonNegative(float value)
{
	return tbIsValidFloat(value) && value >= 0.0f;
}

// --------------------------------------------------------------------------------------------
// The two sides of a restore: the image being read and the world being built from it (a world no
// one can reach until the whole image has been checked).

/// The largest value an image may give a counter the step adds to or multiplies (the broad phase's
/// 16 × enlarged count, the vote's sums): far beyond what any run reaches, far below an overflow.
#define TB_SNAPSHOT_COUNTER_MAX (1 << 26)

/// The body floats written as a mask and the ones that differ from their defaults (tbBodyFloats).
#define TB_BODY_FLOATS 14

/// A slot of a pool as the image describes it.
enum
{
	tb_slotLive = 0,	///< in use: its record is still to come
	tb_slotFree = 1,	///< on the free list
	tb_slotRetired = 2, ///< served its 65,535 generations (tbIdPool_Release)
	tb_slotRead = 3,	///< in use, record read
};

/// Shapes that share a geometry, or a density, material and filter, share one entry of a dictionary
/// (a pile of a few kinds of crate): an entry is written once, then named by its index.
typedef struct tbDictionary
{
	int* entries; ///< the shape that holds each entry, in the order entries were made
	int count, capacity;
	int* slots; ///< writing: hash slots, each an entry index + 1 (0 empty); a power of two of them
	int slotCount;
} tbDictionary;

typedef struct tbDecoder
{
	tbReader r;
	tbWorld* world; ///< the world being built (not registered)
	tbDictionary geometries;
	tbDictionary materials;
	int lastShape;
	int lastContactShape;
	float bodyDefaults[TB_BODY_FLOATS]; ///< tbBodyFloatDefaults, made once
	uint8_t* bodySlots;
	uint8_t* shapeSlots;
	uint8_t* shapeBoxes; ///< per shape slot: its tight box stored (1), its fat box stored (2)
	int* nameLengths; ///< per body slot: the name's length in the image (its bytes: nameSources)
	const char** nameSources;
} tbDecoder;

typedef struct tbEncoder
{
	tbWriter w;
	const tbWorld* world;
	const tbWorld* mixer; ///< the world with the default material mixing (contact predictions)
	tbDictionary geometries;
	tbDictionary materials;
	int lastShape;	 ///< the last shape id written (ids are written as differences)
	int lastContactShape;
	float bodyDefaults[TB_BODY_FLOATS]; ///< tbBodyFloatDefaults, made once
} tbEncoder;

// --------------------------------------------------------------------------------------------
// Settings: the world definition less its host wiring, and what the world keeps beside it.

enum
{
	tb_settingSubStepHertz = 1 << 0,
	tb_settingSleep = 1 << 1,
	tb_settingWarmStarting = 1 << 2,
	tb_settingWideSolver = 1 << 3,
	tb_settingJointTrees = 1 << 4,
	tb_settingCentralFriction = 1 << 5,
	tb_settingRecycling = 1 << 6,
	tb_settingImpactPropagation = 1 << 7,
	tb_settingSpeculative = 1 << 8,
	tb_settingContactSoftening = 1 << 9,
	tb_settingAll = (1 << 10) - 1,
};

static void tbSettingFloats(const tbWorldDef* d, float values[9])
{
	float v[9] = {d->gravity.x,			  d->gravity.y,			d->restitutionThreshold,
				  d->hitEventThreshold,	  d->contactHertz,		d->settledHertzRatio,
				  d->contactDampingRatio, d->contactSpeed, d->maximumLinearSpeed};
	memcpy(values, v, sizeof(v));
}

static void tbPutCapacity(tbWriter* w, const tbCapacity* c)
{
	tbPutUInt(w, (uint32_t)c->staticShapeCount);
	tbPutUInt(w, (uint32_t)c->dynamicShapeCount);
	tbPutUInt(w, (uint32_t)c->staticBodyCount);
	tbPutUInt(w, (uint32_t)c->dynamicBodyCount);
	tbPutUInt(w, (uint32_t)c->contactCount);
}

static void tbWriteSettings(tbEncoder* e)
{
	const tbWorld* world = e->world;
	const tbWorldDef* d = &world->def;
	tbWorldDef defaults = tbDefaultWorldDef();
	float values[9], defaultValues[9];
	tbSettingFloats(d, values);
	tbSettingFloats(&defaults, defaultValues);
	tbPutFloatsOver(&e->w, values, defaultValues, 9);
	uint32_t flags = (d->contactHertzFollowsSubStep ? tb_settingSubStepHertz : 0u) | (d->enableSleep ? tb_settingSleep : 0u) |
					 (d->enableWarmStarting ? tb_settingWarmStarting : 0u) |
					 (d->enableWideSolver ? tb_settingWideSolver : 0u) | (d->enableJointTrees ? tb_settingJointTrees : 0u) |
					 (d->enableCentralFriction ? tb_settingCentralFriction : 0u) |
					 (d->enableManifoldRecycling ? tb_settingRecycling : 0u) |
					 (d->enableImpactPropagation ? tb_settingImpactPropagation : 0u) |
					 (world->enableSpeculative ? tb_settingSpeculative : 0u) |
					 (d->enableContactSoftening ? tb_settingContactSoftening : 0u);
	tbPutUInt(&e->w, flags);
	tbPutUInt(&e->w, (uint32_t)d->broadPhase);
	tbPutUInt(&e->w, (uint32_t)d->narrowPhase);
	tbPutUInt(&e->w, (uint32_t)d->continuous);
	tbPutUInt(&e->w, (uint32_t)d->solver);
	tbPutUInt(&e->w, (uint32_t)world->continuousWhenEnabled);
	tbPutUInt(&e->w, (uint32_t)d->velocityIterations);
	tbPutUInt(&e->w, (uint32_t)d->positionIterations);
	tbPutUInt(&e->w, (uint32_t)d->relaxIterations);
	tbPutUInt(&e->w, (uint32_t)d->finalRelaxIterations);
	tbPutCapacity(&e->w, &d->capacity);
	tbPutCapacity(&e->w, &world->maxCapacity);
	tbPutFloat(&e->w, world->contactRecycleDistance);
	tbPutUInt(&e->w, world->stepIndex);
	tbPutFloat(&e->w, world->stepTime);
	tbPutFloat(&e->w, world->jointInvH);
	tbPutUInt(&e->w, (uint32_t)world->broadPhaseVote.windowSteps);
	tbPutUInt(&e->w, (uint32_t)world->broadPhaseVote.movedProxies);
	tbPutUInt(&e->w, (uint32_t)world->broadPhaseVote.fastBodies);
	tbPutUInt(&e->w, (uint32_t)world->broadPhaseVote.votes);
}

static int tbGetCountValue(tbReader* r, int limit, const char* what)
{
	uint32_t value = tbGetUInt(r);
	if (r->failed == false && value > (uint32_t)limit)
	{
		tbFail(r, "%s is %u (at most %d)", what, value, limit);
		return 0;
	}
	return (int)value;
}

static void tbGetCapacity(tbReader* r, tbCapacity* c, int limit, const char* what)
{
	c->staticShapeCount = tbGetCountValue(r, limit, what);
	c->dynamicShapeCount = tbGetCountValue(r, limit, what);
	c->staticBodyCount = tbGetCountValue(r, limit, what);
	c->dynamicBodyCount = tbGetCountValue(r, limit, what);
	c->contactCount = tbGetCountValue(r, limit, what);
}

static bool tbReadSettings(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	tbWorldDef* def = &world->def;
	r->section = "settings";
	*def = tbDefaultWorldDef();
	float values[9], defaultValues[9];
	tbSettingFloats(def, defaultValues);
	tbGetFloatsOver(r, values, defaultValues, 9, "a world setting");
	def->gravity = tbMakeVec2(values[0], values[1]);
	def->restitutionThreshold = values[2];
	def->hitEventThreshold = values[3];
	def->contactHertz = values[4];
	def->settledHertzRatio = values[5];
	def->contactDampingRatio = values[6];
	def->contactSpeed = values[7];
	def->maximumLinearSpeed = values[8];
	uint32_t flags = tbGetUInt(r);
	def->contactHertzFollowsSubStep = (flags & tb_settingSubStepHertz) != 0;
	def->enableSleep = (flags & tb_settingSleep) != 0;
	def->enableWarmStarting = (flags & tb_settingWarmStarting) != 0;
	def->enableWideSolver = (flags & tb_settingWideSolver) != 0;
	def->enableJointTrees = (flags & tb_settingJointTrees) != 0;
	def->enableCentralFriction = (flags & tb_settingCentralFriction) != 0;
	def->enableManifoldRecycling = (flags & tb_settingRecycling) != 0;
	def->enableImpactPropagation = (flags & tb_settingImpactPropagation) != 0;
	world->enableSpeculative = (flags & tb_settingSpeculative) != 0;
	def->enableContactSoftening = (flags & tb_settingContactSoftening) != 0;
	def->broadPhase = (tbBroadPhaseMethod)tbGetCountValue(r, tb_broadPhaseMethodCount - 1, "the broad-phase method");
	def->narrowPhase = (tbNarrowPhaseMethod)tbGetCountValue(r, tb_narrowPhaseGJK, "the narrow-phase method");
	def->continuous = (tbContinuousMethod)tbGetCountValue(r, tb_continuousMethodCount - 1, "the continuous method");
	def->solver = (tbSolverMethod)tbGetCountValue(r, tb_solverMethodCount - 1, "the solver method");
	world->continuousWhenEnabled =
		(tbContinuousMethod)tbGetCountValue(r, tb_continuousMethodCount - 1, "the continuous method kept aside");
	def->enableContinuous = def->continuous != tb_continuousOff; // one fact, held by the method
	def->velocityIterations = tbGetCountValue(r, TB_MAX_ITERATIONS, "the velocity iterations");
	def->positionIterations = tbGetCountValue(r, TB_MAX_ITERATIONS, "the position iterations");
	def->relaxIterations = tbGetCountValue(r, TB_MAX_ITERATIONS, "the relax iterations");
	def->finalRelaxIterations = tbGetCountValue(r, TB_MAX_ITERATIONS, "the final relax iterations");
	tbGetCapacity(r, &def->capacity, 1 << 22, "a capacity of the world definition");
	tbGetCapacity(r, &world->maxCapacity, INT32_MAX, "a largest count seen");
	world->contactRecycleDistance = tbGetFloat(r, "the contact recycle distance");
	world->stepIndex = tbGetUInt(r);
	world->stepTime = tbGetFloat(r, "the last time step");
	world->jointInvH = tbGetFloat(r, "the joints' inverse sub-step");
	// Counters the step adds to: bounded well below where an int would overflow.
	world->broadPhaseVote.windowSteps = tbGetCountValue(r, TB_SNAPSHOT_COUNTER_MAX, "the broad-phase vote");
	world->broadPhaseVote.movedProxies = tbGetCountValue(r, TB_SNAPSHOT_COUNTER_MAX, "the broad-phase vote");
	world->broadPhaseVote.fastBodies = tbGetCountValue(r, TB_SNAPSHOT_COUNTER_MAX, "the broad-phase vote");
	world->broadPhaseVote.votes = tbGetCountValue(r, TB_SNAPSHOT_COUNTER_MAX, "the broad-phase vote");
	if (r->failed)
	{
		return false;
	}
	// What tbCreateWorld and the setters accept (tbCheckWorldDef), and nothing the step could not use.
	if ((flags & ~(uint32_t)tb_settingAll) != 0 || tbIsNonNegative(def->restitutionThreshold) == false ||
		tbIsNonNegative(def->hitEventThreshold) == false || !(def->contactHertz > 0.0f) ||
		!(def->settledHertzRatio > 0.0f && def->settledHertzRatio <= 1000.0f) ||
		tbIsNonNegative(def->contactDampingRatio) == false || !(def->contactSpeed > 0.0f) ||
		!(def->maximumLinearSpeed > 0.0f && def->maximumLinearSpeed <= TB_MAX_LINEAR_SPEED) || def->velocityIterations < 1)
	{
		return tbFail(r, "its world settings are out of range (a threshold, stiffness, speed or iteration count the API "
						 "refuses)");
	}
	if (tbIsNonNegative(world->contactRecycleDistance) == false || world->contactRecycleDistance > TB_MAX_COORDINATE ||
		tbIsNonNegative(world->jointInvH) == false ||
		(world->stepTime != 0.0f && !(world->stepTime >= TB_MIN_TIME_STEP && world->stepTime <= TB_MAX_TIME_STEP)))
	{
		return tbFail(r, "its recycle distance, last time step or joint sub-step is out of range");
	}
	world->gravityLength = tbLength(def->gravity); // what creation, tbWorld_SetGravity and the step set
	return true;
}

// --------------------------------------------------------------------------------------------
// Id pools: the high water, the free list in order (the next id handed out is its last) and each
// slot's generation as its offset from the slot's first one (small numbers: most slots served few
// objects).

static void tbWritePool(tbEncoder* e, const tbIdPool* pool, const void* slots, size_t stride, size_t offset, int bytes,
						uint32_t first)
{
	tbPutUInt(&e->w, (uint32_t)pool->highWater);
	tbPutUInt(&e->w, (uint32_t)pool->freeCount);
	for (int i = 0; i < pool->freeCount; ++i)
	{
		tbPutUInt(&e->w, (uint32_t)pool->freeIds[i]);
	}
	for (int i = 0; i < pool->highWater; ++i)
	{
		const char* slot = (const char*)slots + (size_t)i * stride + offset;
		uint32_t generation;
		if (bytes == 2)
		{
			uint16_t g;
			memcpy(&g, slot, 2);
			generation = (uint16_t)(g - (uint16_t)first);
		}
		else
		{
			memcpy(&generation, slot, 4);
			generation -= first;
		}
		tbPutUInt(&e->w, generation);
	}
}

/// The pool's slots as the image describes them (tb_slot*), and each slot's generation offset, in
/// arrays the caller frees (highWater + 1 entries). Slots that retire (`retires`: 16-bit
/// generations) are those whose offset reached 65,535; the rest that are not free are in use. The
/// pool is set only when the whole of it was read (a world freed half-read walks its pools).
static bool tbReadPool(tbDecoder* d, tbIdPool* pool, uint8_t** slotsOut, uint32_t** generationsOut, bool retires,
					   const char* what)
{
	tbReader* r = &d->r;
	*slotsOut = NULL;
	*generationsOut = NULL;
	int highWater = tbGetCount(r, 1, what); // a generation byte per slot, at least
	int freeCount = tbGetCount(r, 1, what);
	if (r->failed)
	{
		return false;
	}
	if (freeCount > highWater)
	{
		return tbFail(r, "its %s pool lists %d free ids but has only %d slots", what, freeCount, highWater);
	}
	uint8_t* slots = tbAlloc(highWater + 1);
	uint32_t* generations = tbAlloc((highWater + 1) * (int)sizeof(uint32_t));
	int* freeIds = freeCount > 0 ? tbAlloc(freeCount * (int)sizeof(int)) : NULL;
	memset(slots, tb_slotLive, (size_t)highWater + 1);
	for (int i = 0; i < freeCount && r->failed == false; ++i)
	{
		int id = tbGetIndex(r, highWater, "a free id");
		if (r->failed == false && slots[id] != tb_slotLive)
		{
			tbFail(r, "its %s pool lists id %d as free twice", what, id);
		}
		slots[id] = tb_slotFree;
		freeIds[i] = id;
	}
	int live = 0;
	for (int i = 0; i < highWater && r->failed == false; ++i)
	{
		uint32_t generation = tbGetUInt(r);
		if (retires && generation > UINT16_MAX)
		{
			tbFail(r, "a %s generation is %u (16 bits)", what, generation);
		}
		generations[i] = generation;
		if (retires && generation == UINT16_MAX)
		{
			if (slots[i] == tb_slotFree)
			{
				tbFail(r, "%s slot %d is both free and retired", what, i);
			}
			slots[i] = tb_slotRetired;
		}
		live += slots[i] == tb_slotLive ? 1 : 0;
	}
	if (r->failed)
	{
		tbFree(slots, highWater + 1);
		tbFree(generations, (highWater + 1) * (int)sizeof(uint32_t));
		tbFree(freeIds, freeCount * (int)sizeof(int));
		return false;
	}
	*slotsOut = slots;
	*generationsOut = generations;
	pool->highWater = highWater;
	pool->freeIds = freeIds;
	pool->freeCount = freeCount;
	pool->freeCapacity = freeCount;
	pool->count = live;
	return true;
}

static void tbFreeSlots(uint8_t** slots, uint32_t** generations, int highWater)
{
	tbFree(*slots, highWater + 1);
	tbFree(*generations, (highWater + 1) * (int)sizeof(uint32_t));
	*slots = NULL;
	*generations = NULL;
}

// --------------------------------------------------------------------------------------------
// Bodies and their shapes. A body's record holds its shapes in the order of its list; the values
// derived from them (mass, origin, extents, reach, tight boxes) follow, each stored only when
// recomputing it from what precedes would not give the same bits.

enum
{
	tb_bodyTypeBits = 3,
	tb_bodySleep = 1 << 2,
	tb_bodyFixedRotation = 1 << 3,
	tb_bodyLockX = 1 << 4,
	tb_bodyLockY = 1 << 5,
	tb_bodyBullet = 1 << 6,
	tb_bodyDisabled = 1 << 7,
	tb_bodyFast = 1 << 8,
	tb_bodyNoRecycling = 1 << 9,
	tb_bodyMarked = 1 << 10,
	tb_bodyNamed = 1 << 11,
	tb_bodyMassStored = 1 << 12,
	tb_bodyOriginStored = 1 << 13,
	tb_bodyExtentsStored = 1 << 14,
	tb_bodyReachStored = 1 << 15,
	tb_bodyStartStored = 1 << 16, ///< the pose at the start of the last step differs from the pose now
	tb_bodyFastRotation = 1 << 17,
	tb_bodyAll = (1 << 18) - 1,
};

enum
{
	tb_shapeTypeBits = 7,
	tb_shapeSensor = 1 << 3,
	tb_shapeSensorEvents = 1 << 4,
	tb_shapeContactEvents = 1 << 5,
	tb_shapeHitEvents = 1 << 6,
	tb_shapeCustomFiltering = 1 << 7,
	tb_shapePreSolveEvents = 1 << 8,
	tb_shapeProxyMoved = 1 << 9,
	tb_shapePolygonStored = 1 << 10, ///< normals and centroid written (not tbMakePolygon's)
	tb_shapeBoxStored = 1 << 11,
	tb_shapeFatStored = 1 << 12, ///< the fat box is written (neither the tight box nor a remade one)
	tb_shapeFatRemade = 1 << 13, ///< the fat box is the one the last finalize made (tbRemadeFatAABB)
	tb_shapeAll = (1 << 14) - 1,
};

/// The body floats that are mostly their defaults (velocities, rotation, sleep time, forces,
/// parameters), the most often changed first so that their mask fits a byte.

static void tbBodyFloats(const tbBody* b, float v[TB_BODY_FLOATS])
{
	float values[TB_BODY_FLOATS] = {b->linearVelocity.x, b->linearVelocity.y, b->angularVelocity, b->transform.q.c,
									b->transform.q.s,	 b->sleepTime,		  b->force.x,		  b->force.y,
									b->torque,			 b->gravityScale,	  b->linearDamping,	  b->angularDamping,
									b->sleepThreshold,	 b->safetyFactor};
	memcpy(v, values, sizeof(values));
}

static void tbBodyFloatDefaults(float v[TB_BODY_FLOATS])
{
	tbBodyDef def = tbDefaultBodyDef();
	float values[TB_BODY_FLOATS] = {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, def.gravityScale,
									def.linearDamping, def.angularDamping, def.sleepThreshold, def.safetyFactor};
	memcpy(v, values, sizeof(values));
}

/// The origin the scatter stage writes from the centre of mass (solver.c).
static tbPos tbPredictOrigin(const tbBody* body)
{
	return tbOffsetPos(body->center, tbNeg(tbRotateVector(body->transform.q, body->localCenter)));
}

static bool tbSamePos(tbPos a, tbPos b)
{
	return memcmp(&a.x, &b.x, sizeof(a.x)) == 0 && memcmp(&a.y, &b.y, sizeof(a.y)) == 0;
}

static bool tbSameAABB(tbAABB a, tbAABB b)
{
	return tbSameVec2(a.lowerBound, b.lowerBound) && tbSameVec2(a.upperBound, b.upperBound);
}

static bool tbSameMass(const tbBody* b, tbBodyMass m)
{
	return tbSameFloat(b->mass, m.mass) && tbSameFloat(b->invMass, m.invMass) && tbSameFloat(b->inertia, m.inertia) &&
		   tbSameFloat(b->invInertia, m.invInertia) && tbSameVec2(b->localCenter, m.localCenter);
}

static float tbPredictReach(const tbBody* body)
{
	return tbMaxFloat(TB_SPECULATIVE_REACH, body->safetyFactor * body->minExtent);
}

/// The polygon tbMakePolygon makes of these vertices and radius, when they form a valid hull.
static bool tbRemakePolygon(const tbPolygon* p, tbPolygon* out)
{
	if (p->count < 3 || p->count > TB_MAX_POLYGON_VERTICES)
	{
		return false;
	}
	tbHull hull;
	memset(&hull, 0, sizeof(hull));
	hull.count = p->count;
	memcpy(hull.points, p->vertices, (size_t)p->count * sizeof(tbVec2));
	if (tbValidateHull(&hull) == false || tbIsValidFloat(p->radius) == false || p->radius < 0.0f ||
		p->radius > TB_MAX_COORDINATE)
	{
		return false;
	}
	*out = tbMakePolygon(&hull, p->radius);
	return true;
}

static bool tbSamePolygonDerived(const tbPolygon* a, const tbPolygon* b)
{
	for (int i = 0; i < a->count; ++i)
	{
		if (tbSameVec2(a->normals[i], b->normals[i]) == false)
		{
			return false;
		}
	}
	return tbSameVec2(a->centroid, b->centroid);
}

static bool tbSameGeometry(const tbGeometry* a, const tbGeometry* b)
{
	if (a->type != b->type)
	{
		return false;
	}
	switch (a->type)
	{
		case tb_circleShape:
			return memcmp(&a->circle, &b->circle, sizeof(tbCircle)) == 0;
		case tb_capsuleShape:
			return memcmp(&a->capsule, &b->capsule, sizeof(tbCapsule)) == 0;
		case tb_segmentShape:
			return memcmp(&a->segment, &b->segment, sizeof(tbSegment)) == 0;
		case tb_chainSegmentShape:
			return memcmp(&a->chainSegment, &b->chainSegment, sizeof(tbChainSegment)) == 0;
		default:
		{
			const tbPolygon* p = &a->polygon;
			const tbPolygon* q = &b->polygon;
			return p->count == q->count && memcmp(p->vertices, q->vertices, (size_t)p->count * sizeof(tbVec2)) == 0 &&
				   memcmp(p->normals, q->normals, (size_t)p->count * sizeof(tbVec2)) == 0 &&
				   tbSameVec2(p->centroid, q->centroid) && tbSameFloat(p->radius, q->radius);
		}
	}
}

static bool tbSameMaterial(const tbSurfaceMaterial* a, const tbSurfaceMaterial* b)
{
	return tbSameFloat(a->friction, b->friction) && tbSameFloat(a->restitution, b->restitution) &&
		   tbSameFloat(a->rollingResistance, b->rollingResistance) && tbSameFloat(a->tangentSpeed, b->tangentSpeed) &&
		   a->userMaterialId == b->userMaterialId && a->customColor == b->customColor;
}

static bool tbSameMaterialBlock(const tbShape* a, const tbShape* b)
{
	return tbSameFloat(a->density, b->density) && tbSameMaterial(&a->material, &b->material) &&
		   a->filter.categoryBits == b->filter.categoryBits && a->filter.maskBits == b->filter.maskBits &&
		   a->filter.groupIndex == b->filter.groupIndex;
}

/// A hash of bytes for the dictionaries, four at a time (FNV-1a's step on 32-bit words).
static uint64_t tbHashBytes(uint64_t h, const void* data, size_t count)
{
	const uint8_t* bytes = data;
	size_t i = 0;
	for (; i + 4 <= count; i += 4)
	{
		uint32_t word;
		memcpy(&word, bytes + i, 4);
		h = (h ^ word) * 1099511628211ull;
	}
	for (; i < count; ++i)
	{
		h = (h ^ bytes[i]) * 1099511628211ull;
	}
	return h ^ (h >> 29);
}

static uint64_t tbHashGeometry(const tbGeometry* g)
{
	uint64_t h = tbHashBytes(14695981039346656037ull, &g->type, sizeof(g->type));
	switch (g->type)
	{
		case tb_circleShape:
			return tbHashBytes(h, &g->circle, sizeof(tbCircle));
		case tb_capsuleShape:
			return tbHashBytes(h, &g->capsule, sizeof(tbCapsule));
		case tb_segmentShape:
			return tbHashBytes(h, &g->segment, sizeof(tbSegment));
		case tb_chainSegmentShape:
			return tbHashBytes(h, &g->chainSegment, sizeof(tbChainSegment));
		default:
			h = tbHashBytes(h, g->polygon.vertices, (size_t)g->polygon.count * sizeof(tbVec2));
			return tbHashBytes(h, &g->polygon.radius, sizeof(float));
	}
}

static uint64_t tbHashMaterialBlock(const tbShape* shape)
{
	uint64_t h = tbHashBytes(14695981039346656037ull, &shape->density, sizeof(float));
	h = tbHashBytes(h, &shape->material.friction, 4 * sizeof(float));
	h = tbHashBytes(h, &shape->material.userMaterialId, sizeof(uint64_t));
	h = tbHashBytes(h, &shape->filter.categoryBits, sizeof(uint64_t));
	return tbHashBytes(h, &shape->filter.maskBits, sizeof(uint64_t));
}

static void tbDictionaryFree(tbDictionary* d)
{
	TB_ARRAY_FREE(d->entries, d->capacity);
	tbFree(d->slots, d->slotCount * (int)sizeof(int));
	memset(d, 0, sizeof(*d));
}

/// The entry equal to `shape`'s geometry (materials: its density, material and filter), or −1 after
/// making it the next entry.
static int tbDictionaryFind(tbDictionary* d, const tbWorld* world, int shapeId, bool materials)
{
	const tbShape* shape = world->shapes + shapeId;
	uint64_t h = materials ? tbHashMaterialBlock(shape) : tbHashGeometry(&shape->geometry);
	int mask = d->slotCount - 1;
	for (int slot = (int)(h & (uint64_t)mask);; slot = (slot + 1) & mask)
	{
		int entry = d->slots[slot] - 1;
		if (entry < 0)
		{
			d->slots[slot] = d->count + 1;
			TB_ARRAY_PUSH(d->entries, d->count, d->capacity, shapeId);
			return -1;
		}
		const tbShape* other = world->shapes + d->entries[entry];
		if (materials ? tbSameMaterialBlock(shape, other) : tbSameGeometry(&shape->geometry, &other->geometry))
		{
			return entry;
		}
	}
}

static void tbWriteGeometry(tbWriter* w, const tbGeometry* g, bool polygonStored)
{
	switch (g->type)
	{
		case tb_circleShape:
			tbPutVec2(w, g->circle.center);
			tbPutFloat(w, g->circle.radius);
			break;
		case tb_capsuleShape:
			tbPutVec2(w, g->capsule.center1);
			tbPutVec2(w, g->capsule.center2);
			tbPutFloat(w, g->capsule.radius);
			break;
		case tb_segmentShape:
			tbPutVec2(w, g->segment.point1);
			tbPutVec2(w, g->segment.point2);
			break;
		case tb_chainSegmentShape:
			tbPutVec2(w, g->chainSegment.ghost1);
			tbPutVec2(w, g->chainSegment.segment.point1);
			tbPutVec2(w, g->chainSegment.segment.point2);
			tbPutVec2(w, g->chainSegment.ghost2);
			tbPutInt(w, g->chainSegment.chainId);
			break;
		default:
			tbPutUInt(w, (uint32_t)g->polygon.count);
			for (int i = 0; i < g->polygon.count; ++i)
			{
				tbPutVec2(w, g->polygon.vertices[i]);
			}
			tbPutFloat(w, g->polygon.radius);
			if (polygonStored)
			{
				for (int i = 0; i < g->polygon.count; ++i)
				{
					tbPutVec2(w, g->polygon.normals[i]);
				}
				tbPutVec2(w, g->polygon.centroid);
			}
			break;
	}
}

#define TB_MATERIAL_FLOATS 5

static void tbMaterialFloats(float density, const tbSurfaceMaterial* m, float v[TB_MATERIAL_FLOATS])
{
	float values[TB_MATERIAL_FLOATS] = {density, m->friction, m->restitution, m->rollingResistance, m->tangentSpeed};
	memcpy(v, values, sizeof(values));
}

/// How a shape's fat box is written: as its tight box (static shapes), as the one the last finalize
/// made (shapes that moved), or as it is.
static uint32_t tbFatBoxFlag(const tbWorld* world, const tbBody* body, const tbShape* shape)
{
	if (tbSameAABB(shape->fatAABB, shape->aabb))
	{
		return 0u;
	}
	return tbSameAABB(shape->fatAABB, tbRemadeFatAABB(world, body, shape)) ? (uint32_t)tb_shapeFatRemade
																		 : (uint32_t)tb_shapeFatStored;
}

static void tbWriteShape(tbEncoder* e, int id, const tbShape* shape, const tbBody* body)
{
	tbWriter* w = &e->w;
	uint32_t flags = (uint32_t)shape->geometry.type;
	flags |= (shape->isSensor ? tb_shapeSensor : 0u) | (shape->enableSensorEvents ? tb_shapeSensorEvents : 0u) |
			 (shape->enableContactEvents ? tb_shapeContactEvents : 0u) | (shape->enableHitEvents ? tb_shapeHitEvents : 0u) |
			 (shape->enableCustomFiltering ? tb_shapeCustomFiltering : 0u) |
			 (shape->enablePreSolveEvents ? tb_shapePreSolveEvents : 0u) | (shape->proxyMoved ? tb_shapeProxyMoved : 0u);
	int geometryEntry = tbDictionaryFind(&e->geometries, e->world, id, false);
	bool polygonStored = false;
	if (shape->geometry.type == tb_polygonShape && geometryEntry < 0)
	{
		tbPolygon remade;
		polygonStored = tbRemakePolygon(&shape->geometry.polygon, &remade) == false ||
						tbSamePolygonDerived(&shape->geometry.polygon, &remade) == false;
	}
	flags |= polygonStored ? tb_shapePolygonStored : 0u;
	tbAABB box = tbComputeShapeAABBInternal(shape, body->transform);
	flags |= tbSameAABB(box, shape->aabb) ? 0u : tb_shapeBoxStored;
	flags |= tbFatBoxFlag(e->world, body, shape);
	int materialEntry = tbDictionaryFind(&e->materials, e->world, id, true);

	tbPutDelta(w, id, e->lastShape + 1);
	e->lastShape = id;
	tbPutUInt(w, flags);
	tbPutUInt(w, (uint32_t)(geometryEntry + 1)); // 0: a new geometry follows
	if (geometryEntry < 0)
	{
		tbWriteGeometry(w, &shape->geometry, polygonStored);
	}
	tbPutUInt(w, (uint32_t)(materialEntry + 1));
	if (materialEntry < 0)
	{
		tbShapeDef def = tbDefaultShapeDef();
		float values[TB_MATERIAL_FLOATS], defaults[TB_MATERIAL_FLOATS];
		tbMaterialFloats(shape->density, &shape->material, values);
		tbMaterialFloats(def.density, &def.material, defaults);
		tbPutFloatsOver(w, values, defaults, TB_MATERIAL_FLOATS);
		tbPutU64(w, shape->material.userMaterialId);
		tbPutUInt(w, shape->material.customColor);
		tbPutU64(w, shape->filter.categoryBits ^ def.filter.categoryBits);
		tbPutU64(w, shape->filter.maskBits ^ def.filter.maskBits);
		tbPutInt(w, shape->filter.groupIndex);
	}
	tbPutDelta(w, shape->proxyKey, id); // a shape's proxy key is most often its id
}

static void tbWriteBody(tbEncoder* e, const tbBody* body)
{
	const tbWorld* world = e->world;
	tbWriter* w = &e->w;
	uint32_t flags = (uint32_t)body->type;
	flags |= (body->enableSleep ? tb_bodySleep : 0u) | (body->fixedRotation ? tb_bodyFixedRotation : 0u) |
			 (body->lockLinearX ? tb_bodyLockX : 0u) | (body->lockLinearY ? tb_bodyLockY : 0u) |
			 (body->isBullet ? tb_bodyBullet : 0u) | (body->isDisabled ? tb_bodyDisabled : 0u) |
			 (body->allowFastRotation ? tb_bodyFastRotation : 0u) |
			 (body->isFast ? tb_bodyFast : 0u) | (body->enableContactRecycling ? 0u : tb_bodyNoRecycling) |
			 (body->isMarked ? tb_bodyMarked : 0u) | (body->name != NULL ? tb_bodyNamed : 0u);
	bool massStored = tbSameMass(body, tbComputeBodyMass(world, body)) == false;
	bool originStored = tbSamePos(body->transform.p, tbPredictOrigin(body)) == false;
	float minExtent, maxExtent, coreExtent;
	tbComputeBodyExtents(world, body, &minExtent, &maxExtent, &coreExtent);
	bool extentsStored = tbSameFloat(minExtent, body->minExtent) == false || tbSameFloat(maxExtent, body->maxExtent) == false;
	bool reachStored = tbSameFloat(tbPredictReach(body), body->speculativeReach) == false;
	bool startStored = tbSamePos(body->center0, body->center) == false || tbSameFloat(body->rotation0.c, body->transform.q.c) == false ||
					   tbSameFloat(body->rotation0.s, body->transform.q.s) == false;
	flags |= startStored ? tb_bodyStartStored : 0u;
	flags |= (massStored ? tb_bodyMassStored : 0u) | (originStored ? tb_bodyOriginStored : 0u) |
			 (extentsStored ? tb_bodyExtentsStored : 0u) | (reachStored ? tb_bodyReachStored : 0u);
	tbPutUInt(w, flags);
	tbPutPos(w, body->center);
	float values[TB_BODY_FLOATS];
	tbBodyFloats(body, values);
	tbPutFloatsOver(w, values, e->bodyDefaults, TB_BODY_FLOATS);
	if (body->name != NULL)
	{
		int length = (int)strlen(body->name);
		tbPutUInt(w, (uint32_t)length);
		tbPutBytes(w, body->name, length);
	}
	tbPutUInt(w, (uint32_t)body->shapeCount);
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		tbWriteShape(e, id, world->shapes + id, body);
	}
	if (massStored)
	{
		tbPutFloat(w, body->mass);
		tbPutFloat(w, body->invMass);
		tbPutFloat(w, body->inertia);
		tbPutFloat(w, body->invInertia);
		tbPutVec2(w, body->localCenter);
	}
	if (originStored)
	{
		tbPutPos(w, body->transform.p);
	}
	if (extentsStored)
	{
		tbPutFloat(w, body->minExtent);
		tbPutFloat(w, body->maxExtent);
	}
	if (reachStored)
	{
		tbPutFloat(w, body->speculativeReach);
	}
	if (startStored)
	{
		tbPutPos(w, body->center0);
		tbPutRot(w, body->rotation0);
	}
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		const tbShape* shape = world->shapes + id;
		if (tbSameAABB(tbComputeShapeAABBInternal(shape, body->transform), shape->aabb) == false)
		{
			tbPutAABB(w, shape->aabb);
		}
		if (tbFatBoxFlag(world, body, shape) == tb_shapeFatStored)
		{
			tbPutAABB(w, shape->fatAABB);
		}
	}
}

static void tbWriteBodies(tbEncoder* e)
{
	const tbWorld* world = e->world;
	int slotCount = 16;
	while (slotCount < 2 * world->shapePool.count)
	{
		slotCount *= 2;
	}
	tbDictionary* dictionaries[2] = {&e->geometries, &e->materials};
	for (int k = 0; k < 2; ++k)
	{
		memset(dictionaries[k], 0, sizeof(tbDictionary));
		dictionaries[k]->slots = tbAlloc(slotCount * (int)sizeof(int));
		dictionaries[k]->slotCount = slotCount;
		memset(dictionaries[k]->slots, 0, (size_t)slotCount * sizeof(int));
	}
	tbWritePool(e, &world->bodyPool, world->bodies, sizeof(tbBody), offsetof(tbBody, generation), 2,
				world->bodyGenerationBase);
	tbWritePool(e, &world->shapePool, world->shapes, sizeof(tbShape), offsetof(tbShape, generation), 2,
				world->shapeGenerationBase);
	for (int i = 0; i < world->bodyPool.highWater; ++i)
	{
		if (world->bodies[i].inUse)
		{
			tbWriteBody(e, world->bodies + i);
		}
	}
	tbDictionaryFree(&e->geometries);
	tbDictionaryFree(&e->materials);
}

// Reading. Geometry is checked as tbCreateShape checks it (without reporting: the restore reports
// once, naming what was wrong).

static bool tbIsLength(float value, bool positive)
{
	return tbIsValidFloat(value) && (positive ? value > 0.0f : value >= 0.0f) && value <= TB_MAX_COORDINATE;
}

static bool tbIsValidGeometry(const tbGeometry* g)
{
	float slop2 = TB_LINEAR_SLOP * TB_LINEAR_SLOP;
	switch (g->type)
	{
		case tb_circleShape:
			return tbIsCoordinate(g->circle.center) && tbIsLength(g->circle.radius, true);
		case tb_capsuleShape:
			return tbIsCoordinate(g->capsule.center1) && tbIsCoordinate(g->capsule.center2) &&
				   tbIsLength(g->capsule.radius, true) && tbDistanceSquared(g->capsule.center1, g->capsule.center2) >= slop2;
		case tb_segmentShape:
			return tbIsCoordinate(g->segment.point1) && tbIsCoordinate(g->segment.point2) &&
				   tbDistanceSquared(g->segment.point1, g->segment.point2) >= slop2;
		case tb_chainSegmentShape:
		{
			const tbChainSegment* c = &g->chainSegment;
			return tbIsCoordinate(c->ghost1) && tbIsCoordinate(c->segment.point1) && tbIsCoordinate(c->segment.point2) &&
				   tbIsCoordinate(c->ghost2) && tbDistanceSquared(c->segment.point1, c->segment.point2) >= slop2;
		}
		case tb_polygonShape:
		{
			const tbPolygon* p = &g->polygon;
			if (p->count < 3 || p->count > TB_MAX_POLYGON_VERTICES || tbIsLength(p->radius, false) == false ||
				tbIsCoordinate(p->centroid) == false)
			{
				return false;
			}
			for (int i = 0; i < p->count; ++i)
			{
				if (tbIsCoordinate(p->vertices[i]) == false || tbIsValidVec2(p->normals[i]) == false)
				{
					return false;
				}
			}
			return tbIsConvexPolygon(p);
		}
		default:
			return false;
	}
}

static bool tbReadGeometry(tbDecoder* d, tbGeometry* g, tbShapeType type, bool polygonStored)
{
	tbReader* r = &d->r;
	memset(g, 0, sizeof(*g));
	g->type = type;
	const char* what = "a shape's geometry";
	switch (type)
	{
		case tb_circleShape:
			g->circle.center = tbGetVec2(r, what);
			g->circle.radius = tbGetFloat(r, what);
			break;
		case tb_capsuleShape:
			g->capsule.center1 = tbGetVec2(r, what);
			g->capsule.center2 = tbGetVec2(r, what);
			g->capsule.radius = tbGetFloat(r, what);
			break;
		case tb_segmentShape:
			g->segment.point1 = tbGetVec2(r, what);
			g->segment.point2 = tbGetVec2(r, what);
			break;
		case tb_chainSegmentShape:
			g->chainSegment.ghost1 = tbGetVec2(r, what);
			g->chainSegment.segment.point1 = tbGetVec2(r, what);
			g->chainSegment.segment.point2 = tbGetVec2(r, what);
			g->chainSegment.ghost2 = tbGetVec2(r, what);
			g->chainSegment.chainId = tbGetInt(r);
			break;
		default:
		{
			tbPolygon* p = &g->polygon;
			p->count = tbGetCountValue(r, TB_MAX_POLYGON_VERTICES, "a polygon's vertex count");
			for (int i = 0; i < p->count; ++i)
			{
				p->vertices[i] = tbGetVec2(r, what);
			}
			p->radius = tbGetFloat(r, what);
			if (r->failed)
			{
				return false;
			}
			if (polygonStored)
			{
				for (int i = 0; i < p->count; ++i)
				{
					p->normals[i] = tbGetVec2(r, what);
				}
				p->centroid = tbGetVec2(r, what);
			}
			else
			{
				tbPolygon remade;
				if (tbRemakePolygon(p, &remade) == false)
				{
					return tbFail(r, "a polygon to be made from its vertices is not a valid hull");
				}
				*p = remade;
			}
			break;
		}
	}
	return r->failed == false;
}

static bool tbReadShape(tbDecoder* d, int bodyIndex, int* shapeIdOut)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	int id = tbGetDelta(r, d->lastShape + 1, 0, world->shapePool.highWater, "a body's shape id");
	d->lastShape = id;
	if (r->failed)
	{
		return false;
	}
	if (d->shapeSlots[id] != tb_slotLive)
	{
		return tbFail(r, "shape %d is listed by a body but is free, retired or listed twice", id);
	}
	d->shapeSlots[id] = tb_slotRead;
	*shapeIdOut = id;
	tbShape* shape = world->shapes + id;
	uint32_t flags = tbGetUInt(r);
	uint32_t type = flags & tb_shapeTypeBits;
	if (r->failed == false && ((flags & ~(uint32_t)tb_shapeAll) != 0 || type >= tb_shapeTypeCount))
	{
		return tbFail(r, "shape %d has unknown flags or type", id);
	}
	shape->inUse = true;
	shape->bodyId = bodyIndex;
	shape->isSensor = (flags & tb_shapeSensor) != 0;
	shape->enableSensorEvents = (flags & tb_shapeSensorEvents) != 0;
	shape->enableContactEvents = (flags & tb_shapeContactEvents) != 0;
	shape->enableHitEvents = (flags & tb_shapeHitEvents) != 0;
	shape->enableCustomFiltering = (flags & tb_shapeCustomFiltering) != 0;
	shape->enablePreSolveEvents = (flags & tb_shapePreSolveEvents) != 0;
	shape->proxyMoved = (flags & tb_shapeProxyMoved) != 0;
	if ((flags & tb_shapeFatStored) && (flags & tb_shapeFatRemade))
	{
		return tbFail(r, "shape %d has its fat box both written and remade", id);
	}
	d->shapeBoxes[id] = (uint8_t)(((flags & tb_shapeBoxStored) ? 1u : 0u) | ((flags & tb_shapeFatStored) ? 2u : 0u) |
								  ((flags & tb_shapeFatRemade) ? 4u : 0u));
	// A dictionary entry's value was checked when it was first read.
	int geometryEntry = (int)tbGetUInt(r) - 1;
	if (r->failed == false && geometryEntry >= d->geometries.count)
	{
		return tbFail(r, "shape %d names geometry %d of %d", id, geometryEntry, d->geometries.count);
	}
	if (geometryEntry >= 0)
	{
		const tbShape* other = world->shapes + d->geometries.entries[geometryEntry];
		if (other->geometry.type != (tbShapeType)type)
		{
			return tbFail(r, "shape %d names a geometry of another type", id);
		}
		shape->geometry = other->geometry;
	}
	else if (tbReadGeometry(d, &shape->geometry, (tbShapeType)type, (flags & tb_shapePolygonStored) != 0) == false)
	{
		return false;
	}
	else if (tbIsValidGeometry(&shape->geometry) == false)
	{
		return tbFail(r, "shape %d has invalid geometry (not finite, beyond TB_MAX_COORDINATE, too short, or a polygon "
						 "that is not convex)", id);
	}
	else
	{
		TB_ARRAY_PUSH(d->geometries.entries, d->geometries.count, d->geometries.capacity, id);
	}
	int materialEntry = (int)tbGetUInt(r) - 1;
	if (r->failed == false && materialEntry >= d->materials.count)
	{
		return tbFail(r, "shape %d names material %d of %d", id, materialEntry, d->materials.count);
	}
	if (materialEntry >= 0)
	{
		const tbShape* other = world->shapes + d->materials.entries[materialEntry];
		shape->density = other->density;
		shape->material = other->material;
		shape->filter = other->filter;
	}
	else
	{
		tbShapeDef def = tbDefaultShapeDef();
		float values[TB_MATERIAL_FLOATS], defaults[TB_MATERIAL_FLOATS];
		tbMaterialFloats(def.density, &def.material, defaults);
		tbGetFloatsOver(r, values, defaults, TB_MATERIAL_FLOATS, "a shape's material");
		shape->material = def.material;
		shape->density = values[0];
		shape->material.friction = values[1];
		shape->material.restitution = values[2];
		shape->material.rollingResistance = values[3];
		shape->material.tangentSpeed = values[4];
		shape->material.userMaterialId = tbGetU64(r);
		shape->material.customColor = tbGetUInt(r);
		shape->filter.categoryBits = def.filter.categoryBits ^ tbGetU64(r);
		shape->filter.maskBits = def.filter.maskBits ^ tbGetU64(r);
		shape->filter.groupIndex = tbGetInt(r);
		TB_ARRAY_PUSH(d->materials.entries, d->materials.count, d->materials.capacity, id);
	}
	shape->proxyKey = tbGetDelta(r, id, TB_NULL_INDEX, INT32_MAX, "a shape's proxy key");
	if (r->failed)
	{
		return false;
	}
	const tbSurfaceMaterial* m = &shape->material;
	if (tbIsNonNegative(shape->density) == false || tbIsNonNegative(m->friction) == false ||
		tbIsNonNegative(m->restitution) == false || tbIsNonNegative(m->rollingResistance) == false)
	{
		return tbFail(r, "shape %d has a negative density, friction, restitution or rolling resistance", id);
	}
	tbMassData md = tbComputeShapeMass(&shape->geometry, shape->density);
	if (!(md.mass <= TB_MAX_SHAPE_MASS) || tbIsValidFloat(md.rotationalInertia) == false)
	{
		return tbFail(r, "shape %d weighs more than TB_MAX_SHAPE_MASS", id);
	}
	if (shape->proxyKey < TB_NULL_INDEX)
	{
		return tbFail(r, "shape %d has proxy key %d", id, shape->proxyKey);
	}
	return true;
}

static bool tbReadBody(tbDecoder* d, int index)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	tbBody* body = world->bodies + index;
	uint16_t generation = body->generation;
	memset(body, 0, sizeof(*body));
	body->generation = generation;
	body->inUse = true;
	body->headShapeId = TB_NULL_INDEX;
	body->headContactKey = TB_NULL_INDEX;
	body->headJointKey = TB_NULL_INDEX;
	body->awakeIndex = TB_NULL_INDEX;
	uint32_t flags = tbGetUInt(r);
	if (r->failed == false && ((flags & ~(uint32_t)tb_bodyAll) != 0 || (flags & tb_bodyTypeBits) >= tb_bodyTypeCount))
	{
		return tbFail(r, "body %d has unknown flags or type", index);
	}
	body->type = (uint8_t)(flags & tb_bodyTypeBits);
	body->enableSleep = (flags & tb_bodySleep) != 0;
	body->fixedRotation = (flags & tb_bodyFixedRotation) != 0;
	body->lockLinearX = (flags & tb_bodyLockX) != 0;
	body->lockLinearY = (flags & tb_bodyLockY) != 0;
	body->isBullet = (flags & tb_bodyBullet) != 0;
	body->allowFastRotation = (flags & tb_bodyFastRotation) != 0;
	body->isDisabled = (flags & tb_bodyDisabled) != 0;
	body->isFast = (flags & tb_bodyFast) != 0;
	body->enableContactRecycling = (flags & tb_bodyNoRecycling) == 0;
	body->isMarked = (flags & tb_bodyMarked) != 0;
	body->center = tbGetPos(r, "a body's centre of mass");
	float values[TB_BODY_FLOATS];
	tbGetFloatsOver(r, values, d->bodyDefaults, TB_BODY_FLOATS, "a body's velocity, rotation, force or parameter");
	body->linearVelocity = tbMakeVec2(values[0], values[1]);
	body->angularVelocity = values[2];
	body->transform.q = (tbRot){values[3], values[4]};
	body->sleepTime = values[5];
	body->force = tbMakeVec2(values[6], values[7]);
	body->torque = values[8];
	body->gravityScale = values[9];
	body->linearDamping = values[10];
	body->angularDamping = values[11];
	body->sleepThreshold = values[12];
	body->safetyFactor = values[13];
	if (r->failed)
	{
		return false;
	}
	if (tbIsValidRotation(body->transform.q) == false)
	{
		return tbFail(r, "body %d's rotation is (%g, %g), not a unit rotation", index, (double)body->transform.q.c,
					  (double)body->transform.q.s);
	}
	if ((body->isDisabled == false && tbIsPosition(body->center) == false) || tbIsNonNegative(body->sleepTime) == false ||
		tbIsNonNegative(body->linearDamping) == false || tbIsNonNegative(body->angularDamping) == false ||
		tbIsNonNegative(body->sleepThreshold) == false || tbIsNonNegative(body->safetyFactor) == false)
	{
		return tbFail(r, "body %d has a position beyond TB_MAX_POSITION or a negative damping, sleep threshold, sleep "
						 "time or safety factor", index);
	}
	if (flags & tb_bodyNamed)
	{
		int length = tbGetCount(r, 1, "a body's name length");
		if (r->failed)
		{
			return false;
		}
		const char* name = (const char*)r->data + r->offset;
		if (memchr(name, 0, (size_t)length) != NULL)
		{
			return tbFail(r, "body %d's name holds a zero byte", index);
		}
		d->nameSources[index] = name;
		d->nameLengths[index] = length;
		r->offset += length;
		body->name = name; // for now: the world's own copy replaces it once every body is read
	}
	int shapeCount = tbGetCount(r, 3, "a body's shape count");
	int last = TB_NULL_INDEX;
	for (int i = 0; i < shapeCount && r->failed == false; ++i)
	{
		int shapeId;
		if (tbReadShape(d, index, &shapeId) == false)
		{
			return false;
		}
		if (last == TB_NULL_INDEX)
		{
			body->headShapeId = shapeId;
		}
		else
		{
			world->shapes[last].nextShapeId = shapeId;
		}
		world->shapes[shapeId].nextShapeId = TB_NULL_INDEX;
		last = shapeId;
		body->shapeCount += 1;
	}
	if (r->failed)
	{
		return false;
	}
	if (flags & tb_bodyMassStored)
	{
		body->mass = tbGetFloat(r, "a body's mass");
		body->invMass = tbGetFloat(r, "a body's mass");
		body->inertia = tbGetFloat(r, "a body's inertia");
		body->invInertia = tbGetFloat(r, "a body's inertia");
		body->localCenter = tbGetVec2(r, "a body's local centre");
		if (r->failed == false && (tbIsNonNegative(body->mass) == false || tbIsNonNegative(body->invMass) == false ||
								   tbIsNonNegative(body->inertia) == false || tbIsNonNegative(body->invInertia) == false ||
								   tbIsCoordinate(body->localCenter) == false))
		{
			return tbFail(r, "body %d has a negative mass or inertia, or its centre beyond TB_MAX_COORDINATE", index);
		}
	}
	else
	{
		tbBodyMass mass = tbComputeBodyMass(world, body);
		body->mass = mass.mass;
		body->invMass = mass.invMass;
		body->inertia = mass.inertia;
		body->invInertia = mass.invInertia;
		body->localCenter = mass.localCenter;
	}
	body->transform.p = (flags & tb_bodyOriginStored) ? tbGetPos(r, "a body's origin") : tbPredictOrigin(body);
	if (r->failed == false && body->isDisabled == false && tbIsPosition(body->transform.p) == false)
	{
		return tbFail(r, "body %d has its origin beyond TB_MAX_POSITION", index);
	}
	// The core extent is never stored: it is always the shapes' (body.h).
	tbComputeBodyExtents(world, body, &body->minExtent, &body->maxExtent, &body->coreExtent);
	if (flags & tb_bodyExtentsStored)
	{
		body->minExtent = tbGetFloat(r, "a body's extent");
		body->maxExtent = tbGetFloat(r, "a body's extent");
	}
	body->speculativeReach = (flags & tb_bodyReachStored) ? tbGetFloat(r, "a body's reach") : tbPredictReach(body);
	tbUpdateBodyDerived(body);
	if (r->failed == false && (tbIsNonNegative(body->minExtent) == false || tbIsNonNegative(body->maxExtent) == false ||
							   tbIsNonNegative(body->speculativeReach) == false))
	{
		return tbFail(r, "body %d has a negative extent or reach", index);
	}
	body->center0 = (flags & tb_bodyStartStored) ? tbGetPos(r, "a body's start pose") : body->center;
	body->rotation0 = (flags & tb_bodyStartStored) ? tbGetRot(r, "a body's start pose") : body->transform.q;
	for (int id = body->headShapeId; id != TB_NULL_INDEX && r->failed == false; id = world->shapes[id].nextShapeId)
	{
		tbShape* shape = world->shapes + id;
		uint8_t stored = d->shapeBoxes[id];
		shape->aabb = (stored & 1u) ? tbGetAABB(r, "a shape's box") : tbComputeShapeAABBInternal(shape, body->transform);
		shape->fatAABB = (stored & 2u) ? tbGetAABB(r, "a shape's fat box")
									   : ((stored & 4u) ? tbRemadeFatAABB(world, body, shape) : shape->aabb);
		if (r->failed == false && (tbIsValidVec2(shape->fatAABB.lowerBound) == false ||
								   tbIsValidVec2(shape->fatAABB.upperBound) == false))
		{
			return tbFail(r, "shape %d's remade fat box is not finite", id);
		}
	}
	return r->failed == false;
}

// --------------------------------------------------------------------------------------------
// Chains: the body, the segment shapes in chain order and the materials.

#define TB_CHAIN_MATERIAL_FLOATS 4

static void tbChainMaterialFloats(const tbSurfaceMaterial* m, float v[TB_CHAIN_MATERIAL_FLOATS])
{
	float values[TB_CHAIN_MATERIAL_FLOATS] = {m->friction, m->restitution, m->rollingResistance, m->tangentSpeed};
	memcpy(v, values, sizeof(values));
}

static void tbWriteChains(tbEncoder* e)
{
	const tbWorld* world = e->world;
	tbWritePool(e, &world->chainPool, world->chains, sizeof(tbChain), offsetof(tbChain, generation), 2,
				world->chainGenerationBase);
	tbSurfaceMaterial base = tbDefaultSurfaceMaterial();
	float defaults[TB_CHAIN_MATERIAL_FLOATS];
	tbChainMaterialFloats(&base, defaults);
	for (int i = 0; i < world->chainPool.highWater; ++i)
	{
		const tbChain* chain = world->chains + i;
		if (chain->inUse == false)
		{
			continue;
		}
		tbPutUInt(&e->w, (uint32_t)chain->bodyId);
		tbPutUInt(&e->w, (uint32_t)chain->segmentCount);
		for (int k = 0; k < chain->segmentCount; ++k)
		{
			tbPutUInt(&e->w, (uint32_t)chain->shapeIds[k]);
		}
		tbPutUInt(&e->w, (uint32_t)chain->materialCount);
		for (int k = 0; k < chain->materialCount; ++k)
		{
			float values[TB_CHAIN_MATERIAL_FLOATS];
			tbChainMaterialFloats(chain->materials + k, values);
			tbPutFloatsOver(&e->w, values, defaults, TB_CHAIN_MATERIAL_FLOATS);
			tbPutU64(&e->w, chain->materials[k].userMaterialId);
			tbPutUInt(&e->w, chain->materials[k].customColor);
		}
	}
}

static bool tbReadChains(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	r->section = "chains";
	uint8_t* slots;
	uint32_t* generations;
	if (tbReadPool(d, &world->chainPool, &slots, &generations, true, "chain") == false)
	{
		return false;
	}
	int highWater = world->chainPool.highWater;
	TB_ARRAY_RESERVE(world->chains, world->chainCapacity, highWater);
	for (int i = 0; i < highWater; ++i)
	{
		memset(world->chains + i, 0, sizeof(tbChain));
		world->chains[i].generation = (uint16_t)generations[i]; // the base is added on adoption
	}
	// Which chain claims each shape (−1: none yet).
	int shapeCount = world->shapePool.highWater;
	int* owner = tbAlloc((shapeCount + 1) * (int)sizeof(int));
	for (int i = 0; i < shapeCount; ++i)
	{
		owner[i] = TB_NULL_INDEX;
	}
	tbSurfaceMaterial base = tbDefaultSurfaceMaterial();
	float defaults[TB_CHAIN_MATERIAL_FLOATS];
	tbChainMaterialFloats(&base, defaults);
	for (int i = 0; i < highWater && r->failed == false; ++i)
	{
		if (slots[i] != tb_slotLive)
		{
			continue;
		}
		tbChain* chain = world->chains + i;
		int bodyId = tbGetIndex(r, world->bodyPool.highWater, "a chain's body");
		int segmentCount = tbGetCount(r, 1, "a chain's segment count");
		if (r->failed)
		{
			break;
		}
		if (world->bodies[bodyId].inUse == false || segmentCount < 1)
		{
			tbFail(r, "chain %d is on a body not in use or has no segment", i);
			break;
		}
		chain->bodyId = bodyId;
		chain->shapeIds = tbAlloc(segmentCount * (int)sizeof(int));
		chain->segmentCount = segmentCount;
		chain->materialCount = 1;
		chain->materials = tbAlloc((int)sizeof(tbSurfaceMaterial));
		chain->materials[0] = base;
		chain->inUse = true; // from here tbFreeChains frees it
		for (int k = 0; k < segmentCount && r->failed == false; ++k)
		{
			int shapeId = tbGetIndex(r, shapeCount, "a chain's segment");
			const tbShape* shape = world->shapes + shapeId;
			chain->shapeIds[k] = shapeId;
			if (r->failed == false && (shape->inUse == false || shape->bodyId != bodyId || owner[shapeId] != TB_NULL_INDEX ||
									   shape->geometry.type != tb_chainSegmentShape || shape->geometry.chainSegment.chainId != i))
			{
				tbFail(r, "chain %d lists shape %d, which is not one of its segments", i, shapeId);
			}
			owner[shapeId] = i;
		}
		int materialCount = tbGetCount(r, 1, "a chain's material count");
		if (r->failed)
		{
			break;
		}
		if (materialCount != 1 && materialCount != segmentCount)
		{
			tbFail(r, "chain %d has %d materials for %d segments", i, materialCount, segmentCount);
			break;
		}
		tbFree(chain->materials, (int)sizeof(tbSurfaceMaterial));
		chain->materials = tbAlloc(materialCount * (int)sizeof(tbSurfaceMaterial));
		chain->materialCount = materialCount;
		for (int k = 0; k < materialCount; ++k)
		{
			float values[TB_CHAIN_MATERIAL_FLOATS];
			tbGetFloatsOver(r, values, defaults, TB_CHAIN_MATERIAL_FLOATS, "a chain's material");
			tbSurfaceMaterial* m = chain->materials + k;
			*m = base;
			m->friction = values[0];
			m->restitution = values[1];
			m->rollingResistance = values[2];
			m->tangentSpeed = values[3];
			m->userMaterialId = tbGetU64(r);
			m->customColor = tbGetUInt(r);
			if (r->failed == false && (tbIsNonNegative(m->friction) == false || tbIsNonNegative(m->restitution) == false ||
									   tbIsNonNegative(m->rollingResistance) == false))
			{
				tbFail(r, "chain %d has a negative friction, restitution or rolling resistance", i);
			}
		}
	}
	// Every segment of a chain is listed by it, and no other shape names a chain.
	for (int i = 0; i < shapeCount && r->failed == false; ++i)
	{
		const tbShape* shape = world->shapes + i;
		if (shape->inUse && shape->geometry.type == tb_chainSegmentShape &&
			(shape->geometry.chainSegment.chainId < TB_NULL_INDEX ||
			 (shape->geometry.chainSegment.chainId >= 0 && owner[i] != shape->geometry.chainSegment.chainId)))
		{
			tbFail(r, "shape %d names chain %d, which does not list it", i, shape->geometry.chainSegment.chainId);
		}
	}
	tbFree(owner, (shapeCount + 1) * (int)sizeof(int));
	tbFreeSlots(&slots, &generations, highWater);
	return r->failed == false;
}

// --------------------------------------------------------------------------------------------
// Contacts, then each body's contact list in its order.

enum
{
	tb_contactPointBits = 3,		   ///< the manifold's point count
	tb_contactMaterialsStored = 1 << 2, ///< not the default mixing of its shapes' materials
	tb_contactSimplexStored = 1 << 3,
	tb_contactHitStored = 1 << 4,
	tb_contactPointsPredicted = 1 << 5, ///< the anchors (recycled: the points and separations) are remade
	tb_contactFramePredicted = 1 << 6,	///< the recycling base of a computed manifold is remade
	tb_contactInfoAll = (1 << 7) - 1,
};

// Where a manifold's points and recycling base come from (contact.c): the narrow phase ran with the
// bodies at their poses at the start of the step (the pose a body's start pose keeps: centre0 and
// rotation0, its origin as the last scatter wrote it), computing the points and, from them, the
// anchors and the base; or it recycled the base, moving the points with the bodies and keeping the
// normal and anchors. Either way the anchors and base of a computed manifold, and the points and
// separations of a recycled one, are functions of what else the image holds, and are written only
// where recomputing them would not give the same bits (a manifold made outside the collide stage,
// the large-world build's rounded points).

/// A body's pose when its contacts were last collided: its start pose.
typedef struct tbStartPose
{
	tbWorldTransform transform;
	tbPos center;
} tbStartPose;

static tbStartPose tbStartPoseOf(const tbBody* body)
{
	tbStartPose pose;
	pose.center = body->center0;
	pose.transform.q = body->rotation0;
	bool unmoved = tbSamePos(body->center0, body->center) && tbSameFloat(body->rotation0.c, body->transform.q.c) &&
				   tbSameFloat(body->rotation0.s, body->transform.q.s);
	// The origin the scatter stage wrote at the end of the step before (solver.c), or the origin now.
	pose.transform.p = unmoved ? body->transform.p
							   : tbOffsetPos(body->center0, tbNeg(tbRotateVector(body->rotation0, body->localCenter)));
	return pose;
}

/// The manifold's last narrow phase recycled its base (contact.c), and the base is still there.
static bool tbIsRecycledManifold(uint32_t flags)
{
	const uint32_t both = tb_contactRecycled | tb_contactRecyclable;
	return (flags & both) == both;
}

/// tbComputeManifold's anchors of a computed manifold's points.
static void tbRemakeAnchors(tbManifold* m, tbStartPose a, tbStartPose b)
{
	for (int i = 0; i < m->pointCount; ++i)
	{
		tbPos point = tbToPos(m->points[i].point);
		m->points[i].anchorA = tbSubPos(point, a.center);
		m->points[i].anchorB = tbSubPos(point, b.center);
	}
}

/// tbStoreManifoldBase's base of a computed manifold (its margin aside), from its points.
static void tbRemakeBase(tbManifoldBase* base, const tbManifold* m, tbStartPose a, tbStartPose b)
{
	tbPos points[2] = {tbToPos(m->points[0].point), tbToPos(m->points[1].point)};
	tbFillManifoldBase(base, m, a.transform, b.transform, points);
}

static bool tbSameBase(const tbManifoldBase* a, const tbManifoldBase* b, int pointCount)
{
	bool same = tbSameVec2(a->relative.p, b->relative.p) && tbSameFloat(a->relative.q.c, b->relative.q.c) &&
				tbSameFloat(a->relative.q.s, b->relative.q.s) && tbSameVec2(a->normalA, b->normalA) &&
				tbSameVec2(a->normalB, b->normalB);
	for (int i = 0; same && i < pointCount; ++i)
	{
		same = tbSameVec2(a->pointA[i], b->pointA[i]) && tbSameVec2(a->pointB[i], b->pointB[i]) &&
			   tbSameFloat(a->separation[i], b->separation[i]);
	}
	return same;
}

/// A manifold point's floats, all mostly zero but the point and anchors.
#define TB_POINT_FLOATS 12

static void tbPointFloats(const tbManifoldPoint* p, float v[TB_POINT_FLOATS])
{
	float values[TB_POINT_FLOATS] = {p->point.x,	p->point.y,			p->anchorA.x,		p->anchorA.y,
									 p->anchorB.x,	p->anchorB.y,		p->separation,		p->normalImpulse,
									 p->tangentImpulse, p->totalNormalImpulse, p->normalVelocity, p->baseSeparation};
	memcpy(v, values, sizeof(values));
}

static bool tbSimplexIsEmpty(const tbSimplexCache* c)
{
	tbSimplexCache empty;
	memset(&empty, 0, sizeof(empty));
	return memcmp(c, &empty, sizeof(empty)) == 0;
}

/// Which of a point's TB_POINT_FLOATS are remade rather than written: the anchors of a computed
/// manifold; the point and separation of a recycled one.
static bool tbIsRemadeFloat(int index, bool recycled, bool predicted)
{
	return predicted && (recycled ? (index < 2 || index == 6) : (index >= 2 && index <= 5));
}

static void tbPutBase(tbWriter* w, const tbManifoldBase* b, int pointCount)
{
	tbPutVec2(w, b->relative.p);
	tbPutRot(w, b->relative.q);
	tbPutVec2(w, b->normalA);
	tbPutVec2(w, b->normalB);
	for (int i = 0; i < pointCount; ++i)
	{
		tbPutVec2(w, b->pointA[i]);
		tbPutVec2(w, b->pointB[i]);
		tbPutFloat(w, b->separation[i]);
	}
}

static void tbPutPoints(tbWriter* w, const tbManifold* m, bool recycled, bool predicted)
{
	for (int i = 0; i < m->pointCount; ++i)
	{
		const tbManifoldPoint* p = m->points + i;
		float values[TB_POINT_FLOATS], kept[TB_POINT_FLOATS];
		tbPointFloats(p, values);
		int count = 0;
		for (int k = 0; k < TB_POINT_FLOATS; ++k)
		{
			if (tbIsRemadeFloat(k, recycled, predicted) == false)
			{
				kept[count++] = values[k];
			}
		}
		tbPutFloatsOver(w, kept, NULL, count);
		tbPutUInt(w, (uint32_t)p->id << 1 | (p->persisted ? 1u : 0u));
	}
}

static void tbWriteContact(tbEncoder* e, const tbContact* contact)
{
	tbWriter* w = &e->w;
	const tbWorld* world = e->world;
	const tbManifold* m = &contact->manifold;
	tbContact mixed = *contact;
	tbMixContactMaterials(e->mixer, &mixed);
	bool materialsStored = tbSameFloat(mixed.friction, contact->friction) == false ||
						   tbSameFloat(mixed.restitution, contact->restitution) == false ||
						   tbSameFloat(mixed.rollingResistance, contact->rollingResistance) == false ||
						   tbSameFloat(mixed.tangentSpeed, contact->tangentSpeed) == false;
	bool simplexStored = tbSimplexIsEmpty(&contact->cache) == false;
	bool hitStored = contact->hitSpeed != 0.0f || contact->hitPoint.x != 0.0f || contact->hitPoint.y != 0.0f;

	// What recomputing from the bodies' start poses gives, compared bit for bit with what is there.
	tbStartPose a = tbStartPoseOf(world->bodies + contact->edges[0].bodyId);
	tbStartPose b = tbStartPoseOf(world->bodies + contact->edges[1].bodyId);
	bool recycled = tbIsRecycledManifold(contact->flags);
	bool recyclable = (contact->flags & tb_contactRecyclable) != 0;
	tbManifold remade = *m;
	bool framePredicted = false;
	if (recycled)
	{
		tbMoveRecycledPoints(&remade, &contact->base, a.transform, b.transform);
	}
	else
	{
		tbRemakeAnchors(&remade, a, b);
		if (recyclable)
		{
			tbManifoldBase base = contact->base;
			tbRemakeBase(&base, m, a, b);
			framePredicted = tbSameBase(&base, &contact->base, m->pointCount);
		}
	}
	bool pointsPredicted = m->pointCount > 0;
	for (int i = 0; i < m->pointCount; ++i)
	{
		float values[TB_POINT_FLOATS], again[TB_POINT_FLOATS];
		tbPointFloats(m->points + i, values);
		tbPointFloats(remade.points + i, again);
		for (int k = 0; k < TB_POINT_FLOATS; ++k)
		{
			pointsPredicted = pointsPredicted && (tbIsRemadeFloat(k, recycled, true) == false || tbSameFloat(values[k], again[k]));
		}
	}

	uint32_t info = (uint32_t)m->pointCount | (materialsStored ? tb_contactMaterialsStored : 0u) |
					(simplexStored ? tb_contactSimplexStored : 0u) | (hitStored ? tb_contactHitStored : 0u) |
					(pointsPredicted ? tb_contactPointsPredicted : 0u) | (framePredicted ? tb_contactFramePredicted : 0u);
	tbPutDelta(w, contact->shapeIdA, e->lastContactShape);
	tbPutDelta(w, contact->shapeIdB, contact->shapeIdA);
	e->lastContactShape = contact->shapeIdA;
	tbPutU8(w, contact->flags);
	tbPutUInt(w, info);
	tbPutUInt(w, contact->touchingSteps);
	if (simplexStored)
	{
		tbPutU8(w, contact->cache.count);
		tbPutBytes(w, contact->cache.indexA, 3);
		tbPutBytes(w, contact->cache.indexB, 3);
	}
	if (materialsStored)
	{
		tbPutFloat(w, contact->friction);
		tbPutFloat(w, contact->restitution);
		tbPutFloat(w, contact->rollingResistance);
		tbPutFloat(w, contact->tangentSpeed);
	}
	if (recycled)
	{
		tbPutBase(w, &contact->base, m->pointCount);
		tbPutFloat(w, contact->base.margin);
		float head[3] = {m->normal.x, m->normal.y, m->rollingImpulse};
		tbPutFloatsOver(w, head, NULL, 3);
		tbPutPoints(w, m, true, pointsPredicted);
	}
	else
	{
		float head[3] = {m->normal.x, m->normal.y, m->rollingImpulse};
		tbPutFloatsOver(w, head, NULL, 3);
		tbPutPoints(w, m, false, pointsPredicted);
		if (recyclable)
		{
			if (framePredicted == false)
			{
				tbPutBase(w, &contact->base, m->pointCount);
			}
			tbPutFloat(w, contact->base.margin);
		}
	}
	if (hitStored)
	{
		tbPutFloat(w, contact->hitSpeed);
		tbPutVec2(w, contact->hitPoint);
	}
}

static void tbWriteContactLists(tbEncoder* e)
{
	const tbWorld* world = e->world;
	for (int i = 0; i < world->bodyPool.highWater; ++i)
	{
		const tbBody* body = world->bodies + i;
		if (body->inUse == false)
		{
			continue;
		}
		tbPutUInt(&e->w, (uint32_t)body->contactCount);
		int previous = 0;
		for (int key = body->headContactKey; key != TB_NULL_INDEX; key = world->contacts[key >> 1].edges[key & 1].nextKey)
		{
			tbPutDelta(&e->w, key, previous);
			previous = key;
		}
	}
}

static void tbWriteContacts(tbEncoder* e)
{
	const tbWorld* world = e->world;
	tbWritePool(e, &world->contactPool, world->contacts, sizeof(tbContact), offsetof(tbContact, generation), 4,
				(uint32_t)world->generation << 16);
	for (int i = 0; i < world->contactPool.highWater; ++i)
	{
		if (world->contacts[i].inUse)
		{
			tbWriteContact(e, world->contacts + i);
		}
	}
	tbWriteContactLists(e);
}

/// Points of a shape's GJK proxy (what a simplex cache may index).
static int tbProxyPointCount(const tbShape* shape)
{
	switch (shape->geometry.type)
	{
		case tb_circleShape:
			return 1;
		case tb_polygonShape:
			return shape->geometry.polygon.count;
		default:
			return 2;
	}
}

static void tbGetBase(tbReader* r, tbManifoldBase* base, int pointCount)
{
	const char* what = "a contact's recycling base";
	base->relative.p = tbGetVec2(r, what);
	base->relative.q = tbGetRot(r, what);
	base->normalA = tbGetVec2(r, what);
	base->normalB = tbGetVec2(r, what);
	for (int i = 0; i < pointCount; ++i)
	{
		base->pointA[i] = tbGetVec2(r, what);
		base->pointB[i] = tbGetVec2(r, what);
		base->separation[i] = tbGetFloat(r, what);
	}
}

/// A manifold's points as tbPutPoints wrote them (the remade floats left zero).
static bool tbGetPoints(tbDecoder* d, tbManifold* m, bool recycled, bool predicted, int id)
{
	tbReader* r = &d->r;
	for (int i = 0; i < m->pointCount; ++i)
	{
		float kept[TB_POINT_FLOATS], values[TB_POINT_FLOATS];
		int count = 0;
		for (int k = 0; k < TB_POINT_FLOATS; ++k)
		{
			count += tbIsRemadeFloat(k, recycled, predicted) ? 0 : 1;
		}
		tbGetFloatsOver(r, kept, NULL, count, "a manifold point");
		count = 0;
		for (int k = 0; k < TB_POINT_FLOATS; ++k)
		{
			values[k] = tbIsRemadeFloat(k, recycled, predicted) ? 0.0f : kept[count++];
		}
		tbManifoldPoint* p = m->points + i;
		p->point = tbMakeVec2(values[0], values[1]);
		p->anchorA = tbMakeVec2(values[2], values[3]);
		p->anchorB = tbMakeVec2(values[4], values[5]);
		p->separation = values[6];
		p->normalImpulse = values[7];
		p->tangentImpulse = values[8];
		p->totalNormalImpulse = values[9];
		p->normalVelocity = values[10];
		p->baseSeparation = values[11];
		uint32_t idBits = tbGetUInt(r);
		if (r->failed == false && idBits > 0x1FFFFu)
		{
			return tbFail(r, "contact %d has a feature id beyond 16 bits", id);
		}
		p->id = (uint16_t)(idBits >> 1);
		p->persisted = (idBits & 1u) != 0;
	}
	return r->failed == false;
}

static bool tbReadContact(tbDecoder* d, int id)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	tbContact* contact = world->contacts + id;
	uint32_t generation = contact->generation;
	memset(contact, 0, sizeof(*contact));
	contact->generation = generation;
	int shapeCount = world->shapePool.highWater;
	int a = tbGetDelta(r, d->lastContactShape, 0, shapeCount, "a contact's shape");
	int b = tbGetDelta(r, a, 0, shapeCount, "a contact's shape");
	d->lastContactShape = a;
	uint32_t flags = tbGetU8(r);
	uint32_t info = tbGetUInt(r);
	uint32_t touchingSteps = tbGetUInt(r);
	if (r->failed)
	{
		return false;
	}
	const tbShape* shapeA = world->shapes + a;
	const tbShape* shapeB = world->shapes + b;
	if (shapeA->inUse == false || shapeB->inUse == false || a == b || shapeA->bodyId == shapeB->bodyId)
	{
		return tbFail(r, "contact %d joins shapes %d and %d: not in use, the same shape or the same body", id, a, b);
	}
	if ((info & ~(uint32_t)tb_contactInfoAll) != 0 || (info & tb_contactPointBits) > 2 || touchingSteps > UINT16_MAX)
	{
		return tbFail(r, "contact %d has unknown flags, more than two points or a touching count beyond 16 bits", id);
	}
	contact->inUse = true;
	contact->shapeIdA = a;
	contact->shapeIdB = b;
	contact->edges[0].bodyId = shapeA->bodyId;
	contact->edges[1].bodyId = shapeB->bodyId;
	contact->flags = flags;
	contact->touchingSteps = (uint16_t)touchingSteps;
	// A stamp no coming step uses (island.c and contact.c stamp 2s and 2s + 1 in step s): the
	// contact counts as not yet gathered in the next step, as it does in an uninterrupted run.
	contact->stamp = 2u * world->stepIndex + 1u;
	if (info & tb_contactSimplexStored)
	{
		contact->cache.count = (uint16_t)tbGetU8(r);
		tbGetBytes(r, contact->cache.indexA, 3);
		tbGetBytes(r, contact->cache.indexB, 3);
		int countA = tbProxyPointCount(shapeA), countB = tbProxyPointCount(shapeB);
		bool valid = contact->cache.count <= 3;
		for (int i = 0; valid && i < contact->cache.count; ++i)
		{
			valid = contact->cache.indexA[i] < countA && contact->cache.indexB[i] < countB;
		}
		if (r->failed == false && valid == false)
		{
			return tbFail(r, "contact %d has a simplex cache that names points its shapes do not have", id);
		}
	}
	if (info & tb_contactMaterialsStored)
	{
		// Infinite friction is allowed (a friction callback may return it: contact.c).
		float friction = tbGetRawFloat(r);
		contact->restitution = tbGetFloat(r, "a contact's restitution");
		contact->rollingResistance = tbGetFloat(r, "a contact's rolling resistance");
		contact->tangentSpeed = tbGetFloat(r, "a contact's tangent speed");
		if (r->failed == false && (!(friction >= 0.0f) || tbIsNonNegative(contact->restitution) == false ||
								   tbIsNonNegative(contact->rollingResistance) == false))
		{
			return tbFail(r, "contact %d has a negative or NaN friction, restitution or rolling resistance", id);
		}
		contact->friction = friction;
		tbSetContactMaterialFlags(contact);
	}
	else
	{
		tbMixContactMaterials(world, contact); // the world being built has no mixing callbacks
	}
	tbManifold* m = &contact->manifold;
	m->pointCount = (int)(info & tb_contactPointBits);
	tbStartPose poseA = tbStartPoseOf(world->bodies + contact->edges[0].bodyId);
	tbStartPose poseB = tbStartPoseOf(world->bodies + contact->edges[1].bodyId);
	bool recycled = tbIsRecycledManifold(flags);
	bool pointsPredicted = (info & tb_contactPointsPredicted) != 0;
	bool framePredicted = (info & tb_contactFramePredicted) != 0;
	if ((pointsPredicted && m->pointCount == 0) || (framePredicted && ((flags & tb_contactRecyclable) == 0 || recycled)))
	{
		return tbFail(r, "contact %d says it remakes what it does not have", id);
	}
	if (recycled)
	{
		tbGetBase(r, &contact->base, m->pointCount);
		contact->base.margin = tbGetFloat(r, "a contact's recycling base");
		float head[3];
		tbGetFloatsOver(r, head, NULL, 3, "a contact's normal");
		m->normal = tbMakeVec2(head[0], head[1]);
		m->rollingImpulse = head[2];
		tbGetPoints(d, m, true, pointsPredicted, id);
		if (pointsPredicted)
		{
			tbMoveRecycledPoints(m, &contact->base, poseA.transform, poseB.transform);
		}
	}
	else
	{
		float head[3];
		tbGetFloatsOver(r, head, NULL, 3, "a contact's normal");
		m->normal = tbMakeVec2(head[0], head[1]);
		m->rollingImpulse = head[2];
		tbGetPoints(d, m, false, pointsPredicted, id);
		if (pointsPredicted)
		{
			tbRemakeAnchors(m, poseA, poseB);
		}
		if (flags & tb_contactRecyclable)
		{
			if (framePredicted)
			{
				tbRemakeBase(&contact->base, m, poseA, poseB);
			}
			else
			{
				tbGetBase(r, &contact->base, m->pointCount);
			}
			contact->base.margin = tbGetFloat(r, "a contact's recycling base");
		}
	}
	if (info & tb_contactHitStored)
	{
		contact->hitSpeed = tbGetFloat(r, "a contact's hit speed");
		contact->hitPoint = tbGetVec2(r, "a contact's hit point");
	}
	// Remade values are finite when their inputs are, but not always: a start pose far from the
	// bodies' poses now could overflow them.
	for (int i = 0; r->failed == false && i < m->pointCount; ++i)
	{
		float values[TB_POINT_FLOATS];
		tbPointFloats(m->points + i, values);
		for (int k = 0; k < TB_POINT_FLOATS; ++k)
		{
			if (tbIsValidFloat(values[k]) == false)
			{
				return tbFail(r, "contact %d's remade manifold is not finite", id);
			}
		}
	}
	if (r->failed == false && tbIsValidVec2(m->normal) == false)
	{
		return tbFail(r, "contact %d's remade normal is not finite", id);
	}
	return r->failed == false;
}

/// Link each body's contact edges (or joint edges) in the order the image lists them. `keys` says
/// for each key (id << 1 | edge) whether it is linked yet; each live object's two keys must be
/// linked exactly once, each into the list of its own body.
static bool tbReadEdgeLists(tbDecoder* d, bool joints)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	int highWater = joints ? world->jointPool.highWater : world->contactPool.highWater;
	int liveCount = joints ? world->jointPool.count : world->contactPool.count;
	const char* what = joints ? "joint" : "contact";
	uint8_t* linked = tbAlloc(2 * highWater + 1);
	memset(linked, 0, (size_t)2 * highWater + 1);
	int total = 0;
	for (int i = 0; i < world->bodyPool.highWater && r->failed == false; ++i)
	{
		tbBody* body = world->bodies + i;
		if (body->inUse == false)
		{
			continue;
		}
		int count = tbGetCount(r, 1, joints ? "a body's joint count" : "a body's contact count");
		int previous = TB_NULL_INDEX;
		for (int k = 0; k < count && r->failed == false; ++k)
		{
			int key = tbGetDelta(r, previous == TB_NULL_INDEX ? 0 : previous, 0, 2 * highWater,
								 joints ? "a body's joint key" : "a body's contact key");
			if (r->failed)
			{
				break;
			}
			int id = key >> 1, edge = key & 1;
			bool inUse = joints ? world->joints[id].inUse : world->contacts[id].inUse;
			int edgeBody = joints ? world->joints[id].edges[edge].bodyId : world->contacts[id].edges[edge].bodyId;
			if (inUse == false || edgeBody != i || linked[key])
			{
				tbFail(r, "body %d lists %s %d, which is not in use, not on this body, or listed twice", i, what, id);
				break;
			}
			linked[key] = 1;
			int* prevKey = joints ? &world->joints[id].edges[edge].prevKey : &world->contacts[id].edges[edge].prevKey;
			int* nextKey = joints ? &world->joints[id].edges[edge].nextKey : &world->contacts[id].edges[edge].nextKey;
			*prevKey = previous;
			*nextKey = TB_NULL_INDEX;
			if (previous == TB_NULL_INDEX)
			{
				*(joints ? &body->headJointKey : &body->headContactKey) = key;
			}
			else if (joints)
			{
				world->joints[previous >> 1].edges[previous & 1].nextKey = key;
			}
			else
			{
				world->contacts[previous >> 1].edges[previous & 1].nextKey = key;
			}
			previous = key;
		}
		if (joints)
		{
			body->jointCount = count;
		}
		else
		{
			body->contactCount = count;
		}
		total += count;
	}
	if (r->failed == false && total != 2 * liveCount)
	{
		tbFail(r, "the bodies' lists hold %d %s edges for %d %ss", total, what, liveCount, what);
	}
	tbFree(linked, 2 * highWater + 1);
	return r->failed == false;
}

static bool tbReadContacts(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	r->section = "contacts";
	uint8_t* slots;
	uint32_t* generations;
	if (tbReadPool(d, &world->contactPool, &slots, &generations, false, "contact") == false)
	{
		return false;
	}
	int highWater = world->contactPool.highWater;
	TB_ARRAY_RESERVE(world->contacts, world->contactCapacity, highWater);
	TB_ARRAY_RESERVE(world->cache.contactBodies, world->cache.contactBodyCapacity, highWater);
	for (int i = 0; i < highWater; ++i)
	{
		memset(world->contacts + i, 0, sizeof(tbContact));
		world->contacts[i].generation = generations[i]; // the world's generation is added on adoption
		world->cache.contactBodies[i] = (tbBodyPair){TB_NULL_INDEX, TB_NULL_INDEX};
	}
	for (int i = 0; i < highWater && r->failed == false; ++i)
	{
		if (slots[i] != tb_slotLive || tbReadContact(d, i) == false)
		{
			continue;
		}
		const tbContact* contact = world->contacts + i;
		world->cache.contactBodies[i] = (tbBodyPair){contact->edges[0].bodyId, contact->edges[1].bodyId};
		world->hitContactCount += (contact->flags & tb_contactEnableHits) != 0 ? 1 : 0;
		world->sensorContactCount += (contact->flags & tb_contactSensor) != 0 ? 1 : 0;
		if (tbHashSet_Add(&world->pairSet, tbShapePairKey(contact->shapeIdA, contact->shapeIdB)))
		{
			tbFail(r, "two contacts join shapes %d and %d", contact->shapeIdA, contact->shapeIdB);
		}
	}
	tbFreeSlots(&slots, &generations, highWater);
	r->section = "contact lists";
	return r->failed == false && tbReadEdgeLists(d, false);
}

// --------------------------------------------------------------------------------------------
// Joints: the common part, then the kind's fields from a table (parameters, accumulated impulses,
// the masses and softness its preparation keeps), each checked as the kind's API checks it.

enum
{
	tb_fieldFinite,
	tb_fieldNonNegative,
	tb_fieldBool,
};

typedef struct tbJointField
{
	uint16_t offset; ///< in tbJoint
	uint8_t check;
} tbJointField;

#define TB_JF(kind, field) {(uint16_t)offsetof(tbJoint, kind.field), tb_fieldFinite}
#define TB_JN(kind, field) {(uint16_t)offsetof(tbJoint, kind.field), tb_fieldNonNegative}
#define TB_JB(kind, field) {(uint16_t)offsetof(tbJoint, kind.field), tb_fieldBool}
#define TB_JV(kind, field) TB_JF(kind, field.x), TB_JF(kind, field.y)
#define TB_JS(kind, field) TB_JF(kind, field.biasRate), TB_JF(kind, field.massScale), TB_JF(kind, field.impulseScale)

static const tbJointField tb_distanceFields[] = {
	TB_JN(distance, length),		  TB_JN(distance, hertz),		   TB_JN(distance, dampingRatio),
	TB_JF(distance, lowerSpringForce), TB_JF(distance, upperSpringForce), TB_JN(distance, minLength),
	TB_JN(distance, maxLength),		  TB_JN(distance, maxMotorForce),  TB_JF(distance, motorSpeed),
	TB_JB(distance, enableSpring),	  TB_JB(distance, enableLimit),	   TB_JB(distance, enableMotor),
	TB_JF(distance, impulse),		  TB_JF(distance, lowerImpulse),   TB_JF(distance, upperImpulse),
	TB_JF(distance, motorImpulse),	  TB_JF(distance, axialMass),	   TB_JS(distance, distanceSoftness),
};

static const tbJointField tb_motorFields[] = {
	TB_JV(motor, linearVelocity),		  TB_JN(motor, maxVelocityForce),	 TB_JF(motor, angularVelocity),
	TB_JN(motor, maxVelocityTorque),	  TB_JN(motor, linearHertz),		 TB_JN(motor, linearDampingRatio),
	TB_JN(motor, maxSpringForce),		  TB_JN(motor, angularHertz),		 TB_JN(motor, angularDampingRatio),
	TB_JN(motor, maxSpringTorque),		  TB_JV(motor, linearVelocityImpulse), TB_JV(motor, linearSpringImpulse),
	TB_JF(motor, angularVelocityImpulse), TB_JF(motor, angularSpringImpulse), TB_JS(motor, linearSpring),
	TB_JS(motor, angularSpring),		  TB_JF(motor, angularMass),
};

static const tbJointField tb_moverFields[] = {
	TB_JV(mover, linearVelocity), TB_JN(mover, maxVelocityForce.x), TB_JN(mover, maxVelocityForce.y),
	TB_JV(mover, linearVelocityImpulse), TB_JF(mover, linearMass),
};

static const tbJointField tb_pogoFields[] = {
	TB_JV(pogo, normal),			TB_JN(pogo, hertz),		  TB_JN(pogo, dampingRatio),
	TB_JN(pogo, restLength),		TB_JN(pogo, maxTensionForce), TB_JN(pogo, maxCompressionForce),
	TB_JF(pogo, impulse),			TB_JF(pogo, velocity),	  TB_JF(pogo, normalMass),
};

static const tbJointField tb_prismaticFields[] = {
	TB_JN(prismatic, hertz),		   TB_JN(prismatic, dampingRatio),	  TB_JF(prismatic, targetTranslation),
	TB_JF(prismatic, lowerTranslation), TB_JF(prismatic, upperTranslation), TB_JN(prismatic, maxMotorForce),
	TB_JF(prismatic, motorSpeed),	   TB_JB(prismatic, enableSpring),	  TB_JB(prismatic, enableLimit),
	TB_JB(prismatic, enableMotor),	   TB_JV(prismatic, impulse),		  TB_JF(prismatic, springImpulse),
	TB_JF(prismatic, motorImpulse),	   TB_JF(prismatic, lowerImpulse),	  TB_JF(prismatic, upperImpulse),
	TB_JS(prismatic, springSoftness),
};

static const tbJointField tb_revoluteFields[] = {
	TB_JF(revolute, targetAngle),	TB_JN(revolute, hertz),		  TB_JN(revolute, dampingRatio),
	TB_JF(revolute, lowerAngle),	TB_JF(revolute, upperAngle),	  TB_JN(revolute, maxMotorTorque),
	TB_JF(revolute, motorSpeed),	TB_JB(revolute, enableSpring),  TB_JB(revolute, enableLimit),
	TB_JB(revolute, enableMotor),	TB_JV(revolute, linearImpulse), TB_JF(revolute, springImpulse),
	TB_JF(revolute, motorImpulse),	TB_JF(revolute, lowerImpulse),  TB_JF(revolute, upperImpulse),
	TB_JF(revolute, axialMass),		TB_JS(revolute, springSoftness),
};

static const tbJointField tb_weldFields[] = {
	TB_JN(weld, linearHertz),  TB_JN(weld, linearDampingRatio), TB_JN(weld, angularHertz),
	TB_JN(weld, angularDampingRatio), TB_JV(weld, linearImpulse), TB_JF(weld, angularImpulse),
	TB_JF(weld, axialMass),	   TB_JS(weld, linearSpring),		TB_JS(weld, angularSpring),
};

static const tbJointField tb_wheelFields[] = {
	TB_JN(wheel, hertz),		  TB_JN(wheel, dampingRatio),	TB_JF(wheel, lowerTranslation),
	TB_JF(wheel, upperTranslation), TB_JN(wheel, maxMotorTorque), TB_JF(wheel, motorSpeed),
	TB_JB(wheel, enableSpring),	  TB_JB(wheel, enableLimit),	TB_JB(wheel, enableMotor),
	TB_JF(wheel, perpImpulse),	  TB_JF(wheel, springImpulse),	TB_JF(wheel, motorImpulse),
	TB_JF(wheel, lowerImpulse),	  TB_JF(wheel, upperImpulse),	TB_JF(wheel, motorMass),
	TB_JS(wheel, springSoftness),
};

static const tbJointField* tbJointFields(int type, int* count)
{
	switch (type)
	{
		case tb_distanceJoint:
			*count = (int)(sizeof(tb_distanceFields) / sizeof(tb_distanceFields[0]));
			return tb_distanceFields;
		case tb_motorJoint:
			*count = (int)(sizeof(tb_motorFields) / sizeof(tb_motorFields[0]));
			return tb_motorFields;
		case tb_moverJoint:
			*count = (int)(sizeof(tb_moverFields) / sizeof(tb_moverFields[0]));
			return tb_moverFields;
		case tb_pogoJoint:
			*count = (int)(sizeof(tb_pogoFields) / sizeof(tb_pogoFields[0]));
			return tb_pogoFields;
		case tb_prismaticJoint:
			*count = (int)(sizeof(tb_prismaticFields) / sizeof(tb_prismaticFields[0]));
			return tb_prismaticFields;
		case tb_revoluteJoint:
			*count = (int)(sizeof(tb_revoluteFields) / sizeof(tb_revoluteFields[0]));
			return tb_revoluteFields;
		case tb_weldJoint:
			*count = (int)(sizeof(tb_weldFields) / sizeof(tb_weldFields[0]));
			return tb_weldFields;
		case tb_wheelJoint:
			*count = (int)(sizeof(tb_wheelFields) / sizeof(tb_wheelFields[0]));
			return tb_wheelFields;
		default:
			*count = 0; // the filter joint holds nothing of its own
			return NULL;
	}
}

#define TB_JOINT_FLOATS 13

static void tbJointFloats(const tbJoint* j, float v[TB_JOINT_FLOATS])
{
	float values[TB_JOINT_FLOATS] = {
		j->localFrameA.p.x,	 j->localFrameA.p.y, j->localFrameA.q.c, j->localFrameA.q.s,	 j->localFrameB.p.x,
		j->localFrameB.p.y,	 j->localFrameB.q.c, j->localFrameB.q.s, j->forceThreshold,	 j->torqueThreshold,
		j->constraintHertz, j->constraintDampingRatio, j->drawScale};
	memcpy(v, values, sizeof(values));
}

static void tbJointFloatDefaults(float v[TB_JOINT_FLOATS])
{
	tbJointDef def = tbDefaultRevoluteJointDef().base;
	tbJoint j;
	memset(&j, 0, sizeof(j));
	j.localFrameA = def.localFrameA;
	j.localFrameB = def.localFrameB;
	j.forceThreshold = def.forceThreshold;
	j.torqueThreshold = def.torqueThreshold;
	j.constraintHertz = def.constraintHertz;
	j.constraintDampingRatio = def.constraintDampingRatio;
	j.drawScale = def.drawScale;
	tbJointFloats(&j, v);
}

static void tbWriteJoints(tbEncoder* e)
{
	const tbWorld* world = e->world;
	tbWritePool(e, &world->jointPool, world->joints, sizeof(tbJoint), offsetof(tbJoint, generation), 2,
				world->jointGenerationBase);
	float defaults[TB_JOINT_FLOATS];
	tbJointFloatDefaults(defaults);
	for (int i = 0; i < world->jointPool.highWater; ++i)
	{
		const tbJoint* joint = world->joints + i;
		if (joint->inUse == false)
		{
			continue;
		}
		tbPutUInt(&e->w, joint->type);
		tbPutUInt(&e->w, (uint32_t)joint->edges[0].bodyId);
		tbPutUInt(&e->w, (uint32_t)joint->edges[1].bodyId);
		tbPutUInt(&e->w, joint->collideConnected ? 1u : 0u);
		float values[TB_JOINT_FLOATS];
		tbJointFloats(joint, values);
		tbPutFloatsOver(&e->w, values, defaults, TB_JOINT_FLOATS);
		int count;
		const tbJointField* fields = tbJointFields(joint->type, &count);
		float kindValues[64];
		int floatCount = 0;
		uint32_t bools = 0;
		int boolCount = 0;
		for (int k = 0; k < count; ++k)
		{
			const char* p = (const char*)joint + fields[k].offset;
			if (fields[k].check == tb_fieldBool)
			{
				bool b;
				memcpy(&b, p, sizeof(b));
				bools |= b ? 1u << boolCount : 0u;
				boolCount += 1;
			}
			else
			{
				memcpy(kindValues + floatCount, p, sizeof(float));
				floatCount += 1;
			}
		}
		tbPutUInt(&e->w, bools);
		tbPutFloatsOver(&e->w, kindValues, NULL, floatCount);
	}
	const tbWorld* w = world;
	for (int i = 0; i < w->bodyPool.highWater; ++i)
	{
		const tbBody* body = w->bodies + i;
		if (body->inUse == false)
		{
			continue;
		}
		tbPutUInt(&e->w, (uint32_t)body->jointCount);
		int previous = 0;
		for (int key = body->headJointKey; key != TB_NULL_INDEX; key = w->joints[key >> 1].edges[key & 1].nextKey)
		{
			tbPutDelta(&e->w, key, previous);
			previous = key;
		}
	}
}

/// The checks of the kind's API that no field table expresses: ranges and the pogo's unit normal.
static bool tbJointKindIsValid(const tbJoint* j)
{
	switch (j->type)
	{
		case tb_distanceJoint:
			return j->distance.lowerSpringForce <= j->distance.upperSpringForce &&
				   j->distance.minLength <= j->distance.maxLength;
		case tb_pogoJoint:
			return tbIsNormalized(j->pogo.normal) && j->pogo.restLength <= TB_MAX_COORDINATE;
		case tb_prismaticJoint:
			return j->prismatic.lowerTranslation <= j->prismatic.upperTranslation;
		case tb_revoluteJoint:
			return j->revolute.lowerAngle <= j->revolute.upperAngle && j->revolute.lowerAngle >= -TB_PI &&
				   j->revolute.upperAngle <= TB_PI;
		case tb_wheelJoint:
			return j->wheel.lowerTranslation <= j->wheel.upperTranslation;
		default:
			return true;
	}
}

static bool tbReadJoint(tbDecoder* d, int id)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	tbJoint* joint = world->joints + id;
	uint16_t generation = joint->generation;
	memset(joint, 0, sizeof(*joint));
	joint->generation = generation;
	joint->treeNode = TB_NULL_INDEX;
	uint32_t type = tbGetUInt(r);
	int bodyA = tbGetIndex(r, world->bodyPool.highWater, "a joint's body");
	int bodyB = tbGetIndex(r, world->bodyPool.highWater, "a joint's body");
	uint32_t flags = tbGetUInt(r);
	if (r->failed)
	{
		return false;
	}
	if (type >= tb_jointTypeCount || flags > 1u || bodyA == bodyB || world->bodies[bodyA].inUse == false ||
		world->bodies[bodyB].inUse == false)
	{
		return tbFail(r, "joint %d has an unknown type or flags, or does not join two bodies in use", id);
	}
	joint->inUse = true;
	joint->type = (uint8_t)type;
	joint->collideConnected = flags != 0;
	joint->edges[0].bodyId = bodyA;
	joint->edges[1].bodyId = bodyB;
	float values[TB_JOINT_FLOATS], defaults[TB_JOINT_FLOATS];
	tbJointFloatDefaults(defaults);
	tbGetFloatsOver(r, values, defaults, TB_JOINT_FLOATS, "a joint's frame or threshold");
	joint->localFrameA.p = tbMakeVec2(values[0], values[1]);
	joint->localFrameA.q = (tbRot){values[2], values[3]};
	joint->localFrameB.p = tbMakeVec2(values[4], values[5]);
	joint->localFrameB.q = (tbRot){values[6], values[7]};
	joint->forceThreshold = values[8];
	joint->torqueThreshold = values[9];
	joint->constraintHertz = values[10];
	joint->constraintDampingRatio = values[11];
	joint->drawScale = values[12];
	if (r->failed == false &&
		(tbIsValidRotation(joint->localFrameA.q) == false || tbIsValidRotation(joint->localFrameB.q) == false ||
		 tbIsNonNegative(joint->forceThreshold) == false || tbIsNonNegative(joint->torqueThreshold) == false ||
		 tbIsNonNegative(joint->constraintHertz) == false || tbIsNonNegative(joint->constraintDampingRatio) == false))
	{
		return tbFail(r, "joint %d has a frame that is not a unit rotation or a negative threshold or stiffness", id);
	}
	int count;
	const tbJointField* fields = tbJointFields((int)type, &count);
	uint32_t bools = tbGetUInt(r);
	float kindValues[64];
	int floatCount = 0, boolCount = 0;
	for (int k = 0; k < count; ++k)
	{
		floatCount += fields[k].check != tb_fieldBool ? 1 : 0;
	}
	tbGetFloatsOver(r, kindValues, NULL, floatCount, "a joint's parameter or impulse");
	if (r->failed)
	{
		return false;
	}
	floatCount = 0;
	for (int k = 0; k < count; ++k)
	{
		char* p = (char*)joint + fields[k].offset;
		if (fields[k].check == tb_fieldBool)
		{
			bool b = (bools & (1u << boolCount)) != 0;
			memcpy(p, &b, sizeof(b));
			boolCount += 1;
			continue;
		}
		float value = kindValues[floatCount++];
		if (fields[k].check == tb_fieldNonNegative && value < 0.0f)
		{
			return tbFail(r, "joint %d has a negative parameter that must be >= 0", id);
		}
		memcpy(p, &value, sizeof(value));
	}
	if ((bools >> boolCount) != 0 || tbJointKindIsValid(joint) == false)
	{
		return tbFail(r, "joint %d has unknown flags or parameters out of their ranges", id);
	}
	return true;
}

static bool tbReadJoints(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	r->section = "joints";
	uint8_t* slots;
	uint32_t* generations;
	if (tbReadPool(d, &world->jointPool, &slots, &generations, true, "joint") == false)
	{
		return false;
	}
	int highWater = world->jointPool.highWater;
	TB_ARRAY_RESERVE(world->joints, world->jointCapacity, highWater);
	for (int i = 0; i < highWater; ++i)
	{
		memset(world->joints + i, 0, sizeof(tbJoint));
		world->joints[i].generation = (uint16_t)generations[i]; // the base is added on adoption
	}
	for (int i = 0; i < highWater && r->failed == false; ++i)
	{
		if (slots[i] == tb_slotLive)
		{
			tbReadJoint(d, i);
		}
	}
	tbFreeSlots(&slots, &generations, highWater);
	r->section = "joint lists";
	return r->failed == false && tbReadEdgeLists(d, true);
}

// --------------------------------------------------------------------------------------------
// The awake list, in its order (the solver's body order).

static void tbWriteAwake(tbEncoder* e)
{
	const tbWorld* world = e->world;
	tbPutUInt(&e->w, (uint32_t)tbAwakeBodyCount(world));
	int previous = 0;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		if (world->awakeBodies[i] != TB_NULL_INDEX)
		{
			tbPutDelta(&e->w, world->awakeBodies[i], previous); // holes closed, as the next step does first
			previous = world->awakeBodies[i];
		}
	}
}

static bool tbReadAwake(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	r->section = "awake list";
	int count = tbGetCount(r, 1, "the awake body count");
	if (r->failed)
	{
		return false;
	}
	TB_ARRAY_RESERVE(world->awakeBodies, world->awakeBodyCapacity, count);
	int previous = 0;
	for (int i = 0; i < count && r->failed == false; ++i)
	{
		int id = tbGetDelta(r, previous, 0, world->bodyPool.highWater, "an awake body");
		previous = id;
		tbBody* body = world->bodies + id;
		if (r->failed == false &&
			(body->inUse == false || body->type == tb_staticBody || body->isDisabled || body->awakeIndex != TB_NULL_INDEX))
		{
			return tbFail(r, "the awake list holds body %d, which is not in use, static, disabled or already listed", id);
		}
		body->awakeIndex = i;
		world->awakeBodies[i] = id;
		world->awakeBodyCount = i + 1;
	}
	return r->failed == false;
}

// --------------------------------------------------------------------------------------------
// The broad phase: method, proxy table (its free chain; a live proxy's box, bits and type follow
// from its shape), move buffer, the tree method's two trees node for node, the spatial hash's
// state. Sort-and-sweep and brute force keep nothing that changes a result: their pairs are sorted
// (broad_phase.h's contract) and their queries scan the table, so they are rebuilt from the table.

enum
{
	tb_proxyBoxStored = 1,
	tb_proxyBitsStored = 2,
	tb_proxyIsStatic = 4,
};

enum
{
	tb_nodeLeaf = 1,
	tb_nodeEnlarged = 2,
	tb_nodeBoxStored = 4,
	tb_nodeBitsStored = 8,
	tb_nodeHeightStored = 16,
	tb_nodeAll = 31,
};

static void tbWriteTree(tbEncoder* e, const tbDynamicTree* tree, const tbBroadProxy* proxies)
{
	tbWriter* w = &e->w;
	tbPutUInt(w, (uint32_t)tree->nodeCapacity);
	if (tree->nodeCapacity == 0)
	{
		return;
	}
	tbPutInt(w, tree->root);
	tbPutUInt(w, (uint32_t)(tree->nodeCapacity - tree->nodeCount));
	for (int i = tree->freeList; i != TB_NULL_NODE; i = tree->nodes[i].next)
	{
		tbPutUInt(w, (uint32_t)i);
	}
	for (int i = 0; i < tree->nodeCapacity; ++i)
	{
		const tbTreeNode* node = tree->nodes + i;
		if ((node->flags & tb_allocatedNode) == 0)
		{
			continue;
		}
		bool leaf = (node->flags & tb_leafNode) != 0;
		tbAABB box;
		uint64_t bits;
		int height = 0;
		if (leaf)
		{
			const tbBroadProxy* p = proxies + node->userData;
			box = p->aabb;
			bits = p->categoryBits | TB_PAIR_QUERY_BIT;
		}
		else
		{
			const tbTreeNode* a = tree->nodes + node->children.child1;
			const tbTreeNode* b = tree->nodes + node->children.child2;
			box = tbAABB_Union(a->aabb, b->aabb);
			bits = a->categoryBits | b->categoryBits;
			height = 1 + tbMaxInt(a->height, b->height);
		}
		bool boxStored = tbSameAABB(box, node->aabb) == false;
		bool bitsStored = bits != node->categoryBits;
		bool heightStored = leaf == false && height != node->height;
		uint32_t tag = (leaf ? tb_nodeLeaf : 0u) | ((node->flags & tb_enlargedNode) != 0 ? tb_nodeEnlarged : 0u) |
					   (boxStored ? tb_nodeBoxStored : 0u) | (bitsStored ? tb_nodeBitsStored : 0u) |
					   (heightStored ? tb_nodeHeightStored : 0u);
		tbPutUInt(w, tag);
		if (leaf)
		{
			tbPutU64(w, node->userData);
		}
		else
		{
			tbPutUInt(w, (uint32_t)node->children.child1);
			tbPutUInt(w, (uint32_t)node->children.child2);
		}
		if (boxStored)
		{
			tbPutAABB(w, node->aabb);
		}
		if (bitsStored)
		{
			tbPutU64(w, node->categoryBits);
		}
		if (heightStored)
		{
			tbPutUInt(w, (uint32_t)node->height);
		}
	}
}

static void tbWriteBroadPhase(tbEncoder* e)
{
	const tbWorld* world = e->world;
	const tbBroadPhase* bp = &world->broadPhase;
	tbWriter* w = &e->w;
	TB_ASSERT(bp->refreshPending == false); // the step runs every refresh it defers
	tbPutUInt(w, (uint32_t)bp->method);
	tbPutUInt(w, (uint32_t)bp->table.capacity);
	tbPutUInt(w, (uint32_t)(bp->table.capacity - bp->table.count));
	for (int key = bp->freeProxy; key >= 0; key = bp->table.proxies[key].handle)
	{
		tbPutUInt(w, (uint32_t)key);
	}
	for (int key = 0; key < bp->table.capacity; ++key)
	{
		const tbBroadProxy* p = bp->table.proxies + key;
		if (p->isFree)
		{
			continue;
		}
		const tbShape* shape = world->shapes + p->shapeIndex;
		bool boxStored = tbSameAABB(p->aabb, shape->fatAABB) == false;
		bool bitsStored = p->categoryBits != shape->filter.categoryBits;
		uint32_t flags = (boxStored ? tb_proxyBoxStored : 0u) | (bitsStored ? tb_proxyBitsStored : 0u) |
						 (p->type == tb_proxyStatic ? tb_proxyIsStatic : 0u);
		tbPutUInt(w, flags);
		if (boxStored)
		{
			tbPutAABB(w, p->aabb);
		}
		if (bitsStored)
		{
			tbPutU64(w, p->categoryBits);
		}
	}
	tbPutUInt(w, (uint32_t)bp->moveCount);
	for (int i = 0; i < bp->moveCount; ++i)
	{
		tbPutInt(w, bp->moveBuffer[i]);
	}
	tbPutUInt(w, (uint32_t)bp->staticInsertCount);
	tbPutUInt(w, (uint32_t)bp->enlargedCount);
	if (bp->method == tb_broadPhaseSpatialHash)
	{
		tbSpatialHashState state = tbSpatialHash_GetState(bp->hash);
		tbPutFloat(w, state.cellSize);
		tbPutU8(w, state.staticDirty ? 1u : 0u);
		tbPutUInt(w, (uint32_t)state.updateCount);
	}
	else if (bp->method == tb_broadPhaseTree)
	{
		tbWriteTree(e, &bp->staticTree, bp->table.proxies);
		tbWriteTree(e, &bp->movableTree, bp->table.proxies);
	}
}

static bool tbReadTree(tbDecoder* d, tbDynamicTree* tree, tbBroadPhase* bp, bool staticTree)
{
	tbReader* r = &d->r;
	const char* name = staticTree ? "static tree" : "movable tree";
	int capacity = tbGetCount(r, 1, "a tree's node count");
	if (r->failed || capacity == 0)
	{
		return r->failed == false;
	}
	int root = tbGetInt(r);
	int freeCount = tbGetCount(r, 1, "a tree's free node count");
	if (r->failed)
	{
		return false;
	}
	if (freeCount > capacity || root < TB_NULL_NODE || root >= capacity)
	{
		return tbFail(r, "the %s has %d free nodes or root %d for %d nodes", name, freeCount, root, capacity);
	}
	tree->nodes = tbAlloc(capacity * (int)sizeof(tbTreeNode));
	memset(tree->nodes, 0, (size_t)capacity * sizeof(tbTreeNode));
	tree->nodeCapacity = capacity;
	tree->freeList = TB_NULL_NODE;
	tree->root = TB_NULL_NODE;
	// Per node: 0 in use, 1 free, 2 reached from the root; and what each node's tag stored.
	uint8_t* state = tbAlloc(capacity);
	uint8_t* tags = tbAlloc(capacity);
	int* order = tbAlloc(capacity * (int)sizeof(int));
	memset(state, 0, (size_t)capacity);
	int previous = TB_NULL_NODE;
	for (int i = 0; i < freeCount && r->failed == false; ++i)
	{
		int index = tbGetIndex(r, capacity, "a free tree node");
		if (r->failed == false && state[index] != 0)
		{
			tbFail(r, "the %s lists node %d as free twice", name, index);
			break;
		}
		state[index] = 1;
		tree->nodes[index].flags = 0;
		tree->nodes[index].next = TB_NULL_NODE;
		if (previous == TB_NULL_NODE)
		{
			tree->freeList = index;
		}
		else
		{
			tree->nodes[previous].next = index;
		}
		previous = index;
	}
	int used = capacity - freeCount;
	for (int i = 0; i < capacity && r->failed == false; ++i)
	{
		if (state[i] != 0)
		{
			continue;
		}
		tbTreeNode* node = tree->nodes + i;
		uint32_t tag = tbGetUInt(r);
		if (r->failed == false && (tag & ~(uint32_t)tb_nodeAll) != 0)
		{
			tbFail(r, "node %d of the %s has unknown flags", i, name);
			break;
		}
		tags[i] = (uint8_t)tag;
		node->parent = TB_NULL_NODE;
		node->children.child1 = TB_NULL_NODE;
		node->children.child2 = TB_NULL_NODE;
		node->flags = (uint16_t)(tb_allocatedNode | ((tag & tb_nodeEnlarged) != 0 ? tb_enlargedNode : 0) |
								 ((tag & tb_nodeLeaf) != 0 ? tb_leafNode : 0));
		if (tag & tb_nodeLeaf)
		{
			uint64_t key = tbGetU64(r);
			if (r->failed == false && key >= (uint64_t)bp->table.capacity)
			{
				tbFail(r, "leaf %d of the %s names proxy %llu, out of range", i, name, (unsigned long long)key);
				break;
			}
			node->userData = key;
		}
		else
		{
			node->children.child1 = tbGetIndex(r, capacity, "a tree node's child");
			node->children.child2 = tbGetIndex(r, capacity, "a tree node's child");
		}
		if (tag & tb_nodeBoxStored)
		{
			node->aabb = tbGetAABB(r, "a tree node's box");
		}
		if (tag & tb_nodeBitsStored)
		{
			node->categoryBits = tbGetU64(r);
		}
		if (tag & tb_nodeHeightStored)
		{
			uint32_t height = tbGetUInt(r);
			if (r->failed == false && ((tag & tb_nodeLeaf) != 0 || height < 1 || height > INT16_MAX))
			{
				tbFail(r, "node %d of the %s has height %u", i, name, height);
				break;
			}
			node->height = (uint16_t)height;
		}
	}
	// The nodes in use form one tree under the root: each reached once, from its only parent.
	int reached = 0;
	if (r->failed == false && (root == TB_NULL_NODE) != (used == 0))
	{
		tbFail(r, "the %s has %d nodes in use but root %d", name, used, root);
	}
	else if (r->failed == false && used > 0)
	{
		if (state[root] != 0)
		{
			tbFail(r, "the root of the %s is a free node", name);
		}
		else
		{
			int* stack = tbAlloc(capacity * (int)sizeof(int));
			int top = 0;
			stack[top++] = root;
			state[root] = 2;
			while (top > 0 && r->failed == false)
			{
				int index = stack[--top];
				order[reached++] = index;
				tbTreeNode* node = tree->nodes + index;
				if (tags[index] & tb_nodeLeaf)
				{
					continue;
				}
				int children[2] = {node->children.child1, node->children.child2};
				for (int k = 0; k < 2; ++k)
				{
					if (state[children[k]] != 0)
					{
						tbFail(r, "node %d of the %s is free or has two parents", children[k], name);
						break;
					}
					state[children[k]] = 2;
					tree->nodes[children[k]].parent = index;
					stack[top++] = children[k];
				}
			}
			tbFree(stack, capacity * (int)sizeof(int));
			if (r->failed == false && reached != used)
			{
				tbFail(r, "%d nodes of the %s are not reached from its root", used - reached, name);
			}
		}
	}
	// Leaves claim their proxies; boxes, bits and heights are made from the children up (the
	// reverse of the order reached, which lists each node before its children).
	int leaves = 0;
	for (int k = reached - 1; k >= 0 && r->failed == false; --k)
	{
		int index = order[k];
		tbTreeNode* node = tree->nodes + index;
		uint8_t tag = tags[index];
		if (tag & tb_nodeLeaf)
		{
			tbBroadProxy* p = bp->table.proxies + node->userData;
			if (p->isFree || (p->type == tb_proxyStatic) != staticTree || p->handle != -1)
			{
				tbFail(r, "leaf %d of the %s names a proxy that is free, of the other tree, or named twice", index, name);
				break;
			}
			p->handle = index;
			leaves += 1;
			node->aabb = (tag & tb_nodeBoxStored) ? node->aabb : p->aabb;
			node->categoryBits = (tag & tb_nodeBitsStored) ? node->categoryBits : (p->categoryBits | TB_PAIR_QUERY_BIT);
			node->height = 0;
			continue;
		}
		const tbTreeNode* a = tree->nodes + node->children.child1;
		const tbTreeNode* b = tree->nodes + node->children.child2;
		node->aabb = (tag & tb_nodeBoxStored) ? node->aabb : tbAABB_Union(a->aabb, b->aabb);
		node->categoryBits = (tag & tb_nodeBitsStored) ? node->categoryBits : (a->categoryBits | b->categoryBits);
		if ((tag & tb_nodeHeightStored) == 0)
		{
			int height = 1 + tbMaxInt(a->height, b->height);
			if (height > INT16_MAX)
			{
				tbFail(r, "the %s is deeper than its heights can count", name);
				break;
			}
			node->height = (uint16_t)height;
		}
	}
	tbFree(state, capacity);
	tbFree(tags, capacity);
	tbFree(order, capacity * (int)sizeof(int));
	tree->root = r->failed ? TB_NULL_NODE : root;
	tree->nodeCount = used;
	tree->proxyCount = leaves;
	return r->failed == false;
}

static bool tbReadBroadPhase(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	r->section = "broad phase";
	uint32_t method = tbGetUInt(r);
	if (r->failed == false && (method == tb_broadPhaseAuto || method >= tb_broadPhaseMethodCount))
	{
		return tbFail(r, "its broad-phase method is %u", method);
	}
	int capacity = tbGetCount(r, 1, "the proxy table's size");
	int freeCount = tbGetCount(r, 1, "the free proxy count");
	if (r->failed)
	{
		return false;
	}
	if (freeCount > capacity)
	{
		return tbFail(r, "the proxy table lists %d free proxies of %d", freeCount, capacity);
	}
	tbBroadPhase* bp = &world->broadPhase;
	tbBroadPhase_Destroy(bp);
	tbBroadPhase_Create(bp, (tbBroadPhaseMethod)method);
	tbBroadPhase_SetPairFilter(bp, tbContactPairFilter, tbContactPairPrefetch, world);
	bp->table.proxies = capacity > 0 ? tbAlloc(capacity * (int)sizeof(tbBroadProxy)) : NULL;
	bp->table.capacity = capacity;
	for (int key = 0; key < capacity; ++key)
	{
		bp->table.proxies[key] = (tbBroadProxy){.handle = -1, .moveIndex = -1, .isFree = false};
	}
	int previous = -1;
	for (int i = 0; i < freeCount && r->failed == false; ++i)
	{
		int key = tbGetIndex(r, capacity, "a free proxy");
		if (r->failed == false && bp->table.proxies[key].isFree)
		{
			return tbFail(r, "the proxy table lists proxy %d as free twice", key);
		}
		bp->table.proxies[key].isFree = true;
		if (previous < 0)
		{
			bp->freeProxy = key;
		}
		else
		{
			bp->table.proxies[previous].handle = key;
		}
		previous = key;
	}
	if (r->failed)
	{
		return false;
	}
	// Each shape in the broad phase owns one proxy, and each proxy in use one shape; a shape of a
	// disabled body has none.
	int* owner = tbAlloc((capacity + 1) * (int)sizeof(int));
	for (int key = 0; key < capacity; ++key)
	{
		owner[key] = TB_NULL_INDEX;
	}
	for (int i = 0; i < world->shapePool.highWater && r->failed == false; ++i)
	{
		const tbShape* shape = world->shapes + i;
		if (shape->inUse == false)
		{
			continue;
		}
		bool disabled = world->bodies[shape->bodyId].isDisabled;
		int key = shape->proxyKey;
		if ((key == TB_NULL_INDEX) != disabled || key >= capacity ||
			(key >= 0 && (bp->table.proxies[key].isFree || owner[key] != TB_NULL_INDEX)))
		{
			tbFail(r, "shape %d has proxy %d, which is out of range, free or another shape's, or is (not) in the "
					  "broad phase while its body is (not) disabled", i, key);
			break;
		}
		if (key >= 0)
		{
			owner[key] = i;
		}
	}
	for (int key = 0; key < capacity && r->failed == false; ++key)
	{
		tbBroadProxy* p = bp->table.proxies + key;
		if (p->isFree)
		{
			continue;
		}
		if (owner[key] == TB_NULL_INDEX)
		{
			tbFail(r, "proxy %d is in use but belongs to no shape", key);
			break;
		}
		const tbShape* shape = world->shapes + owner[key];
		uint32_t flags = tbGetUInt(r);
		if (r->failed == false && flags > 7u)
		{
			tbFail(r, "proxy %d has unknown flags", key);
			break;
		}
		p->aabb = (flags & tb_proxyBoxStored) ? tbGetAABB(r, "a proxy's box") : shape->fatAABB;
		p->categoryBits = (flags & tb_proxyBitsStored) ? tbGetU64(r) : shape->filter.categoryBits;
		p->shapeIndex = owner[key];
		p->type = (flags & tb_proxyIsStatic) ? tb_proxyStatic : tb_proxyMovable;
		bp->table.count += 1;
		world->staticProxyCount += p->type == tb_proxyStatic ? 1 : 0;
	}
	tbFree(owner, (capacity + 1) * (int)sizeof(int));
	int moveCount = tbGetCount(r, 1, "the move buffer's length");
	if (r->failed)
	{
		return false;
	}
	bp->moveBuffer = moveCount > 0 ? tbAlloc(moveCount * (int)sizeof(int)) : NULL;
	bp->moveCapacity = moveCount;
	for (int i = 0; i < moveCount && r->failed == false; ++i)
	{
		int key = tbGetInt(r);
		if (r->failed == false && key != -1 &&
			(key < 0 || key >= capacity || bp->table.proxies[key].isFree || bp->table.proxies[key].moveIndex >= 0))
		{
			return tbFail(r, "the move buffer holds proxy %d, which is out of range, free or listed twice", key);
		}
		if (key >= 0)
		{
			bp->table.proxies[key].moveIndex = i;
		}
		bp->moveBuffer[i] = key;
		bp->moveCount = i + 1;
	}
	bp->staticInsertCount = tbGetCountValue(r, TB_SNAPSHOT_COUNTER_MAX, "the static insert count");
	bp->enlargedCount = tbGetCountValue(r, TB_SNAPSHOT_COUNTER_MAX, "the enlarged count");
	if (r->failed)
	{
		return false;
	}
	if (bp->method == tb_broadPhaseSpatialHash)
	{
		tbSpatialHashState state;
		state.cellSize = tbGetFloat(r, "the spatial hash's cell size");
		uint32_t dirty = tbGetU8(r);
		state.updateCount = tbGetCountValue(r, TB_SNAPSHOT_COUNTER_MAX, "the spatial hash's update count");
		state.staticDirty = dirty != 0;
		if (r->failed == false && (dirty > 1u || (state.cellSize != 0.0f && !(state.cellSize > 1e-3f && state.cellSize < 1e6f))))
		{
			return tbFail(r, "the spatial hash's cell size %g is not one it chooses", (double)state.cellSize);
		}
		if (r->failed)
		{
			return false;
		}
		tbSpatialHash_SetState(bp->hash, &bp->table, state);
	}
	else if (bp->method == tb_broadPhaseTree)
	{
		if (tbReadTree(d, &bp->staticTree, bp, true) == false || tbReadTree(d, &bp->movableTree, bp, false) == false)
		{
			return false;
		}
		for (int key = 0; key < capacity; ++key)
		{
			if (bp->table.proxies[key].isFree == false && bp->table.proxies[key].handle < 0)
			{
				return tbFail(r, "proxy %d is in no tree", key);
			}
		}
	}
	else if (bp->method == tb_broadPhaseSortAndSweep)
	{
		for (int key = 0; key < capacity; ++key)
		{
			if (bp->table.proxies[key].isFree == false)
			{
				tbSortAndSweep_AddProxy(bp->sweep, &bp->table, key);
			}
		}
	}
	return true;
}

// --------------------------------------------------------------------------------------------
// End events waiting for the next step (a shape destroyed or filtered between steps): the next
// step reports them, so they are part of what it does. The last step's events are not: a restored
// world reports nothing until it steps, as in Box2D v3.2.

static void tbPutShapeId(tbEncoder* e, tbShapeId id)
{
	tbPutUInt(&e->w, (uint32_t)id.index1);
	tbPutUInt(&e->w, (uint16_t)(id.generation - e->world->shapeGenerationBase));
}

static void tbWriteEvents(tbEncoder* e)
{
	const tbEventBuffers* events = &e->world->events;
	tbPutUInt(&e->w, (uint32_t)events->pendingEndCount);
	for (int i = 0; i < events->pendingEndCount; ++i)
	{
		tbPutShapeId(e, events->pendingEndEvents[i].shapeIdA);
		tbPutShapeId(e, events->pendingEndEvents[i].shapeIdB);
		// The contact's slot and the generation's own part (the world's part, the high 16 bits, is
		// the adopting world's, as for the contacts themselves).
		tbPutUInt(&e->w, (uint32_t)events->pendingEndEvents[i].contactId.index1);
		tbPutUInt(&e->w, events->pendingEndEvents[i].contactId.generation & 0xFFFFu);
	}
	tbPutUInt(&e->w, (uint32_t)events->pendingSensorEndCount);
	for (int i = 0; i < events->pendingSensorEndCount; ++i)
	{
		tbPutShapeId(e, events->pendingSensorEndEvents[i].sensorShapeId);
		tbPutShapeId(e, events->pendingSensorEndEvents[i].visitorShapeId);
	}
}

/// A shape id of an event: its slot (the shape may be gone) and generation offset; the world and
/// its generation base are filled in on adoption.
static tbShapeId tbGetShapeId(tbReader* r)
{
	tbShapeId id = {0, 0, 0};
	uint32_t index1 = tbGetUInt(r);
	uint32_t generation = tbGetUInt(r);
	if (r->failed == false && (index1 == 0 || index1 > INT32_MAX || generation > UINT16_MAX))
	{
		tbFail(r, "an end event names shape slot %u generation %u", index1, generation);
	}
	id.index1 = (int32_t)index1;
	id.generation = (uint16_t)generation;
	return id;
}

static bool tbReadEvents(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbEventBuffers* events = &d->world->events;
	r->section = "pending events";
	int count = tbGetCount(r, 4, "the pending end events");
	for (int i = 0; i < count && r->failed == false; ++i)
	{
		tbContactEndTouchEvent e;
		e.shapeIdA = tbGetShapeId(r);
		e.shapeIdB = tbGetShapeId(r);
		uint32_t contactIndex1 = tbGetUInt(r);
		uint32_t contactGeneration = tbGetUInt(r);
		if (r->failed == false && (contactIndex1 > INT32_MAX || contactGeneration > UINT16_MAX))
		{
			tbFail(r, "an end event names contact slot %u generation %u", contactIndex1, contactGeneration);
		}
		e.contactId = (tbContactId){(int32_t)contactIndex1, 0, 0, contactGeneration};
		TB_ARRAY_PUSH(events->pendingEndEvents, events->pendingEndCount, events->pendingEndCapacity, e);
	}
	count = tbGetCount(r, 4, "the pending sensor end events");
	for (int i = 0; i < count && r->failed == false; ++i)
	{
		tbSensorEndTouchEvent e;
		e.sensorShapeId = tbGetShapeId(r);
		e.visitorShapeId = tbGetShapeId(r);
		TB_ARRAY_PUSH(events->pendingSensorEndEvents, events->pendingSensorEndCount, events->pendingSensorEndCapacity, e);
	}
	return r->failed == false;
}

// --------------------------------------------------------------------------------------------
// The whole image.

static void tbEncodeWorld(tbEncoder* e)
{
	uint8_t header[TB_SNAPSHOT_HEADER_SIZE];
	memset(header, 0, sizeof(header));
	tbPutBytes(&e->w, header, TB_SNAPSHOT_HEADER_SIZE); // filled in by tbWorld_Snapshot
	tbBodyFloatDefaults(e->bodyDefaults);
	tbWriteSettings(e);
	tbWriteBodies(e);
	tbWriteChains(e);
	tbWriteContacts(e);
	tbWriteJoints(e);
	tbWriteAwake(e);
	tbWriteBroadPhase(e);
	tbWriteEvents(e);
}

static bool tbReadBodies(tbDecoder* d)
{
	tbReader* r = &d->r;
	tbWorld* world = d->world;
	r->section = "bodies";
	uint32_t* bodyGenerations = NULL;
	uint32_t* shapeGenerations = NULL;
	bool ok = tbReadPool(d, &world->bodyPool, &d->bodySlots, &bodyGenerations, true, "body") &&
			  tbReadPool(d, &world->shapePool, &d->shapeSlots, &shapeGenerations, true, "shape");
	int bodyCount = world->bodyPool.highWater, shapeCount = world->shapePool.highWater;
	if (ok)
	{
		TB_ARRAY_RESERVE(world->bodies, world->bodyCapacity, bodyCount);
		TB_ARRAY_RESERVE(world->shapes, world->shapeCapacity, shapeCount);
		for (int i = 0; i < bodyCount; ++i)
		{
			memset(world->bodies + i, 0, sizeof(tbBody));
			world->bodies[i].generation = (uint16_t)bodyGenerations[i]; // the base is added on adoption
		}
		for (int i = 0; i < shapeCount; ++i)
		{
			memset(world->shapes + i, 0, sizeof(tbShape));
			world->shapes[i].generation = (uint16_t)shapeGenerations[i];
			world->shapes[i].proxyKey = TB_NULL_INDEX;
			world->shapes[i].nextShapeId = TB_NULL_INDEX;
		}
		d->shapeBoxes = tbAlloc(shapeCount + 1);
		d->nameLengths = tbAlloc((bodyCount + 1) * (int)sizeof(int));
		d->nameSources = tbAlloc((bodyCount + 1) * (int)sizeof(const char*));
		memset(d->nameLengths, 0, (size_t)(bodyCount + 1) * sizeof(int));
		memset(d->nameSources, 0, (size_t)(bodyCount + 1) * sizeof(const char*));
		for (int i = 0; i < bodyCount && r->failed == false; ++i)
		{
			if (d->bodySlots[i] == tb_slotLive)
			{
				d->bodySlots[i] = tb_slotRead;
				tbReadBody(d, i);
			}
		}
		for (int i = 0; i < shapeCount && r->failed == false; ++i)
		{
			if (d->shapeSlots[i] == tb_slotLive)
			{
				tbFail(r, "shape %d is in use but no body lists it", i);
			}
		}
	}
	tbFree(bodyGenerations, (bodyCount + 1) * (int)sizeof(uint32_t));
	tbFree(shapeGenerations, (shapeCount + 1) * (int)sizeof(uint32_t));
	for (int i = 0; i < bodyCount && r->failed == false; ++i)
	{
		const tbBody* body = world->bodies + i;
		if (body->inUse)
		{
			world->kinematicBodyCount += body->type == tb_kinematicBody ? 1 : 0;
			world->staticBodyCount += body->type == tb_staticBody ? 1 : 0;
			world->linearLockCount += body->lockLinearX || body->lockLinearY ? 1 : 0;
			world->fastRotationCount += body->allowFastRotation ? 1 : 0;
		}
	}
	return r->failed == false;
}

/// The world's own copies of the body names (a body's name is otherwise the game's string).
static void tbCopyNames(tbDecoder* d)
{
	tbWorld* world = d->world;
	int total = 0;
	for (int i = 0; i < world->bodyPool.highWater; ++i)
	{
		total += d->nameSources[i] != NULL ? d->nameLengths[i] + 1 : 0;
	}
	if (total == 0)
	{
		return;
	}
	world->snapshotNames = tbAlloc(total);
	world->snapshotNamesSize = total;
	char* next = world->snapshotNames;
	for (int i = 0; i < world->bodyPool.highWater; ++i)
	{
		if (d->nameSources[i] != NULL)
		{
			memcpy(next, d->nameSources[i], (size_t)d->nameLengths[i]);
			next[d->nameLengths[i]] = 0;
			world->bodies[i].name = next;
			next += d->nameLengths[i] + 1;
		}
	}
}

static tbWorld* tbNewStagingWorld(void)
{
	tbWorld* world = tbAlloc((int)sizeof(tbWorld));
	memset(world, 0, sizeof(tbWorld));
	world->def = tbDefaultWorldDef();
	tbHashSet_Create(&world->pairSet, 64);
	tbBroadPhase_Create(&world->broadPhase, tb_broadPhaseTree);
	return world;
}

static void tbFreeStagingWorld(tbWorld* world)
{
	tbFreeWorldContents(world);
	tbFree(world, (int)sizeof(tbWorld));
}

static void tbFreeDecoder(tbDecoder* d)
{
	int bodies = d->world->bodyPool.highWater, shapes = d->world->shapePool.highWater;
	tbFree(d->bodySlots, bodies + 1);
	tbFree(d->shapeSlots, shapes + 1);
	tbFree(d->shapeBoxes, shapes + 1);
	tbFree(d->nameLengths, (bodies + 1) * (int)sizeof(int));
	tbFree(d->nameSources, (bodies + 1) * (int)sizeof(const char*));
	tbDictionaryFree(&d->geometries);
	tbDictionaryFree(&d->materials);
}

/// The step cache of a world that has not stepped since it was restored: every version differs
/// from every stamp, so each stage rebuilds what it would otherwise keep (step_cache.h), and what
/// it rebuilds is what it would have kept.
static void tbInvalidateStepCache(tbWorld* world)
{
	tbStepCache* cache = &world->cache;
	cache->awakeSetVersion = 1;
	cache->gatheredVersion = 0;
	cache->awakeRemovals = 1;
	cache->gatheredRemovals = 0;
	cache->contactEpoch = 1;
	cache->touchingEpoch = 0;
	cache->colorCacheStep = world->stepIndex - 2u;
	cache->partitionRetryStep = world->stepIndex;
	cache->jointWakeDirty = true;
	cache->jointTreesStale = true;
	cache->fastMarkedStep = world->stepIndex;
	cache->fastMarkedCount = 0;
}

/// Decode and check a whole image (the header checked already) into a new world no one can reach.
/// NULL and a message in `r` when the image is refused.
static tbWorld* tbDecodeWorld(tbReader* r)
{
	tbDecoder d;
	memset(&d, 0, sizeof(d));
	d.r = *r;
	d.world = tbNewStagingWorld();
	tbBodyFloatDefaults(d.bodyDefaults);
	bool ok = tbReadSettings(&d) && tbReadBodies(&d) && tbReadChains(&d) && tbReadContacts(&d) && tbReadJoints(&d) &&
			  tbReadAwake(&d) && tbReadBroadPhase(&d) && tbReadEvents(&d);
	if (ok && d.r.offset != d.r.size)
	{
		ok = tbFail(&d.r, "%d bytes follow the end of its content", d.r.size - d.r.offset);
	}
	// Shapes in contact are in the broad phase (the narrow phase reads their proxies).
	for (int i = 0; ok && i < d.world->contactPool.highWater; ++i)
	{
		const tbContact* c = d.world->contacts + i;
		if (c->inUse && (d.world->shapes[c->shapeIdA].proxyKey < 0 || d.world->shapes[c->shapeIdB].proxyKey < 0))
		{
			ok = tbFail(&d.r, "contact %d joins a shape that is not in the broad phase", i);
		}
	}
	if (ok)
	{
		tbCopyNames(&d);
		tbInvalidateStepCache(d.world);
	}
	tbFreeDecoder(&d);
	*r = d.r;
	if (ok == false)
	{
		tbFreeStagingWorld(d.world);
		return NULL;
	}
	return d.world;
}

/// The header's checks, in the order that names the most telling problem.
static bool tbOpenImage(tbReader* r, const uint8_t* image, int size)
{
	memset(r, 0, sizeof(*r));
	r->data = image;
	r->size = size;
	r->section = "header";
	if (size < TB_SNAPSHOT_HEADER_SIZE)
	{
		return tbFail(r, "the image is %d bytes, shorter than a snapshot's %d-byte header (truncated)", size,
					  TB_SNAPSHOT_HEADER_SIZE);
	}
	if (tbLoadU32(image) != TB_SNAPSHOT_MAGIC)
	{
		return tbFail(r, "the image does not start with \"TBSN\": not a Tumble snapshot (tbWorld_Snapshot makes one)");
	}
	uint32_t version = (uint32_t)image[4] | (uint32_t)image[5] << 8;
	if (version != TB_SNAPSHOT_VERSION)
	{
		return tbFail(r, "the image is snapshot version %u; this library reads version %u", version, TB_SNAPSHOT_VERSION);
	}
	if (image[6] != TB_SNAPSHOT_PRECISION)
	{
		return tbFail(r, "the image was made by the %s build; this is the %s build (TUMBLE_DOUBLE_PRECISION)",
					  image[6] == 1 ? "double-precision (large-world)" : "float", TB_SNAPSHOT_PRECISION ? "double-precision" : "float");
	}
	uint32_t declared = tbLoadU32(image + 8);
	if (image[7] != TB_SNAPSHOT_HEADER_SIZE || image[6] > 1)
	{
		return tbFail(r, "the image's header is damaged");
	}
	if (declared != (uint32_t)size)
	{
		return tbFail(r, "the image says it is %u bytes but %d were given (truncated or padded)", declared, size);
	}
	if (tbLoadU64(image + 16) != tbSnapshotChecksum(image, size))
	{
		return tbFail(r, "the image is corrupt: its checksum does not match its bytes");
	}
	float units;
	uint32_t unitBits = tbLoadU32(image + 12);
	memcpy(&units, &unitBits, sizeof(units));
	if (units != tbGetLengthUnitsPerMeter())
	{
		return tbFail(r, "the image was made with %g length units per metre; this process uses %g "
						 "(tbSetLengthUnitsPerMeter)", (double)units, (double)tbGetLengthUnitsPerMeter());
	}
	r->offset = TB_SNAPSHOT_HEADER_SIZE;
	return true;
}

// --------------------------------------------------------------------------------------------
// Adoption: the decoded state goes into a registered world, which keeps its identity and, in
// place, its host wiring.

static void tbApplyGenerations(tbWorld* world)
{
	for (int i = 0; i < world->bodyPool.highWater; ++i)
	{
		world->bodies[i].generation = (uint16_t)(world->bodies[i].generation + world->bodyGenerationBase);
	}
	for (int i = 0; i < world->shapePool.highWater; ++i)
	{
		world->shapes[i].generation = (uint16_t)(world->shapes[i].generation + world->shapeGenerationBase);
	}
	for (int i = 0; i < world->jointPool.highWater; ++i)
	{
		world->joints[i].generation = (uint16_t)(world->joints[i].generation + world->jointGenerationBase);
	}
	for (int i = 0; i < world->chainPool.highWater; ++i)
	{
		world->chains[i].generation = (uint16_t)(world->chains[i].generation + world->chainGenerationBase);
	}
	for (int i = 0; i < world->contactPool.highWater; ++i)
	{
		world->contacts[i].generation += (uint32_t)world->generation << 16;
	}
	tbEventBuffers* events = &world->events;
	for (int i = 0; i < events->pendingEndCount; ++i)
	{
		tbContactId* contactId = &events->pendingEndEvents[i].contactId;
		contactId->world0 = world->worldId;
		contactId->generation = (contactId->generation & 0xFFFFu) + ((uint32_t)world->generation << 16);
		tbShapeId* ids[2] = {&events->pendingEndEvents[i].shapeIdA, &events->pendingEndEvents[i].shapeIdB};
		for (int k = 0; k < 2; ++k)
		{
			ids[k]->world0 = world->worldId;
			ids[k]->generation = (uint16_t)(ids[k]->generation + world->shapeGenerationBase);
		}
	}
	for (int i = 0; i < events->pendingSensorEndCount; ++i)
	{
		tbShapeId* ids[2] = {&events->pendingSensorEndEvents[i].sensorShapeId,
							 &events->pendingSensorEndEvents[i].visitorShapeId};
		for (int k = 0; k < 2; ++k)
		{
			ids[k]->world0 = world->worldId;
			ids[k]->generation = (uint16_t)(ids[k]->generation + world->shapeGenerationBase);
		}
	}
}

/// Replace the contents of `target` with the decoded `staged` (freed here). The target keeps its
/// slot, generations, generation bases and host wiring: task system and worker count, user data,
/// callbacks (what Box2D v3.2's in-place restore keeps).
static void tbAdoptWorld(tbWorld* target, tbWorld* staged)
{
	tbNoteGenerationPeaks(target); // ids made since the snapshot stay out of the next world in this slot
	tbWorld kept = *target;
	tbFreeWorldContents(target);
	*target = *staged;
	tbFree(staged, (int)sizeof(tbWorld));
	target->worldId = kept.worldId;
	target->generation = kept.generation;
	target->bodyGenerationBase = kept.bodyGenerationBase;
	target->shapeGenerationBase = kept.shapeGenerationBase;
	target->jointGenerationBase = kept.jointGenerationBase;
	target->chainGenerationBase = kept.chainGenerationBase;
	memcpy(target->generationPeaks, kept.generationPeaks, sizeof(kept.generationPeaks));
	target->def.frictionCallback = kept.def.frictionCallback;
	target->def.restitutionCallback = kept.def.restitutionCallback;
	target->def.workerCount = kept.def.workerCount;
	target->def.enqueueTask = kept.def.enqueueTask;
	target->def.finishTask = kept.def.finishTask;
	target->def.userTaskContext = kept.def.userTaskContext;
	target->def.userData = kept.def.userData;
	target->def.internalValue = kept.def.internalValue;
	target->customFilterFcn = kept.customFilterFcn;
	target->customFilterContext = kept.customFilterContext;
	target->preSolveFcn = kept.preSolveFcn;
	target->preContinuousFcn = kept.preContinuousFcn;
	target->preSolveContext = kept.preSolveContext;
	target->userData = kept.userData;
	target->recording = kept.recording;
	target->locked = false;
	target->queryDepth = 0;
	memset(&target->profile, 0, sizeof(target->profile));
	memset(&target->counters, 0, sizeof(target->counters));
	// The broad phase's pair filter names its world.
	tbBroadPhase_SetPairFilter(&target->broadPhase, tbContactPairFilter, tbContactPairPrefetch, target);
	tbApplyGenerations(target);
}

// --------------------------------------------------------------------------------------------
// The API

int tbWorld_Snapshot(tbWorldId worldId, uint8_t* image, int capacity)
{
	const char* f = "tbWorld_Snapshot";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL)
	{
		return 0;
	}
	if (world->locked)
	{
		tbReportError(f, "the world is locked (stepping); take snapshots between steps");
		return 0;
	}
	if (image == NULL && capacity != 0)
	{
		tbReportError(f, "image is NULL but capacity is %d; pass NULL and 0 to ask for the size, or a buffer of that "
						 "size", capacity);
		return 0;
	}
	if (capacity < 0)
	{
		tbReportError(f, "capacity is %d; pass the size of image in bytes", capacity);
		return 0;
	}
	// Contact materials are predicted with the default mixing, whatever callbacks the world has.
	tbWorld* mixer = tbAlloc((int)sizeof(tbWorld));
	*mixer = *world;
	mixer->def.frictionCallback = NULL;
	mixer->def.restitutionCallback = NULL;
	tbEncoder e;
	memset(&e, 0, sizeof(e));
	e.world = world;
	e.mixer = mixer;
	if (image != NULL)
	{
		e.w.capacity = capacity > 0 ? capacity : 4096; // a first guess: the caller's buffer's size
		e.w.data = tbAlloc((int)e.w.capacity);
	}
	tbEncodeWorld(&e);
	tbFree(mixer, (int)sizeof(tbWorld));
	int64_t size = e.w.size;
	if (size > INT32_MAX)
	{
		tbFree(e.w.data, (int)e.w.capacity);
		tbReportError(f, "the world's image would be %lld bytes, beyond what an int counts", (long long)size);
		return 0;
	}
	if (image != NULL && size <= capacity)
	{
		uint8_t* out = e.w.data;
		memcpy(out, "TBSN", 4);
		tbStoreU16(out + 4, TB_SNAPSHOT_VERSION);
		out[6] = (uint8_t)TB_SNAPSHOT_PRECISION;
		out[7] = (uint8_t)TB_SNAPSHOT_HEADER_SIZE;
		tbStoreU32(out + 8, (uint32_t)size);
		float units = tbGetLengthUnitsPerMeter();
		uint32_t unitBits;
		memcpy(&unitBits, &units, sizeof(unitBits));
		tbStoreU32(out + 12, unitBits);
		tbStoreU32(out + 24, world->stepIndex);
		tbStoreU32(out + 28, (uint32_t)world->bodyPool.count);
		tbSnapshotSeal(out, (int)size);
		memcpy(image, out, (size_t)size);
	}
	tbFree(e.w.data, (int)e.w.capacity);
	return (int)size;
}

/// The checks both restores share; the decoded world, or NULL after reporting to `f`.
static tbWorld* tbDecodeImage(const char* f, const uint8_t* image, int size)
{
	if (image == NULL)
	{
		tbReportError(f, "image is NULL; pass a snapshot made by tbWorld_Snapshot");
		return NULL;
	}
	if (size < 0)
	{
		tbReportError(f, "size is %d; pass the image's size in bytes", size);
		return NULL;
	}
	tbReader r;
	if (tbOpenImage(&r, image, size) == false)
	{
		tbReportError(f, "%s; the world is unchanged", r.message);
		return NULL;
	}
	tbWorld* staged = tbDecodeWorld(&r);
	if (staged == NULL)
	{
		tbReportError(f, "%s; the world is unchanged", r.message);
	}
	return staged;
}

bool tbWorld_Restore(tbWorldId worldId, const uint8_t* image, int size)
{
	const char* f = "tbWorld_Restore";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL || tbStructureLocked(world, f, "restore snapshots"))
	{
		return false;
	}
	if (world->recording != NULL)
	{
		// A recording replays calls on the state it has seen: a jump to another state is not a call.
		tbReportError(f, "the world is recording; stop the recording (tbWorld_StopRecording) before restoring");
		return false;
	}
	tbWorld* staged = tbDecodeImage(f, image, size);
	if (staged == NULL)
	{
		return false;
	}
	tbAdoptWorld(world, staged);
	return true;
}

tbWorldId tbCreateWorldFromSnapshot(const uint8_t* image, int size, int workerCount)
{
	const char* f = "tbCreateWorldFromSnapshot";
	if (workerCount < 0 || workerCount > TB_MAX_WORKERS)
	{
		tbReportError(f, "workerCount is %d; pass 0 to %d (0 and 1: the step runs on the caller)", workerCount,
					  TB_MAX_WORKERS);
		return TB_NULL_WORLD_ID;
	}
	tbWorld* staged = tbDecodeImage(f, image, size);
	if (staged == NULL)
	{
		return TB_NULL_WORLD_ID;
	}
	tbWorldDef def = tbDefaultWorldDef();
	def.workerCount = workerCount > 0 ? workerCount : 1;
	tbWorldId id = tbCreateWorld(&def);
	tbWorld* world = tbWorld_IsValid(id) ? tbGetWorldChecked(id, f) : NULL;
	if (world == NULL)
	{
		tbFreeStagingWorld(staged);
		return TB_NULL_WORLD_ID; // tbCreateWorld reported why
	}
	tbAdoptWorld(world, staged);
	return id;
}
