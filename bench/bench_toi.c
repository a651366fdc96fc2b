// Cost of a time-of-impact query: the closed form for circles (toi_quadratic.c) against
// conservative advancement (toi_conservative.c) on the same circle pairs, then conservative
// advancement on a thin box (4 × 0.1 m) sweeping into a wall (0.1 m thick) at 100 m/s for one
// 1/60 s step as its spin grows from 0 to 100 rad/s. Prints a table and CSV lines.
#include "tumble/collision.h"

#include <stdint.h>
#include <stdio.h>

#define PAIR_COUNT 4096
#define REPEATS 50
#define LAUNCH_COUNT 2000

// Numerical Recipes LCG (Press et al., §7.1), seeded, so every run times the same queries.
static uint32_t lcgNext(uint32_t* state)
{
	*state = *state * 1664525u + 1013904223u;
	return *state;
}

static float lcgRange(uint32_t* state, float lower, float upper)
{
	return lower + (upper - lower) * (float)(lcgNext(state) >> 8) / 16777216.0f;
}

static tbSweep makeSweep(tbVec2 c1, tbVec2 c2, float angle1, float angle2)
{
	tbSweep sweep = {{0.0f, 0.0f}, c1, c2, tbMakeRot(angle1), tbMakeRot(angle2)};
	return sweep;
}

static tbShapeProxy boxProxy(float halfWidth, float halfHeight)
{
	tbVec2 points[4] = {{-halfWidth, -halfHeight}, {halfWidth, -halfHeight}, {halfWidth, halfHeight},
						{-halfWidth, halfHeight}};
	return tbMakeProxy(points, 4, 0.0f);
}

typedef struct CircleCase
{
	tbCircle circleA, circleB;
	tbTOIInput input;
} CircleCase;

static CircleCase s_circles[PAIR_COUNT];
static volatile float s_sink;

static void makeCircleCases(void)
{
	uint32_t seed = 7u;
	for (int i = 0; i < PAIR_COUNT; ++i)
	{
		CircleCase* c = s_circles + i;
		c->circleA = (tbCircle){{0.0f, 0.0f}, lcgRange(&seed, 0.05f, 1.0f)};
		c->circleB = (tbCircle){{0.0f, 0.0f}, lcgRange(&seed, 0.05f, 1.0f)};
		tbVec2 startB = {lcgRange(&seed, -3.0f, 3.0f), lcgRange(&seed, -3.0f, 3.0f)};
		tbVec2 moveB = tbAdd(tbMulSV(-1.5f, startB), tbMakeVec2(lcgRange(&seed, -1.0f, 1.0f), lcgRange(&seed, -1.0f, 1.0f)));
		c->input.proxyA = tbMakeProxy(&c->circleA.center, 1, c->circleA.radius);
		c->input.proxyB = tbMakeProxy(&c->circleB.center, 1, c->circleB.radius);
		c->input.sweepA = makeSweep(tbVec2_zero, tbVec2_zero, 0.0f, 0.0f);
		c->input.sweepB = makeSweep(startB, tbAdd(startB, moveB), 0.0f, 0.0f);
		c->input.maxFraction = 1.0f;
	}
}

static double timeQuadratic(void)
{
	uint64_t ticks = tbGetTicks();
	for (int r = 0; r < REPEATS; ++r)
	{
		for (int i = 0; i < PAIR_COUNT; ++i)
		{
			const CircleCase* c = s_circles + i;
			s_sink = tbTimeOfImpactCircles(&c->circleA, &c->input.sweepA, &c->circleB, &c->input.sweepB, 1.0f,
										   TB_TOI_TARGET_SEPARATION)
						 .fraction;
		}
	}
	return 1.0e6 * tbGetMilliseconds(ticks) / (double)(REPEATS * PAIR_COUNT);
}

static double timeConservative(const tbTOIInput* inputs, int stride, int count, int repeats, int* iterationMax,
							   double* iterationMean)
{
	long iterationSum = 0;
	*iterationMax = 0;
	uint64_t ticks = tbGetTicks();
	for (int r = 0; r < repeats; ++r)
	{
		for (int i = 0; i < count; ++i)
		{
			const tbTOIInput* input = (const tbTOIInput*)((const char*)inputs + (size_t)i * (size_t)stride);
			tbTOIOutput output = tbTimeOfImpact(input);
			s_sink = output.fraction;
			iterationSum += output.iterations;
			*iterationMax = output.iterations > *iterationMax ? output.iterations : *iterationMax;
		}
	}
	double ns = 1.0e6 * tbGetMilliseconds(ticks) / (double)(repeats * count);
	*iterationMean = (double)iterationSum / (double)(repeats * count);
	return ns;
}

// Thin box launched at the wall within ±30° of its normal, spin of fixed size and random sign.
static tbTOIInput spinningLaunch(uint32_t* seed, float omega)
{
	tbTOIInput input;
	input.proxyA = boxProxy(0.05f, 10.0f);
	input.proxyB = boxProxy(2.0f, 0.05f);
	input.sweepA = makeSweep(tbVec2_zero, tbVec2_zero, 0.0f, 0.0f);
	input.maxFraction = 1.0f;
	float heading = lcgRange(seed, -0.5236f, 0.5236f);
	float spin = (lcgNext(seed) & 1u) ? omega : -omega;
	float angle = lcgRange(seed, -3.1416f, 3.1416f);
	// Start 2.1 m from the wall face so that no orientation overlaps; 100 m/s × 1/60 s = 1.67 m,
	// so some launches reach the wall within the step and some do not.
	tbVec2 start = {lcgRange(seed, -2.6f, -2.1f), lcgRange(seed, -2.0f, 2.0f)};
	tbVec2 travel = tbMulSV(100.0f / 60.0f, tbMakeVec2(cosf(heading), sinf(heading)));
	input.sweepB = makeSweep(start, tbAdd(start, travel), angle, angle + spin / 60.0f);
	return input;
}

int main(void)
{
	makeCircleCases();
	int iterationMax;
	double iterationMean;
	double quadraticNs = timeQuadratic();
	double conservativeNs =
		timeConservative(&s_circles[0].input, (int)sizeof(CircleCase), PAIR_COUNT, REPEATS, &iterationMax, &iterationMean);
	printf("circle pairs (%d pairs x %d repeats)\n", PAIR_COUNT, REPEATS);
	printf("  quadratic               %8.1f ns/query\n", quadraticNs);
	printf("  conservative advance    %8.1f ns/query  (iterations mean %.2f, max %d)\n", conservativeNs, iterationMean,
		   iterationMax);
	printf("csv,method,ns_per_query\ncsv,quadratic,%.1f\ncsv,conservative,%.1f\n\n", quadraticNs, conservativeNs);

	static tbTOIInput launches[LAUNCH_COUNT];
	printf("thin box 4 x 0.1 m at 100 m/s into a 0.1 m wall, %d launches per row\n", LAUNCH_COUNT);
	printf("  omega(rad/s)  iterations_mean  iterations_max  ns_per_query\n");
	char csv[11][96];
	for (int row = 0; row <= 10; ++row)
	{
		float omega = 10.0f * (float)row;
		uint32_t seed = 99u;
		for (int i = 0; i < LAUNCH_COUNT; ++i)
		{
			launches[i] = spinningLaunch(&seed, omega);
		}
		double ns = timeConservative(launches, (int)sizeof(tbTOIInput), LAUNCH_COUNT, 10, &iterationMax, &iterationMean);
		printf("  %12.0f  %15.2f  %14d  %12.1f\n", (double)omega, iterationMean, iterationMax, ns);
		snprintf(csv[row], sizeof(csv[row]), "%.0f,%.2f,%d,%.1f", (double)omega, iterationMean, iterationMax, ns);
	}
	printf("\nomega,iterations_mean,iterations_max,ns_per_query\n");
	for (int row = 0; row <= 10; ++row)
	{
		printf("%s\n", csv[row]);
	}
	return 0;
}
