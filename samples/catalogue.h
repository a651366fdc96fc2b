// The scene catalogue: named scene builders shared by tests, samples and benchmarks, so what is
// drawn is what is tested and what is timed. Each scene carries a suggested step count.
#pragma once

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Number of scenes.
int Catalogue_Count(void);

/// Name of scene index (0 ≤ index < Catalogue_Count()), NULL when out of range.
const char* Catalogue_Name(int index);

/// One-line description of scene index, NULL when out of range.
const char* Catalogue_Description(int index);

/// Index of a named scene, −1 if unknown.
int Catalogue_Find(const char* name);

/// Build a named scene (free with Scene_Destroy). NULL if the name is unknown.
Scene* Catalogue_Build(const char* name);

#ifdef __cplusplus
}
#endif
