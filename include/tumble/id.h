// Tumble: value handles. An id is an index plus a generation, never a pointer.
// All-zero is null. A handle to a destroyed object is detected and refused.
#pragma once

#include "base.h"

/// World handle. index1 is the world slot plus one (zero means null).
typedef struct tbWorldId
{
	uint16_t index1;
	uint16_t generation;
} tbWorldId;

/// Body handle.
typedef struct tbBodyId
{
	int32_t index1;
	uint16_t world0;
	uint16_t generation;
} tbBodyId;

/// Shape handle.
typedef struct tbShapeId
{
	int32_t index1;
	uint16_t world0;
	uint16_t generation;
} tbShapeId;

/// Joint handle.
typedef struct tbJointId
{
	int32_t index1;
	uint16_t world0;
	uint16_t generation;
} tbJointId;

/// Chain handle (tbCreateChain).
typedef struct tbChainId
{
	int32_t index1;
	uint16_t world0;
	uint16_t generation;
} tbChainId;

/// Contact handle: a contact lives while two shapes' fat boxes overlap, so it may be destroyed by
/// any step; check it with tbContact_IsValid. The generation counts every reuse of the slot.
typedef struct tbContactId
{
	int32_t index1;
	uint16_t world0;
	int16_t padding;
	uint32_t generation;
} tbContactId;

#ifdef __cplusplus
#define TB_NULL_WORLD_ID (tbWorldId{})
#define TB_NULL_BODY_ID (tbBodyId{})
#define TB_NULL_SHAPE_ID (tbShapeId{})
#define TB_NULL_JOINT_ID (tbJointId{})
#define TB_NULL_CHAIN_ID (tbChainId{})
#define TB_NULL_CONTACT_ID (tbContactId{})
#else
#define TB_NULL_WORLD_ID ((tbWorldId){0})
#define TB_NULL_BODY_ID ((tbBodyId){0})
#define TB_NULL_SHAPE_ID ((tbShapeId){0})
#define TB_NULL_JOINT_ID ((tbJointId){0})
#define TB_NULL_CHAIN_ID ((tbChainId){0})
#define TB_NULL_CONTACT_ID ((tbContactId){0})
#endif

/// Null ids as constants (Box2D v3's b2_nullBodyId and the rest).
static const tbWorldId tb_nullWorldId = TB_ZERO_INIT;
static const tbBodyId tb_nullBodyId = TB_ZERO_INIT;
static const tbShapeId tb_nullShapeId = TB_ZERO_INIT;
static const tbChainId tb_nullChainId = TB_ZERO_INIT;
static const tbJointId tb_nullJointId = TB_ZERO_INIT;
static const tbContactId tb_nullContactId = TB_ZERO_INIT;

/// True if the id is null (all zero). A non-null id may still be stale: use tbBody_IsValid etc.
#define TB_IS_NULL(id) ((id).index1 == 0)
#define TB_IS_NON_NULL(id) ((id).index1 != 0)

/// Ids as integers, for saving (Box2D v3's store/load functions; TB_STORE_ID is the same packing).
TB_INLINE uint32_t tbStoreWorldId(tbWorldId id)
{
	return ((uint32_t)id.index1 << 16) | (uint32_t)id.generation;
}

TB_INLINE tbWorldId tbLoadWorldId(uint32_t x)
{
	tbWorldId id = {(uint16_t)(x >> 16), (uint16_t)x};
	return id;
}

TB_INLINE uint64_t tbStoreBodyId(tbBodyId id)
{
	return ((uint64_t)(uint32_t)id.index1 << 32) | ((uint64_t)id.world0 << 16) | (uint64_t)id.generation;
}

TB_INLINE tbBodyId tbLoadBodyId(uint64_t x)
{
	tbBodyId id = {(int32_t)(x >> 32), (uint16_t)(x >> 16), (uint16_t)x};
	return id;
}

TB_INLINE uint64_t tbStoreShapeId(tbShapeId id)
{
	return ((uint64_t)(uint32_t)id.index1 << 32) | ((uint64_t)id.world0 << 16) | (uint64_t)id.generation;
}

TB_INLINE tbShapeId tbLoadShapeId(uint64_t x)
{
	tbShapeId id = {(int32_t)(x >> 32), (uint16_t)(x >> 16), (uint16_t)x};
	return id;
}

TB_INLINE uint64_t tbStoreJointId(tbJointId id)
{
	return ((uint64_t)(uint32_t)id.index1 << 32) | ((uint64_t)id.world0 << 16) | (uint64_t)id.generation;
}

TB_INLINE tbJointId tbLoadJointId(uint64_t x)
{
	tbJointId id = {(int32_t)(x >> 32), (uint16_t)(x >> 16), (uint16_t)x};
	return id;
}

TB_INLINE uint64_t tbStoreChainId(tbChainId id)
{
	return ((uint64_t)(uint32_t)id.index1 << 32) | ((uint64_t)id.world0 << 16) | (uint64_t)id.generation;
}

TB_INLINE tbChainId tbLoadChainId(uint64_t x)
{
	tbChainId id = {(int32_t)(x >> 32), (uint16_t)(x >> 16), (uint16_t)x};
	return id;
}

/// A contact id in three 32-bit values.
TB_INLINE void tbStoreContactId(tbContactId id, uint32_t values[3])
{
	values[0] = (uint32_t)id.index1;
	values[1] = (uint32_t)id.world0;
	values[2] = id.generation;
}

TB_INLINE tbContactId tbLoadContactId(const uint32_t values[3])
{
	tbContactId id = {(int32_t)values[0], (uint16_t)values[1], 0, values[2]};
	return id;
}

/// Compare two ids of the same kind.
#define TB_ID_EQUALS(id1, id2) ((id1).index1 == (id2).index1 && (id1).generation == (id2).generation)

/// Pack a body, shape or joint id into 64 bits (for user data, hash keys, files).
#define TB_STORE_ID(id) (((uint64_t)(uint32_t)(id).index1 << 32) | ((uint64_t)(id).world0 << 16) | (uint64_t)(id).generation)
