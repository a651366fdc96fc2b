// Shared helpers of the Box2D 2.4.1 verification tests: a seeded generator and the report lines
// that tools/verify.sh collects into docs/verification.md.
//
// Report lines (stdout, one per line, fields separated by '|'):
//   VERIFY|<check>|<tolerance>|<cases>|<agreeing>|<worst value>|<worst input>
//   DISAGREE|<check>|<input>|<reason>
//   NOTE|<check>|<text>
#pragma once

#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <string>

// Numerical Recipes LCG (Press et al., §7.1) with the high bits taken: reproducible on every
// platform, so a case number identifies an input for good.
struct VerifyRandom
{
	uint32_t state;

	explicit VerifyRandom(uint32_t seed) : state(seed) {}

	uint32_t Next()
	{
		state = state * 1664525u + 1013904223u;
		return state;
	}

	/// Uniform in [lo, hi).
	float Range(float lo, float hi)
	{
		float u = (float)(Next() >> 8) * (1.0f / 16777216.0f);
		return lo + (hi - lo) * u;
	}

	/// Log-uniform in [lo, hi): sizes spread evenly over the decades.
	float LogRange(float lo, float hi);

	int Int(int lo, int hiInclusive)
	{
		return lo + (int)(Next() % (uint32_t)(hiInclusive - lo + 1));
	}
};

std::string VerifyFormat(const char* format, ...) __attribute__((format(printf, 1, 2)));

inline std::string VerifyFormat(const char* format, ...)
{
	char buffer[1024];
	va_list args;
	va_start(args, format);
	vsnprintf(buffer, sizeof(buffer), format, args);
	va_end(args);
	return std::string(buffer);
}

inline float VerifyRandom::LogRange(float lo, float hi)
{
	float u = Range(0.0f, 1.0f);
	return lo * powf(hi / lo, u);
}

inline void VerifyReport(const char* check, const char* tolerance, int cases, int agreeing, const std::string& worst,
						 const std::string& worstInput)
{
	printf("VERIFY|%s|%s|%d|%d|%s|%s\n", check, tolerance, cases, agreeing, worst.c_str(), worstInput.c_str());
	fflush(stdout);
}

inline void VerifyDisagree(const char* check, const std::string& input, const std::string& reason)
{
	printf("DISAGREE|%s|%s|%s\n", check, input.c_str(), reason.c_str());
	fflush(stdout);
}

inline void VerifyNote(const char* check, const std::string& text)
{
	printf("NOTE|%s|%s\n", check, text.c_str());
	fflush(stdout);
}
