/*
 * The C baseline against the conformance vectors (conformance/README.md): the same files the
 * Java workload is tested against, written by an independent reference of ALGORITHM.md.
 *
 * Usage: test_conformance [CONFORMANCE_DIR]   (default ../conformance, as run by make -C native)
 * Prints one line per file and exits 0 when every vector holds, 1 otherwise.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "angles.h"
#include "mcl.h"
#include "rng.h"
#include "stats.h"

#define MAX_TOKENS 1024
#define BEARING_TOL 1e-12
#define MCL_TOL 1e-9

/* One vector file being read: the current line's tokens and where it is. */
struct vfile {
	FILE *f;
	char path[4096];
	int lineno;
	char *buf;
	size_t cap;
	int ntok;
	char *tok[MAX_TOKENS];
};

static int failures;

static void fail(const struct vfile *v, const char *fmt, ...)
{
	va_list ap;

	fprintf(stderr, "%s:%d: ", v->path, v->lineno);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	failures++;
}

static int vopen(struct vfile *v, const char *dir, const char *name)
{
	memset(v, 0, sizeof(*v));
	snprintf(v->path, sizeof(v->path), "%s/%s", dir, name);
	v->f = fopen(v->path, "r");
	if (!v->f) {
		fprintf(stderr, "%s: %s\n", v->path, strerror(errno));
		failures++;
		return -1;
	}
	return 0;
}

static void vclose(struct vfile *v)
{
	if (v->f)
		fclose(v->f);
	free(v->buf);
	v->f = NULL;
	v->buf = NULL;
}

/* Reads the next data line into tokens; 0 at the end of the file. */
static int vnext(struct vfile *v)
{
	for (;;) {
		char *save = NULL, *t, *s;

		if (getline(&v->buf, &v->cap, v->f) < 0)
			return 0;
		v->lineno++;
		s = v->buf;
		while (*s == ' ' || *s == '\t')
			s++;
		if (*s == '#' || *s == '\n' || *s == '\0')
			continue;
		v->ntok = 0;
		for (t = strtok_r(s, " \t\n", &save); t; t = strtok_r(NULL, " \t\n", &save)) {
			if (v->ntok == MAX_TOKENS) {
				fail(v, "more than %d tokens", MAX_TOKENS);
				break;
			}
			v->tok[v->ntok++] = t;
		}
		return 1;
	}
}

static int need(struct vfile *v, int n)
{
	if (v->ntok < n) {
		fail(v, "expected at least %d tokens, found %d", n, v->ntok);
		return -1;
	}
	return 0;
}

static uint64_t hex64(struct vfile *v, int i)
{
	char *end;
	uint64_t u;

	errno = 0;
	u = strtoull(v->tok[i], &end, 16);
	if (errno || *end || strlen(v->tok[i]) != 16)
		fail(v, "token %d is not 16 hex digits: %s", i, v->tok[i]);
	return u;
}

static double hexdouble(struct vfile *v, int i)
{
	uint64_t u = hex64(v, i);
	double d;

	memcpy(&d, &u, sizeof(d));
	return d;
}

static uint64_t bits(double d)
{
	uint64_t u;

	memcpy(&u, &d, sizeof(u));
	return u;
}

static double dec(struct vfile *v, int i)
{
	char *end;
	double d = strtod(v->tok[i], &end);

	if (*end)
		fail(v, "token %d is not a number: %s", i, v->tok[i]);
	return d;
}

static long integer(struct vfile *v, int i)
{
	char *end;
	long l = strtol(v->tok[i], &end, 10);

	if (*end)
		fail(v, "token %d is not an integer: %s", i, v->tok[i]);
	return l;
}

/* Distance of two angles on the circle, in [0, pi]. */
static double circular(double a, double b)
{
	double d = fmod(fabs(a - b), JM_TWO_PI);

	return d < JM_TWO_PI - d ? d : JM_TWO_PI - d;
}

static void report(const char *name, int before, int checked)
{
	printf("conformance %-15s %5d vectors  %s\n", name, checked, failures == before ? "ok" : "FAILED");
}

/* Generators kept per seed while a file lists their outputs in call order. */
struct seeded {
	uint64_t seed;
	jm_rng r;
	long calls;
};

static struct seeded *seeded_get(struct seeded *tab, int *n, uint64_t seed)
{
	for (int i = 0; i < *n; i++)
		if (tab[i].seed == seed)
			return &tab[i];
	tab[*n].seed = seed;
	tab[*n].calls = 0;
	jm_rng_seed(&tab[*n].r, seed);
	return &tab[(*n)++];
}

static void check_rng(const char *dir)
{
	struct vfile v;
	struct seeded tab[64];
	int ntab = 0, checked = 0, before = failures;

	if (vopen(&v, dir, "rng.txt"))
		return;
	while (vnext(&v)) {
		struct seeded *s;
		long call;
		uint64_t got = 0;

		if (need(&v, 3) || ntab == 64)
			break;
		s = seeded_get(tab, &ntab, hex64(&v, 0));
		call = integer(&v, 1);
		if (call < s->calls) {
			fail(&v, "calls must increase per seed");
			continue;
		}
		for (; s->calls <= call; s->calls++)
			got = jm_rng_next(&s->r);
		if (got != hex64(&v, 2))
			fail(&v, "next() = %016llx", (unsigned long long)got);
		checked++;
	}
	vclose(&v);
	report("rng.txt", before, checked);
}

static void check_doubles(const char *dir, const char *name, int gaussian)
{
	struct vfile v;
	struct seeded tab[64];
	int ntab = 0, checked = 0, before = failures;

	if (vopen(&v, dir, name))
		return;
	while (vnext(&v)) {
		struct seeded *s;
		double got;

		if (need(&v, 3) || ntab == 64)
			break;
		s = seeded_get(tab, &ntab, hex64(&v, 0));
		if (integer(&v, 1) != s->calls) {
			fail(&v, "calls are listed in order, without gaps");
			continue;
		}
		got = gaussian ? jm_rng_gaussian(&s->r) : jm_rng_uniform(&s->r);
		s->calls++;
		if (bits(got) != hex64(&v, 2))
			fail(&v, "got %.17g (%016llx)", got, (unsigned long long)bits(got));
		checked++;
	}
	vclose(&v);
	report(name, before, checked);
}

static void check_wrap(const char *dir)
{
	struct vfile v;
	int checked = 0, before = failures;

	if (vopen(&v, dir, "wrap.txt"))
		return;
	while (vnext(&v)) {
		double a, got;

		if (need(&v, 3))
			break;
		a = hexdouble(&v, 1);
		if (!strcmp(v.tok[0], "wrap2pi")) {
			got = jm_wrap2pi(a);
		} else if (!strcmp(v.tok[0], "wrappi")) {
			got = jm_wrappi(a);
		} else {
			fail(&v, "unknown function %s", v.tok[0]);
			continue;
		}
		if (bits(got) != hex64(&v, 2))
			fail(&v, "%s(%.17g) = %.17g (%016llx)", v.tok[0], a, got, (unsigned long long)bits(got));
		checked++;
	}
	vclose(&v);
	report("wrap.txt", before, checked);
}

static void check_bearing(const char *dir)
{
	struct vfile v;
	int checked = 0, before = failures;

	if (vopen(&v, dir, "bearing.txt"))
		return;
	while (vnext(&v)) {
		double got, want;

		if (need(&v, 6))
			break;
		got = jm_bearing(dec(&v, 0), dec(&v, 1), dec(&v, 2), dec(&v, 3), dec(&v, 4));
		want = dec(&v, 5);
		if (!(got >= 0 && got < JM_TWO_PI) || !(circular(got, want) <= BEARING_TOL))
			fail(&v, "bearing %.17g, expected %.17g", got, want);
		checked++;
	}
	vclose(&v);
	report("bearing.txt", before, checked);
}

static void check_likelihood(const char *dir)
{
	struct vfile v;
	jm_playground pg;
	int checked = 0, before = failures;

	jm_playground_default(&pg);
	if (vopen(&v, dir, "likelihood.txt"))
		return;
	while (vnext(&v)) {
		if (!strcmp(v.tok[0], "playground")) {
			long b;

			if (need(&v, 4))
				break;
			b = integer(&v, 3);
			if (b < 1 || b > JM_MAX_BEACONS || need(&v, 4 + 2 * (int)b))
				break;
			memset(&pg, 0, sizeof(pg));
			pg.width = dec(&v, 1);
			pg.height = dec(&v, 2);
			pg.nbeacons = (int)b;
			for (int i = 0; i < b; i++) {
				pg.beacon[i][0] = dec(&v, 4 + 2 * i);
				pg.beacon[i][1] = dec(&v, 5 + 2 * i);
			}
		} else if (!strcmp(v.tok[0], "case")) {
			double got, want, rtol;

			if (need(&v, 7))
				break;
			got = jm_likelihood(dec(&v, 1), dec(&v, 2), dec(&v, 3), dec(&v, 4), &pg);
			want = dec(&v, 5);
			rtol = dec(&v, 6);
			if (!(fabs(got - want) <= rtol * want))
				fail(&v, "likelihood %.17g, expected %.17g (relative %g)", got, want, rtol);
			checked++;
		} else {
			fail(&v, "unknown line %s", v.tok[0]);
		}
	}
	vclose(&v);
	report("likelihood.txt", before, checked);
}

static void check_resample(const char *dir)
{
	struct vfile v;
	int checked = 0, before = failures;

	if (vopen(&v, dir, "resample.txt"))
		return;
	while (vnext(&v)) {
		long n;
		double *w;
		int *got;

		if (need(&v, 2))
			break;
		n = integer(&v, 1);
		if (n < 1 || n > 400 || need(&v, 3 + 2 * (int)n))
			break;
		w = malloc(sizeof(*w) * (size_t)n);
		got = malloc(sizeof(*got) * (size_t)n);
		if (!w || !got) {
			fail(&v, "out of memory");
			free(w);
			free(got);
			break;
		}
		for (int i = 0; i < n; i++)
			w[i] = hexdouble(&v, 3 + i);
		if (!strcmp(v.tok[0], "systematic")) {
			jm_resample_systematic(w, (int)n, hexdouble(&v, 2), got);
		} else if (!strcmp(v.tok[0], "multinomial")) {
			jm_rng r;

			if (need(&v, 4 + 2 * (int)n))
				goto next;
			jm_rng_seed(&r, hex64(&v, 2));
			jm_resample_multinomial(w, (int)n, &r, got);
			if (jm_rng_next(&r) != hex64(&v, 3 + 2 * (int)n))
				fail(&v, "the generator drew other than %ld uniforms", n);
		} else {
			fail(&v, "unknown method %s", v.tok[0]);
			goto next;
		}
		for (int i = 0; i < n; i++) {
			if (got[i] != integer(&v, 3 + (int)n + i)) {
				fail(&v, "new particle %d copies %d, expected %ld", i, got[i],
				     integer(&v, 3 + (int)n + i));
				break;
			}
		}
		checked++;
next:
		free(w);
		free(got);
	}
	vclose(&v);
	report("resample.txt", before, checked);
}

static void near(struct vfile *v, const char *what, double want, double got)
{
	if (!(fabs(got - want) <= MCL_TOL))
		fail(v, "%s = %.17g, expected %.17g", what, got, want);
}

static void near_angle(struct vfile *v, const char *what, double want, double got)
{
	if (!(got >= 0 && got < JM_TWO_PI) || !(circular(got, want) <= MCL_TOL))
		fail(v, "%s = %.17g, expected %.17g", what, got, want);
}

static int parse_enum(struct vfile *v, int i, const char *a, const char *b)
{
	if (!strcmp(v->tok[i], a))
		return 0;
	if (!strcmp(v->tok[i], b))
		return 1;
	fail(v, "expected %s or %s: %s", a, b, v->tok[i]);
	return 0;
}

/* Replays mcl.txt through a filter of one memory style. */
static void check_mcl(const char *dir, enum jm_memory memory)
{
	struct vfile v;
	jm_mcl m;
	jm_playground pg;
	int live = 0, scenarios = 0, checked = 0, before = failures;

	memset(&m, 0, sizeof(m));
	jm_playground_default(&pg);
	if (vopen(&v, dir, "mcl.txt"))
		return;
	while (vnext(&v)) {
		const char *k = v.tok[0];

		if (!strcmp(k, "scenario")) {
			jm_mcl_config c;

			if (need(&v, 11))
				break;
			if (live)
				jm_mcl_free(&m);
			memset(&c, 0, sizeof(c));
			c.particles = (int)integer(&v, 2);
			c.seed = hex64(&v, 3);
			c.estimate = parse_enum(&v, 4, "mean", "best") ? JM_ESTIMATE_BEST : JM_ESTIMATE_MEAN;
			c.resample = parse_enum(&v, 5, "systematic", "multinomial") ? JM_RESAMPLE_MULTINOMIAL
										     : JM_RESAMPLE_SYSTEMATIC;
			c.init = parse_enum(&v, 6, "known", "uniform") ? JM_INIT_UNIFORM : JM_INIT_KNOWN;
			c.covariance = integer(&v, 7) == 1;
			c.memory = memory;
			c.start_x = dec(&v, 8);
			c.start_y = dec(&v, 9);
			c.start_theta = dec(&v, 10);
			if (jm_mcl_init(&m, &c, &pg)) {
				fail(&v, "jm_mcl_init failed");
				break;
			}
			live = 1;
			scenarios++;
		} else if (!live) {
			fail(&v, "%s before any scenario", k);
			break;
		} else if (!strcmp(k, "init") || !strcmp(k, "margin") || !strcmp(k, "end")) {
			continue;
		} else if (!strcmp(k, "predict")) {
			if (need(&v, 4))
				break;
			if (jm_mcl_predict(&m, dec(&v, 1), dec(&v, 2), dec(&v, 3), NULL) != JM_JOB_DONE)
				fail(&v, "predict did not complete");
		} else if (!strcmp(k, "update")) {
			if (need(&v, 2))
				break;
			if (jm_mcl_update(&m, dec(&v, 1), NULL) != JM_JOB_DONE)
				fail(&v, "update did not complete");
		} else if (!strcmp(k, "particle")) {
			const jm_particles *p = jm_mcl_particles(&m);
			long i;

			if (need(&v, 5))
				break;
			i = integer(&v, 1);
			if (i < 0 || i >= m.n) {
				fail(&v, "particle %ld of %d", i, m.n);
				continue;
			}
			near(&v, "x", dec(&v, 2), p->x[i]);
			near(&v, "y", dec(&v, 3), p->y[i]);
			near_angle(&v, "theta", dec(&v, 4), p->th[i]);
			checked++;
		} else if (!strcmp(k, "estimate")) {
			double x, y, th;

			if (need(&v, 4))
				break;
			jm_mcl_estimate(&m, &x, &y, &th);
			near(&v, "x", dec(&v, 1), x);
			near(&v, "y", dec(&v, 2), y);
			near_angle(&v, "theta", dec(&v, 3), th);
			checked++;
		} else if (!strcmp(k, "covariance")) {
			double cov[6];
			static const char *name[6] = { "cxx", "cxy", "cxt", "cyy", "cyt", "ctt" };

			if (need(&v, 7))
				break;
			jm_mcl_covariance(&m, cov);
			for (int i = 0; i < 6; i++)
				near(&v, name[i], dec(&v, 1 + i), cov[i]);
			checked++;
		} else {
			fail(&v, "unknown line %s", k);
		}
	}
	if (live)
		jm_mcl_free(&m);
	if (scenarios < 3) {
		fprintf(stderr, "%s: too few scenarios (%d)\n", v.path, scenarios);
		failures++;
	}
	vclose(&v);
	report(memory == JM_MEMORY_PREALLOCATED ? "mcl.txt (prealloc)" : "mcl.txt (alloc)", before, checked);
}

static enum jm_outcome outcome_of(struct vfile *v, const char *name)
{
	static const char *const names[] = { "pending", "done", "late", "skipped", "terminated" };
	int o;

	for (o = 0; o < 5; o++)
		if (!strcmp(name, names[o]))
			return (enum jm_outcome)o;
	fail(v, "unknown outcome %s", name);
	return JM_OUTCOME_PENDING;
}

/* deadlines.txt: the accounting, released quantiles and abort latency of summary.json, as the Java side computes them. */
static void check_deadlines(const char *dir)
{
	struct vfile v;
	jm_timeline tl = { 0 };
	int checked = 0, before = failures;

	if (vopen(&v, dir, "deadlines.txt"))
		return;
	while (vnext(&v)) {
		jm_task_summary s;
		const char *kind = v.tok[0];
		int task, q;

		if (!strcmp(kind, "case")) {
			if (need(&v, 3))
				break;
			free(tl.events);
			free(tl.jobs);
			memset(&tl, 0, sizeof(tl));
			tl.n = (int)integer(&v, 2);
			tl.events = calloc((size_t)tl.n + 1, sizeof(*tl.events));
			tl.jobs = calloc((size_t)tl.n + 1, sizeof(*tl.jobs));
			for (int k = 0; k < tl.n; k++) {
				if (!vnext(&v) || need(&v, 7) || strcmp(v.tok[0], "job")) {
					fail(&v, "expected a job line");
					goto out;
				}
				tl.events[k].task = strcmp(v.tok[1], "predict") ? JM_TASK_UPDATE : JM_TASK_PREDICT;
				tl.jobs[k].outcome = outcome_of(&v, v.tok[2]);
				tl.jobs[k].release_ns = integer(&v, 3);
				tl.jobs[k].start_ns = integer(&v, 4);
				tl.jobs[k].end_ns = integer(&v, 5);
				tl.jobs[k].abort_ns = integer(&v, 6);
				tl.jobs[k].seen_ns = -1; /* the vectors check the abort latency whole */
				tl.jobs[k].cpu_ns = -1;
			}
			continue;
		}
		if (!strcmp(kind, "end"))
			continue;
		if (need(&v, 10))
			break;
		task = !strcmp(v.tok[1], "all") ? -1 : !strcmp(v.tok[1], "predict") ? JM_TASK_PREDICT : JM_TASK_UPDATE;
		if (jm_task_summary_compute(&s, &tl, task)) {
			fail(&v, "out of memory");
			break;
		}
		if (!strcmp(kind, "count")) {
			long want[6], got[6] = { s.released, s.done, s.late, s.skipped, s.terminated, s.deadline_misses };
			double ratio = jm_miss_ratio(&s);

			for (q = 0; q < 6; q++) {
				want[q] = integer(&v, 2 + q);
				if (want[q] != got[q])
					fail(&v, "column %d: expected %ld, got %ld", 2 + q, want[q], got[q]);
			}
			if (!strcmp(v.tok[8], "null") ? !isnan(ratio) : bits(ratio) != bits(hexdouble(&v, 8)))
				fail(&v, "missRatio: got %.17g", ratio);
		} else if (!strcmp(kind, "response")) {
			if (integer(&v, 2) != s.released || integer(&v, 3) != s.response.count)
				fail(&v, "count/completed: got %ld %ld", s.released, s.response.count);
			for (q = 0; q < JM_RELEASED_QUANTILES; q++) {
				const char *want = v.tok[4 + q];
				char got[32];

				if (s.released == 0)
					snprintf(got, sizeof(got), "null");
				else if (s.released_response[q] == JM_NOT_COMPLETED)
					snprintf(got, sizeof(got), "inf");
				else
					snprintf(got, sizeof(got), "%lld", (long long)s.released_response[q]);
				if (strcmp(want, got))
					fail(&v, "%s: expected %s, got %s", jm_released_names[q], want, got);
			}
		} else if (!strcmp(kind, "abort")) {
			const jm_stats *a = &s.abort_latency;
			int64_t got[6] = { a->min, a->p50, a->p90, a->p99, a->p999, a->max };

			if (integer(&v, 2) != a->count || integer(&v, 3) != s.aborts_completed)
				fail(&v, "count/completed: got %ld %ld", a->count, s.aborts_completed);
			for (q = 0; q < 6; q++) {
				char want[32];

				if (a->count == 0)
					snprintf(want, sizeof(want), "null");
				else
					snprintf(want, sizeof(want), "%lld", (long long)got[q]);
				if (strcmp(v.tok[4 + q], want))
					fail(&v, "abort quantile %d: expected %s, got %s", q, v.tok[4 + q], want);
			}
		} else {
			fail(&v, "unknown line kind %s", kind);
		}
		checked++;
	}
out:
	free(tl.events);
	free(tl.jobs);
	vclose(&v);
	report("deadlines.txt", before, checked);
}

int main(int argc, char **argv)
{
	const char *dir = argc > 1 ? argv[1] : "../conformance";

	check_rng(dir);
	check_doubles(dir, "uniform.txt", 0);
	check_doubles(dir, "gaussian.txt", 1);
	check_wrap(dir);
	check_bearing(dir);
	check_likelihood(dir);
	check_resample(dir);
	check_mcl(dir, JM_MEMORY_PREALLOCATED);
	check_mcl(dir, JM_MEMORY_ALLOCATING);
	check_deadlines(dir);
	if (failures) {
		fprintf(stderr, "conformance: %d failures\n", failures);
		return 1;
	}
	return 0;
}
