// Scene files: JSON text ↔ Scene. The format is documented in docs/scene-format.md.
// Parsing validates everything and reports the first problem as one line naming the field
// path, e.g. "bodies[3].shapes[0].circle.radius: must be > 0". Unknown keys are errors.
#pragma once

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Parse scene text. Returns NULL and writes a one-line message into error on failure, also when
/// the library refuses a body or shape of the scene (the message names it, e.g. bodies[2].shapes[0]).
Scene* SceneFile_Parse(const char* text, char* error, int errorSize);

/// Read and parse a file. Returns NULL and writes a one-line message into error on failure.
Scene* SceneFile_Load(const char* path, char* error, int errorSize);

/// Bounds on what a scene file may ask for, so that an untrusted file cannot exhaust memory or
/// run for days: bodies and shapes in a scene, and the default number of steps of a run.
/// (sub_steps and time_step are bounded by the library's TB_MAX_SUB_STEPS, TB_MIN_TIME_STEP and
/// TB_MAX_TIME_STEP.)
#define SCENE_MAX_BODIES 100000
#define SCENE_MAX_CHAIN_POINTS 100000 ///< points in one chain of a scene file
#define SCENE_MAX_SHAPES 100000
#define SCENE_MAX_STEPS 1000000

/// Scene as JSON text (floats with %.9g, so floats survive the round trip exactly). Free with
/// free(). NULL with a one-line message naming the body or shape when a number is not finite
/// (JSON has no infinity or NaN), or when memory runs out.
char* SceneFile_Export(const Scene* scene, char* error, int errorSize);

/// Write the export to a file. False with a message on a non-finite number or an I/O error.
bool SceneFile_Save(const Scene* scene, const char* path, char* error, int errorSize);

#ifdef __cplusplus
}
#endif
