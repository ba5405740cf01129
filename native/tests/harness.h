/* A tiny assert harness: checks count, failures print file:line, the run ends with a summary line. */
#ifndef JM_HARNESS_H
#define JM_HARNESS_H

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int jt_passed, jt_failed;

/* Makes a fresh folder /tmp/jmcl-<name>-XXXXXX for a test program's files, into dir: 0, or -1 after perror. */
static inline int jt_tempdir(char *dir, size_t size, const char *name)
{
	snprintf(dir, size, "/tmp/jmcl-%s-XXXXXX", name);
	if (!mkdtemp(dir)) {
		perror("mkdtemp");
		return -1;
	}
	return 0;
}

#define JT_FAIL(...)                                                    \
	do {                                                            \
		jt_failed++;                                            \
		fprintf(stderr, "%s:%d: FAILED: ", __FILE__, __LINE__); \
		fprintf(stderr, __VA_ARGS__);                           \
		fputc('\n', stderr);                                    \
	} while (0)

#define CHECK(cond)                                 \
	do {                                        \
		if (cond)                           \
			jt_passed++;                \
		else                                \
			JT_FAIL("%s", #cond);       \
	} while (0)

#define CHECK_U64(got, want)                                                                 \
	do {                                                                                 \
		uint64_t g_ = (got), w_ = (want);                                            \
		if (g_ == w_)                                                                \
			jt_passed++;                                                         \
		else                                                                         \
			JT_FAIL("%s = 0x%016" PRIx64 ", want 0x%016" PRIx64, #got, g_, w_); \
	} while (0)

/* Bit-exact double comparison. */
#define CHECK_BITS(got, want)                                                       \
	do {                                                                        \
		double g_ = (got), w_ = (want);                                     \
		if (memcmp(&g_, &w_, sizeof(double)) == 0)                          \
			jt_passed++;                                                \
		else                                                                \
			JT_FAIL("%s = %a (%.17g), want %a (%.17g)", #got, g_, g_, w_, w_); \
	} while (0)

#define CHECK_NEAR(got, want, tol)                                                \
	do {                                                                      \
		double g_ = (got), w_ = (want);                                   \
		if (fabs(g_ - w_) <= (tol))                                       \
			jt_passed++;                                              \
		else                                                              \
			JT_FAIL("%s = %.17g, want %.17g +- %g", #got, g_, w_, (double)(tol)); \
	} while (0)

#define CHECK_INT(got, want)                                                     \
	do {                                                                     \
		long long g_ = (got), w_ = (want);                               \
		if (g_ == w_)                                                    \
			jt_passed++;                                             \
		else                                                             \
			JT_FAIL("%s = %lld, want %lld", #got, g_, w_);           \
	} while (0)

#define CHECK_STR_PREFIX(got, prefix)                                                       \
	do {                                                                                \
		const char *g_ = (got), *p_ = (prefix);                                     \
		if (g_ && !strncmp(g_, p_, strlen(p_)))                                     \
			jt_passed++;                                                        \
		else                                                                        \
			JT_FAIL("%s = \"%s\", want a string starting \"%s\"", #got, g_ ? g_ : "(null)", p_); \
	} while (0)

#define CHECK_CONTAINS(got, needle)                                                       \
	do {                                                                              \
		const char *g_ = (got), *n_ = (needle);                                   \
		if (g_ && strstr(g_, n_))                                                 \
			jt_passed++;                                                      \
		else                                                                      \
			JT_FAIL("%s = \"%s\", want it to contain \"%s\"", #got, g_ ? g_ : "(null)", n_); \
	} while (0)

/* Prints the summary line; the exit status of the test program. */
static inline int jt_report(void)
{
	printf("%d passed, %d failed\n", jt_passed, jt_failed);
	return jt_failed ? 1 : 0;
}

#endif
