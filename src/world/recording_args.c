// The arguments of recorded API calls (recording.h): how each kind is written into a record and
// read back. One letter a kind, as recording_ops.h lists them:
//   W world (nothing written: replay targets its own world); b s c j a body, shape, chain or joint
//   id (its index: a replay world numbers its objects as the recorded one did, and replay.c gives
//   the index the replay world's generation); f float, i int or enum, ? bool, u and U unsigned
//   integers of 64 and 32 bits; v vector, r rotation, p world position (doubles in the double
//   precision build), x transform, X world transform; n a name (length, bytes, a terminating zero);
//   M L F mass data, motion locks and filter passed by value;
//   D H C K P G Q T E a body definition, shape definition, circle, capsule, polygon, segment, chain
//   segment, surface material and explosion passed by pointer; 0 to 8 the joint definitions
//   (distance, filter, motor, mover, pogo, prismatic, revolute, weld, wheel); Y a geometry (its
//   type, then that shape); N a chain definition (its points and materials inline).
// A pointer argument starts with a byte: 0 for NULL, 1 when the value follows. A structure is
// written field by field from the tables below, never as memory, so neither padding nor pointers
// (user data) reach the file and the bytes are the same for the same calls. Numbers are
// little-endian; floats are their bit patterns, read back exactly. A definition is read into its
// tbDefault*Def() first, which sets what is not recorded (user data, the internal cookie).
#include "recording.h"

#include "core/core.h"

#include <stddef.h>
#include <string.h>

typedef struct tbRecField
{
	uint16_t offset;
	char kind;
	uint8_t count;
} tbRecField;

static const tbRecField s_bodyDef[] = {
	{offsetof(tbBodyDef, type), 'i', 1},
	{offsetof(tbBodyDef, position), 'p', 1},
	{offsetof(tbBodyDef, rotation), 'r', 1},
	{offsetof(tbBodyDef, linearVelocity), 'v', 1},
	{offsetof(tbBodyDef, angularVelocity), 'f', 1},
	{offsetof(tbBodyDef, linearDamping), 'f', 1},
	{offsetof(tbBodyDef, angularDamping), 'f', 1},
	{offsetof(tbBodyDef, gravityScale), 'f', 1},
	{offsetof(tbBodyDef, sleepThreshold), 'f', 1},
	{offsetof(tbBodyDef, safetyFactor), 'f', 1},
	{offsetof(tbBodyDef, name), 'n', 1},
	{offsetof(tbBodyDef, enableSleep), '?', 1},
	{offsetof(tbBodyDef, isAwake), '?', 1},
	{offsetof(tbBodyDef, fixedRotation), '?', 1},
	{offsetof(tbBodyDef, motionLocks.linearX), '?', 1},
	{offsetof(tbBodyDef, motionLocks.linearY), '?', 1},
	{offsetof(tbBodyDef, motionLocks.angularZ), '?', 1},
	{offsetof(tbBodyDef, enableContactRecycling), '?', 1},
	{offsetof(tbBodyDef, isBullet), '?', 1},
	{offsetof(tbBodyDef, isEnabled), '?', 1},
	{offsetof(tbBodyDef, allowFastRotation), '?', 1},
};

static const tbRecField s_shapeDef[] = {
	{offsetof(tbShapeDef, material.friction), 'f', 1},
	{offsetof(tbShapeDef, material.restitution), 'f', 1},
	{offsetof(tbShapeDef, material.rollingResistance), 'f', 1},
	{offsetof(tbShapeDef, material.tangentSpeed), 'f', 1},
	{offsetof(tbShapeDef, material.userMaterialId), 'u', 1},
	{offsetof(tbShapeDef, material.customColor), 'U', 1},
	{offsetof(tbShapeDef, density), 'f', 1},
	{offsetof(tbShapeDef, filter.categoryBits), 'u', 1},
	{offsetof(tbShapeDef, filter.maskBits), 'u', 1},
	{offsetof(tbShapeDef, filter.groupIndex), 'i', 1},
	{offsetof(tbShapeDef, isSensor), '?', 1},
	{offsetof(tbShapeDef, enableSensorEvents), '?', 1},
	{offsetof(tbShapeDef, enableContactEvents), '?', 1},
	{offsetof(tbShapeDef, enableHitEvents), '?', 1},
	{offsetof(tbShapeDef, updateBodyMass), '?', 1},
	{offsetof(tbShapeDef, enableCustomFiltering), '?', 1},
	{offsetof(tbShapeDef, enablePreSolveEvents), '?', 1},
	{offsetof(tbShapeDef, invokeContactCreation), '?', 1},
};

static const tbRecField s_circle[] = {
	{offsetof(tbCircle, center), 'v', 1},
	{offsetof(tbCircle, radius), 'f', 1},
};

static const tbRecField s_capsule[] = {
	{offsetof(tbCapsule, center1), 'v', 1},
	{offsetof(tbCapsule, center2), 'v', 1},
	{offsetof(tbCapsule, radius), 'f', 1},
};

static const tbRecField s_polygon[] = {
	{offsetof(tbPolygon, vertices), 'v', TB_MAX_POLYGON_VERTICES},
	{offsetof(tbPolygon, normals), 'v', TB_MAX_POLYGON_VERTICES},
	{offsetof(tbPolygon, centroid), 'v', 1},
	{offsetof(tbPolygon, radius), 'f', 1},
	{offsetof(tbPolygon, count), 'i', 1},
};

static const tbRecField s_segment[] = {
	{offsetof(tbSegment, point1), 'v', 1},
	{offsetof(tbSegment, point2), 'v', 1},
};

static const tbRecField s_chainSegment[] = {
	{offsetof(tbChainSegment, ghost1), 'v', 1},
	{offsetof(tbChainSegment, segment.point1), 'v', 1},
	{offsetof(tbChainSegment, segment.point2), 'v', 1},
	{offsetof(tbChainSegment, ghost2), 'v', 1},
	{offsetof(tbChainSegment, chainId), 'i', 1},
};

static const tbRecField s_material[] = {
	{offsetof(tbSurfaceMaterial, friction), 'f', 1},
	{offsetof(tbSurfaceMaterial, restitution), 'f', 1},
	{offsetof(tbSurfaceMaterial, rollingResistance), 'f', 1},
	{offsetof(tbSurfaceMaterial, tangentSpeed), 'f', 1},
	{offsetof(tbSurfaceMaterial, userMaterialId), 'u', 1},
	{offsetof(tbSurfaceMaterial, customColor), 'U', 1},
};

static const tbRecField s_explosion[] = {
	{offsetof(tbExplosionDef, maskBits), 'u', 1},
	{offsetof(tbExplosionDef, position), 'p', 1},
	{offsetof(tbExplosionDef, radius), 'f', 1},
	{offsetof(tbExplosionDef, falloff), 'f', 1},
	{offsetof(tbExplosionDef, impulsePerLength), 'f', 1},
};

static const tbRecField s_massData[] = {
	{offsetof(tbMassData, mass), 'f', 1},
	{offsetof(tbMassData, center), 'v', 1},
	{offsetof(tbMassData, rotationalInertia), 'f', 1},
};

static const tbRecField s_locks[] = {
	{offsetof(tbMotionLocks, linearX), '?', 1},
	{offsetof(tbMotionLocks, linearY), '?', 1},
	{offsetof(tbMotionLocks, angularZ), '?', 1},
};

static const tbRecField s_filter[] = {
	{offsetof(tbFilter, categoryBits), 'u', 1},
	{offsetof(tbFilter, maskBits), 'u', 1},
	{offsetof(tbFilter, groupIndex), 'i', 1},
};

static const tbRecField s_jointBase[] = {
	{offsetof(tbJointDef, bodyIdA), 'b', 1},
	{offsetof(tbJointDef, bodyIdB), 'b', 1},
	{offsetof(tbJointDef, localFrameA), 'x', 1},
	{offsetof(tbJointDef, localFrameB), 'x', 1},
	{offsetof(tbJointDef, forceThreshold), 'f', 1},
	{offsetof(tbJointDef, torqueThreshold), 'f', 1},
	{offsetof(tbJointDef, constraintHertz), 'f', 1},
	{offsetof(tbJointDef, constraintDampingRatio), 'f', 1},
	{offsetof(tbJointDef, drawScale), 'f', 1},
	{offsetof(tbJointDef, collideConnected), '?', 1},
};

static const tbRecField s_distanceJointDef[] = {
	{offsetof(tbDistanceJointDef, length), 'f', 1},
	{offsetof(tbDistanceJointDef, enableSpring), '?', 1},
	{offsetof(tbDistanceJointDef, lowerSpringForce), 'f', 1},
	{offsetof(tbDistanceJointDef, upperSpringForce), 'f', 1},
	{offsetof(tbDistanceJointDef, hertz), 'f', 1},
	{offsetof(tbDistanceJointDef, dampingRatio), 'f', 1},
	{offsetof(tbDistanceJointDef, enableLimit), '?', 1},
	{offsetof(tbDistanceJointDef, minLength), 'f', 1},
	{offsetof(tbDistanceJointDef, maxLength), 'f', 1},
	{offsetof(tbDistanceJointDef, enableMotor), '?', 1},
	{offsetof(tbDistanceJointDef, maxMotorForce), 'f', 1},
	{offsetof(tbDistanceJointDef, motorSpeed), 'f', 1},
};

static const tbRecField s_motorJointDef[] = {
	{offsetof(tbMotorJointDef, linearVelocity), 'v', 1},
	{offsetof(tbMotorJointDef, maxVelocityForce), 'f', 1},
	{offsetof(tbMotorJointDef, angularVelocity), 'f', 1},
	{offsetof(tbMotorJointDef, maxVelocityTorque), 'f', 1},
	{offsetof(tbMotorJointDef, linearHertz), 'f', 1},
	{offsetof(tbMotorJointDef, linearDampingRatio), 'f', 1},
	{offsetof(tbMotorJointDef, maxSpringForce), 'f', 1},
	{offsetof(tbMotorJointDef, angularHertz), 'f', 1},
	{offsetof(tbMotorJointDef, angularDampingRatio), 'f', 1},
	{offsetof(tbMotorJointDef, maxSpringTorque), 'f', 1},
};

static const tbRecField s_moverJointDef[] = {
	{offsetof(tbMoverJointDef, linearVelocity), 'v', 1},
	{offsetof(tbMoverJointDef, maxVelocityForce), 'v', 1},
};

static const tbRecField s_pogoJointDef[] = {
	{offsetof(tbPogoJointDef, normal), 'v', 1},
	{offsetof(tbPogoJointDef, hertz), 'f', 1},
	{offsetof(tbPogoJointDef, dampingRatio), 'f', 1},
	{offsetof(tbPogoJointDef, restLength), 'f', 1},
	{offsetof(tbPogoJointDef, maxTensionForce), 'f', 1},
	{offsetof(tbPogoJointDef, maxCompressionForce), 'f', 1},
	{offsetof(tbPogoJointDef, impulse), 'f', 1},
	{offsetof(tbPogoJointDef, velocity), 'f', 1},
};

static const tbRecField s_prismaticJointDef[] = {
	{offsetof(tbPrismaticJointDef, enableSpring), '?', 1},
	{offsetof(tbPrismaticJointDef, hertz), 'f', 1},
	{offsetof(tbPrismaticJointDef, dampingRatio), 'f', 1},
	{offsetof(tbPrismaticJointDef, targetTranslation), 'f', 1},
	{offsetof(tbPrismaticJointDef, enableLimit), '?', 1},
	{offsetof(tbPrismaticJointDef, lowerTranslation), 'f', 1},
	{offsetof(tbPrismaticJointDef, upperTranslation), 'f', 1},
	{offsetof(tbPrismaticJointDef, enableMotor), '?', 1},
	{offsetof(tbPrismaticJointDef, maxMotorForce), 'f', 1},
	{offsetof(tbPrismaticJointDef, motorSpeed), 'f', 1},
};

static const tbRecField s_revoluteJointDef[] = {
	{offsetof(tbRevoluteJointDef, targetAngle), 'f', 1},
	{offsetof(tbRevoluteJointDef, enableSpring), '?', 1},
	{offsetof(tbRevoluteJointDef, hertz), 'f', 1},
	{offsetof(tbRevoluteJointDef, dampingRatio), 'f', 1},
	{offsetof(tbRevoluteJointDef, enableLimit), '?', 1},
	{offsetof(tbRevoluteJointDef, lowerAngle), 'f', 1},
	{offsetof(tbRevoluteJointDef, upperAngle), 'f', 1},
	{offsetof(tbRevoluteJointDef, enableMotor), '?', 1},
	{offsetof(tbRevoluteJointDef, maxMotorTorque), 'f', 1},
	{offsetof(tbRevoluteJointDef, motorSpeed), 'f', 1},
};

static const tbRecField s_weldJointDef[] = {
	{offsetof(tbWeldJointDef, linearHertz), 'f', 1},
	{offsetof(tbWeldJointDef, angularHertz), 'f', 1},
	{offsetof(tbWeldJointDef, linearDampingRatio), 'f', 1},
	{offsetof(tbWeldJointDef, angularDampingRatio), 'f', 1},
};

static const tbRecField s_wheelJointDef[] = {
	{offsetof(tbWheelJointDef, enableSpring), '?', 1},
	{offsetof(tbWheelJointDef, hertz), 'f', 1},
	{offsetof(tbWheelJointDef, dampingRatio), 'f', 1},
	{offsetof(tbWheelJointDef, enableLimit), '?', 1},
	{offsetof(tbWheelJointDef, lowerTranslation), 'f', 1},
	{offsetof(tbWheelJointDef, upperTranslation), 'f', 1},
	{offsetof(tbWheelJointDef, enableMotor), '?', 1},
	{offsetof(tbWheelJointDef, maxMotorTorque), 'f', 1},
	{offsetof(tbWheelJointDef, motorSpeed), 'f', 1},
};

#define TB_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/// A structure kind: its field table, size, whether it comes by pointer, whether a joint's common
/// part precedes its own fields, and the default a decoded value starts from.
typedef struct tbRecStruct
{
	char kind;
	const tbRecField* fields;
	int count;
	int size;
	bool pointer;
	bool joint;
	void (*defaults)(void* out);
} tbRecStruct;

static void tbZero(void* out)
{
	(void)out; // the decoder zeroes every value before its defaults
}

#define TB_DEFAULTS(T, fn)                                                                                            \
	static void tbDefault##T(void* out)                                                                               \
	{                                                                                                                 \
		*(T*)out = fn();                                                                                              \
	}
TB_DEFAULTS(tbBodyDef, tbDefaultBodyDef)
TB_DEFAULTS(tbShapeDef, tbDefaultShapeDef)
TB_DEFAULTS(tbSurfaceMaterial, tbDefaultSurfaceMaterial)
TB_DEFAULTS(tbExplosionDef, tbDefaultExplosionDef)
TB_DEFAULTS(tbFilter, tbDefaultFilter)
TB_DEFAULTS(tbDistanceJointDef, tbDefaultDistanceJointDef)
TB_DEFAULTS(tbFilterJointDef, tbDefaultFilterJointDef)
TB_DEFAULTS(tbMotorJointDef, tbDefaultMotorJointDef)
TB_DEFAULTS(tbMoverJointDef, tbDefaultMoverJointDef)
TB_DEFAULTS(tbPogoJointDef, tbDefaultPogoJointDef)
TB_DEFAULTS(tbPrismaticJointDef, tbDefaultPrismaticJointDef)
TB_DEFAULTS(tbRevoluteJointDef, tbDefaultRevoluteJointDef)
TB_DEFAULTS(tbWeldJointDef, tbDefaultWeldJointDef)
TB_DEFAULTS(tbWheelJointDef, tbDefaultWheelJointDef)
#undef TB_DEFAULTS

// A joint definition's common part is its first member, so the common table's offsets hold in every kind.
_Static_assert(offsetof(tbDistanceJointDef, base) == 0 && offsetof(tbWheelJointDef, base) == 0 &&
				   offsetof(tbFilterJointDef, base) == 0 && offsetof(tbMotorJointDef, base) == 0 &&
				   offsetof(tbMoverJointDef, base) == 0 && offsetof(tbPogoJointDef, base) == 0 &&
				   offsetof(tbPrismaticJointDef, base) == 0 && offsetof(tbRevoluteJointDef, base) == 0 &&
				   offsetof(tbWeldJointDef, base) == 0,
			   "joint definitions start with their common part");

#define TB_STRUCT(k, table, T, byPointer, isJoint, def)                                                               \
	{k, table, TB_COUNT(table), (int)sizeof(T), byPointer, isJoint, def}
#define TB_JOINT(k, table, T) TB_STRUCT(k, table, T, true, true, tbDefault##T)
static const tbRecStruct s_structs[] = {
	TB_STRUCT('M', s_massData, tbMassData, false, false, tbZero),
	TB_STRUCT('L', s_locks, tbMotionLocks, false, false, tbZero),
	TB_STRUCT('F', s_filter, tbFilter, false, false, tbDefaulttbFilter),
	TB_STRUCT('D', s_bodyDef, tbBodyDef, true, false, tbDefaulttbBodyDef),
	TB_STRUCT('H', s_shapeDef, tbShapeDef, true, false, tbDefaulttbShapeDef),
	TB_STRUCT('C', s_circle, tbCircle, true, false, tbZero),
	TB_STRUCT('K', s_capsule, tbCapsule, true, false, tbZero),
	TB_STRUCT('P', s_polygon, tbPolygon, true, false, tbZero),
	TB_STRUCT('G', s_segment, tbSegment, true, false, tbZero),
	TB_STRUCT('Q', s_chainSegment, tbChainSegment, true, false, tbZero),
	TB_STRUCT('T', s_material, tbSurfaceMaterial, true, false, tbDefaulttbSurfaceMaterial),
	TB_STRUCT('E', s_explosion, tbExplosionDef, true, false, tbDefaulttbExplosionDef),
	TB_JOINT('0', s_distanceJointDef, tbDistanceJointDef),
	TB_STRUCT('1', s_jointBase, tbFilterJointDef, true, false, tbDefaulttbFilterJointDef),
	TB_JOINT('2', s_motorJointDef, tbMotorJointDef),
	TB_JOINT('3', s_moverJointDef, tbMoverJointDef),
	TB_JOINT('4', s_pogoJointDef, tbPogoJointDef),
	TB_JOINT('5', s_prismaticJointDef, tbPrismaticJointDef),
	TB_JOINT('6', s_revoluteJointDef, tbRevoluteJointDef),
	TB_JOINT('7', s_weldJointDef, tbWeldJointDef),
	TB_JOINT('8', s_wheelJointDef, tbWheelJointDef),
};
#undef TB_JOINT
#undef TB_STRUCT

static const tbRecStruct* tbFindStruct(char kind)
{
	for (int i = 0; i < TB_COUNT(s_structs); ++i)
	{
		if (s_structs[i].kind == kind)
		{
			return s_structs + i;
		}
	}
	return NULL;
}

// --------------------------------------------------------------------------------------------
// Writing

void tbRecPutBytes(tbRecBytes* out, const void* bytes, int count)
{
	if (out->size + count > out->capacity)
	{
		int capacity = out->capacity > 0 ? out->capacity : 256;
		while (capacity < out->size + count)
		{
			capacity *= 2;
		}
		out->data = tbGrowAlloc(out->data, out->capacity, capacity);
		out->capacity = capacity;
	}
	memcpy(out->data + out->size, bytes, (size_t)count);
	out->size += count;
}

void tbRecPutU32(tbRecBytes* out, uint32_t value)
{
	uint8_t bytes[4];
	for (int k = 0; k < 4; ++k)
	{
		bytes[k] = (uint8_t)(value >> (8 * k));
	}
	tbRecPutBytes(out, bytes, 4);
}

void tbRecPutU64(tbRecBytes* out, uint64_t value)
{
	tbRecPutU32(out, (uint32_t)value);
	tbRecPutU32(out, (uint32_t)(value >> 32));
}

void tbRecPutFloat(tbRecBytes* out, float value)
{
	uint32_t bits;
	memcpy(&bits, &value, sizeof(bits));
	tbRecPutU32(out, bits);
}

static void tbPutFloats(tbRecBytes* out, const float* values, int count)
{
	for (int i = 0; i < count; ++i)
	{
		tbRecPutFloat(out, values[i]);
	}
}

/// A world position: its coordinates as the build holds them (the header names the precision).
static void tbPutPos(tbRecBytes* out, const tbPos* p)
{
#if defined(TUMBLE_DOUBLE_PRECISION)
	uint64_t bits[2];
	memcpy(bits, p, sizeof(bits));
	tbRecPutU64(out, bits[0]);
	tbRecPutU64(out, bits[1]);
#else
	tbPutFloats(out, &p->x, 1);
	tbPutFloats(out, &p->y, 1);
#endif
}

static void tbPutName(tbRecBytes* out, const char* name)
{
	if (name == NULL)
	{
		tbRecPutU32(out, UINT32_MAX);
		return;
	}
	size_t length = strlen(name);
	length = length < 4096 ? length : 4096; // a name is for tools: a longer one is cut
	tbRecPutU32(out, (uint32_t)length);
	tbRecPutBytes(out, name, (int)length);
	uint8_t zero = 0;
	tbRecPutBytes(out, &zero, 1);
}

static void tbPutStruct(tbRecBytes* out, const tbRecStruct* s, const void* value);

static void tbPutScalar(tbRecBytes* out, char kind, const void* value)
{
	switch (kind)
	{
		case 'b':
		case 's':
		case 'c':
		case 'j':
			tbRecPutU32(out, (uint32_t)((const tbBodyId*)value)->index1); // every id starts with index1
			break;
		case 'f':
			tbPutFloats(out, value, 1);
			break;
		case 'i':
		case 'U':
			tbRecPutU32(out, *(const uint32_t*)value);
			break;
		case '?':
			tbRecPutBytes(out, &(uint8_t){*(const bool*)value ? 1u : 0u}, 1);
			break;
		case 'u':
			tbRecPutU64(out, *(const uint64_t*)value);
			break;
		case 'v':
		case 'r':
			tbPutFloats(out, value, 2);
			break;
		case 'x':
			tbPutFloats(out, value, 4);
			break;
		case 'p':
			tbPutPos(out, value);
			break;
		case 'X':
		{
			const tbWorldTransform* xf = value;
			tbPutPos(out, &xf->p);
			float cs[2] = {xf->q.c, xf->q.s}; // an array: not a pointer past the member c
			tbPutFloats(out, cs, 2);
			break;
		}
		case 'n':
			tbPutName(out, *(const char* const*)value);
			break;
		default:
			TB_ASSERT(false);
	}
}

static void tbPutFields(tbRecBytes* out, const tbRecField* fields, int count, const void* value)
{
	for (int i = 0; i < count; ++i)
	{
		const uint8_t* field = (const uint8_t*)value + fields[i].offset;
		int stride = fields[i].kind == 'v' ? (int)sizeof(tbVec2) : 0;
		for (int k = 0; k < fields[i].count; ++k)
		{
			tbPutScalar(out, fields[i].kind, field + k * stride);
		}
	}
}

static void tbPutStruct(tbRecBytes* out, const tbRecStruct* s, const void* value)
{
	if (s->joint)
	{
		tbPutFields(out, s_jointBase, TB_COUNT(s_jointBase), value);
	}
	tbPutFields(out, s->fields, s->count, value);
}

static void tbPutGeometry(tbRecBytes* out, const tbGeometry* g)
{
	tbRecPutU32(out, (uint32_t)g->type);
	static const char kinds[tb_shapeTypeCount] = {'C', 'K', 'G', 'P', 'Q'};
	if ((unsigned)g->type < (unsigned)tb_shapeTypeCount)
	{
		tbPutStruct(out, tbFindStruct(kinds[g->type]), &g->circle);
	}
}

/// A chain definition: its filter and flags, then its points and materials (the counts clamped to
/// what the pointers can hold: a NULL array is written empty, and tbCreateChain refuses it again).
static void tbPutChainDef(tbRecBytes* out, const tbChainDef* def)
{
	tbPutStruct(out, tbFindStruct('F'), &def->filter);
	tbPutScalar(out, '?', &def->isLoop);
	tbPutScalar(out, '?', &def->enableSensorEvents);
	int count = def->points != NULL && def->count > 0 ? def->count : 0;
	tbRecPutU32(out, (uint32_t)count);
	tbPutFloats(out, (const float*)def->points, 2 * count);
	int materialCount = def->materials != NULL && def->materialCount > 0 ? def->materialCount : 0;
	tbRecPutU32(out, (uint32_t)materialCount);
	for (int i = 0; i < materialCount; ++i)
	{
		tbPutStruct(out, tbFindStruct('T'), def->materials + i);
	}
}

void tbRecPutArg(tbRecBytes* out, char kind, const void* value)
{
	if (kind == 'W')
	{
		return;
	}
	const tbRecStruct* s = tbFindStruct(kind);
	bool pointer = (s != NULL && s->pointer) || kind == 'Y' || kind == 'N';
	if (pointer)
	{
		tbRecPutBytes(out, &(uint8_t){value != NULL ? 1u : 0u}, 1);
		if (value == NULL)
		{
			return;
		}
	}
	if (kind == 'Y')
	{
		tbPutGeometry(out, value);
	}
	else if (kind == 'N')
	{
		tbPutChainDef(out, value);
	}
	else if (s != NULL)
	{
		tbPutStruct(out, s, value);
	}
	else
	{
		tbPutScalar(out, kind, value);
	}
}

// --------------------------------------------------------------------------------------------
// Reading

static const uint8_t* tbTake(tbRecArgReader* r, int count)
{
	if (r->failed || count < 0 || r->size - r->offset < count)
	{
		r->failed = true;
		return NULL;
	}
	const uint8_t* p = r->data + r->offset;
	r->offset += count;
	return p;
}

bool tbRecGetU32(tbRecArgReader* r, uint32_t* value)
{
	const uint8_t* p = tbTake(r, 4);
	*value = 0;
	for (int k = 0; p != NULL && k < 4; ++k)
	{
		*value |= (uint32_t)p[k] << (8 * k);
	}
	return p != NULL;
}

bool tbRecGetU64(tbRecArgReader* r, uint64_t* value)
{
	uint32_t low = 0, high = 0;
	bool ok = tbRecGetU32(r, &low) && tbRecGetU32(r, &high);
	*value = ((uint64_t)high << 32) | low;
	return ok;
}

bool tbRecGetFloat(tbRecArgReader* r, float* value)
{
	uint32_t bits = 0;
	bool ok = tbRecGetU32(r, &bits);
	memcpy(value, &bits, sizeof(bits));
	return ok;
}

static bool tbGetFloats(tbRecArgReader* r, float* values, int count)
{
	for (int i = 0; i < count; ++i)
	{
		tbRecGetFloat(r, values + i);
	}
	return r->failed == false;
}

static void tbGetPos(tbRecArgReader* r, tbPos* p)
{
#if defined(TUMBLE_DOUBLE_PRECISION)
	uint64_t bits[2] = {0, 0};
	tbRecGetU64(r, bits);
	tbRecGetU64(r, bits + 1);
	memcpy(p, bits, sizeof(bits));
#else
	// Through an array: a pointer to x stepping on to y is, to the compiler, past the end of x.
	float xy[2] = {0.0f, 0.0f};
	tbGetFloats(r, xy, 2);
	p->x = xy[0];
	p->y = xy[1];
#endif
}

static bool tbGetName(tbRecArgReader* r, const char** name)
{
	uint32_t length = 0;
	*name = NULL;
	if (tbRecGetU32(r, &length) == false || length == UINT32_MAX)
	{
		return r->failed == false;
	}
	const uint8_t* bytes = tbTake(r, length > 4096 ? -1 : (int)length + 1);
	if (bytes == NULL || bytes[length] != 0)
	{
		r->failed = true;
		return false;
	}
	*name = (const char*)bytes;
	return true;
}

static bool tbGetScalar(tbRecArgReader* r, char kind, void* value)
{
	switch (kind)
	{
		case 'b':
		case 's':
		case 'c':
		case 'j':
		{
			uint32_t index1 = 0;
			tbRecGetU32(r, &index1);
			((tbBodyId*)value)->index1 = (int32_t)index1; // every id starts with index1
			return r->failed == false;
		}
		case 'f':
			return tbGetFloats(r, value, 1);
		case 'i':
		case 'U':
			return tbRecGetU32(r, value);
		case '?':
		{
			const uint8_t* p = tbTake(r, 1);
			r->failed = r->failed || (p != NULL && *p > 1u);
			*(bool*)value = p != NULL && *p == 1u;
			return r->failed == false;
		}
		case 'u':
			return tbRecGetU64(r, value);
		case 'v':
		case 'r':
			return tbGetFloats(r, value, 2);
		case 'x':
			return tbGetFloats(r, value, 4);
		case 'p':
			tbGetPos(r, value);
			return r->failed == false;
		case 'X':
		{
			tbWorldTransform* xf = value;
			tbGetPos(r, &xf->p);
			float cs[2] = {0.0f, 0.0f};
			bool ok = tbGetFloats(r, cs, 2);
			xf->q.c = cs[0];
			xf->q.s = cs[1];
			return ok;
		}
		case 'n':
			return tbGetName(r, value);
		default:
			r->failed = true;
			return false;
	}
}

static bool tbGetFields(tbRecArgReader* r, const tbRecField* fields, int count, void* value)
{
	for (int i = 0; i < count && r->failed == false; ++i)
	{
		uint8_t* field = (uint8_t*)value + fields[i].offset;
		int stride = fields[i].kind == 'v' ? (int)sizeof(tbVec2) : 0;
		for (int k = 0; k < fields[i].count; ++k)
		{
			tbGetScalar(r, fields[i].kind, field + k * stride);
		}
	}
	return r->failed == false;
}

static bool tbGetStruct(tbRecArgReader* r, const tbRecStruct* s, void* value)
{
	s->defaults(value);
	if (s->joint && tbGetFields(r, s_jointBase, TB_COUNT(s_jointBase), value) == false)
	{
		return false;
	}
	return tbGetFields(r, s->fields, s->count, value);
}

static bool tbGetGeometry(tbRecArgReader* r, tbGeometry* g)
{
	uint32_t type = 0;
	static const char kinds[tb_shapeTypeCount] = {'C', 'K', 'G', 'P', 'Q'};
	if (tbRecGetU32(r, &type) == false)
	{
		return false;
	}
	g->type = (tbShapeType)type;
	if (type >= (uint32_t)tb_shapeTypeCount)
	{
		return true; // tbCreateShape refuses the type, as it did when recorded
	}
	return tbGetStruct(r, tbFindStruct(kinds[type]), &g->circle);
}

/// An array of count items of itemSize bytes into scratch slot `slot`, or NULL after failing the
/// reader when the payload cannot hold that many (a count read from the bytes is not trusted).
static void* tbScratch(tbRecArgReader* r, int slot, uint32_t count, int itemSize, int minimumWireSize)
{
	if (count == 0 || r->failed || count > (uint32_t)((r->size - r->offset) / minimumWireSize))
	{
		r->failed = r->failed || count != 0;
		return NULL;
	}
	int bytes = (int)count * itemSize;
	r->scratch[slot] = tbAlloc(bytes);
	r->scratchBytes[slot] = bytes;
	return r->scratch[slot];
}

static bool tbGetChainDef(tbRecArgReader* r, tbChainDef* def)
{
	*def = tbDefaultChainDef();
	tbGetStruct(r, tbFindStruct('F'), &def->filter);
	tbGetScalar(r, '?', &def->isLoop);
	tbGetScalar(r, '?', &def->enableSensorEvents);
	uint32_t count = 0;
	tbRecGetU32(r, &count);
	tbVec2* points = tbScratch(r, 0, count, (int)sizeof(tbVec2), 8);
	tbGetFloats(r, (float*)points, points != NULL ? 2 * (int)count : 0);
	def->points = points;
	def->count = (int)count;
	uint32_t materialCount = 0;
	tbRecGetU32(r, &materialCount);
	tbSurfaceMaterial* materials = tbScratch(r, 1, materialCount, (int)sizeof(tbSurfaceMaterial), 28);
	for (uint32_t i = 0; materials != NULL && i < materialCount; ++i)
	{
		tbGetStruct(r, tbFindStruct('T'), materials + i);
	}
	def->materials = materials;
	def->materialCount = (int)materialCount;
	return r->failed == false;
}

bool tbRecGetArg(tbRecArgReader* r, char kind, tbRecArg* out)
{
	memset(out, 0, sizeof(*out));
	out->present = true;
	if (kind == 'W')
	{
		return r->failed == false;
	}
	const tbRecStruct* s = tbFindStruct(kind);
	if ((s != NULL && s->pointer) || kind == 'Y' || kind == 'N')
	{
		const uint8_t* flag = tbTake(r, 1);
		r->failed = r->failed || (flag != NULL && *flag > 1u);
		out->present = flag != NULL && *flag == 1u;
		if (out->present == false)
		{
			return r->failed == false;
		}
	}
	if (kind == 'Y')
	{
		return tbGetGeometry(r, &out->geometry);
	}
	if (kind == 'N')
	{
		return tbGetChainDef(r, &out->chainDef);
	}
	return s != NULL ? tbGetStruct(r, s, &out->bodyDef) : tbGetScalar(r, kind, &out->body);
}

void tbRecArgsFree(tbRecArgReader* r)
{
	for (int slot = 0; slot < 2; ++slot)
	{
		tbFree(r->scratch[slot], r->scratchBytes[slot]);
		r->scratch[slot] = NULL;
		r->scratchBytes[slot] = 0;
	}
}

int tbRecArgBodyIds(char kind, tbRecArg* arg, tbBodyId* ids[2])
{
	const tbRecStruct* s = tbFindStruct(kind);
	if (s == NULL || (s->joint == false && kind != '1') || arg->present == false)
	{
		return 0;
	}
	tbJointDef* base = &arg->distance.base; // every joint definition starts with it
	ids[0] = &base->bodyIdA;
	ids[1] = &base->bodyIdB;
	return 2;
}
