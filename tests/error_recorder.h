// Test helper: records the messages that Tumble's error hook receives, so tests can assert that a
// bad call reported exactly one error naming the function and the argument. Include after
// <criterion/criterion.h>. Use SetupErrors/TeardownErrors as a test's .init/.fini.
#pragma once

#include "tumble/base.h"

#include <string.h>

static char s_lastError[512];
static int s_errors;

static inline void RecordError(const char* message, void* context)
{
	(void)context;
	strncpy(s_lastError, message, sizeof(s_lastError) - 1);
	s_errors += 1;
}

static inline void SetupErrors(void)
{
	s_lastError[0] = 0;
	s_errors = 0;
	tbSetErrorCallback(RecordError, NULL);
}

static inline void TeardownErrors(void)
{
	tbSetErrorCallback(NULL, NULL);
}

/// Expect exactly one new error since `before` whose message contains both fragments.
static inline void ExpectError(int before, const char* function, const char* argument)
{
	cr_assert_eq(s_errors, before + 1, "expected one error from %s, got %d", function, s_errors - before);
	cr_assert(strstr(s_lastError, function) != NULL, "message '%s' should name %s", s_lastError, function);
	cr_assert(strstr(s_lastError, argument) != NULL, "message '%s' should name %s", s_lastError, argument);
}
