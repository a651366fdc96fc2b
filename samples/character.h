// A platformer character on Tumble's mover kit (Box2D v3.2's grammar): a capsule moved by the game,
// not by forces. Each frame it gathers the planes it touches (tbWorld_CollideMover), finds the
// motion toward its target they allow (tbSolvePlanes), sweeps it (tbWorld_CastMover) and clips
// its velocity (tbClipVector). Its capsule is also a kinematic body driven to the character's
// pose (tbBody_SetTargetTransform), so it pushes the dynamic bodies it walks into and is drawn
// with the world; the character's own queries leave that body out (CHARACTER_CATEGORY).
#pragma once

#include "tumble/tumble.h"

/// Category bit of the character's body; its queries do not see it.
#define CHARACTER_CATEGORY 0x8000000000000000ull

typedef struct Character
{
	tbBodyId body;	  ///< kinematic capsule following the character
	tbCapsule capsule; ///< relative to the feet point
	tbVec2 position;  ///< feet point (bottom of the capsule), world
	tbVec2 velocity;  ///< m/s
	bool onGround;	  ///< a walkable plane (normal within 45° of up) touched this frame
	float gravity;	  ///< m/s², downward
	float jumpSpeed;  ///< m/s, upward, given when jumping from the ground
	int planeCount;	  ///< planes touched this frame (diagnostics)
} Character;

/// A character of capsule radius `radius` and total height `height`, feet at `feet`.
Character Character_Create(tbWorldId world, tbVec2 feet, float radius, float height);

/// One frame: walk at moveSpeed (m/s, signed), jump when asked and on the ground, fall otherwise.
/// Call before the world steps; the body reaches the new pose during that step.
void Character_Step(Character* character, tbWorldId world, float moveSpeed, bool jump, float dt);
