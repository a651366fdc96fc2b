// Scene files: a validating JSON reader (cJSON does the syntax, this file the meaning) and a
// writer. Each reader function takes the field path of the value it reads so that every error
// names the exact field; the first error stops the parse.
#include "scene_file.h"

#include <cJSON.h>

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PATH_SIZE 256

typedef struct Parser
{
	char* error;
	int errorSize;
	// Shapes of `countedScene` so far: counting them afresh for every body made reading a scene of
	// n bodies O(n²) (many_pyramids' 22,000 bodies: most of a minute).
	const Scene* countedScene;
	int countedShapes;
} Parser;

// Report "path: message" (or just the message at the root). Always returns false.
static bool Fail(Parser* parser, const char* path, const char* format, ...)
{
	char message[256];
	va_list args;
	va_start(args, format);
	vsnprintf(message, sizeof(message), format, args);
	va_end(args);
	if (parser->error != NULL && parser->errorSize > 0)
	{
		if (path[0] != '\0')
		{
			snprintf(parser->error, (size_t)parser->errorSize, "%s: %s", path, message);
		}
		else
		{
			snprintf(parser->error, (size_t)parser->errorSize, "%s", message);
		}
	}
	return false;
}

// Paths longer than PATH_SIZE are cut short (still a useful message).
static void KeyPath(char* out, const char* path, const char* key)
{
	int length = path[0] == '\0' ? snprintf(out, PATH_SIZE, "%s", key) : snprintf(out, PATH_SIZE, "%s.%s", path, key);
	if (length < 0 || length >= PATH_SIZE)
	{
		out[PATH_SIZE - 1] = '\0';
	}
}

static void IndexPath(char* out, const char* path, int index)
{
	int length = snprintf(out, PATH_SIZE, "%s[%d]", path, index);
	if (length < 0 || length >= PATH_SIZE)
	{
		out[PATH_SIZE - 1] = '\0';
	}
}

static bool IsAllowed(const char* key, const char* const* allowed)
{
	for (int i = 0; allowed[i] != NULL; ++i)
	{
		if (strcmp(key, allowed[i]) == 0)
		{
			return true;
		}
	}
	return false;
}

// Every key must be known and appear once.
static bool CheckKeys(Parser* parser, const cJSON* object, const char* path, const char* const* allowed)
{
	char child[PATH_SIZE];
	for (const cJSON* item = object->child; item != NULL; item = item->next)
	{
		KeyPath(child, path, item->string);
		if (IsAllowed(item->string, allowed) == false)
		{
			return Fail(parser, child, "unknown key");
		}
		for (const cJSON* other = object->child; other != item; other = other->next)
		{
			if (strcmp(other->string, item->string) == 0)
			{
				return Fail(parser, child, "duplicate key");
			}
		}
	}
	return true;
}

static bool RequireObject(Parser* parser, const cJSON* item, const char* path)
{
	return cJSON_IsObject(item) ? true : Fail(parser, path, "must be an object");
}

// ---------------------------------------------------------------------------------------------
// Values. Each reader leaves *out untouched when the key is absent and not required.

static bool ToFloat(Parser* parser, const cJSON* item, const char* path, float* out)
{
	if (cJSON_IsNumber(item) == false)
	{
		return Fail(parser, path, "must be a number");
	}
	double value = item->valuedouble;
	if (value != value || value > FLT_MAX || value < -FLT_MAX)
	{
		return Fail(parser, path, "must be a finite number");
	}
	*out = (float)value;
	return true;
}

static bool ToVec2(Parser* parser, const cJSON* item, const char* path, tbVec2* out)
{
	if (cJSON_IsArray(item) == false || cJSON_GetArraySize(item) != 2)
	{
		return Fail(parser, path, "must be an array of 2 numbers");
	}
	char child[PATH_SIZE];
	IndexPath(child, path, 0);
	if (ToFloat(parser, item->child, child, &out->x) == false)
	{
		return false;
	}
	IndexPath(child, path, 1);
	return ToFloat(parser, item->child->next, child, &out->y);
}

static const cJSON* Find(const cJSON* object, const char* key)
{
	return cJSON_GetObjectItemCaseSensitive(object, key);
}

static bool Missing(Parser* parser, const char* path, const char* key)
{
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return Fail(parser, child, "missing (required)");
}

static bool ReadFloat(Parser* parser, const cJSON* object, const char* path, const char* key, float* out,
					  bool required)
{
	const cJSON* item = Find(object, key);
	if (item == NULL)
	{
		return required ? Missing(parser, path, key) : true;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return ToFloat(parser, item, child, out);
}

static bool ReadVec2(Parser* parser, const cJSON* object, const char* path, const char* key, tbVec2* out,
					 bool required)
{
	const cJSON* item = Find(object, key);
	if (item == NULL)
	{
		return required ? Missing(parser, path, key) : true;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return ToVec2(parser, item, child, out);
}

static bool ReadBool(Parser* parser, const cJSON* object, const char* path, const char* key, bool* out)
{
	const cJSON* item = Find(object, key);
	if (item == NULL)
	{
		return true;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	if (cJSON_IsBool(item) == false)
	{
		return Fail(parser, child, "must be true or false");
	}
	*out = cJSON_IsTrue(item);
	return true;
}

/// 64 filter bits: a string of hexadecimal digits ("0x2", "0xfffffffffffffffd"; JSON numbers
/// cannot hold 64 bits exactly) or a whole number up to 2^53.
static bool ReadBits(Parser* parser, const cJSON* object, const char* path, const char* key, uint64_t* out)
{
	const cJSON* item = Find(object, key);
	if (item == NULL)
	{
		return true;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	if (cJSON_IsNumber(item))
	{
		double value = item->valuedouble;
		if (!(value >= 0.0 && value <= 9007199254740992.0) || value != floor(value))
		{
			return Fail(parser, child, "must be a whole number 0..2^53 or a hexadecimal string such as \"0x2\"");
		}
		*out = (uint64_t)value;
		return true;
	}
	const char* text = cJSON_IsString(item) ? item->valuestring : NULL;
	if (text == NULL || text[0] != '0' || (text[1] != 'x' && text[1] != 'X') || text[2] == '\0' || strlen(text) > 18)
	{
		return Fail(parser, child, "must be a hexadecimal string of up to 16 digits such as \"0x2\"");
	}
	uint64_t value = 0;
	for (const char* c = text + 2; *c != '\0'; ++c)
	{
		int digit = isdigit((unsigned char)*c) ? *c - '0' : (isxdigit((unsigned char)*c) ? tolower((unsigned char)*c) - 'a' + 10 : -1);
		if (digit < 0)
		{
			return Fail(parser, child, "must be a hexadecimal string of up to 16 digits such as \"0x2\"");
		}
		value = (value << 4) | (uint64_t)digit;
	}
	*out = value;
	return true;
}

static bool ReadInt(Parser* parser, const cJSON* object, const char* path, const char* key, int minimum, int maximum,
					int* out)
{
	const cJSON* item = Find(object, key);
	if (item == NULL)
	{
		return true;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	double value = cJSON_IsNumber(item) ? item->valuedouble : 0.5;
	if (!(value >= INT_MIN && value <= INT_MAX) || value != floor(value))
	{
		return Fail(parser, child, "must be an integer");
	}
	if (value < minimum || value > maximum)
	{
		return Fail(parser, child, "must be %d..%d", minimum, maximum);
	}
	*out = (int)value;
	return true;
}

// A string value; *out is NULL when the key is absent.
static bool ReadString(Parser* parser, const cJSON* object, const char* path, const char* key, const char** out)
{
	*out = NULL;
	const cJSON* item = Find(object, key);
	if (item == NULL)
	{
		return true;
	}
	if (cJSON_IsString(item) == false)
	{
		char child[PATH_SIZE];
		KeyPath(child, path, key);
		return Fail(parser, child, "must be a string");
	}
	*out = item->valuestring;
	return true;
}

// Range checks on a value already read.
static bool CheckPositive(Parser* parser, const char* path, const char* key, float value)
{
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return value > 0.0f ? true : Fail(parser, child, "must be > 0");
}

static bool CheckNonNegative(Parser* parser, const char* path, const char* key, float value)
{
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return value >= 0.0f ? true : Fail(parser, child, "must be >= 0");
}

// ---------------------------------------------------------------------------------------------
// Methods

static bool ReadMethodName(Parser* parser, const cJSON* object, const char* path, const char* key,
						   const char** name)
{
	if (ReadString(parser, object, path, key, name) == false)
	{
		return false;
	}
	return true;
}

static bool BadOption(Parser* parser, const char* path, const char* key, const char* options)
{
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return Fail(parser, child, "must be one of %s", options);
}

static bool ReadMethods(Parser* parser, const cJSON* item, SceneMethods* methods)
{
	static const char* const keys[] = {"broadphase", "narrowphase", "toi", "solver", NULL};
	const char* path = "methods";
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	const char* name = NULL;
	if (ReadMethodName(parser, item, path, "broadphase", &name) == false)
	{
		return false;
	}
	if (name != NULL && !(methods->hasBroadPhase = Scene_ParseBroadPhase(name, &methods->broadPhase)))
	{
		return BadOption(parser, path, "broadphase", "tree, sap, brute, auto");
	}
	if (ReadMethodName(parser, item, path, "narrowphase", &name) == false)
	{
		return false;
	}
	if (name != NULL && !(methods->hasNarrowPhase = Scene_ParseNarrowPhase(name, &methods->narrowPhase)))
	{
		return BadOption(parser, path, "narrowphase", "sat, gjk, auto");
	}
	if (ReadMethodName(parser, item, path, "toi", &name) == false)
	{
		return false;
	}
	if (name != NULL && !(methods->hasContinuous = Scene_ParseContinuous(name, &methods->continuous)))
	{
		return BadOption(parser, path, "toi", "off, quadratic, ca");
	}
	if (ReadMethodName(parser, item, path, "solver", &name) == false)
	{
		return false;
	}
	if (name != NULL && !(methods->hasSolver = Scene_ParseSolver(name, &methods->solver)))
	{
		return BadOption(parser, path, "solver", "baumgarte, ngs, soft");
	}
	return true;
}

// ---------------------------------------------------------------------------------------------
// Geometry

static bool ReadBox(Parser* parser, const cJSON* item, const char* path, tbGeometry* geometry)
{
	static const char* const keys[] = {"half_width", "half_height", "center", "angle", NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	float hx = 0.0f, hy = 0.0f, angle = 0.0f;
	tbVec2 center = {0.0f, 0.0f};
	bool ok = ReadFloat(parser, item, path, "half_width", &hx, true) && CheckPositive(parser, path, "half_width", hx) &&
			  ReadFloat(parser, item, path, "half_height", &hy, true) &&
			  CheckPositive(parser, path, "half_height", hy) && ReadVec2(parser, item, path, "center", &center, false) &&
			  ReadFloat(parser, item, path, "angle", &angle, false);
	if (ok)
	{
		*geometry = Scene_MakeBoxGeometry(hx, hy, center, angle);
	}
	return ok;
}

static bool ReadCircle(Parser* parser, const cJSON* item, const char* path, tbGeometry* geometry)
{
	static const char* const keys[] = {"center", "radius", NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	tbVec2 center = {0.0f, 0.0f};
	float radius = 0.0f;
	bool ok = ReadVec2(parser, item, path, "center", &center, false) &&
			  ReadFloat(parser, item, path, "radius", &radius, true) && CheckPositive(parser, path, "radius", radius);
	if (ok)
	{
		*geometry = Scene_MakeCircleGeometry(center, radius);
	}
	return ok;
}

static bool CheckDistinct(Parser* parser, const char* path, const char* key, tbVec2 a, tbVec2 b, const char* other)
{
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	if (tbDistance(a, b) > TB_LINEAR_SLOP)
	{
		return true;
	}
	return Fail(parser, child, "must be more than %g m from %s", (double)TB_LINEAR_SLOP, other);
}

static bool ReadCapsule(Parser* parser, const cJSON* item, const char* path, tbGeometry* geometry)
{
	static const char* const keys[] = {"center1", "center2", "radius", NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	tbVec2 c1 = {0.0f, 0.0f}, c2 = {0.0f, 0.0f};
	float radius = 0.0f;
	bool ok = ReadVec2(parser, item, path, "center1", &c1, true) && ReadVec2(parser, item, path, "center2", &c2, true) &&
			  CheckDistinct(parser, path, "center2", c1, c2, "center1") &&
			  ReadFloat(parser, item, path, "radius", &radius, true) && CheckPositive(parser, path, "radius", radius);
	if (ok)
	{
		*geometry = Scene_MakeCapsuleGeometry(c1, c2, radius);
	}
	return ok;
}

static bool ReadSegment(Parser* parser, const cJSON* item, const char* path, tbGeometry* geometry)
{
	static const char* const keys[] = {"point1", "point2", NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	tbVec2 p1 = {0.0f, 0.0f}, p2 = {0.0f, 0.0f};
	bool ok = ReadVec2(parser, item, path, "point1", &p1, true) && ReadVec2(parser, item, path, "point2", &p2, true) &&
			  CheckDistinct(parser, path, "point2", p1, p2, "point1");
	if (ok)
	{
		*geometry = Scene_MakeSegmentGeometry(p1, p2);
	}
	return ok;
}

static bool ReadVertices(Parser* parser, const cJSON* item, const char* path, tbVec2* points, int* count)
{
	char child[PATH_SIZE];
	KeyPath(child, path, "vertices");
	if (item == NULL)
	{
		return Fail(parser, child, "missing (required)");
	}
	if (cJSON_IsArray(item) == false)
	{
		return Fail(parser, child, "must be an array of [x, y] points");
	}
	int n = cJSON_GetArraySize(item);
	if (n < 3 || n > TB_MAX_POLYGON_VERTICES)
	{
		return Fail(parser, child, "must have 3 to %d vertices (has %d)", TB_MAX_POLYGON_VERTICES, n);
	}
	int i = 0;
	for (const cJSON* point = item->child; point != NULL; point = point->next, ++i)
	{
		char pointPath[PATH_SIZE];
		IndexPath(pointPath, child, i);
		if (ToVec2(parser, point, pointPath, points + i) == false)
		{
			return false;
		}
	}
	*count = n;
	return true;
}

// Vertices already convex and counter-clockwise keep their order (so a saved scene reloads
// bit for bit); any other order is replaced by the hull, which must keep every point.
static bool MakeHull(Parser* parser, const char* path, const tbVec2* points, int count, tbHull* hull)
{
	memset(hull, 0, sizeof(*hull));
	memcpy(hull->points, points, (size_t)count * sizeof(tbVec2));
	hull->count = count;
	if (tbValidateHull(hull))
	{
		return true;
	}
	*hull = tbComputeHull(points, count);
	char child[PATH_SIZE];
	KeyPath(child, path, "vertices");
	if (hull->count == 0)
	{
		return Fail(parser, child, "no valid convex hull (points collinear, duplicate or closer than %g m)",
					(double)TB_LINEAR_SLOP);
	}
	if (hull->count != count)
	{
		return Fail(parser, child, "not convex: the hull keeps %d of %d points", hull->count, count);
	}
	return true;
}

static bool ReadPolygon(Parser* parser, const cJSON* item, const char* path, tbGeometry* geometry)
{
	static const char* const keys[] = {"vertices", "radius", NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	tbVec2 points[TB_MAX_POLYGON_VERTICES];
	int count = 0;
	float radius = 0.0f;
	tbHull hull;
	bool ok = ReadVertices(parser, Find(item, "vertices"), path, points, &count) &&
			  ReadFloat(parser, item, path, "radius", &radius, false) &&
			  CheckNonNegative(parser, path, "radius", radius) && MakeHull(parser, path, points, count, &hull);
	if (ok)
	{
		memset(geometry, 0, sizeof(*geometry));
		geometry->type = tb_polygonShape;
		geometry->polygon = tbMakePolygon(&hull, radius);
	}
	return ok;
}

// ---------------------------------------------------------------------------------------------
// Shapes and bodies

typedef bool GeometryReader(Parser* parser, const cJSON* item, const char* path, tbGeometry* geometry);

typedef struct ShapeKind
{
	const char* key;
	GeometryReader* read;
} ShapeKind;

static const ShapeKind s_shapeKinds[] = {
	{"box", ReadBox}, {"circle", ReadCircle}, {"polygon", ReadPolygon}, {"capsule", ReadCapsule}, {"segment", ReadSegment},
};

#define SHAPE_KIND_COUNT ((int)(sizeof(s_shapeKinds) / sizeof(s_shapeKinds[0])))

static bool ReadGeometry(Parser* parser, const cJSON* item, const char* path, tbGeometry* geometry)
{
	int found = -1;
	for (int i = 0; i < SHAPE_KIND_COUNT; ++i)
	{
		if (Find(item, s_shapeKinds[i].key) == NULL)
		{
			continue;
		}
		if (found >= 0)
		{
			return Fail(parser, path, "must have exactly one of box, circle, polygon, capsule, segment (has %s and %s)",
						s_shapeKinds[found].key, s_shapeKinds[i].key);
		}
		found = i;
	}
	if (found < 0)
	{
		return Fail(parser, path, "must have exactly one of box, circle, polygon, capsule, segment");
	}
	char child[PATH_SIZE];
	KeyPath(child, path, s_shapeKinds[found].key);
	return s_shapeKinds[found].read(parser, Find(item, s_shapeKinds[found].key), child, geometry);
}

static bool ReadShape(Parser* parser, const cJSON* item, const char* path, SceneShape* shape)
{
	static const char* const keys[] = {"box",	  "circle",	  "polygon",	 "capsule", "segment",
									   "density", "friction", "restitution", "sensor",	"hit_events", "group",
									   "category_bits", "mask_bits", NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	*shape = Scene_DefaultShape();
	return ReadGeometry(parser, item, path, &shape->geometry) &&
		   ReadFloat(parser, item, path, "density", &shape->density, false) &&
		   CheckNonNegative(parser, path, "density", shape->density) &&
		   ReadFloat(parser, item, path, "friction", &shape->friction, false) &&
		   CheckNonNegative(parser, path, "friction", shape->friction) &&
		   ReadFloat(parser, item, path, "restitution", &shape->restitution, false) &&
		   CheckNonNegative(parser, path, "restitution", shape->restitution) &&
		   ReadBool(parser, item, path, "sensor", &shape->isSensor) &&
		   ReadBool(parser, item, path, "hit_events", &shape->enableHitEvents) &&
		   ReadInt(parser, item, path, "group", INT_MIN, INT_MAX, &shape->groupIndex) &&
		   ReadBits(parser, item, path, "category_bits", &shape->categoryBits) &&
		   ReadBits(parser, item, path, "mask_bits", &shape->maskBits);
}

static bool ReadShapes(Parser* parser, const cJSON* item, const char* path, Scene* scene, int bodyIndex)
{
	if (item == NULL)
	{
		return true;
	}
	if (cJSON_IsArray(item) == false)
	{
		return Fail(parser, path, "must be an array of shapes");
	}
	int count = cJSON_GetArraySize(item);
	if (parser->countedScene != scene)
	{
		parser->countedScene = scene;
		parser->countedShapes = Scene_ShapeCount(scene);
	}
	if (parser->countedShapes + count > SCENE_MAX_SHAPES)
	{
		return Fail(parser, path, "at most %d shapes in a scene (this one reaches %d)", SCENE_MAX_SHAPES,
					parser->countedShapes + count);
	}
	int i = 0;
	for (const cJSON* shapeItem = item->child; shapeItem != NULL; shapeItem = shapeItem->next, ++i)
	{
		char child[PATH_SIZE];
		IndexPath(child, path, i);
		SceneShape shape;
		if (ReadShape(parser, shapeItem, child, &shape) == false)
		{
			return false;
		}
		Scene_AddShape(scene, bodyIndex, &shape);
		parser->countedShapes += 1;
	}
	return true;
}

static bool ReadBodyType(Parser* parser, const cJSON* item, const char* path, tbBodyType* type)
{
	const char* name = NULL;
	if (ReadString(parser, item, path, "type", &name) == false)
	{
		return false;
	}
	if (name != NULL && Scene_ParseBodyType(name, type) == false)
	{
		return BadOption(parser, path, "type", "static, kinematic, dynamic");
	}
	return true;
}

static bool ReadName(Parser* parser, const cJSON* item, const char* path, char* name)
{
	const char* text = NULL;
	if (ReadString(parser, item, path, "name", &text) == false)
	{
		return false;
	}
	if (text != NULL && strlen(text) >= SCENE_NAME_SIZE)
	{
		char child[PATH_SIZE];
		KeyPath(child, path, "name");
		return Fail(parser, child, "must be at most %d characters", SCENE_NAME_SIZE - 1);
	}
	if (text != NULL)
	{
		snprintf(name, SCENE_NAME_SIZE, "%s", text);
	}
	return true;
}

// A body's scripted path: {"amplitude": [x, y], "angular_frequency": w}, both required.
static bool ReadDrive(Parser* parser, const cJSON* item, const char* path, SceneDrive* drive)
{
	static const char* const keys[] = {"amplitude", "angular_frequency", NULL};
	if (item == NULL)
	{
		return true;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, "drive");
	if (RequireObject(parser, item, child) == false || CheckKeys(parser, item, child, keys) == false)
	{
		return false;
	}
	drive->enabled = true;
	return ReadVec2(parser, item, child, "amplitude", &drive->amplitude, true) &&
		   ReadFloat(parser, item, child, "angular_frequency", &drive->angularFrequency, true);
}

static bool ReadBodyFields(Parser* parser, const cJSON* item, const char* path, SceneBody* body)
{
	return ReadBodyType(parser, item, path, &body->type) && ReadName(parser, item, path, body->name) &&
		   ReadVec2(parser, item, path, "position", &body->position, false) &&
		   ReadFloat(parser, item, path, "angle", &body->angle, false) &&
		   ReadVec2(parser, item, path, "linear_velocity", &body->linearVelocity, false) &&
		   ReadFloat(parser, item, path, "angular_velocity", &body->angularVelocity, false) &&
		   ReadFloat(parser, item, path, "linear_damping", &body->linearDamping, false) &&
		   CheckNonNegative(parser, path, "linear_damping", body->linearDamping) &&
		   ReadFloat(parser, item, path, "angular_damping", &body->angularDamping, false) &&
		   CheckNonNegative(parser, path, "angular_damping", body->angularDamping) &&
		   ReadFloat(parser, item, path, "gravity_scale", &body->gravityScale, false) &&
		   ReadFloat(parser, item, path, "sleep_threshold", &body->sleepThreshold, false) &&
		   CheckNonNegative(parser, path, "sleep_threshold", body->sleepThreshold) &&
		   ReadBool(parser, item, path, "bullet", &body->bullet) &&
		   ReadBool(parser, item, path, "fixed_rotation", &body->fixedRotation) &&
		   ReadBool(parser, item, path, "awake", &body->isAwake) &&
		   ReadDrive(parser, Find(item, "drive"), path, &body->drive);
}

static bool ReadBody(Parser* parser, const cJSON* item, const char* path, Scene* scene)
{
	static const char* const keys[] = {"type",			 "name",		   "position",		"angle",
									   "linear_velocity", "angular_velocity", "linear_damping", "angular_damping",
									   "gravity_scale",	 "bullet",		   "awake",			"drive", "fixed_rotation",
									   "sleep_threshold", "shapes",		 NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	int index = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	if (ReadBodyFields(parser, item, path, scene->bodies + index) == false)
	{
		return false;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, "shapes");
	return ReadShapes(parser, Find(item, "shapes"), child, scene, index);
}

// The bodies of the scene (path "bodies") or of a template ("templates[i].bodies").
static bool ReadBodies(Parser* parser, const cJSON* item, const char* path, Scene* scene)
{
	if (item == NULL)
	{
		return true;
	}
	if (cJSON_IsArray(item) == false)
	{
		return Fail(parser, path, "must be an array of bodies");
	}
	int count = cJSON_GetArraySize(item);
	if (count > SCENE_MAX_BODIES)
	{
		return Fail(parser, path, "at most %d bodies (has %d)", SCENE_MAX_BODIES, count);
	}
	int i = 0;
	for (const cJSON* body = item->child; body != NULL; body = body->next, ++i)
	{
		char child[PATH_SIZE];
		IndexPath(child, path, i);
		if (ReadBody(parser, body, child, scene) == false)
		{
			return false;
		}
	}
	return true;
}

static bool CheckAtLeast(Parser* parser, const char* path, const char* key, float value, float minimum)
{
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return value >= minimum ? true : Fail(parser, child, "must be at least %g", (double)minimum);
}

static bool CheckAtMost(Parser* parser, const char* path, const char* key, float value, float maximum)
{
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return value <= maximum ? true : Fail(parser, child, "must be at most %g", (double)maximum);
}

// The library's own checks decide what a shape may be (sizes within TB_MAX_COORDINATE, a polygon
// that is not too thin to be convex in float, a mass within TB_MAX_SHAPE_MASS, ...). Build the
// scene into a scratch world and name the first body or shape the library refuses; its error
// hook has printed the reason. A scene that loads is then a scene whose every part exists.
static bool CheckBuilds(Parser* parser, const Scene* scene)
{
	char item[PATH_SIZE];
	if (Scene_FindRefusedItem(scene, item, (int)sizeof(item)) == false)
	{
		return true;
	}
	return Fail(parser, item, "refused by the library (see its message above: size, thinness, density or position)");
}

// ---------------------------------------------------------------------------------------------
// Joints. The keys of each kind are its definition's fields in snake case, read and written from
// one table per kind (offsets into the definition, which every kind starts with its `base`).

typedef enum FieldKind
{
	FIELD_FLOAT,
	FIELD_NON_NEGATIVE,
	FIELD_BOOL,
	FIELD_VEC2,
	FIELD_NON_NEGATIVE_VEC2, ///< both coordinates >= 0 (the mover joint's force caps)
} FieldKind;

typedef struct JointField
{
	const char* key;
	size_t offset;
	FieldKind kind;
} JointField;

#define FIELD(Def, member, key, kind) {key, offsetof(Def, member), kind}

static const JointField s_distanceFields[] = {
	FIELD(tbDistanceJointDef, length, "length", FIELD_NON_NEGATIVE),
	FIELD(tbDistanceJointDef, enableSpring, "enable_spring", FIELD_BOOL),
	FIELD(tbDistanceJointDef, lowerSpringForce, "lower_spring_force", FIELD_FLOAT),
	FIELD(tbDistanceJointDef, upperSpringForce, "upper_spring_force", FIELD_FLOAT),
	FIELD(tbDistanceJointDef, hertz, "hertz", FIELD_NON_NEGATIVE),
	FIELD(tbDistanceJointDef, dampingRatio, "damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbDistanceJointDef, enableLimit, "enable_limit", FIELD_BOOL),
	FIELD(tbDistanceJointDef, minLength, "min_length", FIELD_NON_NEGATIVE),
	FIELD(tbDistanceJointDef, maxLength, "max_length", FIELD_NON_NEGATIVE),
	FIELD(tbDistanceJointDef, enableMotor, "enable_motor", FIELD_BOOL),
	FIELD(tbDistanceJointDef, maxMotorForce, "max_motor_force", FIELD_NON_NEGATIVE),
	FIELD(tbDistanceJointDef, motorSpeed, "motor_speed", FIELD_FLOAT),
	{NULL, 0, FIELD_FLOAT}};

static const JointField s_filterFields[] = {{NULL, 0, FIELD_FLOAT}};

static const JointField s_motorFields[] = {
	FIELD(tbMotorJointDef, linearVelocity, "linear_velocity", FIELD_VEC2),
	FIELD(tbMotorJointDef, maxVelocityForce, "max_velocity_force", FIELD_NON_NEGATIVE),
	FIELD(tbMotorJointDef, angularVelocity, "angular_velocity", FIELD_FLOAT),
	FIELD(tbMotorJointDef, maxVelocityTorque, "max_velocity_torque", FIELD_NON_NEGATIVE),
	FIELD(tbMotorJointDef, linearHertz, "linear_hertz", FIELD_NON_NEGATIVE),
	FIELD(tbMotorJointDef, linearDampingRatio, "linear_damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbMotorJointDef, maxSpringForce, "max_spring_force", FIELD_NON_NEGATIVE),
	FIELD(tbMotorJointDef, angularHertz, "angular_hertz", FIELD_NON_NEGATIVE),
	FIELD(tbMotorJointDef, angularDampingRatio, "angular_damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbMotorJointDef, maxSpringTorque, "max_spring_torque", FIELD_NON_NEGATIVE),
	{NULL, 0, FIELD_FLOAT}};

static const JointField s_moverFields[] = {
	FIELD(tbMoverJointDef, linearVelocity, "linear_velocity", FIELD_VEC2),
	FIELD(tbMoverJointDef, maxVelocityForce, "max_velocity_force", FIELD_NON_NEGATIVE_VEC2),
	{NULL, 0, FIELD_FLOAT}};

static const JointField s_pogoFields[] = {
	FIELD(tbPogoJointDef, normal, "normal", FIELD_VEC2),
	FIELD(tbPogoJointDef, hertz, "hertz", FIELD_NON_NEGATIVE),
	FIELD(tbPogoJointDef, dampingRatio, "damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbPogoJointDef, restLength, "rest_length", FIELD_NON_NEGATIVE),
	FIELD(tbPogoJointDef, maxTensionForce, "max_tension_force", FIELD_NON_NEGATIVE),
	FIELD(tbPogoJointDef, maxCompressionForce, "max_compression_force", FIELD_NON_NEGATIVE),
	FIELD(tbPogoJointDef, impulse, "impulse", FIELD_FLOAT),
	FIELD(tbPogoJointDef, velocity, "velocity", FIELD_FLOAT),
	{NULL, 0, FIELD_FLOAT}};

static const JointField s_prismaticFields[] = {
	FIELD(tbPrismaticJointDef, enableSpring, "enable_spring", FIELD_BOOL),
	FIELD(tbPrismaticJointDef, hertz, "hertz", FIELD_NON_NEGATIVE),
	FIELD(tbPrismaticJointDef, dampingRatio, "damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbPrismaticJointDef, targetTranslation, "target_translation", FIELD_FLOAT),
	FIELD(tbPrismaticJointDef, enableLimit, "enable_limit", FIELD_BOOL),
	FIELD(tbPrismaticJointDef, lowerTranslation, "lower_translation", FIELD_FLOAT),
	FIELD(tbPrismaticJointDef, upperTranslation, "upper_translation", FIELD_FLOAT),
	FIELD(tbPrismaticJointDef, enableMotor, "enable_motor", FIELD_BOOL),
	FIELD(tbPrismaticJointDef, maxMotorForce, "max_motor_force", FIELD_NON_NEGATIVE),
	FIELD(tbPrismaticJointDef, motorSpeed, "motor_speed", FIELD_FLOAT),
	{NULL, 0, FIELD_FLOAT}};

static const JointField s_revoluteFields[] = {
	FIELD(tbRevoluteJointDef, targetAngle, "target_angle", FIELD_FLOAT),
	FIELD(tbRevoluteJointDef, enableSpring, "enable_spring", FIELD_BOOL),
	FIELD(tbRevoluteJointDef, hertz, "hertz", FIELD_NON_NEGATIVE),
	FIELD(tbRevoluteJointDef, dampingRatio, "damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbRevoluteJointDef, enableLimit, "enable_limit", FIELD_BOOL),
	FIELD(tbRevoluteJointDef, lowerAngle, "lower_angle", FIELD_FLOAT),
	FIELD(tbRevoluteJointDef, upperAngle, "upper_angle", FIELD_FLOAT),
	FIELD(tbRevoluteJointDef, enableMotor, "enable_motor", FIELD_BOOL),
	FIELD(tbRevoluteJointDef, maxMotorTorque, "max_motor_torque", FIELD_NON_NEGATIVE),
	FIELD(tbRevoluteJointDef, motorSpeed, "motor_speed", FIELD_FLOAT),
	{NULL, 0, FIELD_FLOAT}};

static const JointField s_weldFields[] = {
	FIELD(tbWeldJointDef, linearHertz, "linear_hertz", FIELD_NON_NEGATIVE),
	FIELD(tbWeldJointDef, angularHertz, "angular_hertz", FIELD_NON_NEGATIVE),
	FIELD(tbWeldJointDef, linearDampingRatio, "linear_damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbWeldJointDef, angularDampingRatio, "angular_damping_ratio", FIELD_NON_NEGATIVE),
	{NULL, 0, FIELD_FLOAT}};

static const JointField s_wheelFields[] = {
	FIELD(tbWheelJointDef, enableSpring, "enable_spring", FIELD_BOOL),
	FIELD(tbWheelJointDef, hertz, "hertz", FIELD_NON_NEGATIVE),
	FIELD(tbWheelJointDef, dampingRatio, "damping_ratio", FIELD_NON_NEGATIVE),
	FIELD(tbWheelJointDef, enableLimit, "enable_limit", FIELD_BOOL),
	FIELD(tbWheelJointDef, lowerTranslation, "lower_translation", FIELD_FLOAT),
	FIELD(tbWheelJointDef, upperTranslation, "upper_translation", FIELD_FLOAT),
	FIELD(tbWheelJointDef, enableMotor, "enable_motor", FIELD_BOOL),
	FIELD(tbWheelJointDef, maxMotorTorque, "max_motor_torque", FIELD_NON_NEGATIVE),
	FIELD(tbWheelJointDef, motorSpeed, "motor_speed", FIELD_FLOAT),
	{NULL, 0, FIELD_FLOAT}};

#undef FIELD

/// The fields of a kind, indexed by tbJointType.
static const JointField* const s_jointFields[tb_jointTypeCount] = {
	s_distanceFields, s_filterFields,	 s_motorFields, s_moverFields, s_pogoFields,
	s_prismaticFields, s_revoluteFields, s_weldFields,	s_wheelFields};

/// Keys every joint has.
static const char* const s_jointBaseKeys[] = {"type",	"body_a",	"body_b",			 "anchor_a",
											  "angle_a", "anchor_b", "angle_b",			 "collide_connected",
											  "constraint_hertz", "constraint_damping_ratio", NULL};

static bool ReadJointField(Parser* parser, const cJSON* item, const char* path, const JointField* field, void* def)
{
	char* target = (char*)def + field->offset;
	switch (field->kind)
	{
		case FIELD_BOOL:
			return ReadBool(parser, item, path, field->key, (bool*)target);
		case FIELD_VEC2:
			return ReadVec2(parser, item, path, field->key, (tbVec2*)target, false);
		case FIELD_NON_NEGATIVE_VEC2:
			return ReadVec2(parser, item, path, field->key, (tbVec2*)target, false) &&
				   CheckNonNegative(parser, path, field->key, ((tbVec2*)target)->x) &&
				   CheckNonNegative(parser, path, field->key, ((tbVec2*)target)->y);
		case FIELD_NON_NEGATIVE:
			return ReadFloat(parser, item, path, field->key, (float*)target, false) &&
				   CheckNonNegative(parser, path, field->key, *(float*)target);
		case FIELD_FLOAT:
		default:
			return ReadFloat(parser, item, path, field->key, (float*)target, false);
	}
}

/// lower <= upper for a kind's ranges (the library refuses the joint otherwise).
static bool CheckOrder(Parser* parser, const char* path, const char* lowerKey, float lower, const char* upperKey,
					   float upper)
{
	if (lower <= upper)
	{
		return true;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, lowerKey);
	return Fail(parser, child, "must be <= %s", upperKey);
}

static bool CheckJointRanges(Parser* parser, const char* path, const SceneJoint* joint)
{
	switch (joint->type)
	{
		case tb_distanceJoint:
			return CheckOrder(parser, path, "min_length", joint->def.distance.minLength, "max_length",
							  joint->def.distance.maxLength) &&
				   CheckOrder(parser, path, "lower_spring_force", joint->def.distance.lowerSpringForce,
							  "upper_spring_force", joint->def.distance.upperSpringForce);
		case tb_prismaticJoint:
			return CheckOrder(parser, path, "lower_translation", joint->def.prismatic.lowerTranslation,
							  "upper_translation", joint->def.prismatic.upperTranslation);
		case tb_revoluteJoint:
		{
			const tbRevoluteJointDef* r = &joint->def.revolute;
			char child[PATH_SIZE];
			KeyPath(child, path, r->lowerAngle < -TB_PI ? "lower_angle" : "upper_angle");
			if (r->lowerAngle < -TB_PI || r->upperAngle > TB_PI)
			{
				return Fail(parser, child, "must lie in [-pi, pi]");
			}
			return CheckOrder(parser, path, "lower_angle", r->lowerAngle, "upper_angle", r->upperAngle);
		}
		case tb_wheelJoint:
			return CheckOrder(parser, path, "lower_translation", joint->def.wheel.lowerTranslation,
							  "upper_translation", joint->def.wheel.upperTranslation);
		default:
			return true;
	}
}

static bool ReadJointBody(Parser* parser, const cJSON* item, const char* path, const char* key, int bodyCount, int* out)
{
	*out = -1;
	if (Find(item, key) == NULL)
	{
		return Missing(parser, path, key);
	}
	if (ReadInt(parser, item, path, key, 0, INT_MAX, out) == false)
	{
		return false;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, key);
	return *out < bodyCount ? true : Fail(parser, child, "must be the index of a body (there are %d)", bodyCount);
}

static bool ReadJointType(Parser* parser, const cJSON* item, const char* path, tbJointType* type)
{
	const char* name = NULL;
	if (ReadString(parser, item, path, "type", &name) == false)
	{
		return false;
	}
	if (name == NULL)
	{
		return Missing(parser, path, "type");
	}
	if (Scene_ParseJointType(name, type))
	{
		return true;
	}
	// The list from the scene model's own names, so that a new kind cannot be left out of it.
	char options[256] = "";
	for (int kind = 0; kind < tb_jointTypeCount; ++kind)
	{
		const char* kindName = Scene_JointTypeName((tbJointType)kind);
		if (kindName != NULL && strlen(options) + strlen(kindName) + 3 < sizeof(options))
		{
			strcat(options, kind > 0 ? ", " : "");
			strcat(options, kindName);
		}
	}
	return BadOption(parser, path, "type", options);
}

// The frames: an anchor (the frame's origin) and an angle per body, in the body's frame.
static bool ReadJointBase(Parser* parser, const cJSON* item, const char* path, SceneJoint* joint)
{
	tbJointDef* base = &joint->def.base;
	float angleA = tbRot_GetAngle(base->localFrameA.q);
	float angleB = tbRot_GetAngle(base->localFrameB.q);
	bool ok = ReadVec2(parser, item, path, "anchor_a", &base->localFrameA.p, false) &&
			  ReadFloat(parser, item, path, "angle_a", &angleA, false) &&
			  ReadVec2(parser, item, path, "anchor_b", &base->localFrameB.p, false) &&
			  ReadFloat(parser, item, path, "angle_b", &angleB, false) &&
			  ReadBool(parser, item, path, "collide_connected", &base->collideConnected) &&
			  ReadFloat(parser, item, path, "constraint_hertz", &base->constraintHertz, false) &&
			  CheckNonNegative(parser, path, "constraint_hertz", base->constraintHertz) &&
			  ReadFloat(parser, item, path, "constraint_damping_ratio", &base->constraintDampingRatio, false) &&
			  CheckNonNegative(parser, path, "constraint_damping_ratio", base->constraintDampingRatio);
	base->localFrameA.q = tbMakeRot(angleA);
	base->localFrameB.q = tbMakeRot(angleB);
	return ok;
}

static bool ReadJoint(Parser* parser, const cJSON* item, const char* path, Scene* scene)
{
	tbJointType type = tb_revoluteJoint;
	if (RequireObject(parser, item, path) == false || ReadJointType(parser, item, path, &type) == false)
	{
		return false;
	}
	const char* keys[32];
	int keyCount = 0;
	for (int i = 0; s_jointBaseKeys[i] != NULL; ++i)
	{
		keys[keyCount++] = s_jointBaseKeys[i];
	}
	const JointField* fields = s_jointFields[type];
	for (int i = 0; fields[i].key != NULL; ++i)
	{
		keys[keyCount++] = fields[i].key;
	}
	keys[keyCount] = NULL;
	int bodyA, bodyB;
	if (CheckKeys(parser, item, path, keys) == false ||
		ReadJointBody(parser, item, path, "body_a", scene->bodyCount, &bodyA) == false ||
		ReadJointBody(parser, item, path, "body_b", scene->bodyCount, &bodyB) == false)
	{
		return false;
	}
	if (bodyA == bodyB)
	{
		char child[PATH_SIZE];
		KeyPath(child, path, "body_b");
		return Fail(parser, child, "must differ from body_a (a joint joins two bodies)");
	}
	SceneJoint* joint = Scene_AddJoint(scene, type, bodyA, bodyB);
	if (ReadJointBase(parser, item, path, joint) == false)
	{
		return false;
	}
	for (int i = 0; fields[i].key != NULL; ++i)
	{
		if (ReadJointField(parser, item, path, fields + i, &joint->def) == false)
		{
			return false;
		}
	}
	return CheckJointRanges(parser, path, joint);
}

// The joints of the scene (path "joints") or of a template ("templates[i].joints").
static bool ReadJoints(Parser* parser, const cJSON* item, const char* path, Scene* scene)
{
	if (item == NULL)
	{
		return true;
	}
	if (cJSON_IsArray(item) == false)
	{
		return Fail(parser, path, "must be an array of joints");
	}
	int i = 0;
	for (const cJSON* joint = item->child; joint != NULL; joint = joint->next, ++i)
	{
		char child[PATH_SIZE];
		IndexPath(child, path, i);
		if (ReadJoint(parser, joint, child, scene) == false)
		{
			return false;
		}
	}
	return true;
}

// ---------------------------------------------------------------------------------------------
// Chains: {"body": index, "points": [[x, y], …], "loop": bool, "friction": f, "restitution": e}

static bool ReadChainPoints(Parser* parser, const cJSON* item, const char* path, SceneChain* chain)
{
	char child[PATH_SIZE];
	KeyPath(child, path, "points");
	if (item == NULL)
	{
		return Fail(parser, child, "missing (required)");
	}
	int n = cJSON_IsArray(item) ? cJSON_GetArraySize(item) : 0;
	if (n < 4 || n > SCENE_MAX_CHAIN_POINTS)
	{
		return Fail(parser, child, "must be an array of 4 to %d [x, y] points", SCENE_MAX_CHAIN_POINTS);
	}
	tbVec2* points = malloc(sizeof(tbVec2) * (size_t)n);
	if (points == NULL)
	{
		return Fail(parser, child, "out of memory");
	}
	int i = 0;
	for (const cJSON* point = item->child; point != NULL; point = point->next, ++i)
	{
		char pointPath[PATH_SIZE];
		IndexPath(pointPath, child, i);
		if (ToVec2(parser, point, pointPath, points + i) == false)
		{
			free(points);
			return false;
		}
	}
	free(chain->points);
	chain->points = points;
	chain->count = n;
	return true;
}

static bool ReadChain(Parser* parser, const cJSON* item, const char* path, Scene* scene)
{
	static const char* const keys[] = {"body", "points", "loop", "friction", "restitution", NULL};
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false)
	{
		return false;
	}
	int body;
	if (ReadJointBody(parser, item, path, "body", scene->bodyCount, &body) == false)
	{
		return false;
	}
	SceneChain* chain = Scene_AddChain(scene, body, NULL, 0, false);
	return ReadChainPoints(parser, Find(item, "points"), path, chain) &&
		   ReadBool(parser, item, path, "loop", &chain->isLoop) &&
		   ReadFloat(parser, item, path, "friction", &chain->friction, false) &&
		   CheckNonNegative(parser, path, "friction", chain->friction) &&
		   ReadFloat(parser, item, path, "restitution", &chain->restitution, false) &&
		   CheckNonNegative(parser, path, "restitution", chain->restitution);
}

/// A top-level array whose items `read` takes one by one, each with its path ("chains[2]").
typedef bool ReadItemFcn(Parser* parser, const cJSON* item, const char* path, Scene* scene);

static bool ReadEach(Parser* parser, const cJSON* item, const char* key, const char* what, ReadItemFcn* read,
					 Scene* scene)
{
	if (item == NULL)
	{
		return true;
	}
	if (cJSON_IsArray(item) == false)
	{
		return Fail(parser, key, "must be an array of %s", what);
	}
	int i = 0;
	for (const cJSON* entry = item->child; entry != NULL; entry = entry->next, ++i)
	{
		char child[PATH_SIZE];
		IndexPath(child, key, i);
		if (read(parser, entry, child, scene) == false)
		{
			return false;
		}
	}
	return true;
}

static bool ReadChains(Parser* parser, const cJSON* item, Scene* scene)
{
	return ReadEach(parser, item, "chains", "chains", ReadChain, scene);
}

// ---------------------------------------------------------------------------------------------
// Spawn schedules: templates {"name", "bodies", "joints"} (bodies placed relative to the spawn
// point, joints between the template's own bodies) and spawners {"template", "first_step",
// "interval", "count", "keep", "lifetime", "slots", "origin", "slot_step"} (see SceneSpawner).

// Spawned bodies are not driven (SceneWorld_Step drives the scene's bodies only).
static bool CheckTemplateBodies(Parser* parser, const char* path, const Scene* parts)
{
	for (int i = 0; i < parts->bodyCount; ++i)
	{
		if (parts->bodies[i].drive.enabled)
		{
			char child[PATH_SIZE], body[PATH_SIZE];
			IndexPath(body, path, i);
			KeyPath(child, body, "drive");
			return Fail(parser, child, "not allowed in a template (spawned bodies are not driven)");
		}
	}
	return true;
}

static bool ReadTemplate(Parser* parser, const cJSON* item, const char* path, Scene* scene)
{
	static const char* const keys[] = {"name", "bodies", "joints", NULL};
	const char* name = NULL;
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false ||
		ReadString(parser, item, path, "name", &name) == false)
	{
		return false;
	}
	char child[PATH_SIZE];
	KeyPath(child, path, "name");
	if (name == NULL)
	{
		return Missing(parser, path, "name");
	}
	if (name[0] == '\0' || strlen(name) >= SCENE_NAME_SIZE)
	{
		return Fail(parser, child, "must be 1..%d characters", SCENE_NAME_SIZE - 1);
	}
	if (Scene_FindTemplate(scene, name) >= 0)
	{
		return Fail(parser, child, "a template called \"%s\" comes earlier (names must differ)", name);
	}
	int index = Scene_AddTemplate(scene, name); // may move scene->templates
	Scene* parts = scene->templates[index].parts;
	char bodies[PATH_SIZE], joints[PATH_SIZE];
	KeyPath(bodies, path, "bodies");
	KeyPath(joints, path, "joints");
	return ReadBodies(parser, Find(item, "bodies"), bodies, parts) && CheckTemplateBodies(parser, bodies, parts) &&
		   ReadJoints(parser, Find(item, "joints"), joints, parts);
}

static bool ReadTemplates(Parser* parser, const cJSON* item, Scene* scene)
{
	return ReadEach(parser, item, "templates", "templates", ReadTemplate, scene);
}

static bool ReadSpawnerTemplate(Parser* parser, const cJSON* item, const char* path, const Scene* scene, int* index)
{
	const char* name = NULL;
	if (ReadString(parser, item, path, "template", &name) == false)
	{
		return false;
	}
	if (name == NULL)
	{
		return Missing(parser, path, "template");
	}
	*index = Scene_FindTemplate(scene, name);
	char child[PATH_SIZE];
	KeyPath(child, path, "template");
	return *index >= 0 ? true : Fail(parser, child, "no template called \"%s\" (see \"templates\")", name);
}

// An untrusted file may not pile up instances without end, nor keep more bodies alive than a
// scene may hold.
static bool CheckSpawnerBounds(Parser* parser, const char* path, const SceneSpawner* spawner, const Scene* parts)
{
	if (spawner->count == 0 && spawner->keep == 0 && spawner->lifetime == 0)
	{
		char child[PATH_SIZE];
		KeyPath(child, path, "keep");
		return Fail(parser, child, "must be > 0 when count and lifetime are 0 (else instances pile up without end)");
	}
	int live = SceneSpawner_Capacity(spawner);
	if ((double)live * (double)parts->bodyCount > (double)SCENE_MAX_BODIES)
	{
		return Fail(parser, path, "keeps up to %d instances of %d bodies alive: at most %d bodies", live,
					parts->bodyCount, SCENE_MAX_BODIES);
	}
	return true;
}

static bool ReadSpawner(Parser* parser, const cJSON* item, const char* path, Scene* scene)
{
	static const char* const keys[] = {"template", "first_step", "interval",  "count",	"keep",
									   "lifetime", "slots",		 "origin",	  "slot_step", NULL};
	int templateIndex = -1;
	if (RequireObject(parser, item, path) == false || CheckKeys(parser, item, path, keys) == false ||
		ReadSpawnerTemplate(parser, item, path, scene, &templateIndex) == false)
	{
		return false;
	}
	if (Find(item, "interval") == NULL)
	{
		return Missing(parser, path, "interval");
	}
	SceneSpawner* spawner = Scene_AddSpawner(scene, templateIndex, 1, tbVec2_zero);
	return ReadInt(parser, item, path, "first_step", 0, SCENE_MAX_STEPS, &spawner->firstStep) &&
		   ReadInt(parser, item, path, "interval", 1, SCENE_MAX_STEPS, &spawner->interval) &&
		   ReadInt(parser, item, path, "count", 0, SCENE_MAX_STEPS, &spawner->count) &&
		   ReadInt(parser, item, path, "keep", 0, SCENE_MAX_STEPS, &spawner->keep) &&
		   ReadInt(parser, item, path, "lifetime", 0, SCENE_MAX_STEPS, &spawner->lifetime) &&
		   ReadInt(parser, item, path, "slots", 1, SCENE_MAX_STEPS, &spawner->slotCount) &&
		   ReadVec2(parser, item, path, "origin", &spawner->origin, false) &&
		   ReadVec2(parser, item, path, "slot_step", &spawner->slotStep, false) &&
		   CheckSpawnerBounds(parser, path, spawner, scene->templates[templateIndex].parts);
}

static bool ReadSpawners(Parser* parser, const cJSON* item, Scene* scene)
{
	return ReadEach(parser, item, "spawners", "spawners", ReadSpawner, scene);
}

// Each template's parts must build too; the message names the template's item.
static bool CheckTemplatesBuild(Parser* parser, const Scene* scene)
{
	for (int i = 0; i < scene->templateCount; ++i)
	{
		char item[PATH_SIZE], path[PATH_SIZE + 32];
		if (Scene_FindRefusedItem(scene->templates[i].parts, item, (int)sizeof(item)))
		{
			snprintf(path, sizeof(path), "templates[%d].%s", i, item);
			return Fail(parser, path, "refused by the library (see its message above: size, thinness, density or "
									  "position)");
		}
	}
	return true;
}

static bool ReadScene(Parser* parser, const cJSON* root, Scene* scene)
{
	static const char* const keys[] = {"gravity", "time_step", "sub_steps", "steps",	 "enable_sleep", "methods",
									   "bodies",  "joints",	   "chains",	"templates", "spawners",	 NULL};
	if (cJSON_IsObject(root) == false)
	{
		return Fail(parser, "", "scene: must be a JSON object");
	}
	const cJSON* methods = Find(root, "methods");
	return CheckKeys(parser, root, "", keys) && ReadVec2(parser, root, "", "gravity", &scene->gravity, false) &&
		   ReadFloat(parser, root, "", "time_step", &scene->timeStep, false) &&
		   CheckAtLeast(parser, "", "time_step", scene->timeStep, TB_MIN_TIME_STEP) &&
		   CheckAtMost(parser, "", "time_step", scene->timeStep, TB_MAX_TIME_STEP) &&
		   ReadInt(parser, root, "", "sub_steps", 1, TB_MAX_SUB_STEPS, &scene->subSteps) &&
		   ReadInt(parser, root, "", "steps", 0, SCENE_MAX_STEPS, &scene->steps) &&
		   ReadBool(parser, root, "", "enable_sleep", &scene->enableSleep) &&
		   (methods == NULL || ReadMethods(parser, methods, &scene->methods)) &&
		   ReadBodies(parser, Find(root, "bodies"), "bodies", scene) &&
		   ReadJoints(parser, Find(root, "joints"), "joints", scene) &&
		   ReadChains(parser, Find(root, "chains"), scene) && ReadTemplates(parser, Find(root, "templates"), scene) &&
		   ReadSpawners(parser, Find(root, "spawners"), scene) && CheckBuilds(parser, scene) &&
		   CheckTemplatesBuild(parser, scene);
}

// Line and column (from 1) of a position in text, for syntax errors.
static void LineAndColumn(const char* text, const char* position, int* line, int* column)
{
	*line = 1;
	*column = 1;
	for (const char* c = text; *c != '\0' && c < position; ++c)
	{
		*column = *c == '\n' ? 1 : *column + 1;
		*line += *c == '\n' ? 1 : 0;
	}
}

/// How deeply arrays and objects are open at `at` (brackets inside strings not counted).
static int NestingDepth(const char* text, const char* at)
{
	int depth = 0;
	bool inString = false;
	for (const char* c = text; c < at && *c != '\0'; ++c)
	{
		if (inString)
		{
			if (*c == '\\' && c[1] != '\0')
			{
				c += 1; // the escaped character, whatever it is
				continue;
			}
			inString = *c != '"';
			continue;
		}
		inString = *c == '"';
		depth += *c == '[' || *c == '{' ? 1 : 0;
		depth -= *c == ']' || *c == '}' ? 1 : 0;
	}
	return depth;
}

Scene* SceneFile_Parse(const char* text, char* error, int errorSize)
{
	Parser parser = {.error = error, .errorSize = errorSize};
	if (text == NULL)
	{
		Fail(&parser, "", "no scene text");
		return NULL;
	}
	const char* end = NULL;
	cJSON* root = cJSON_ParseWithOpts(text, &end, true);
	if (root == NULL)
	{
		int line = 0, column = 0;
		LineAndColumn(text, end != NULL ? end : text, &line, &column);
		int depth = NestingDepth(text, end != NULL ? end : text);
		if (depth >= CJSON_NESTING_LIMIT)
		{
			Fail(&parser, "", "line %d, column %d: arrays and objects nested more than %d deep, the parser's limit (a "
							  "scene needs fewer than 10 levels)",
				 line, column, CJSON_NESTING_LIMIT);
			return NULL;
		}
		Fail(&parser, "", "line %d, column %d: invalid JSON", line, column);
		return NULL;
	}
	Scene* scene = Scene_Create();
	if (scene == NULL || ReadScene(&parser, root, scene) == false)
	{
		Scene_Destroy(scene);
		scene = NULL;
	}
	cJSON_Delete(root);
	return scene;
}

static char* ReadWholeFile(const char* path, char* error, int errorSize)
{
	FILE* file = fopen(path, "rb");
	if (file == NULL)
	{
		snprintf(error, (size_t)errorSize, "%s: cannot open (%s)", path, strerror(errno));
		return NULL;
	}
	size_t capacity = 1 << 16, size = 0;
	char* text = malloc(capacity);
	while (text != NULL)
	{
		size += fread(text + size, 1, capacity - size - 1, file);
		if (size < capacity - 1)
		{
			break;
		}
		capacity *= 2;
		char* grown = realloc(text, capacity);
		if (grown == NULL)
		{
			free(text);
		}
		text = grown;
	}
	bool failed = ferror(file) != 0 || text == NULL;
	fclose(file);
	if (failed)
	{
		free(text);
		snprintf(error, (size_t)errorSize, "%s: cannot read", path);
		return NULL;
	}
	text[size] = '\0';
	return text;
}

Scene* SceneFile_Load(const char* path, char* error, int errorSize)
{
	char* text = ReadWholeFile(path, error, errorSize);
	if (text == NULL)
	{
		return NULL;
	}
	char message[512];
	Scene* scene = SceneFile_Parse(text, message, (int)sizeof(message));
	free(text);
	if (scene == NULL)
	{
		snprintf(error, (size_t)errorSize, "%s: %s", path, message);
	}
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Writer

typedef struct TextBuffer
{
	char* data;
	size_t size;
	size_t capacity;
	bool failed;
	char item[64];	   ///< the body or shape being written, for messages
	char error[160];   ///< why the export failed
} TextBuffer;

// Every number is written by a %.9g conversion. A non-finite one would come out as inf or nan,
// which JSON cannot spell and which would not reload: refuse the export and name the item.
static bool WroteNonFinite(const char* format, const char* text)
{
	return strstr(format, "%.9g") != NULL && (strstr(text, "inf") != NULL || strstr(text, "nan") != NULL);
}

static void Append(TextBuffer* buffer, const char* format, ...)
{
	if (buffer->failed)
	{
		return;
	}
	va_list args;
	va_start(args, format);
	int length = vsnprintf(NULL, 0, format, args);
	va_end(args);
	if (buffer->size + (size_t)length + 1 > buffer->capacity)
	{
		size_t capacity = buffer->capacity < 4096 ? 4096 : buffer->capacity;
		while (buffer->size + (size_t)length + 1 > capacity)
		{
			capacity *= 2;
		}
		char* grown = realloc(buffer->data, capacity);
		if (grown == NULL)
		{
			buffer->failed = true;
			return;
		}
		buffer->data = grown;
		buffer->capacity = capacity;
	}
	va_start(args, format);
	vsnprintf(buffer->data + buffer->size, (size_t)length + 1, format, args);
	va_end(args);
	if (WroteNonFinite(format, buffer->data + buffer->size))
	{
		snprintf(buffer->error, sizeof(buffer->error), "%s: a number is not finite (%s); JSON cannot hold it",
				 buffer->item[0] != '\0' ? buffer->item : "scene", buffer->data + buffer->size);
		buffer->failed = true;
		return;
	}
	buffer->size += (size_t)length;
}

static void AppendFloat(TextBuffer* buffer, float value)
{
	Append(buffer, "%.9g", (double)value);
}

static void AppendVec2(TextBuffer* buffer, tbVec2 v)
{
	Append(buffer, "[%.9g, %.9g]", (double)v.x, (double)v.y);
}

// JSON string with the escapes the format needs (quotes, backslash, control characters).
static void AppendString(TextBuffer* buffer, const char* text)
{
	Append(buffer, "\"");
	for (const unsigned char* c = (const unsigned char*)text; *c != '\0'; ++c)
	{
		if (*c == '"' || *c == '\\')
		{
			Append(buffer, "\\%c", *c);
		}
		else if (*c < 0x20)
		{
			Append(buffer, "\\u%04x", *c);
		}
		else
		{
			Append(buffer, "%c", *c);
		}
	}
	Append(buffer, "\"");
}

typedef struct BoxForm
{
	float halfWidth, halfHeight, angle;
	tbVec2 center;
} BoxForm;

// A polygon that tbMakeBox / tbMakeOffsetBox would rebuild (to 1e-6) is written in box form:
// shorter, and it keeps boxes thinner than the hull tolerance (cards) loadable.
static bool AsBox(const tbPolygon* polygon, BoxForm* box)
{
	if (polygon->count != 4 || polygon->radius != 0.0f)
	{
		return false;
	}
	const tbVec2* v = polygon->vertices;
	tbVec2 edge = tbSub(v[1], v[0]);
	box->halfWidth = 0.5f * tbLength(edge);
	box->halfHeight = 0.5f * tbDistance(v[2], v[1]);
	box->angle = atan2f(edge.y, edge.x);
	box->center = tbMulSV(0.5f, tbAdd(v[0], v[2]));
	if (box->halfWidth <= 0.0f || box->halfHeight <= 0.0f)
	{
		return false;
	}
	tbGeometry rebuilt = Scene_MakeBoxGeometry(box->halfWidth, box->halfHeight, box->center, box->angle);
	float tolerance = 1e-6f * (1.0f + tbLength(box->center) + box->halfWidth + box->halfHeight);
	for (int i = 0; i < 4; ++i)
	{
		if (tbDistance(rebuilt.polygon.vertices[i], v[i]) > tolerance)
		{
			return false;
		}
	}
	return true;
}

static void AppendBox(TextBuffer* buffer, const BoxForm* box)
{
	Append(buffer, "\"box\": {\"half_width\": %.9g, \"half_height\": %.9g", (double)box->halfWidth,
		   (double)box->halfHeight);
	if (box->center.x != 0.0f || box->center.y != 0.0f)
	{
		Append(buffer, ", \"center\": ");
		AppendVec2(buffer, box->center);
	}
	if (box->angle != 0.0f)
	{
		Append(buffer, ", \"angle\": %.9g", (double)box->angle);
	}
	Append(buffer, "}");
}

static void AppendPolygon(TextBuffer* buffer, const tbPolygon* polygon)
{
	BoxForm box;
	if (AsBox(polygon, &box))
	{
		AppendBox(buffer, &box);
		return;
	}
	Append(buffer, "\"polygon\": {\"vertices\": [");
	for (int i = 0; i < polygon->count; ++i)
	{
		Append(buffer, i > 0 ? ", " : "");
		AppendVec2(buffer, polygon->vertices[i]);
	}
	Append(buffer, "], \"radius\": %.9g}", (double)polygon->radius);
}

static void AppendGeometry(TextBuffer* buffer, const tbGeometry* geometry)
{
	switch (geometry->type)
	{
		case tb_circleShape:
			Append(buffer, "\"circle\": {\"center\": ");
			AppendVec2(buffer, geometry->circle.center);
			Append(buffer, ", \"radius\": %.9g}", (double)geometry->circle.radius);
			break;
		case tb_capsuleShape:
			Append(buffer, "\"capsule\": {\"center1\": ");
			AppendVec2(buffer, geometry->capsule.center1);
			Append(buffer, ", \"center2\": ");
			AppendVec2(buffer, geometry->capsule.center2);
			Append(buffer, ", \"radius\": %.9g}", (double)geometry->capsule.radius);
			break;
		case tb_segmentShape:
			Append(buffer, "\"segment\": {\"point1\": ");
			AppendVec2(buffer, geometry->segment.point1);
			Append(buffer, ", \"point2\": ");
			AppendVec2(buffer, geometry->segment.point2);
			Append(buffer, "}");
			break;
		default:
			AppendPolygon(buffer, &geometry->polygon);
			break;
	}
}

static void AppendShape(TextBuffer* buffer, const SceneShape* shape)
{
	Append(buffer, "{");
	AppendGeometry(buffer, &shape->geometry);
	Append(buffer, ", \"density\": %.9g, \"friction\": %.9g", (double)shape->density, (double)shape->friction);
	if (shape->restitution != 0.0f)
	{
		Append(buffer, ", \"restitution\": %.9g", (double)shape->restitution);
	}
	if (shape->isSensor)
	{
		Append(buffer, ", \"sensor\": true");
	}
	if (shape->enableHitEvents)
	{
		Append(buffer, ", \"hit_events\": true");
	}
	if (shape->groupIndex != 0)
	{
		Append(buffer, ", \"group\": %d", shape->groupIndex);
	}
	if (shape->categoryBits != TB_DEFAULT_CATEGORY_BITS)
	{
		Append(buffer, ", \"category_bits\": \"0x%llx\"", (unsigned long long)shape->categoryBits);
	}
	if (shape->maskBits != TB_DEFAULT_MASK_BITS)
	{
		Append(buffer, ", \"mask_bits\": \"0x%llx\"", (unsigned long long)shape->maskBits);
	}
	Append(buffer, "}");
}

// Optional body fields: written only when they differ from the defaults.
static void AppendBodyExtras(TextBuffer* buffer, const SceneBody* body)
{
	if (body->linearVelocity.x != 0.0f || body->linearVelocity.y != 0.0f)
	{
		Append(buffer, ", \"linear_velocity\": ");
		AppendVec2(buffer, body->linearVelocity);
	}
	if (body->angularVelocity != 0.0f)
	{
		Append(buffer, ", \"angular_velocity\": %.9g", (double)body->angularVelocity);
	}
	if (body->linearDamping != 0.0f)
	{
		Append(buffer, ", \"linear_damping\": %.9g", (double)body->linearDamping);
	}
	if (body->angularDamping != 0.0f)
	{
		Append(buffer, ", \"angular_damping\": %.9g", (double)body->angularDamping);
	}
	if (body->gravityScale != 1.0f)
	{
		Append(buffer, ", \"gravity_scale\": %.9g", (double)body->gravityScale);
	}
	if (body->sleepThreshold != TB_LINEAR_SLEEP_TOLERANCE)
	{
		Append(buffer, ", \"sleep_threshold\": %.9g", (double)body->sleepThreshold);
	}
	if (body->bullet)
	{
		Append(buffer, ", \"bullet\": true");
	}
	if (body->fixedRotation)
	{
		Append(buffer, ", \"fixed_rotation\": true");
	}
	if (body->isAwake == false)
	{
		Append(buffer, ", \"awake\": false");
	}
	if (body->drive.enabled)
	{
		Append(buffer, ", \"drive\": {\"amplitude\": ");
		AppendVec2(buffer, body->drive.amplitude);
		Append(buffer, ", \"angular_frequency\": %.9g}", (double)body->drive.angularFrequency);
	}
}

// prefix: "" for the scene's bodies, "templates[i]." for a template's (for messages).
static void AppendBody(TextBuffer* buffer, const char* prefix, const SceneBody* body, int index)
{
	snprintf(buffer->item, sizeof(buffer->item), "%sbodies[%d]", prefix, index);
	Append(buffer, "    {\"type\": \"%s\"", Scene_BodyTypeName(body->type));
	if (body->name[0] != '\0')
	{
		Append(buffer, ", \"name\": ");
		AppendString(buffer, body->name);
	}
	Append(buffer, ", \"position\": ");
	AppendVec2(buffer, body->position);
	Append(buffer, ", \"angle\": ");
	AppendFloat(buffer, body->angle);
	AppendBodyExtras(buffer, body);
	Append(buffer, ",\n      \"shapes\": [");
	for (int i = 0; i < body->shapeCount; ++i)
	{
		Append(buffer, i > 0 ? ",\n        " : "\n        ");
		snprintf(buffer->item, sizeof(buffer->item), "%sbodies[%d].shapes[%d]", prefix, index, i);
		AppendShape(buffer, body->shapes + i);
	}
	Append(buffer, body->shapeCount > 0 ? "\n      ]}" : "]}");
}

static void AppendMethod(TextBuffer* buffer, bool has, const char* key, const char* name, bool* first)
{
	if (has == false || name == NULL)
	{
		return;
	}
	Append(buffer, "%s\"%s\": \"%s\"", *first ? "" : ", ", key, name);
	*first = false;
}

static void AppendMethods(TextBuffer* buffer, const SceneMethods* methods)
{
	if (!(methods->hasBroadPhase || methods->hasNarrowPhase || methods->hasContinuous || methods->hasSolver))
	{
		return;
	}
	bool first = true;
	Append(buffer, "  \"methods\": {");
	AppendMethod(buffer, methods->hasBroadPhase, "broadphase", Scene_BroadPhaseName(methods->broadPhase), &first);
	AppendMethod(buffer, methods->hasNarrowPhase, "narrowphase", Scene_NarrowPhaseName(methods->narrowPhase), &first);
	AppendMethod(buffer, methods->hasContinuous, "toi", Scene_ContinuousName(methods->continuous), &first);
	AppendMethod(buffer, methods->hasSolver, "solver", Scene_SolverName(methods->solver), &first);
	Append(buffer, "},\n");
}

// A joint: its kind, bodies and frames, then every field that differs from the kind's default.
static void AppendChain(TextBuffer* buffer, const SceneChain* chain)
{
	Append(buffer, "    {\"body\": %d, \"loop\": %s, \"friction\": %.9g, \"restitution\": %.9g, \"points\": [", chain->body,
		   chain->isLoop ? "true" : "false", (double)chain->friction, (double)chain->restitution);
	for (int i = 0; i < chain->count; ++i)
	{
		Append(buffer, i > 0 ? ", " : "");
		AppendVec2(buffer, chain->points[i]);
	}
	Append(buffer, "]}");
}

static void AppendJoint(TextBuffer* buffer, const SceneJoint* joint)
{
	SceneJoint defaults;
	Scene_DefaultJointDef(joint->type, &defaults);
	const tbJointDef* base = &joint->def.base;
	Append(buffer, "    {\"type\": \"%s\", \"body_a\": %d, \"body_b\": %d", Scene_JointTypeName(joint->type),
		   joint->bodyA, joint->bodyB);
	Append(buffer, ", \"anchor_a\": ");
	AppendVec2(buffer, base->localFrameA.p);
	Append(buffer, ", \"anchor_b\": ");
	AppendVec2(buffer, base->localFrameB.p);
	float angleA = tbRot_GetAngle(base->localFrameA.q);
	float angleB = tbRot_GetAngle(base->localFrameB.q);
	if (angleA != 0.0f)
	{
		Append(buffer, ", \"angle_a\": %.9g", (double)angleA);
	}
	if (angleB != 0.0f)
	{
		Append(buffer, ", \"angle_b\": %.9g", (double)angleB);
	}
	if (base->collideConnected)
	{
		Append(buffer, ", \"collide_connected\": true");
	}
	if (base->constraintHertz != defaults.def.base.constraintHertz)
	{
		Append(buffer, ", \"constraint_hertz\": %.9g", (double)base->constraintHertz);
	}
	if (base->constraintDampingRatio != defaults.def.base.constraintDampingRatio)
	{
		Append(buffer, ", \"constraint_damping_ratio\": %.9g", (double)base->constraintDampingRatio);
	}
	const JointField* fields = s_jointFields[joint->type];
	for (int i = 0; fields[i].key != NULL; ++i)
	{
		const char* value = (const char*)&joint->def + fields[i].offset;
		const char* standard = (const char*)&defaults.def + fields[i].offset;
		bool isVec2 = fields[i].kind == FIELD_VEC2 || fields[i].kind == FIELD_NON_NEGATIVE_VEC2;
		size_t size = fields[i].kind == FIELD_BOOL ? sizeof(bool) : (isVec2 ? sizeof(tbVec2) : sizeof(float));
		if (memcmp(value, standard, size) == 0)
		{
			continue;
		}
		Append(buffer, ", \"%s\": ", fields[i].key);
		if (fields[i].kind == FIELD_BOOL)
		{
			Append(buffer, *(const bool*)value ? "true" : "false");
		}
		else if (isVec2)
		{
			AppendVec2(buffer, *(const tbVec2*)value);
		}
		else
		{
			AppendFloat(buffer, *(const float*)value);
		}
	}
	Append(buffer, "}");
}

// `"bodies": […]` is already open; writes the bodies, then `, "joints": […]` when there are any.
static void AppendBodiesAndJoints(TextBuffer* buffer, const char* prefix, const Scene* scene)
{
	Append(buffer, "[");
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		Append(buffer, i > 0 ? ",\n" : "\n");
		AppendBody(buffer, prefix, scene->bodies + i, i);
	}
	Append(buffer, scene->bodyCount > 0 ? "\n  ]" : "]");
	if (scene->jointCount > 0)
	{
		Append(buffer, ",\n  \"joints\": [");
		for (int i = 0; i < scene->jointCount; ++i)
		{
			Append(buffer, i > 0 ? ",\n" : "\n");
			AppendJoint(buffer, scene->joints + i);
		}
		Append(buffer, "\n  ]");
	}
}

static void AppendTemplates(TextBuffer* buffer, const Scene* scene)
{
	if (scene->templateCount == 0)
	{
		return;
	}
	Append(buffer, ",\n  \"templates\": [");
	for (int i = 0; i < scene->templateCount; ++i)
	{
		char prefix[32];
		snprintf(prefix, sizeof(prefix), "templates[%d].", i);
		Append(buffer, i > 0 ? ",\n  {\"name\": " : "\n  {\"name\": ");
		AppendString(buffer, scene->templates[i].name);
		Append(buffer, ",\n  \"bodies\": ");
		AppendBodiesAndJoints(buffer, prefix, scene->templates[i].parts);
		Append(buffer, "}");
	}
	Append(buffer, "\n  ]");
}

static void AppendSpawners(TextBuffer* buffer, const Scene* scene)
{
	if (scene->spawnerCount == 0)
	{
		return;
	}
	Append(buffer, ",\n  \"spawners\": [");
	for (int i = 0; i < scene->spawnerCount; ++i)
	{
		const SceneSpawner* spawner = scene->spawners + i;
		snprintf(buffer->item, sizeof(buffer->item), "spawners[%d]", i);
		Append(buffer, i > 0 ? ",\n    {\"template\": " : "\n    {\"template\": ");
		AppendString(buffer, scene->templates[spawner->templateIndex].name);
		Append(buffer, ", \"first_step\": %d, \"interval\": %d, \"count\": %d, \"keep\": %d, \"lifetime\": %d",
			   spawner->firstStep, spawner->interval, spawner->count, spawner->keep, spawner->lifetime);
		Append(buffer, ", \"slots\": %d", spawner->slotCount);
		Append(buffer, ", \"origin\": ");
		AppendVec2(buffer, spawner->origin);
		Append(buffer, ", \"slot_step\": ");
		AppendVec2(buffer, spawner->slotStep);
		Append(buffer, "}");
	}
	Append(buffer, "\n  ]");
}

char* SceneFile_Export(const Scene* scene, char* error, int errorSize)
{
	TextBuffer buffer;
	memset(&buffer, 0, sizeof(buffer));
	snprintf(buffer.error, sizeof(buffer.error), "out of memory");
	Append(&buffer, "{\n  \"gravity\": ");
	AppendVec2(&buffer, scene->gravity);
	Append(&buffer, ",\n  \"time_step\": %.9g,\n  \"sub_steps\": %d,\n  \"steps\": %d,\n  \"enable_sleep\": %s,\n",
		   (double)scene->timeStep, scene->subSteps, scene->steps, scene->enableSleep ? "true" : "false");
	AppendMethods(&buffer, &scene->methods);
	Append(&buffer, "  \"bodies\": ");
	AppendBodiesAndJoints(&buffer, "", scene);
	if (scene->chainCount > 0)
	{
		Append(&buffer, ",\n  \"chains\": [");
		for (int i = 0; i < scene->chainCount; ++i)
		{
			Append(&buffer, i > 0 ? ",\n" : "\n");
			AppendChain(&buffer, scene->chains + i);
		}
		Append(&buffer, "\n  ]");
	}
	AppendTemplates(&buffer, scene);
	AppendSpawners(&buffer, scene);
	Append(&buffer, "\n}\n");
	if (buffer.failed)
	{
		snprintf(error, (size_t)errorSize, "%s", buffer.error);
		free(buffer.data);
		return NULL;
	}
	return buffer.data;
}

bool SceneFile_Save(const Scene* scene, const char* path, char* error, int errorSize)
{
	char* text = SceneFile_Export(scene, error, errorSize);
	FILE* file = text != NULL ? fopen(path, "wb") : NULL;
	bool ok = file != NULL && fwrite(text, 1, strlen(text), file) == strlen(text);
	if (file != NULL)
	{
		ok = (fclose(file) == 0) && ok;
	}
	if (text != NULL && ok == false)
	{
		snprintf(error, (size_t)errorSize, "%s: cannot write the file", path);
	}
	free(text);
	return ok;
}
