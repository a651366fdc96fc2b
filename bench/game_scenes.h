// Game-scale scenes for tumble-bench-games, as seen by the timing program (bench_games.c).
//
// The scenes are written once, in bench/game_scenes.c, against the Box2D v3.2 API through a prefix
// macro (P(CreateWorld) is tbCreateWorld or b2CreateWorld), and that file is compiled twice: once
// against Tumble (GAME_TUMBLE) and once against Box2D v3.2 (GAME_BOX2D3). Each compilation exports
// one GameEngine: the same table of scenes, in the same order, built and stepped by its engine.
// This header names no engine type, so the timing program sees both engines the same way.
#pragma once

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct Game Game;

/// What the timing program hands every scene.
typedef struct GameOptions
{
	int param;		  ///< the scene's size (bodies, worlds), from the scene table or the size sweep
	void* taskSystem; ///< the reference task system (samples/task_system.c) of 2 workers, for the scenes with workers
} GameOptions;

/// A comparable end state, read the same way from both engines.
typedef struct GameStats
{
	int bodies;		///< bodies the scene made (and did not destroy)
	int awake;		///< awake bodies (World_GetAwakeBodyCount, summed over worlds)
	int touching;	///< touching contacts: Body_GetContactData over every body, pairs counted once
	int joints;		///< joints alive
	int64_t events; ///< events the scene read during the timed steps (begin-touch or hit events)
	double x, y;	///< the tracked body (ball, car, character, projectile; NaN when none)
	int contacts;	///< contacts the last step's collide stage updated (Counters.awakeContactCount)
	int recycled;	///< of those, manifolds recycled instead of recomputed (Counters.recycledContactCount)
	float fastest;	///< the largest |v| + |ω|·(1 m) of an awake body, m/s (what keeps a pile from sleeping)
	int fastestBody; ///< which body that is, in the order the scene made them (−1: none awake)
} GameStats;

/// One scene. create builds it (settling steps, where the scene has them, run here, untimed);
/// step advances it one game frame (1/60 s, 4 sub-steps); run times `steps` frames and returns
/// the seconds they took (NULL: the timing program times step); stats reads the end state.
typedef struct GameScene
{
	const char* name;
	int param;			///< default size
	int steps;			///< default timed steps
	double tolerance;	///< metres the tracked body may differ by between engines (0: it is only checked to be finite)
	bool usesWorkers;	///< needs GameOptions::taskSystem
	Game* (*create)(const GameOptions* options);
	void (*step)(Game* game);
	double (*run)(Game* game, int steps);
	GameStats (*stats)(Game* game);
	void (*destroy)(Game* game);
} GameScene;

/// Bytes each kind of object costs an engine, from its allocator hook (live bytes before and after
/// making `count` of them, divided by `count`; arrays grow by doubling, so spare capacity counts).
typedef struct GameMemory
{
	int count;
	double body, shape, contact, joint;
	int contacts; ///< touching contacts in the contact measurement
	/// Allocator high-water marks (bytes) of Box2D v3's joint_grid and many_pyramids benchmark
	/// scenes, built and stepped 60 frames.
	int64_t jointGridPeak, manyPyramidsPeak;
} GameMemory;

typedef struct GameEngine
{
	const char* name;
	const GameScene* scenes;
	int sceneCount;
	/// The size sweep's scene: `param` mixed bodies falling into a box (awake), then settled untimed
	/// until asleep (at most `settleSteps` frames).
	const GameScene* sweep;
	/// Step a game untimed until no body is awake or maxSteps frames have passed; returns the awake count left.
	int (*settle)(Game* game, int maxSteps);
	/// Route the engine's allocations through a counting hook; call before anything is allocated.
	void (*installAllocator)(void);
	int64_t (*liveBytes)(void);
	GameMemory (*measureMemory)(int count);
} GameEngine;

/// Seconds on a monotonic clock (bench_games.c): the scenes that time themselves use it.
double GameClockSeconds(void);

/// Frames a settling loop may take before it gives up (untimed; the awake count it leaves is reported).
#define GAME_SETTLE_STEPS 900

extern const GameEngine gameEngineTumble;
extern const GameEngine gameEngineBox2D3;

#ifdef __cplusplus
}
#endif
