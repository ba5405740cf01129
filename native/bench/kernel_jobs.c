/*
 * Time per job of the C MCL kernel: the C half of the Java/C comparison of SPEC section 11
 * (the Java half is bench/.../KernelBenchmark.java under JMH; bench/kernel-ratio.sh divides).
 *
 * The same work as the JMH benchmark: for each job kind (predict, update), particle count and
 * memory style, a fresh filter (seed 1, known start from the dataset) replays that kind's
 * events of the dataset in order, wrapping around. Like JMH's average-time mode: warm-up
 * iterations, then measured iterations of a fixed duration, each reporting elapsed time / jobs;
 * the score is the mean of the measured iterations. A benchmark, not a test.
 *
 * Output: one '#' header line, then per configuration
 *   job particles memory ns_per_job min_iteration_ns max_iteration_ns jobs cpu_share cpu_ns_per_job
 * cpu_share is the thread's CPU time over the wall time of the measured iterations: below
 * about 0.95 the machine was busy and the wall times include waiting for a CPU, which
 * cpu_ns_per_job (the thread's CPU time per job) does not.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "dataset.h"
#include "mcl.h"
#include "loop_options.h"

#define MAX_COUNTS 16

struct bench_opts {
	const char *dataset;
	int counts[MAX_COUNTS];
	int ncounts;
	int memory_mask; /* bit 0 preallocated, bit 1 allocating */
	int job_mask;    /* bit 0 predict, bit 1 update */
	struct loop_shape shape;
};

/* Keeps the compiler from discarding the jobs' results. */
static volatile double sink;

static void usage(FILE *out)
{
	fprintf(out,
		"usage: kernel-jobs [options]\n"
		"  -d, --dataset DIR        dataset folder (default ../data/match-short)\n"
		"  -p, --particles N[,N..]  particle counts (default 1000,4000)\n"
		"  -m, --memory STYLE       preallocated, allocating or both (default both)\n"
		"  -j, --job KIND           predict, update or both (default both)\n"
		"  -w, --warmup N           warm-up iterations (default 3)\n"
		"  -i, --iterations N       measured iterations (default 5)\n"
		"  -r, --time S             seconds per iteration (default 1)\n"
		"  -h, --help               this help\n");
}

/* The bit mask that value names: bit 0 for "first", bit 1 for "second", both for "both"; 0 for anything else. */
static int mask_of(const char *value, const char *first, const char *second)
{
	if (!strcmp(value, first))
		return 1;
	if (!strcmp(value, second))
		return 2;
	if (!strcmp(value, "both"))
		return 3;
	return 0;
}

static int parse_counts(struct bench_opts *o, char *s)
{
	char *save = NULL;

	o->ncounts = 0;
	for (char *t = strtok_r(s, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
		char *end;
		long n = strtol(t, &end, 10);

		if (*end || n < 1 || n > 10000000 || o->ncounts == MAX_COUNTS)
			return -1;
		o->counts[o->ncounts++] = (int)n;
	}
	return o->ncounts ? 0 : -1;
}

/* Runs one job of the given kind on event k (wrapping); returns the next k. */
static int one_job(jm_mcl *m, const jm_dataset *ds, int update, int k)
{
	double x, y, th;

	if (update) {
		jm_mcl_update(m, JM_ROW(&ds->laser, k)[1], NULL);
		k = k + 1 == ds->laser.n ? 0 : k + 1;
	} else {
		const double *r = JM_ROW(&ds->odometry, k);

		jm_mcl_predict(m, r[1], r[2], r[3], NULL);
		k = k + 1 == ds->odometry.n ? 0 : k + 1;
	}
	jm_mcl_estimate(m, &x, &y, &th);
	sink = x;
	return k;
}

/* One configuration: returns 0, or -1 when the filter cannot be built. */
static int bench_one(const struct bench_opts *o, const jm_dataset *ds, int update, int n,
		     enum jm_memory memory)
{
	jm_mcl m;
	jm_mcl_config c;
	int64_t budget = (int64_t)(o->shape.seconds * 1e9);
	double sum = 0, min = 0, max = 0;
	int64_t wall = 0, cpu = 0;
	long total = 0;
	int k = 0;

	memset(&c, 0, sizeof(c));
	memset(&m, 0, sizeof(m));
	c.particles = n;
	c.memory = memory;
	c.estimate = JM_ESTIMATE_MEAN;
	c.resample = JM_RESAMPLE_SYSTEMATIC;
	c.init = JM_INIT_KNOWN;
	c.seed = 1;
	c.start_x = ds->start_x;
	c.start_y = ds->start_y;
	c.start_theta = ds->start_theta;
	if (jm_mcl_init(&m, &c, &ds->pg))
		return -1;
	for (int it = 0; it < o->shape.warmup + o->shape.iterations; it++) {
		int64_t start = jm_now_ns(), cpu0 = jm_thread_cpu_ns(), now;
		long jobs = 0;
		double per;

		do {
			k = one_job(&m, ds, update, k);
			jobs++;
			now = jm_now_ns();
		} while (now - start < budget);
		per = (double)(now - start) / (double)jobs;
		if (it < o->shape.warmup)
			continue;
		wall += now - start;
		cpu += jm_thread_cpu_ns() - cpu0;
		sum += per;
		total += jobs;
		if (it == o->shape.warmup || per < min)
			min = per;
		if (it == o->shape.warmup || per > max)
			max = per;
	}
	jm_mcl_free(&m);
	printf("%s %d %s %.1f %.1f %.1f %ld %.3f %.1f\n", update ? "update" : "predict", n,
	       memory == JM_MEMORY_PREALLOCATED ? "preallocated" : "allocating", sum / o->shape.iterations,
	       min, max, total, (double)cpu / (double)wall, (double)cpu / (double)total);
	fflush(stdout);
	return 0;
}

int main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{ "dataset", required_argument, NULL, 'd' },
		{ "particles", required_argument, NULL, 'p' },
		{ "memory", required_argument, NULL, 'm' },
		{ "job", required_argument, NULL, 'j' },
		{ "warmup", required_argument, NULL, 'w' },
		{ "iterations", required_argument, NULL, 'i' },
		{ "time", required_argument, NULL, 'r' },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	struct bench_opts o = { "../data/match-short", { 1000, 4000 }, 2, 3, 3, { 3, 5, 1.0 } };
	jm_dataset ds;
	char err[PATH_MAX + 256];
	int opt, rc = 0;

	opterr = 0; /* with ':' first: loop_options.h's one-line errors, not getopt's */
	while ((opt = getopt_long(argc, argv, ":d:p:m:j:w:i:r:h", longopts, NULL)) != -1) {
		switch (opt) {
		case 'd':
			o.dataset = optarg;
			break;
		case 'p':
			if (parse_counts(&o, optarg))
				goto bad;
			break;
		case 'm':
			if (!(o.memory_mask = mask_of(optarg, "preallocated", "allocating")))
				goto bad;
			break;
		case 'j':
			if (!(o.job_mask = mask_of(optarg, "predict", "update")))
				goto bad;
			break;
		case 'h':
			usage(stdout);
			return 0;
		default:
			switch (loop_shape_option(&o.shape, opt, optarg)) {
			case 1:
				continue;
			case -1:
				goto bad;
			}
			return loop_getopt_error("kernel-jobs", opt, argv);
		}
		continue;
bad:
		return loop_bad_value("kernel-jobs", opt, optarg);
	}
	if (loop_no_operands("kernel-jobs", argc, argv))
		return 2;
	if (jm_dataset_load(&ds, o.dataset, NULL, NULL, NULL, err, sizeof(err))) {
		fprintf(stderr, "kernel-jobs: %s\n", err);
		return 2;
	}
	printf("# job particles memory ns_per_job min_iteration_ns max_iteration_ns jobs cpu_share cpu_ns_per_job"
	       "  (dataset %s, %d warm-up + %d x %.3g s)\n", o.dataset, o.shape.warmup, o.shape.iterations,
	       o.shape.seconds);
	for (int update = 0; update <= 1 && !rc; update++)
		for (int c = 0; c < o.ncounts && !rc; c++)
			for (int mem = 0; mem <= 1 && !rc; mem++)
				if (o.job_mask & (1 << update) && o.memory_mask & (1 << mem) &&
				    bench_one(&o, &ds, update, o.counts[c],
					      mem ? JM_MEMORY_ALLOCATING : JM_MEMORY_PREALLOCATED)) {
					fprintf(stderr, "kernel-jobs: out of memory\n");
					rc = 1;
				}
	jm_dataset_free(&ds);
	return rc;
}
