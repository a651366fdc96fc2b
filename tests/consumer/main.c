// A minimal game: a box falls onto the ground for one second. Built against the installed package.
#include <tumble/tumble.h>

#include <stdio.h>

int main(void)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);

	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon groundBox = tbMakeOffsetBox(50.0f, 1.0f, tbMakeVec2(0.0f, -1.0f), tbRot_identity);
	tbCreatePolygonShape(ground, &shapeDef, &groundBox);

	tbBodyDef boxDef = tbDefaultBodyDef();
	boxDef.type = tb_dynamicBody;
	boxDef.position = tbMakeVec2(0.0f, 4.0f);
	tbBodyId box = tbCreateBody(world, &boxDef);
	tbPolygon square = tbMakeSquare(0.5f);
	tbCreatePolygonShape(box, &shapeDef, &square);

	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	tbVec2 p = tbBody_GetPosition(box);
	printf("box at (%.3f, %.3f)\n", p.x, p.y);
	tbDestroyWorld(world);
	// After one second of free fall from 4 m the box is still in the air above 0.5 m.
	return (p.y < 4.0f && p.y > 0.4f) ? 0 : 1;
}
