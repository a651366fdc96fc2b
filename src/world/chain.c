// Chains: runs of one-sided segments on one body (Box2D v3.2's chain grammar). A chain owns the
// ids of its segment shapes and its surface materials; the segments are ordinary shapes of kind
// tb_chainSegmentShape whose ghost points are the chain's neighbouring points, which is what lets
// the narrow phase (manifold.c, "Chain segments") slide shapes across the joints without bumps.
#include "chain.h"

#include "core/array.h"
#include "world.h"

#include "tumble/tumble.h"
#include "recording.h"

#include <stdio.h>
#include <string.h>

#define TB_CHAIN_DEF_MAGIC 0x6C3E91A5

tbChainDef tbDefaultChainDef(void)
{
	tbChainDef def;
	memset(&def, 0, sizeof(def));
	static const tbSurfaceMaterial defaultMaterial = {0.6f, 0.0f, 0.0f, 0.0f, 0u, 0u}; // tbDefaultSurfaceMaterial
	def.materials = &defaultMaterial;
	def.materialCount = 1;
	def.filter = tbDefaultFilter();
	def.internalValue = TB_CHAIN_DEF_MAGIC;
	return def;
}

static tbChainId tbMakeChainId(const tbWorld* world, int index)
{
	tbChainId id = {index + 1, world->worldId, world->chains[index].generation};
	return id;
}

static tbChain* tbLookUpChain(tbChainId id, tbWorld** worldOut)
{
	if (id.index1 <= 0 || id.world0 >= TB_MAX_WORLDS)
	{
		return NULL;
	}
	tbWorld* world = tbGetWorldFromIndex(id.world0);
	int index = id.index1 - 1;
	if (world == NULL || index >= world->chainPool.highWater || world->chains[index].inUse == false ||
		world->chains[index].generation != id.generation)
	{
		return NULL;
	}
	*worldOut = world;
	return world->chains + index;
}

static tbChain* tbGetChainChecked(tbChainId id, const char* f, tbWorld** worldOut, bool mutating)
{
	tbWorld* world = NULL;
	tbChain* chain = tbLookUpChain(id, &world);
	if (chain == NULL)
	{
		tbReportError(f, "chainId is null or refers to a destroyed chain, body or world; do not use a chain id after "
						 "tbDestroyChain or destroying its body or world (check with tbChain_IsValid)");
		return NULL;
	}
	if (mutating && tbStructureLocked(world, f, "change chains"))
	{
		return NULL;
	}
	if (worldOut != NULL)
	{
		*worldOut = world;
	}
	return chain;
}

bool tbChain_IsValid(tbChainId chainId)
{
	tbWorld* world;
	return tbLookUpChain(chainId, &world) != NULL;
}

static bool tbCheckMaterial(const char* f, const tbSurfaceMaterial* material, int index)
{
	char name[32];
	snprintf(name, sizeof(name), "materials[%d]", index);
	return tbCheckSurfaceMaterial(f, name, material);
}

/// Everything about a chain definition that can be wrong, before anything is created.
static bool tbCheckChainDef(const char* f, const tbChainDef* def)
{
	if (def == NULL || def->internalValue != TB_CHAIN_DEF_MAGIC)
	{
		tbReportError(f, "def is %s; start it from tbDefaultChainDef()", def == NULL ? "NULL" : "not initialised");
		return false;
	}
	if (def->points == NULL || def->count < 4)
	{
		tbReportError(f, "def->points is %s with count %d; a chain needs at least 4 points",
					  def->points == NULL ? "NULL" : "given", def->count);
		return false;
	}
	int segments = def->isLoop ? def->count : def->count - 3;
	if (def->materials == NULL || (def->materialCount != 1 && def->materialCount != segments))
	{
		tbReportError(f, "def->materialCount is %d; pass 1 material or one per segment (%d)", def->materialCount,
					  segments);
		return false;
	}
	for (int i = 0; i < def->materialCount; ++i)
	{
		if (tbCheckMaterial(f, def->materials + i, i) == false)
		{
			return false;
		}
	}
	int n = def->count;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 p = def->points[i];
		if (tbIsValidVec2(p) == false || tbAbsFloat(p.x) > TB_MAX_COORDINATE || tbAbsFloat(p.y) > TB_MAX_COORDINATE)
		{
			tbReportError(f, "def->points[%d] is (%g, %g): not finite or beyond %g m", i, (double)p.x, (double)p.y,
						  (double)TB_MAX_COORDINATE);
			return false;
		}
		bool last = i == n - 1;
		if ((last == false || def->isLoop) && tbDistance(p, def->points[(i + 1) % n]) < TB_LINEAR_SLOP)
		{
			tbReportError(f, "def->points[%d] and [%d] are closer than %g m (duplicate points); remove one", i,
						  (i + 1) % n, (double)TB_LINEAR_SLOP);
			return false;
		}
	}
	return true;
}

static int tbAllocChainSlot(tbWorld* world)
{
	bool isNew;
	int index = tbIdPool_Alloc(&world->chainPool, &isNew);
	if (isNew)
	{
		TB_ARRAY_RESERVE(world->chains, world->chainCapacity, index + 1);
		memset(world->chains + index, 0, sizeof(tbChain));
		world->chains[index].generation = world->chainGenerationBase;
	}
	return index;
}

/// Segment i of the chain with its ghosts: open chains run over points 1..n−2 (points 0 and n−1
/// are ghosts only), loops over every point.
static tbChainSegment tbMakeChainSegment(const tbChainDef* def, int i, int chainIndex)
{
	int n = def->count;
	int first = def->isLoop ? i : i + 1;
	tbChainSegment segment;
	segment.ghost1 = def->points[(first + n - 1) % n];
	segment.segment.point1 = def->points[first % n];
	segment.segment.point2 = def->points[(first + 1) % n];
	segment.ghost2 = def->points[(first + 2) % n];
	segment.chainId = chainIndex;
	return segment;
}

tbChainId tbCreateChain(tbBodyId bodyId, const tbChainDef* def)
{
	TB_RECORD(CreateChain, &bodyId, def);
	const char* f = "tbCreateChain";
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, true);
	if (body == NULL || tbCheckChainDef(f, def) == false || tbStructureLocked(world, f, "create chains"))
	{
		return TB_NULL_CHAIN_ID;
	}
	int index = tbAllocChainSlot(world);
	tbChain* chain = world->chains + index;
	chain->inUse = true; // generation: advanced when the last chain here was destroyed
	chain->bodyId = bodyId.index1 - 1;
	chain->segmentCount = def->isLoop ? def->count : def->count - 3;
	chain->materialCount = def->materialCount;
	chain->shapeIds = tbAlloc(chain->segmentCount * (int)sizeof(int));
	chain->materials = tbAlloc(chain->materialCount * (int)sizeof(tbSurfaceMaterial));
	memcpy(chain->materials, def->materials, (size_t)chain->materialCount * sizeof(tbSurfaceMaterial));

	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.userData = def->userData;
	shapeDef.filter = def->filter;
	shapeDef.enableSensorEvents = def->enableSensorEvents;
	shapeDef.density = 0.0f;
	shapeDef.updateBodyMass = false;
	tbGeometry geometry;
	memset(&geometry, 0, sizeof(geometry));
	geometry.type = tb_chainSegmentShape;
	for (int i = 0; i < chain->segmentCount; ++i)
	{
		const tbSurfaceMaterial* material = chain->materials + (chain->materialCount == 1 ? 0 : i);
		shapeDef.material = *material;
		geometry.chainSegment = tbMakeChainSegment(def, i, index);
		chain = world->chains + index; // tbAddShape does not move chains, but stay explicit
		chain->shapeIds[i] = tbAddShape(world, bodyId.index1 - 1, &shapeDef, &geometry);
	}
	return tbMakeChainId(world, index);
}

static void tbRemoveChain(tbWorld* world, int index, bool removeShapes)
{
	tbChain* chain = world->chains + index;
	if (removeShapes)
	{
		for (int i = 0; i < chain->segmentCount; ++i)
		{
			tbRemoveShape(world, chain->shapeIds[i], false);
		}
	}
	tbFree(chain->shapeIds, chain->segmentCount * (int)sizeof(int));
	tbFree(chain->materials, chain->materialCount * (int)sizeof(tbSurfaceMaterial));
	chain->shapeIds = NULL;
	chain->materials = NULL;
	chain->inUse = false;
	tbIdPool_Release(&world->chainPool, index, &chain->generation, world->chainGenerationBase);
}

void tbDestroyChain(tbChainId chainId)
{
	TB_RECORD(DestroyChain, &chainId);
	tbWorld* world;
	tbChain* chain = tbGetChainChecked(chainId, "tbDestroyChain", &world, true);
	if (chain != NULL)
	{
		tbWakeBody(world, world->bodies + chain->bodyId);
		tbRemoveChain(world, chainId.index1 - 1, true);
	}
}

void tbDestroyBodyChains(tbWorld* world, int bodyIndex)
{
	for (int i = 0; i < world->chainPool.highWater; ++i)
	{
		if (world->chains[i].inUse && world->chains[i].bodyId == bodyIndex)
		{
			tbRemoveChain(world, i, false); // the body frees the shapes with its own
		}
	}
}

void tbFreeChains(tbWorld* world)
{
	for (int i = 0; i < world->chainPool.highWater; ++i)
	{
		if (world->chains[i].inUse)
		{
			tbRemoveChain(world, i, false);
		}
	}
	TB_ARRAY_FREE(world->chains, world->chainCapacity);
	tbIdPool_Destroy(&world->chainPool);
}

tbWorldId tbChain_GetWorld(tbChainId chainId)
{
	tbWorld* world;
	tbChain* chain = tbGetChainChecked(chainId, "tbChain_GetWorld", &world, false);
	if (chain == NULL)
	{
		return TB_NULL_WORLD_ID;
	}
	tbWorldId id = {(uint16_t)(world->worldId + 1), world->generation};
	return id;
}

tbBodyId tbChain_GetBody(tbChainId chainId)
{
	tbWorld* world;
	tbChain* chain = tbGetChainChecked(chainId, "tbChain_GetBody", &world, false);
	return chain != NULL ? tbMakeBodyId(world, chain->bodyId) : TB_NULL_BODY_ID;
}

int tbChain_GetSegmentCount(tbChainId chainId)
{
	tbChain* chain = tbGetChainChecked(chainId, "tbChain_GetSegmentCount", NULL, false);
	return chain != NULL ? chain->segmentCount : 0;
}

int tbChain_GetSegments(tbChainId chainId, tbShapeId* segmentArray, int capacity)
{
	const char* f = "tbChain_GetSegments";
	tbWorld* world;
	tbChain* chain = tbGetChainChecked(chainId, f, &world, false);
	if (chain == NULL || (segmentArray == NULL && capacity > 0))
	{
		if (chain != NULL)
		{
			tbReportError(f, "segmentArray is NULL with capacity %d", capacity);
		}
		return 0;
	}
	int count = tbMinInt(capacity, chain->segmentCount);
	for (int i = 0; i < count; ++i)
	{
		segmentArray[i] = tbMakeShapeId(world, chain->shapeIds[i]);
	}
	return count;
}

int tbChain_GetSurfaceMaterialCount(tbChainId chainId)
{
	tbChain* chain = tbGetChainChecked(chainId, "tbChain_GetSurfaceMaterialCount", NULL, false);
	return chain != NULL ? chain->materialCount : 0;
}

static bool tbCheckMaterialIndex(const char* f, const tbChain* chain, int materialIndex)
{
	if (materialIndex < 0 || materialIndex >= chain->materialCount)
	{
		tbReportError(f, "materialIndex %d is outside 0..%d", materialIndex, chain->materialCount - 1);
		return false;
	}
	return true;
}

bool tbChain_SetSurfaceMaterial(tbChainId chainId, const tbSurfaceMaterial* material, int materialIndex)
{
	TB_RECORD(ChainSetSurfaceMaterial, &chainId, material, &materialIndex);
	const char* f = "tbChain_SetSurfaceMaterial";
	tbWorld* world;
	tbChain* chain = tbGetChainChecked(chainId, f, &world, false);
	if (chain == NULL || tbCheckPointer(f, "material", material) == false ||
		tbCheckMaterialIndex(f, chain, materialIndex) == false || tbCheckMaterial(f, material, 0) == false)
	{
		return false;
	}
	chain->materials[materialIndex] = *material;
	for (int i = 0; i < chain->segmentCount; ++i)
	{
		if (chain->materialCount == 1 || i == materialIndex)
		{
			tbShape* shape = world->shapes + chain->shapeIds[i];
			shape->material = *material;
			tbRemixShapeContacts(world, shape);
		}
	}
	return true;
}

tbSurfaceMaterial tbChain_GetSurfaceMaterial(tbChainId chainId, int materialIndex)
{
	const char* f = "tbChain_GetSurfaceMaterial";
	tbChain* chain = tbGetChainChecked(chainId, f, NULL, false);
	if (chain == NULL || tbCheckMaterialIndex(f, chain, materialIndex) == false)
	{
		tbSurfaceMaterial none = {0.0f, 0.0f, 0.0f, 0.0f, 0u, 0u};
		return none;
	}
	return chain->materials[materialIndex];
}

tbChainId tbShape_GetParentChain(tbShapeId shapeId)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetParentChain", &world, false);
	if (shape == NULL || shape->geometry.type != tb_chainSegmentShape || shape->geometry.chainSegment.chainId < 0)
	{
		return TB_NULL_CHAIN_ID;
	}
	return tbMakeChainId(world, shape->geometry.chainSegment.chainId);
}
