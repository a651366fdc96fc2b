// Scene files: JSON text ↔ Scene. The format is documented in docs/scene-format.md.
// Parsing validates everything and reports the first problem as one line naming the field
// path, e.g. "bodies[3].shapes[0].circle.radius: must be > 0". Unknown keys are errors.
#pragma once

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Parse scene text. Returns NULL and writes a one-line message into error on failure.
Scene* SceneFile_Parse(const char* text, char* error, int errorSize);

/// Read and parse a file. Returns NULL and writes a one-line message into error on failure.
Scene* SceneFile_Load(const char* path, char* error, int errorSize);

/// Scene as JSON text (floats with %.9g, so floats survive the round trip exactly). Free with free().
char* SceneFile_Export(const Scene* scene);

/// Write the export to a file. False on an I/O error.
bool SceneFile_Save(const Scene* scene, const char* path);

#ifdef __cplusplus
}
#endif
