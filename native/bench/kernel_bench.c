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

	for (i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--dataset") && i + 1 < argc)
			dataset = argv[++i];
		else if (!strcmp(argv[i], "--particles") && i + 1 < argc)
			plist = argv[++i];
		else if (!strcmp(argv[i], "--repetitions") && i + 1 < argc)
			reps = atoi(argv[++i]);
		else if (!strcmp(argv[i], "--memory") && i + 1 < argc)
			memory = strcmp(argv[++i], "allocating") ? JM_MEMORY_PREALLOCATED : JM_MEMORY_ALLOCATING;
		else {
			fprintf(stderr, "jmclbench: %s: unknown option\n"
				"usage: kernel-bench [--dataset DIR] [--particles N,N,...] [--repetitions R] "
				"[--memory preallocated|allocating]\n", argv[i]);
			return 2;
		}
	}
	if (reps < 1)
		reps = 1;
	if (jm_dataset_load(&ds, dataset, NULL, NULL, NULL, err, sizeof(err))) {
		fprintf(stderr, "jmclbench: %s\n", err);
		return 2;
	}
	if (jm_timeline_build(&tl, &ds, 1.0, -1.0, 1)) {
		fprintf(stderr, "jmclbench: out of memory\n");
		return 1;
	}
	printf("# dataset %s: %d predict and %d update jobs a repetition, memory %s, %d repetitions\n",
	       dataset, tl.ntask[0], tl.ntask[1], memory == JM_MEMORY_ALLOCATING ? "allocating" : "preallocated", reps);
	printf("# particles  predict_ns_per_particle(best median)  update_ns_per_particle(best median)  checksum\n");
	snprintf(pbuf, sizeof(pbuf), "%s", plist);
	for (tok = strtok_r(pbuf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
		int n = atoi(tok), r, k;
		double *tp = calloc((size_t)reps, sizeof(double)), *tu = calloc((size_t)reps, sizeof(double));
		double checksum = 0.0;

		if (n <= 0 || !tp || !tu) {
			fprintf(stderr, "jmclbench: --particles: %s: not a positive integer\n", tok);
			return 2;
		}
		for (r = 0; r < reps; r++) {
			jm_mcl_config c = { .particles = n, .memory = memory, .seed = 1,
					    .start_x = ds.start_x, .start_y = ds.start_y,
					    .start_theta = ds.start_theta };
			jm_mcl m;
			int64_t sp = 0, su = 0;
			double x, y, t;

			if (jm_mcl_init(&m, &c, &ds.pg)) {
				fprintf(stderr, "jmclbench: out of memory\n");
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
