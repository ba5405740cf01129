/*
 * The C side of the kernel comparison (SPEC 11): time per particle of predict and update jobs
 * on a dataset's own events, single thread, no release timing. Each repetition replays every
 * event of the dataset through a fresh filter; the best and the median repetition are
 * reported, in nanoseconds per particle per job.
 *
 *   build/kernel-bench [--dataset DIR] [--particles N[,N...]] [--repetitions R] [--memory M]
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "dataset.h"
#include "engine.h"
#include "mcl.h"

#define USAGE "usage: kernel-bench [--dataset DIR] [--particles N,N,...] [--repetitions R] " \
	      "[--memory preallocated|allocating]\n"

/* A bad command line: one line naming the option, exit 2 (the usage is --help's). */
static int bad(const char *option, const char *problem, const char *value)
{
	if (value)
		fprintf(stderr, "kernel-bench: %s: %s: '%s'\n", option, problem, value);
	else
		fprintf(stderr, "kernel-bench: %s: %s\n", option, problem);
	return 2;
}

/* A count in [1, max]: digits only, no sign, blank or suffix; -1 otherwise. */
static long count_in(const char *s, long max)
{
	char *end;
	long n;

	if (!*s || strspn(s, "0123456789") != strlen(s) || strlen(s) > 9)
		return -1;
	n = strtol(s, &end, 10);
	return n >= 1 && n <= max ? n : -1;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
	const char *dataset = "../data/match-short", *plist = "100,1000,10000";
	enum jm_memory memory = JM_MEMORY_PREALLOCATED;
	int reps = 5, i;
	char err[PATH_MAX + 256], pbuf[256], *tok, *save = NULL;
	jm_dataset ds;
	jm_timeline tl;

	/*
	 * Each option takes a value. It used to be read with atoi and a default for anything else:
	 * --repetitions x ran 1 repetition, --memory allocatin the preallocated style, a last option
	 * without its value was an "unknown option", and a bad line printed the usage as a second line.
	 */
	for (i = 1; i < argc; i++) {
		const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;

		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			fputs(USAGE, stdout);
			return 0;
		}
		if (strcmp(a, "--dataset") && strcmp(a, "--particles") && strcmp(a, "--repetitions") &&
		    strcmp(a, "--memory"))
			return bad(a, a[0] == '-' ? "unknown option (see --help)" : "unexpected argument (see --help)",
				   NULL);
		if (!v)
			return bad(a, "needs a value", NULL);
		i++;
		if (!strcmp(a, "--dataset")) {
			dataset = v;
		} else if (!strcmp(a, "--particles")) {
			plist = v;
		} else if (!strcmp(a, "--repetitions")) {
			if ((reps = (int)count_in(v, 1000000)) < 0)
				return bad(a, "not a count in [1, 1000000]", v);
		} else if (!strcmp(v, "preallocated") || !strcmp(v, "allocating")) {
			memory = strcmp(v, "allocating") ? JM_MEMORY_PREALLOCATED : JM_MEMORY_ALLOCATING;
		} else {
			return bad(a, "not one of preallocated|allocating", v);
		}
	}
	/* the particle counts before the data: each a count, no empty one */
	if (strlen(plist) >= sizeof(pbuf))
		return bad("--particles", "too long", NULL);
	snprintf(pbuf, sizeof(pbuf), "%s", plist);
	for (tok = pbuf;; tok++) {
		char *comma = strchr(tok, ',');

		if (comma)
			*comma = '\0';
		if (count_in(tok, 100000000) < 0)
			return bad("--particles", "not a count in [1, 100000000]", tok);
		if (!comma)
			break;
		tok = comma;
	}
	if (jm_dataset_load(&ds, dataset, NULL, NULL, NULL, err, sizeof(err))) {
		fprintf(stderr, "kernel-bench: %s\n", err);
		return 2;
	}
	if (jm_timeline_build(&tl, &ds, 1.0, -1.0, 1)) {
		fprintf(stderr, "kernel-bench: out of memory\n");
		return 1;
	}
	printf("# dataset %s: %d predict and %d update jobs a repetition, memory %s, %d repetitions\n",
	       dataset, tl.ntask[0], tl.ntask[1], memory == JM_MEMORY_ALLOCATING ? "allocating" : "preallocated", reps);
	printf("# particles  predict_ns_per_particle(best median)  update_ns_per_particle(best median)  checksum\n");
	snprintf(pbuf, sizeof(pbuf), "%s", plist);
	for (tok = strtok_r(pbuf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
		int n = (int)count_in(tok, 100000000), r, k;
		double *tp = calloc((size_t)reps, sizeof(double)), *tu = calloc((size_t)reps, sizeof(double));
		double checksum = 0.0;

		if (!tp || !tu) {
			fprintf(stderr, "kernel-bench: out of memory\n");
			return 1;
		}
		for (r = 0; r < reps; r++) {
			jm_mcl_config c = { .particles = n, .memory = memory, .seed = 1,
					    .start_x = ds.start_x, .start_y = ds.start_y,
					    .start_theta = ds.start_theta };
			jm_mcl m;
			int64_t sp = 0, su = 0;
			double x, y, t;

			if (jm_mcl_init(&m, &c, &ds.pg)) {
				fprintf(stderr, "kernel-bench: out of memory\n");
				return 1;
			}
			for (k = 0; k < tl.n; k++) {
				const jm_event *e = &tl.events[k];
				int64_t t0 = jm_now_ns();

				if (e->task == JM_TASK_PREDICT) {
					jm_mcl_predict(&m, e->arg[0], e->arg[1], e->arg[2], NULL);
					sp += jm_now_ns() - t0;
				} else {
					jm_mcl_update(&m, e->arg[0], NULL);
					su += jm_now_ns() - t0;
				}
			}
			jm_mcl_estimate(&m, &x, &y, &t);
			checksum = x + y + t; /* keeps the work observable */
			tp[r] = (double)sp / ((double)tl.ntask[0] * n);
			tu[r] = (double)su / ((double)(tl.ntask[1] ? tl.ntask[1] : 1) * n);
			jm_mcl_free(&m);
		}
		qsort(tp, (size_t)reps, sizeof(double), cmp_double);
		qsort(tu, (size_t)reps, sizeof(double), cmp_double);
		printf("%d  %.2f %.2f  %.2f %.2f  %.17g\n", n, tp[0], tp[reps / 2], tu[0], tu[reps / 2], checksum);
		free(tp);
		free(tu);
	}
	jm_timeline_free(&tl);
	jm_dataset_free(&ds);
	return 0;
}
