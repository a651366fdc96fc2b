// scripts/ab-race.sh's program: two builds of Tumble (A and B, runner.c linked with each) step the
// same scene side by side in one process, step by step, each step timed alone and the order
// alternated, so that both meet the same machine: on a shared machine whose speed wanders by tens
// of per cent from minute to minute, the ratio of two builds' steps taken this way is steady to
// about 1–2 % (a build against itself gives 0.98–1.02). Prints the medians and B/A three ways, and
// whether the two worlds end in the same state.
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

void* A_create(const char* name, int workers);
void A_step(void* run);
unsigned long long A_hash(void* run);
void A_destroy(void* run);
void* B_create(const char* name, int workers);
void B_step(void* run);
unsigned long long B_hash(void* run);
void B_destroy(void* run);

static double NowMs(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int CompareDoubles(const void* a, const void* b)
{
	double x = *(const double*)a, y = *(const double*)b;
	return x < y ? -1 : (x > y ? 1 : 0);
}

static double Median(double* values, int count)
{
	qsort(values, (size_t)count, sizeof(double), CompareDoubles);
	return values[count / 2];
}

int main(int argc, char** argv)
{
	if (argc < 4)
	{
		fprintf(stderr, "usage: %s STEPS WORKERS SCENE...\n", argv[0]);
		return 2;
	}
	int steps = atoi(argv[1]);
	int workers = atoi(argv[2]);
	if (steps < 1 || workers < 1)
	{
		fprintf(stderr, "ab-race: STEPS and WORKERS must be at least 1\n");
		return 2;
	}
	double* timeA = malloc(sizeof(double) * (size_t)steps);
	double* timeB = malloc(sizeof(double) * (size_t)steps);
	double* ratio = malloc(sizeof(double) * (size_t)steps);
	for (int i = 3; i < argc; ++i)
	{
		void* a = A_create(argv[i], workers);
		void* b = B_create(argv[i], workers);
		if (a == NULL || b == NULL)
		{
			fprintf(stderr, "ab-race: no scene named %s\n", argv[i]);
			return 2;
		}
		double sumA = 0.0, sumB = 0.0;
		for (int s = 0; s < steps; ++s)
		{
			double t0 = NowMs();
			if (s % 2 == 0)
			{
				A_step(a);
				double t1 = NowMs();
				B_step(b);
				timeA[s] = t1 - t0;
				timeB[s] = NowMs() - t1;
			}
			else
			{
				B_step(b);
				double t1 = NowMs();
				A_step(a);
				timeB[s] = t1 - t0;
				timeA[s] = NowMs() - t1;
			}
			sumA += timeA[s];
			sumB += timeB[s];
			ratio[s] = timeB[s] / timeA[s];
		}
		const char* same = A_hash(a) == B_hash(b) ? "same state" : "DIFFERENT state";
		double medianRatio = Median(ratio, steps);
		double medianA = Median(timeA, steps), medianB = Median(timeB, steps);
		printf("%-16s %d worker(s) %d steps: A %.3f ms, B %.3f ms (medians); B/A median of step ratios %.4f, "
			   "of medians %.4f, of sums %.4f; %s\n",
			   argv[i], workers, steps, medianA, medianB, medianRatio, medianB / medianA, sumB / sumA, same);
		fflush(stdout);
		A_destroy(a);
		B_destroy(b);
	}
	free(timeA);
	free(timeB);
	free(ratio);
	return 0;
}
