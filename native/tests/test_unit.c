/*
 * Unit tests of libjmcl: the generator against reference values (computed with the Python
 * lines in tests/reference.py), angles, bearings, likelihood, resampling on known weights,
 * termination, memory styles, the reader's and the option parser's rejections, statistics,
 * JSON escaping and each overrun policy's rule.
 */
#define _GNU_SOURCE
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "angles.h"
#include "dataset.h"
#include "harness.h"
#include "json.h"
#include "mcl.h"
#include "options.h"
#include "output.h"
#include "policy.h"
#include "rng.h"
#include "stats.h"

static void test_rng_reference(void)
{
	jm_rng r;

	jm_rng_seed(&r, 0);
	/* splitmix64(0)'s first output, the well-known reference value */
	CHECK_U64(r.s[0], 0xe220a8397b1dcdafULL);
	CHECK_U64(r.s[1], 0x6e789e6aa1b965f4ULL);
	CHECK_U64(r.s[2], 0x06c45d188009454fULL);
	CHECK_U64(r.s[3], 0xf88bb8a8724c81ecULL);
	CHECK_U64(jm_rng_next(&r), 0x99ec5f36cb75f2b4ULL);
	CHECK_U64(jm_rng_next(&r), 0xbf6e1f784956452aULL);
	CHECK_U64(jm_rng_next(&r), 0x1a5f849d4933e6e0ULL);

	jm_rng_seed(&r, 1);
	CHECK_U64(r.s[0], 0x910a2dec89025cc1ULL);
	CHECK_U64(r.s[3], 0x71c18690ee42c90bULL);
	CHECK_U64(jm_rng_next(&r), 0xb3f2af6d0fc710c5ULL);
	CHECK_U64(jm_rng_next(&r), 0x853b559647364ceaULL);
	CHECK_U64(jm_rng_next(&r), 0x92f89756082a4514ULL);

	/* a negative Java long seed is the same 64 bits */
	jm_rng_seed(&r, (uint64_t)(int64_t)-1);
	CHECK_U64(r.s[0], 0xe4d971771b652c20ULL);
	CHECK_U64(jm_rng_next(&r), 0x8f5520d52a7ead08ULL);

	jm_rng_seed(&r, 1);
	CHECK_BITS(jm_rng_uniform(&r), 0x1.67e55eda1f8e2p-1);
	CHECK_BITS(jm_rng_uniform(&r), 0x1.0a76ab2c8e6c9p-1);
	jm_rng_seed(&r, 0);
	CHECK_BITS(jm_rng_uniform(&r), 0x1.33d8be6d96ebep-1);
	CHECK_BITS(jm_rng_uniform(&r), 0x1.7edc3ef092ac8p-1);
}

static void test_gaussian(void)
{
	jm_rng r;
	double sum = 0.0, sq = 0.0, lo = 0.0, hi = 0.0;
	int i, n = 200000;

	jm_rng_seed(&r, 1);
	CHECK_BITS(jm_rng_gaussian(&r), 0x1.94b2b1b56c670p-1);
	CHECK_BITS(jm_rng_gaussian(&r), -0x1.39535085d55f0p-2);
	CHECK_BITS(jm_rng_gaussian(&r), 0x1.88c8ffb969500p-3);
	jm_rng_seed(&r, 0);
	CHECK_BITS(jm_rng_gaussian(&r), 0x1.07c359d721fc0p-1);
	CHECK_BITS(jm_rng_gaussian(&r), -0x1.309a997d3b858p+0);
	CHECK_BITS(jm_rng_gaussian(&r), 0x1.ff78ccf47f730p+0);

	/* seeded, so deterministic: the moments of Irwin-Hall(12) - 6 */
	jm_rng_seed(&r, 42);
	for (i = 0; i < n; i++) {
		double g = jm_rng_gaussian(&r);

		sum += g;
		sq += g * g;
		lo = g < lo ? g : lo;
		hi = g > hi ? g : hi;
	}
	CHECK_NEAR(sum / n, 0.0, 0.01);
	CHECK_NEAR(sq / n, 1.0, 0.02);
	CHECK(lo >= -6.0 && hi <= 6.0);
	CHECK(lo < -3.5 && hi > 3.5);
}

static void test_angles(void)
{
	int i;

	CHECK_BITS(jm_wrap2pi(0.0), 0.0);
	CHECK_BITS(jm_wrap2pi(JM_TWO_PI), 0.0);
	CHECK_BITS(jm_wrap2pi(1.0), 1.0);
	CHECK_NEAR(jm_wrap2pi(-0.25), JM_TWO_PI - 0.25, 1e-15);
	CHECK_NEAR(jm_wrap2pi(7.0), 7.0 - JM_TWO_PI, 1e-15);
	CHECK_NEAR(jm_wrap2pi(-13.0), -13.0 + 3 * JM_TWO_PI, 1e-14);
	/* a tiny negative angle rounds to 2pi, which the rule folds back to 0 */
	CHECK_BITS(jm_wrap2pi(-1e-20), 0.0);
	CHECK_BITS(jm_wrappi(JM_PI), -JM_PI);
	CHECK_BITS(jm_wrappi(0.0), 0.0);
	CHECK_NEAR(jm_wrappi(1.5 * JM_PI), -0.5 * JM_PI, 1e-15);
	CHECK_NEAR(jm_wrappi(-0.5), -0.5, 1e-15);
	for (i = -1000; i <= 1000; i++) {
		double a = i * 0.0137, w = jm_wrap2pi(a), p = jm_wrappi(a);

		if (!(w >= 0.0 && w < JM_TWO_PI) || !(p >= -JM_PI && p < JM_PI)) {
			JT_FAIL("wrap of %.17g out of range: %.17g %.17g", a, w, p);
			return;
		}
	}
	jt_passed++;
}

static void test_bearings(void)
{
	jm_playground pg;
	double s1, s2, s3;

	jm_playground_default(&pg);
	CHECK_NEAR(jm_bearing(0, 0, 0, 0, 1), JM_PI / 2, 1e-15);
	CHECK_NEAR(jm_bearing(0, 0, 0, 3, 0), 0.0, 1e-15);
	CHECK_NEAR(jm_bearing(0, 0, JM_PI / 2, 3, 0), 1.5 * JM_PI, 1e-15);
	CHECK_NEAR(jm_bearing(1, 1, JM_PI, 0, 1), 0.0, 1e-15);
	/* the thesis's figures: from (0, 0), S1 -> S2 is 270 degrees and S2 -> S3 about 34 */
	s1 = jm_bearing(0, 0, 0, pg.beacon[0][0], pg.beacon[0][1]);
	s2 = jm_bearing(0, 0, 0, pg.beacon[1][0], pg.beacon[1][1]);
	s3 = jm_bearing(0, 0, 0, pg.beacon[2][0], pg.beacon[2][1]);
	CHECK_NEAR(jm_wrap2pi(s2 - s1) * 180 / JM_PI, 270.0, 1e-12);
	CHECK_NEAR(jm_wrap2pi(s3 - s2) * 180 / JM_PI, 33.69, 0.01);
}

static void test_likelihood(void)
{
	jm_playground pg;
	double a, l;

	jm_playground_default(&pg);
	a = jm_bearing(1.0, 1.0, 0.3, 3.0, 2.0);
	l = jm_likelihood(1.0, 1.0, 0.3, a, &pg);
	CHECK(l >= 1.0 && l < 1.0 + 1e-6); /* one beacon exactly, the others many sigmas away */
	l = jm_likelihood(1.0, 1.0, 0.3, jm_wrap2pi(a + 0.05), &pg);
	CHECK_NEAR(l, exp(-0.5), 1e-9);    /* one sigma off */
	/* a particle at the field's centre heading 0 sees S1 at pi and S2, S3 symmetric */
	l = jm_likelihood(1.5, 1.0, 0.0, JM_PI, &pg);
	CHECK_NEAR(l, 1.0, 1e-9);
}

static void test_systematic(void)
{
	const double w[4] = { 0.5, 0.25, 0.125, 0.125 };
	const double one[4] = { 0.0, 0.0, 1.0, 0.0 };
	const double flat[5] = { 0.2, 0.2, 0.2, 0.2, 0.2 };
	int idx[5];

	/* t = 1/16 + m/4: 0.0625 0.3125 0.5625 0.8125 against cumulative 0.5 0.75 0.875 1 */
	jm_resample_systematic(w, 4, 0.0625, idx);
	CHECK(idx[0] == 0 && idx[1] == 0 && idx[2] == 1 && idx[3] == 2);
	jm_resample_systematic(one, 4, 0.2, idx);
	CHECK(idx[0] == 2 && idx[1] == 2 && idx[2] == 2 && idx[3] == 2);
	jm_resample_systematic(flat, 5, 0.1, idx);
	CHECK(idx[0] == 0 && idx[1] == 1 && idx[2] == 2 && idx[3] == 3 && idx[4] == 4);
	/* never past the last particle, even when rounding leaves the sum short of 1 */
	{
		const double shortw[3] = { 0.3, 0.3, 0.3 };

		jm_resample_systematic(shortw, 3, 0.33, idx);
		CHECK(idx[0] == 1 && idx[1] == 2 && idx[2] == 2);
	}
}

static void test_multinomial(void)
{
	const double w[4] = { 0.5, 0.25, 0.125, 0.125 };
	const double one[4] = { 0.0, 1.0, 0.0, 0.0 };
	int idx[4];
	jm_rng r;

	/* uniforms of seed 1: 0.7029 0.5204 0.5741 0.3913 */
	jm_rng_seed(&r, 1);
	jm_resample_multinomial(w, 4, &r, idx);
	CHECK(idx[0] == 1 && idx[1] == 1 && idx[2] == 1 && idx[3] == 0);
	jm_rng_seed(&r, 9);
	jm_resample_multinomial(one, 4, &r, idx);
	CHECK(idx[0] == 1 && idx[1] == 1 && idx[2] == 1 && idx[3] == 1);
}

static void config(jm_mcl_config *c, int n, enum jm_memory mem)
{
	memset(c, 0, sizeof(*c));
	c->particles = n;
	c->memory = mem;
	c->seed = 7;
	c->start_x = 0.5;
	c->start_y = 0.5;
	c->start_theta = 0.0;
	c->covariance = 1;
}

static void test_init(void)
{
	jm_playground pg;
	jm_mcl_config c;
	jm_mcl m;
	const jm_particles *p;
	double x, y, t;
	int i, ok = 1;

	jm_playground_default(&pg);
	config(&c, 100, JM_MEMORY_PREALLOCATED);
	CHECK(jm_mcl_init(&m, &c, &pg) == 0);
	p = jm_mcl_particles(&m);
	CHECK_BITS(p->x[0], 0x1.10d5cd05dd50dp-1);
	CHECK_BITS(p->y[0], 0x1.ec5e81b94bf4ap-2);
	CHECK_BITS(p->th[0], 0x1.90a79acbdeed0p+2);
	CHECK_BITS(p->w[0], 1.0 / 100);
	jm_mcl_estimate(&m, &x, &y, &t);
	CHECK(x == 0.5 && y == 0.5 && t == 0.0);
	jm_mcl_free(&m);

	c.init = JM_INIT_UNIFORM;
	CHECK(jm_mcl_init(&m, &c, &pg) == 0);
	p = jm_mcl_particles(&m);
	for (i = 0; i < 100; i++)
		if (!(p->x[i] >= 0 && p->x[i] < 3 && p->y[i] >= 0 && p->y[i] < 2 && p->th[i] >= 0 && p->th[i] < JM_TWO_PI))
			ok = 0;
	CHECK(ok);
	jm_mcl_estimate(&m, &x, &y, &t);
	CHECK(x == 1.5 && y == 1.0 && t == 0.0);
	jm_mcl_free(&m);
}

/* Everything a job may change: particles, generator, estimate, covariance. */
static int same_state(const jm_mcl *a, const jm_mcl *b)
{
	const jm_particles *pa = jm_mcl_particles(a), *pb = jm_mcl_particles(b);
	size_t bytes = sizeof(double) * (size_t)a->n;

	return a->n == b->n && !memcmp(pa->x, pb->x, bytes) && !memcmp(pa->y, pb->y, bytes) &&
	       !memcmp(pa->th, pb->th, bytes) && !memcmp(pa->w, pb->w, bytes) &&
	       !memcmp(&a->rng, &b->rng, sizeof(a->rng)) && a->ex == b->ex && a->ey == b->ey &&
	       a->et == b->et && !memcmp(a->cov, b->cov, sizeof(a->cov));
}

static void steps(jm_mcl *m, int k)
{
	int i;

	for (i = 0; i < k; i++) {
		jm_mcl_predict(m, 0.01, 0.002, 0.02, NULL);
		jm_mcl_update(m, jm_bearing(0.5 + 0.01 * i, 0.5, 0.02 * i, 3.0, 2.0), NULL);
	}
}

static void test_termination(void)
{
	jm_playground pg;
	jm_mcl_config c;
	jm_mcl a, b;
	jm_abort abort_req;
	enum jm_memory mem;

	jm_playground_default(&pg);
	for (mem = JM_MEMORY_PREALLOCATED; mem <= JM_MEMORY_ALLOCATING; mem++) {
		config(&c, 300, mem);
		CHECK(jm_mcl_init(&a, &c, &pg) == 0);
		CHECK(jm_mcl_init(&b, &c, &pg) == 0);
		steps(&a, 3);
		steps(&b, 3);
		CHECK(same_state(&a, &b));
		atomic_init(&abort_req.requested, 1);
		abort_req.seen_ns = -1;
		CHECK_INT(jm_mcl_predict(&a, 0.02, 0.0, 0.1, &abort_req), JM_JOB_ABORTED);
		CHECK(abort_req.seen_ns > 0); /* the poll that saw it noted when */
		CHECK(same_state(&a, &b));
		CHECK_INT(jm_mcl_update(&a, 1.0, &abort_req), JM_JOB_ABORTED);
		CHECK(same_state(&a, &b));
		/* after the aborted jobs, the same completed jobs give the same bits */
		atomic_store(&abort_req.requested, 0);
		abort_req.seen_ns = -1;
		CHECK_INT(jm_mcl_predict(&a, 0.02, 0.0, 0.1, &abort_req), JM_JOB_DONE);
		CHECK_INT(jm_mcl_predict(&b, 0.02, 0.0, 0.1, NULL), JM_JOB_DONE);
		CHECK_INT(jm_mcl_update(&a, 1.0, &abort_req), JM_JOB_DONE);
		CHECK_INT(jm_mcl_update(&b, 1.0, NULL), JM_JOB_DONE);
		CHECK(abort_req.seen_ns == -1); /* nothing asked: nothing seen */
		CHECK(same_state(&a, &b));
		jm_mcl_free(&a);
		jm_mcl_free(&b);
	}
}

static void test_memory_styles_agree(void)
{
	jm_playground pg;
	jm_mcl_config c;
	jm_mcl a, b;
	enum jm_resample rs;

	jm_playground_default(&pg);
	for (rs = JM_RESAMPLE_SYSTEMATIC; rs <= JM_RESAMPLE_MULTINOMIAL; rs++) {
		config(&c, 257, JM_MEMORY_PREALLOCATED);
		c.resample = rs;
		CHECK(jm_mcl_init(&a, &c, &pg) == 0);
		c.memory = JM_MEMORY_ALLOCATING;
		CHECK(jm_mcl_init(&b, &c, &pg) == 0);
		steps(&a, 20);
		steps(&b, 20);
		CHECK(same_state(&a, &b));
		jm_mcl_free(&a);
		jm_mcl_free(&b);
	}
}

static void test_filter_tracks(void)
{
	jm_playground pg;
	jm_mcl_config c;
	jm_mcl m;
	double x = 0.5, y = 0.5, th = 0.0, ex, ey, et;
	int i, b;

	/* a robot driving a gentle arc, seen perfectly by the three beacons: the estimate follows */
	jm_playground_default(&pg);
	config(&c, 500, JM_MEMORY_PREALLOCATED);
	CHECK(jm_mcl_init(&m, &c, &pg) == 0);
	for (i = 0; i < 60; i++) {
		double dx = 0.01, dth = 0.01;

		x += dx * cos(th);
		y += dx * sin(th);
		th = jm_wrap2pi(th + dth);
		jm_mcl_predict(&m, dx, 0.0, dth, NULL);
		for (b = 0; b < 3; b++)
			jm_mcl_update(&m, jm_bearing(x, y, th, pg.beacon[b][0], pg.beacon[b][1]), NULL);
	}
	jm_mcl_estimate(&m, &ex, &ey, &et);
	CHECK_NEAR(ex, x, 0.05);
	CHECK_NEAR(ey, y, 0.05);
	CHECK_NEAR(jm_wrappi(et - th), 0.0, 0.05);
	jm_mcl_free(&m);
}

static char tmpdir[64];

static const char *write_file(const char *name, const char *content)
{
	static char path[256];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", tmpdir, name);
	f = fopen(path, "w");
	if (f) {
		fputs(content, f);
		fclose(f);
	}
	return path;
}

/* Reads content as a 4-column file; returns the error message ("" when accepted). */
static const char *read_err(const char *content, int *line_ok, const char *want_line)
{
	static char err[512], want[320];
	jm_series s;
	const char *path = write_file("x.txt", content);

	err[0] = '\0';
	if (jm_series_read(&s, path, 4, &jm_rule_none, err, sizeof(err)) == 0) {
		jm_series_free(&s);
		return "";
	}
	if (want_line)
		snprintf(want, sizeof(want), "%s:%s: ", path, want_line);
	else
		snprintf(want, sizeof(want), "%s: ", path);
	*line_ok = !strncmp(err, want, strlen(want));
	return err;
}

static void test_reader(void)
{
	char err[512];
	jm_series s;
	int ok = 0;
	const char *e;

	CHECK(jm_series_read(&s, write_file("good.txt",
		"# comment\n\n0.0  0.1 0 0\n5.0000000000000003e-02  1e-2 -0 0.5\n\t0.1 0 0 0\n"), 4, &jm_rule_none, err,
		sizeof(err)) == 0);
	CHECK_INT(s.n, 3);
	CHECK_BITS(JM_ROW(&s, 1)[0], 0.05);
	CHECK_BITS(JM_ROW(&s, 1)[3], 0.5);
	jm_series_free(&s);

	e = read_err("0 1 2\n", &ok, "1");
	CHECK_CONTAINS(e, "expected 4 columns but found 3");
	CHECK(ok);
	e = read_err("0 1 2 3\n0.05 1 2 3 4\n", &ok, "2");
	CHECK_CONTAINS(e, "found 5");
	CHECK(ok);
	e = read_err("0 1 2 3\n\n0.05 1 abc 3\n", &ok, "3");
	CHECK_CONTAINS(e, "not a number: 'abc'");
	CHECK(ok);
	e = read_err("0 NaN 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a finite number");
	CHECK(ok);
	e = read_err("0 1 inf 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a finite number");
	CHECK(ok);
	e = read_err("0 1 1e999 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a finite number");
	CHECK(ok);
	e = read_err("-0.05 1 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "negative time -0.05");
	CHECK(ok);
	e = read_err("0.1 1 2 3\n0.05 1 2 3\n", &ok, "2");
	CHECK_CONTAINS(e, "time 0.05 is before the previous line's (not sorted by time)");
	CHECK(ok);
	e = read_err("1.5x 1 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a number");
	CHECK(ok);
	e = read_err("0x1p-2 1 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a number: '0x1p-2'");
	CHECK(ok);
	e = read_err("0 1 2d 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a number: '2d'");
	CHECK(ok);
	e = read_err("0 1 -Infinity 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a finite number: '-Infinity'");
	CHECK(ok);
	e = read_err("0 . 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a number: '.'");
	CHECK(ok);
	e = read_err("0 1e 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a number: '1e'");
	CHECK(ok);
	e = read_err("0 1e999 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "not a finite number: '1e999' (overflows)");
	CHECK(ok);
	/* beyond the data's range (docs/FORMATS.md 1.1): a NaN filter or an overflowing release time */
	e = read_err("0 1e308 2 3\n", &ok, "1");
	CHECK_CONTAINS(e, "out of range: '1e308' (more than 1e9 in magnitude)");
	CHECK(ok);
	e = read_err("0 0 0 0\n9.3e9 0 0 0\n", &ok, "2");
	CHECK_CONTAINS(e, "out of range: '9.3e9' (more than 1e9 in magnitude)");
	CHECK(ok);
	e = read_err("1e9 1e9 -1e9 0\n", &ok, NULL);
	CHECK_INT(strlen(e), 0);
	e = read_err("+0. .5 -1.e-3 3E+2\n", &ok, NULL);
	CHECK_INT(strlen(e), 0);
	e = read_err("", &ok, NULL);
	CHECK_CONTAINS(e, "empty file (no data lines)");
	CHECK(ok);
	e = read_err("# only a comment\n\n", &ok, NULL);
	CHECK_CONTAINS(e, "empty file");
	CHECK(ok);
	/* equal times are sorted */
	e = read_err("0.1 1 2 3\n0.1 1 2 3\n", &ok, NULL);
	CHECK_INT(strlen(e), 0);

	snprintf(err, sizeof(err), "%s/missing.txt", tmpdir);
	{
		char msg[512], want[600];

		CHECK(jm_series_read(&s, err, 4, &jm_rule_none, msg, sizeof(msg)) == -1);
		snprintf(want, sizeof(want), "%s: no such file", err);
		CHECK_STR_PREFIX(msg, want);
	}
}

/* The grammar's corners (docs/FORMATS.md 1.1): what the C reader once took differently from Java's. */
static const char *parse_err(const char *bytes, size_t len, int cols)
{
	static char err[512];
	FILE *f = fmemopen((void *)bytes, len, "r");
	jm_series s;

	err[0] = '\0';
	if (!f)
		return "fmemopen failed";
	if (jm_series_parse(&s, f, "in", cols, cols == 2 ? &jm_rule_laser : &jm_rule_none, err, sizeof(err)) == 0)
		jm_series_free(&s);
	fclose(f);
	return err;
}

#define PARSE_ERR(lit, cols) parse_err(lit, sizeof(lit) - 1, cols)

static void test_reader_grammar(void)
{
	char err[512], dir[128];
	jm_series s;

	/* a NUL no longer ends the line: main's C reader ran on this file, Java refused it */
	CHECK_STR_PREFIX(PARSE_ERR("0.05 1 2 3\0junk\n", 4), "in:1: not a number: '3\\x00junk'");
	CHECK_STR_PREFIX(PARSE_ERR("0 nan\0 2 3\n", 4), "in:1: not a number: 'nan\\x00'");
	CHECK_STR_PREFIX(PARSE_ERR("0.05 1\r0.1 1\r", 2), "in:1: expected 2 columns but found 3");
	CHECK_STR_PREFIX(PARSE_ERR("0.05 1\v2 3 4\n", 4), "in:1: not a number: '1\\x0b2'");
	CHECK_STR_PREFIX(PARSE_ERR("\xef\xbb\xbf" "0 1\n", 2), "in:1: not a number: '\\xef\\xbb\\xbf0'");
	CHECK_STR_PREFIX(PARSE_ERR("abc 1 2\n", 4), "in:1: expected 4 columns but found 3");
	CHECK_INT((int)strlen(PARSE_ERR("0 1\r\n0.1 2\r\n", 2)), 0);
	CHECK_STR_PREFIX(PARSE_ERR("0 12345678901234567890123456789012345678901x\n", 2),
			 "in:1: not a number: '1234567890123456789012345678901234567890...'");
	snprintf(dir, sizeof(dir), "%s/adir", tmpdir);
	CHECK(mkdir(dir, 0700) == 0);
	CHECK(jm_series_read(&s, dir, 2, &jm_rule_laser, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "adir: is a directory");
	rmdir(dir);
}

static void test_dataset_properties(void)
{
	jm_dataset ds;
	char err[512];

	write_file("odometry.txt", "0 0 0 0\n0.05 0.01 0 0\n");
	write_file("laser.txt", "0.02 1.0\n");
	write_file("real.txt", "0 1.25 0.75 0.5\n0.05 1.26 0.75 0.5\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == 0);
	CHECK(ds.start_x == 1.25 && ds.start_y == 0.75 && ds.start_theta == 0.5);
	CHECK(ds.pg.nbeacons == 3 && ds.pg.width == 3.0);
	jm_dataset_free(&ds);
	/* a time scale may not take the last event past a run's largest time, 1e9 s */
	write_file("laser.txt", "0.02 1.0\n1e6 1.0\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == 0);
	CHECK(jm_dataset_check_time_scale(&ds, 1000.0, err, sizeof(err)) == 0);
	CHECK(jm_dataset_check_time_scale(&ds, 1000.0000001, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "--time-scale: scales the last time of ");
	CHECK_CONTAINS(err, "/laser.txt past 1e9 s, the largest time of a run");
	jm_dataset_free(&ds);
	/* a warm-up must leave an event after it: 0.05 s is the odometry's last time, later than the laser's */
	write_file("laser.txt", "0.02 1.0\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == 0);
	CHECK(jm_dataset_check_warmup(&ds, 0.0, err, sizeof(err)) == 0);
	CHECK(jm_dataset_check_warmup(&ds, 0.049, err, sizeof(err)) == 0);
	CHECK(jm_dataset_check_warmup(&ds, 0.05, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "--warmup: reaches the last time of ");
	CHECK_CONTAINS(err, "/odometry.txt: a warm-up replays the data before it and must leave an event after it");
	CHECK(jm_dataset_check_warmup(&ds, 1000.0, err, sizeof(err)) == -1);
	jm_dataset_free(&ds);
	write_file("laser.txt", "0.02 1.0\n0.06 1.0\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == 0);
	CHECK(jm_dataset_check_warmup(&ds, 0.05, err, sizeof(err)) == 0);
	CHECK(jm_dataset_check_warmup(&ds, 0.06, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "/laser.txt: a warm-up replays");
	jm_dataset_free(&ds);
	write_file("laser.txt", "0.02 1.0\n");
	/* a laser angle is the beacon's from the heading, in [0, 2pi) (SPEC section 1): 2pi itself is not */
	write_file("laser.txt", "0.02 -0\n0.03 6.283185307179585\n0.04 6.283185307179586\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "/laser.txt:3: angle 6.283185307179586 is not in [0, 2pi) (the beacon's angle from the heading)");
	write_file("laser.txt", "0.02 1.0\n0.03 -7\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "/laser.txt:2: angle -7 is not in [0, 2pi)");
	write_file("laser.txt", "0.02 1.0\n");
	/* the ground truth is at the odometry times, one record each (docs/ALGORITHM.md 10) */
	write_file("real.txt", "0 1.25 0.75 0.5\n# a comment\n0.06 1.26 0.75 0.5\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "/real.txt:3: time 0.06 is not that of record 2 of ");
	CHECK_CONTAINS(err, "/odometry.txt (the ground truth is at the odometry times)");
	write_file("real.txt", "0 1.25 0.75 0.5\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "/real.txt: 1 records for the 2 of ");
	write_file("real.txt", "0 1.25 0.75 0.5\n0.05 1.26 0.75 0.5\n0.05 1.26 0.75 0.5\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "/real.txt:3: time 0.05 after the last of the 2 records of ");
	write_file("real.txt", "0 1.25 0.75 0.5\n0.05 1.26 0.75 0.5\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == 0);
	jm_dataset_free(&ds);

	CHECK(!strcmp(ds.name, strrchr(tmpdir, '/') + 1)); /* no scenario: the folder's name */
	write_file("dataset.properties", "scenario=unit\nstart.x=0.5\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "dataset.properties: start.y: missing");
	write_file("dataset.properties", "# metadata\nscenario=unit\nstart.x=0.5\nstart.y=0.25\nstart.theta=1\n"
		   "beacons=0,0;4,0;4,4;0,4\nplayground.width=4\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == 0);
	CHECK(ds.start_x == 0.5 && ds.start_y == 0.25 && ds.start_theta == 1.0);
	CHECK(!strcmp(ds.name, "unit"));
	CHECK(ds.pg.nbeacons == 4 && ds.pg.beacon[3][1] == 4.0 && ds.pg.width == 4.0 && ds.pg.height == 2.0);
	CHECK(!strcmp(ds.scenario, "unit"));
	jm_dataset_free(&ds);

	write_file("dataset.properties", "scenario=unit\nstart.y=half\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "dataset.properties:2: start.y: not a number: 'half'");
	{
		char nodir[128];

		snprintf(nodir, sizeof(nodir), "%s/none", tmpdir);
		CHECK(jm_dataset_load(&ds, nodir, NULL, NULL, NULL, err, sizeof(err)) == -1);
		CHECK_CONTAINS(err, "/none: no such dataset folder");
	}
	write_file("dataset.properties", "beacons=1;2\n");
	CHECK(jm_dataset_load(&ds, tmpdir, NULL, NULL, NULL, err, sizeof(err)) == -1);
	CHECK_CONTAINS(err, "dataset.properties:1: beacons");
	unlink(write_file("dataset.properties", ""));
}

static int parse(const char *line, jm_options *o, char *err, size_t errlen)
{
	char buf[512], *argv[40], *save = NULL, *tok;
	int argc = 0;

	snprintf(buf, sizeof(buf), "jmclbench-native %s", line);
	for (tok = strtok_r(buf, " ", &save); tok && argc < 39; tok = strtok_r(NULL, " ", &save))
		argv[argc++] = tok;
	argv[argc] = NULL;
	return jm_options_parse(o, argc, argv, err, errlen);
}

static void test_options(void)
{
	jm_options o;
	char err[512];

	CHECK(parse("run", &o, err, sizeof(err)) == 0);
	CHECK(o.particles == 400 && o.number == 1 && !strcmp(o.runtime_name, "native") &&
	      !strcmp(o.out, "results") && o.policy == JM_POLICY_SKIP && o.seed == 1 &&
	      o.time_scale == 1.0 && o.fifo && o.cpu_time && !o.ideal && !o.covariance);
	CHECK(parse("-p 100 -n 3 -j c-gcc -O out -odo a -laser b -real c -T -c", &o, err, sizeof(err)) == 0);
	CHECK(o.particles == 100 && o.number == 3 && !strcmp(o.runtime_name, "c-gcc") &&
	      !strcmp(o.out, "out") && !strcmp(o.odometry, "a") && !strcmp(o.laser, "b") &&
	      !strcmp(o.real, "c") && o.policy == JM_POLICY_TERMINATE && o.covariance);
	CHECK(parse("run --particles=2000 --policy queue --memory allocating --estimate best "
		    "--resample multinomial --init uniform --seed -5 --time-scale 0.5 --warmup 2 "
		    "--spin-us 50 --force --gc-log --no-fifo --no-cpu-time --dataset d", &o, err, sizeof(err)) == 0);
	CHECK(o.particles == 2000 && o.policy == JM_POLICY_QUEUE && o.memory == JM_MEMORY_ALLOCATING &&
	      o.estimate == JM_ESTIMATE_BEST && o.resample == JM_RESAMPLE_MULTINOMIAL &&
	      o.init == JM_INIT_UNIFORM && o.seed == -5 && o.time_scale == 0.5 && o.warmup_s == 2.0 &&
	      o.spin_us == 50 && !o.ideal && o.force && o.gc_log && !o.fifo && !o.cpu_time &&
	      !strcmp(o.dataset, "d"));
	/* an ideal run has no releases: a spin was recorded (parameters.spinUs) that never happened */
	CHECK(parse("--ideal --spin-us 50", &o, err, sizeof(err)) == -1);
	CHECK(!strcmp(err, "--spin-us: an ideal run has no releases to spin before (--ideal)"));
	CHECK(parse("--ideal --spin-us 0 --force --gc-log --no-cpu-time", &o, err, sizeof(err)) == 0 && o.ideal && o.gc_log &&
	      !o.cpu_time);
	CHECK(parse("-h", &o, err, sizeof(err)) == 0 && o.help);

	CHECK(parse("--bogus", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--bogus: unknown option");
	CHECK(parse("-x", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "-x: unknown option");
	CHECK(parse("--part 10", &o, err, sizeof(err)) == -1);   /* no abbreviations */
	CHECK_STR_PREFIX(err, "--part: ");
	CHECK(parse("-p", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "-p: needs a value");
	CHECK(parse("-p abc", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "-p: not an integer");
	CHECK(parse("--particles 0", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--particles: 0 is out of range [1, 100000000]");
	CHECK(parse("--particles=-4", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--particles: -4 is out of range");
	CHECK(parse("--policy fast", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--policy: 'fast' is not one of skip|terminate|queue");
	CHECK(parse("--memory=lots", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--memory: 'lots' is not one of preallocated|allocating");
	CHECK(parse("--ideal=yes", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--ideal: takes no value");
	CHECK(parse("--bogus=1", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--bogus: unknown option");
	CHECK(parse("-T --policy queue", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "-T: contradicts --policy queue");
	CHECK(parse("--policy terminate -T", &o, err, sizeof(err)) == 0 && o.policy == JM_POLICY_TERMINATE);
	CHECK(parse("--odo a --laser=b --real c", &o, err, sizeof(err)) == 0 && !strcmp(o.laser, "b"));
	CHECK(parse("-O ", &o, err, sizeof(err)) == -1);
	CHECK(parse("--time-scale 0", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--time-scale: '0' must be a finite number > 0");
	CHECK(parse("--warmup 0", &o, err, sizeof(err)) == 0 && o.warmup_s == 0.0);
	CHECK(parse("--time-scale 1e-320", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--time-scale: '1e-320' is out of range [1e-6, 1000]");
	CHECK(parse("--time-scale 1e300", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--time-scale: '1e300' is out of range [1e-6, 1000]");
	CHECK(parse("--time-scale nan", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--time-scale: ");
	CHECK(parse("--seed 1.5", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--seed: ");
	CHECK(parse("-j a/b", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "-j: 'a/b' must be letters, digits");
	CHECK(parse("-odo a", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "-laser: missing");
	CHECK(parse("-odo a -laser b -real c --dataset d", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "--dataset: cannot be combined with -odo/-laser/-real");
	CHECK(parse("stray", &o, err, sizeof(err)) == -1);
	CHECK_STR_PREFIX(err, "stray: unexpected argument");
}

/* The run path: the output root as Java's File writes it, whatever slashes -O has. */
static void test_run_dir(void)
{
	static const struct {
		const char *out, *want;
	} cases[] = {
		{ "results", "results/native/nocov/400/SkipTest/1" },
		{ "out/", "out/native/nocov/400/SkipTest/1" },
		{ "a//b///", "a/b/native/nocov/400/SkipTest/1" },
		{ "/", "/native/nocov/400/SkipTest/1" },
		{ "//", "/native/nocov/400/SkipTest/1" },
		{ "/tmp//x", "/tmp/x/native/nocov/400/SkipTest/1" },
	};
	jm_options o;
	char err[512], buf[64];
	size_t i;

	CHECK(parse("run", &o, err, sizeof(err)) == 0);
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		o.out = cases[i].out;
		CHECK(jm_run_dir(&o, buf, sizeof(buf)) == 0 && !strcmp(buf, cases[i].want));
	}
	/* too long for the buffer, in the root or in what follows it */
	o.out = "a-root-of-forty-characters-for-the-test";
	CHECK(jm_run_dir(&o, buf, 40) == -1);
	CHECK(jm_run_dir(&o, buf, 50) == -1);
	CHECK(jm_run_dir(&o, buf, sizeof(buf)) == -1);
	o.out = "short";
	CHECK(jm_run_dir(&o, buf, sizeof(buf)) == 0 && !strcmp(buf, "short/native/nocov/400/SkipTest/1"));
}

static void test_stats(void)
{
	int64_t v[100];
	jm_stats s;
	int i;

	for (i = 0; i < 100; i++)
		v[i] = 100 - i; /* 100 .. 1, unsorted */
	jm_stats_compute(&s, v, 100);
	CHECK(s.count == 100 && s.min == 1 && s.max == 100);
	CHECK(s.p50 == 50 && s.p90 == 90 && s.p99 == 99 && s.p999 == 100);
	CHECK_NEAR(s.mean, 50.5, 1e-12);
	CHECK_NEAR(s.stdev, sqrt((100.0 * 100.0 - 1.0) / 12.0), 1e-9);
	v[0] = 7;
	jm_stats_compute(&s, v, 1);
	CHECK(s.count == 1 && s.p50 == 7 && s.p999 == 7 && s.stdev == 0.0);
	jm_stats_compute(&s, v, 0);
	CHECK(s.count == 0);
}

static void test_json(void)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	jm_json j;

	jm_json_init(&j, f);
	jm_json_open(&j, NULL, '{');
	jm_json_str(&j, "s", "a\"b\\c\nd\te\x01 f/\xc3\xa9");
	jm_json_double(&j, "d", 0.1);
	jm_json_double(&j, "one", 1.0);
	jm_json_double(&j, "nan", NAN);
	jm_json_i64(&j, "i", -42);
	jm_json_open(&j, "empty", '[');
	jm_json_close(&j, ']');
	jm_json_close(&j, '}');
	fclose(f);
	CHECK_CONTAINS(buf, "\"s\": \"a\\\"b\\\\c\\nd\\te\\u0001 f/\xc3\xa9\"");
	CHECK_CONTAINS(buf, "\"d\": 0.1,");
	CHECK_CONTAINS(buf, "\"one\": 1.0,");
	CHECK_CONTAINS(buf, "\"nan\": null,");
	CHECK_CONTAINS(buf, "\"i\": -42,");
	CHECK_CONTAINS(buf, "\"empty\": []\n}");
	free(buf);
}

/*
 * The robot's state after a step of test_policy_rules: the event on the robot (- none), the
 * waiting ones, whether its job is asked to stop, per event its outcome (. pending, s skipped,
 * t terminated) and its abort request time (- none).
 */
static void describe_robot(const struct jm_robot *r, int n, char *buf, size_t size)
{
	size_t len;
	int i;

	len = (size_t)snprintf(buf, size, "run=%d wait=[", r->running);
	for (i = r->head; i < r->tail && len < size; i++)
		len += (size_t)snprintf(buf + len, size - len, i > r->head ? ",%d" : "%d", r->fifo[i]);
	if (len < size)
		len += (size_t)snprintf(buf + len, size - len, "] abort=%d out=",
					atomic_load(&r->abort.requested));
	for (i = 0; i < n && len < size; i++) {
		enum jm_outcome o = r->jobs[i].outcome;

		buf[len++] = o == JM_OUTCOME_SKIPPED ? 's' : o == JM_OUTCOME_TERMINATED ? 't' :
			     o == JM_OUTCOME_PENDING ? '.' : '?';
	}
	for (i = 0; i < n && len < size; i++) {
		int64_t a = r->jobs[i].abort_ns;

		len += (size_t)snprintf(buf + len, size - len, a < 0 ? "%s-" : "%s%" PRId64,
					i ? "," : " req=", a);
	}
	if (len >= size)
		buf[size - 1] = '\0';
	else
		buf[len] = '\0';
}

/*
 * Each policy's rule (policy.h) on one scripted run, without threads or clocks: r releases the
 * next event (event k at 10 (k + 1) ns), s starts the robot's next job if there is one, e ends
 * the running job. The same script for every policy; each row says the state after each step.
 * A policy of policy.h without a row here fails.
 */
#define RULE_SCRIPT "rrsrresreser"
#define RULE_EVENTS 6
static void test_policy_rules(void)
{
	static const char *const want[][sizeof(RULE_SCRIPT) - 1] = {
		[JM_POLICY_SKIP] = {
			/* r */ "run=-1 wait=[0] abort=0 out=...... req=-,-,-,-,-,-",
			/* r: 0 waits to start */ "run=-1 wait=[0] abort=0 out=.s.... req=-,-,-,-,-,-",
			/* s */ "run=0 wait=[] abort=0 out=.s.... req=-,-,-,-,-,-",
			/* r: 0 runs */ "run=0 wait=[] abort=0 out=.ss... req=-,-,-,-,-,-",
			/* r */ "run=0 wait=[] abort=0 out=.sss.. req=-,-,-,-,-,-",
			/* e */ "run=-1 wait=[] abort=0 out=.sss.. req=-,-,-,-,-,-",
			/* s: nothing waits */ "run=-1 wait=[] abort=0 out=.sss.. req=-,-,-,-,-,-",
			/* r: idle robot */ "run=-1 wait=[4] abort=0 out=.sss.. req=-,-,-,-,-,-",
			/* e: nothing ran */ "run=-1 wait=[4] abort=0 out=.sss.. req=-,-,-,-,-,-",
			/* s */ "run=4 wait=[] abort=0 out=.sss.. req=-,-,-,-,-,-",
			/* e */ "run=-1 wait=[] abort=0 out=.sss.. req=-,-,-,-,-,-",
			/* r */ "run=-1 wait=[5] abort=0 out=.sss.. req=-,-,-,-,-,-",
		},
		[JM_POLICY_TERMINATE] = {
			"run=-1 wait=[0] abort=0 out=...... req=-,-,-,-,-,-",
			/* 0 superseded before it started: terminated, its request at 1's release */
			"run=-1 wait=[1] abort=0 out=t..... req=20,-,-,-,-,-",
			"run=1 wait=[] abort=0 out=t..... req=20,-,-,-,-,-",
			/* the running job is asked to stop */
			"run=1 wait=[2] abort=1 out=t..... req=20,30,-,-,-,-",
			"run=1 wait=[3] abort=1 out=t.t... req=20,30,40,-,-,-",
			"run=-1 wait=[3] abort=1 out=t.t... req=20,30,40,-,-,-",
			/* a start clears the request */
			"run=3 wait=[] abort=0 out=t.t... req=20,30,40,-,-,-",
			"run=3 wait=[4] abort=1 out=t.t... req=20,30,40,50,-,-",
			"run=-1 wait=[4] abort=1 out=t.t... req=20,30,40,50,-,-",
			"run=4 wait=[] abort=0 out=t.t... req=20,30,40,50,-,-",
			"run=-1 wait=[] abort=0 out=t.t... req=20,30,40,50,-,-",
			/* an ended job's event is superseded too: its request, nothing to stop */
			"run=-1 wait=[5] abort=0 out=t.t... req=20,30,40,50,60,-",
		},
		[JM_POLICY_QUEUE] = {
			"run=-1 wait=[0] abort=0 out=...... req=-,-,-,-,-,-",
			"run=-1 wait=[0,1] abort=0 out=...... req=-,-,-,-,-,-",
			"run=0 wait=[1] abort=0 out=...... req=-,-,-,-,-,-",
			"run=0 wait=[1,2] abort=0 out=...... req=-,-,-,-,-,-",
			"run=0 wait=[1,2,3] abort=0 out=...... req=-,-,-,-,-,-",
			"run=-1 wait=[1,2,3] abort=0 out=...... req=-,-,-,-,-,-",
			"run=1 wait=[2,3] abort=0 out=...... req=-,-,-,-,-,-",
			"run=1 wait=[2,3,4] abort=0 out=...... req=-,-,-,-,-,-",
			"run=-1 wait=[2,3,4] abort=0 out=...... req=-,-,-,-,-,-",
			"run=2 wait=[3,4] abort=0 out=...... req=-,-,-,-,-,-",
			"run=-1 wait=[3,4] abort=0 out=...... req=-,-,-,-,-,-",
			"run=-1 wait=[3,4,5] abort=0 out=...... req=-,-,-,-,-,-",
		},
	};
	/* missCount from late 1, skipped 2, terminated 4 */
	static const long want_misses[] = {
		[JM_POLICY_SKIP] = 6, [JM_POLICY_TERMINATE] = 6, [JM_POLICY_QUEUE] = 1,
	};
	const int npolicies = (int)(sizeof(jm_policy_table) / sizeof(jm_policy_table[0]));
	int p;

	CHECK_INT((long long)(sizeof(want) / sizeof(want[0])), npolicies);
	CHECK_INT((long long)(sizeof(want_misses) / sizeof(want_misses[0])), npolicies);
	for (p = 0; p < npolicies && p < (int)(sizeof(want) / sizeof(want[0])); p++) {
		jm_job jobs[RULE_EVENTS];
		int fifo[RULE_EVENTS], next = 0, i;
		struct jm_robot r;
		char got[256];

		for (i = 0; i < RULE_EVENTS; i++) {
			jobs[i].outcome = JM_OUTCOME_PENDING;
			jobs[i].abort_ns = -1;
		}
		jm_robot_init(&r, fifo, jobs);
		for (i = 0; RULE_SCRIPT[i]; i++) {
			if (RULE_SCRIPT[i] == 'r') {
				jm_policy_release((enum jm_policy)p, &r, next, 10 * (int64_t)(next + 1));
				next++;
			} else if (RULE_SCRIPT[i] == 's') {
				if (jm_robot_next(&r) >= 0)
					jm_robot_start(&r);
			} else {
				jm_robot_end(&r);
			}
			describe_robot(&r, RULE_EVENTS, got, sizeof(got));
			if (want[p][i] && !strcmp(got, want[p][i]))
				jt_passed++;
			else
				JT_FAIL("%s, step %d (%c): got \"%s\", want \"%s\"", jm_policy_name((enum jm_policy)p),
					i + 1, RULE_SCRIPT[i], got, want[p][i] ? want[p][i] : "(none)");
		}
		if (p < (int)(sizeof(want_misses) / sizeof(want_misses[0])))
			CHECK_INT(jm_policy_misses((enum jm_policy)p, 1, 2, 4), want_misses[p]);
	}
}

int main(void)
{
	if (jt_tempdir(tmpdir, sizeof(tmpdir), "unit"))
		return 1;
	test_rng_reference();
	test_gaussian();
	test_angles();
	test_bearings();
	test_likelihood();
	test_systematic();
	test_multinomial();
	test_init();
	test_termination();
	test_memory_styles_agree();
	test_filter_tracks();
	test_reader();
	test_reader_grammar();
	test_dataset_properties();
	test_options();
	test_run_dir();
	test_stats();
	test_json();
	test_policy_rules();
	if (jm_remove_tree(tmpdir))
		fprintf(stderr, "could not remove %s\n", tmpdir);
	return jt_report();
}
