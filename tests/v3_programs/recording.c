// A bug report as a game files it with Box2D v3.2's recording: a level with a crate pile and a
// player body is recorded for 180 frames while the game pushes the player, drops a crate and
// destroys another; the recording is saved, loaded and checked by replay, then played frame by
// frame and seeked back. (Damaged recordings are not compared: Tumble's carry a checksum and are
// refused, where v3.2 may replay a changed byte that no step reads; tests/test_recording.c.)
#include "program.h"


#define CRATES 12

static void BuildLevel(b2WorldId world, b2BodyId* player, b2BodyId* crates)
{
	b2BodyDef groundDef = b2DefaultBodyDef();
	b2BodyId ground = b2CreateBody(world, &groundDef);
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	b2Polygon floor = b2MakeBox(20.0f, 0.5f);
	b2CreatePolygonShape(ground, &shapeDef, &floor);
	b2Polygon box = b2MakeBox(0.4f, 0.4f);
	for (int i = 0; i < CRATES; ++i)
	{
		b2BodyDef def = b2DefaultBodyDef();
		def.type = b2_dynamicBody;
		def.position = (b2Pos){2.0f + 0.9f * (float)(i % 4), 1.0f + 0.9f * (float)(i / 4)};
		crates[i] = b2CreateBody(world, &def);
		b2CreatePolygonShape(crates[i], &shapeDef, &box);
	}
	b2BodyDef playerDef = b2DefaultBodyDef();
	playerDef.type = b2_dynamicBody;
	playerDef.position = (b2Pos){-4.0f, 1.0f};
	*player = b2CreateBody(world, &playerDef);
	b2Capsule capsule = {{0.0f, -0.3f}, {0.0f, 0.3f}, 0.3f};
	b2CreateCapsuleShape(*player, &shapeDef, &capsule);
}

/// The game's frame: input first (a push each 30 frames, a crate dropped at 60 and one destroyed
/// at 90), then the step.
static void PlayFrame(b2WorldId world, int frame, b2BodyId player, b2BodyId* crates)
{
	if (frame % 30 == 0)
	{
		b2Body_SetLinearVelocity(player, (b2Vec2){4.0f, 2.0f});
	}
	if (frame == 60)
	{
		b2BodyDef def = b2DefaultBodyDef();
		def.type = b2_dynamicBody;
		def.position = (b2Pos){3.0f, 8.0f};
		b2BodyId crate = b2CreateBody(world, &def);
		b2ShapeDef shapeDef = b2DefaultShapeDef();
		b2Polygon box = b2MakeBox(0.4f, 0.4f);
		b2CreatePolygonShape(crate, &shapeDef, &box);
	}
	if (frame == 90)
	{
		b2DestroyBody(crates[5]);
	}
	b2World_Step(world, 1.0f / 60.0f, 4);
}

int main(void)
{
	b2WorldDef worldDef = b2DefaultWorldDef();
	b2WorldId world = b2CreateWorld(&worldDef);
	b2BodyId player, crates[CRATES];
	BuildLevel(world, &player, crates);
	b2Recording* recording = b2CreateRecording(1 << 20);
	b2World_StartRecording(world, recording);
	for (int frame = 0; frame < 180; ++frame)
	{
		PlayFrame(world, frame, player, crates);
	}
	b2World_StopRecording(world);
	printf("recorded: %s\n", b2Recording_GetSize(recording) > 0 ? "yes" : "no");

	const char* path = "v3_program_recording.bin";
	bool saved = b2SaveRecordingToFile(recording, path);
	b2Recording* loaded = b2LoadRecordingFromFile(path);
	printf("saved and loaded: %s\n", saved && loaded != NULL ? "yes" : "no");
	bool same = loaded != NULL && b2Recording_GetSize(loaded) == b2Recording_GetSize(recording) &&
				memcmp(b2Recording_GetData(loaded), b2Recording_GetData(recording), (size_t)b2Recording_GetSize(recording)) == 0;
	printf("the loaded bytes are the recorded ones: %s\n", same ? "yes" : "no");
	printf("the replay validates: %s\n",
		   b2ValidateReplay(b2Recording_GetData(recording), b2Recording_GetSize(recording), 0) ? "yes" : "no");

	b2RecPlayer* player2 = b2RecPlayer_Create(b2Recording_GetData(recording), b2Recording_GetSize(recording), 0);
	int frames = 0;
	while (player2 != NULL && b2RecPlayer_IsAtEnd(player2) == false && b2RecPlayer_StepFrame(player2))
	{
		frames += 1;
	}
	printf("the player plays %d frames without diverging: %s\n", frames,
		   player2 != NULL && b2RecPlayer_HasDiverged(player2) == false ? "yes" : "no");
	if (player2 != NULL)
	{
		b2RecPlayer_SeekFrame(player2, 45);
		printf("seeked back to frame %d\n", b2RecPlayer_GetFrame(player2));
		b2RecPlayer_Destroy(player2);
	}

	remove(path);
	b2DestroyRecording(loaded);
	b2DestroyRecording(recording);
	b2DestroyWorld(world);
	return 0;
}
