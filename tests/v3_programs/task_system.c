// A game's own thread pool behind Box2D v3.2's task interface: enqueueTask hands the task to a
// worker thread and returns a handle, finishTask waits for it. A pyramid with a ball fired into it
// is stepped with 1, 2 and 4 workers; each engine must give the same state whatever the count.
#include "program.h"

#include <pthread.h>
#include <stdbool.h>

#define MAX_THREADS 4
#define MAX_TASKS 256

typedef struct Task
{
	b2TaskCallback* callback;
	void* context;
	bool done;
} Task;

typedef struct Pool
{
	pthread_t threads[MAX_THREADS];
	int threadCount;
	pthread_mutex_t mutex;
	pthread_cond_t wake;
	pthread_cond_t finished;
	Task tasks[MAX_TASKS];
	int head; ///< the next task a worker takes
	int tail; ///< where the next task goes
	bool quit;
} Pool;

static void* WorkerMain(void* arg)
{
	Pool* pool = arg;
	pthread_mutex_lock(&pool->mutex);
	for (;;)
	{
		while (pool->head == pool->tail && pool->quit == false)
		{
			pthread_cond_wait(&pool->wake, &pool->mutex);
		}
		if (pool->quit)
		{
			break;
		}
		Task* task = pool->tasks + pool->head % MAX_TASKS;
		pool->head += 1;
		pthread_mutex_unlock(&pool->mutex);
		task->callback(task->context);
		pthread_mutex_lock(&pool->mutex);
		task->done = true;
		pthread_cond_broadcast(&pool->finished);
	}
	pthread_mutex_unlock(&pool->mutex);
	return NULL;
}

static void* EnqueueTask(b2TaskCallback* callback, void* taskContext, void* userContext)
{
	Pool* pool = userContext;
	pthread_mutex_lock(&pool->mutex);
	if (pool->tail - pool->head >= MAX_TASKS)
	{
		pthread_mutex_unlock(&pool->mutex);
		callback(taskContext); // full: run it here, nothing to finish
		return NULL;
	}
	Task* task = pool->tasks + pool->tail % MAX_TASKS;
	task->callback = callback;
	task->context = taskContext;
	task->done = false;
	pool->tail += 1;
	pthread_cond_signal(&pool->wake);
	pthread_mutex_unlock(&pool->mutex);
	return task;
}

static void FinishTask(void* userTask, void* userContext)
{
	Pool* pool = userContext;
	Task* task = userTask;
	pthread_mutex_lock(&pool->mutex);
	while (task->done == false)
	{
		pthread_cond_wait(&pool->finished, &pool->mutex);
	}
	pthread_mutex_unlock(&pool->mutex);
}

static void StartPool(Pool* pool, int threadCount)
{
	memset(pool, 0, sizeof(*pool));
	pthread_mutex_init(&pool->mutex, NULL);
	pthread_cond_init(&pool->wake, NULL);
	pthread_cond_init(&pool->finished, NULL);
	pool->threadCount = threadCount;
	for (int i = 0; i < threadCount; ++i)
	{
		pthread_create(pool->threads + i, NULL, WorkerMain, pool);
	}
}

static void StopPool(Pool* pool)
{
	pthread_mutex_lock(&pool->mutex);
	pool->quit = true;
	pthread_cond_broadcast(&pool->wake);
	pthread_mutex_unlock(&pool->mutex);
	for (int i = 0; i < pool->threadCount; ++i)
	{
		pthread_join(pool->threads[i], NULL);
	}
	pthread_mutex_destroy(&pool->mutex);
	pthread_cond_destroy(&pool->wake);
	pthread_cond_destroy(&pool->finished);
}

#define ROWS 20
#define BODY_COUNT (ROWS * (ROWS + 1) / 2 + 1)

static uint64_t Run(int workerCount, int* awakeOut)
{
	Pool pool;
	StartPool(&pool, workerCount);
	b2WorldDef worldDef = b2DefaultWorldDef();
	worldDef.workerCount = workerCount;
	worldDef.enqueueTask = EnqueueTask;
	worldDef.finishTask = FinishTask;
	worldDef.userTaskContext = &pool;
	b2WorldId world = b2CreateWorld(&worldDef);

	b2BodyDef groundDef = b2DefaultBodyDef();
	b2BodyId ground = b2CreateBody(world, &groundDef);
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	b2Polygon floor = b2MakeBox(40.0f, 1.0f);
	b2CreatePolygonShape(ground, &shapeDef, &floor);

	b2BodyId bodies[BODY_COUNT];
	int count = 0;
	b2Polygon box = b2MakeBox(0.5f, 0.5f);
	for (int row = 0; row < ROWS; ++row)
	{
		for (int i = 0; i < ROWS - row; ++i)
		{
			b2BodyDef bodyDef = b2DefaultBodyDef();
			bodyDef.type = b2_dynamicBody;
			bodyDef.position = (b2Pos){(float)i - 0.5f * (float)(ROWS - row) + 0.5f, 1.5f + 1.0f * (float)row};
			bodies[count] = b2CreateBody(world, &bodyDef);
			b2CreatePolygonShape(bodies[count], &shapeDef, &box);
			count += 1;
		}
	}
	b2BodyDef ballDef = b2DefaultBodyDef();
	ballDef.type = b2_dynamicBody;
	ballDef.isBullet = true;
	ballDef.position = (b2Pos){-30.0f, 4.0f};
	ballDef.linearVelocity = (b2Vec2){40.0f, 0.0f};
	bodies[count] = b2CreateBody(world, &ballDef);
	b2Circle circle = {{0.0f, 0.0f}, 0.5f};
	b2ShapeDef heavy = b2DefaultShapeDef();
	heavy.density = 10.0f;
	b2CreateCircleShape(bodies[count], &heavy, &circle);
	count += 1;

	for (int step = 0; step < 300; ++step)
	{
		b2World_Step(world, 1.0f / 60.0f, 4);
	}
	uint64_t hash = HashBodies(bodies, count);
	*awakeOut = b2World_GetAwakeBodyCount(world);
	b2DestroyWorld(world);
	StopPool(&pool);
	return hash;
}

int main(void)
{
	int awake1, awake2, awake4;
	uint64_t h1 = Run(1, &awake1);
	uint64_t h2 = Run(2, &awake2);
	uint64_t h4 = Run(4, &awake4);
	printf("1, 2 and 4 workers give the same state: %s\n", h1 == h2 && h1 == h4 ? "yes" : "no");
	printf("1, 2 and 4 workers leave as many bodies awake: %s\n", awake1 == awake2 && awake1 == awake4 ? "yes" : "no");
	return 0;
}
