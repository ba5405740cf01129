/*
 * The cost of recording one job in the C engines: the C half of bench/record-cost.sh (the Java
 * half is bench/.../RecordCostBenchmark.java under JMH). It calls the engines' own recorder
 * (src/record.h) around an empty job, into job records of RECORD_EVENTS events written in turn,
 * with the thread CPU clock (cpu on, a run's default) and without it (off, --no-cpu-time); beside
 * it the parts: one read of each clock, and the share done while a job holds the robot ("held":
 * start and end; the record itself follows the robot's release). A benchmark, not a test.
 *
 * Like JMH's average-time mode: warm-up iterations, then measured iterations of a fixed
 * duration, each reporting elapsed time / operations; the score is the mean of the measured
 * iterations. The clock is looked at once per BATCH operations, so that its own cost stays out.
 *
 * Output: one '#' header line, then per part
 *   part cpu ns_per_op min_iteration_ns max_iteration_ns ops cpu_share cpu_ns_per_op
 * cpu_share is the thread's CPU time over the wall time of the measured iterations: below about
 * 0.95 the machine was busy and the wall times include waiting for a CPU, which cpu_ns_per_op
 * (the thread's CPU time per operation) does not.
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
#include "engine.h"
#include "record.h"
#include "loop_options.h"

#define RECORD_EVENTS 4096
#define BATCH 256

enum part { PART_RECORD, PART_HELD, PART_NOW, PART_THREAD_CPU };
static const char *const part_names[] = { "record", "held", "nanoTime", "cpuClock" };

/* Keeps the compiler from discarding the clock reads. */
static volatile int64_t sink;

static jm_job jobs[RECORD_EVENTS];

static void usage(FILE *out)
{
	fprintf(out,
		"usage: record-cost [options]\n"
		"  -w, --warmup N           warm-up iterations (default 3)\n"
		"  -i, --iterations N       measured iterations (default 5)\n"
		"  -r, --time S             seconds per iteration (default 1)\n"
		"  -h, --help               this help\n");
}

/* BATCH operations of the part; k is the next event. */
static void batch(enum part p, jm_recorder *rec, int *k)
{
	int64_t s = 0;

	for (int b = 0; b < BATCH; b++) {
		switch (p) {
		case PART_RECORD:
			jm_recorder_start(rec);
			jm_recorder_end(rec);
			jm_recorder_record(rec, &jobs[*k], 1);
			*k = *k + 1 == RECORD_EVENTS ? 0 : *k + 1;
			break;
		case PART_HELD:
			jm_recorder_start(rec);
			jm_recorder_end(rec);
			break;
		case PART_NOW:
			s += jm_now_ns();
			break;
		case PART_THREAD_CPU:
			s += jm_thread_cpu_ns();
			break;
		}
	}
	sink = s + rec->end;
}

static void bench_one(enum part p, int cpu, int warmup, int iterations, double seconds)
{
	int64_t budget = (int64_t)(seconds * 1e9), wall = 0, cpu_ns = 0;
	double sum = 0, min = 0, max = 0;
	long total = 0;
	int k = 0;
	jm_recorder rec;

	for (int i = 0; i < RECORD_EVENTS; i++) {
		jobs[i].deadline_ns = INT64_MAX / 2; /* done, as most jobs of a run are */
		jobs[i].release_ns = 0;
	}
	jm_recorder_init(&rec, cpu, jm_now_ns());
	for (int it = 0; it < warmup + iterations; it++) {
		int64_t start = jm_now_ns(), cpu0 = jm_thread_cpu_ns(), now;
		long ops = 0;
		double per;

		do {
			batch(p, &rec, &k);
			ops += BATCH;
			now = jm_now_ns();
		} while (now - start < budget);
		per = (double)(now - start) / (double)ops;
		if (it < warmup)
			continue;
		wall += now - start;
		cpu_ns += jm_thread_cpu_ns() - cpu0;
		sum += per;
		total += ops;
		if (it == warmup || per < min)
			min = per;
		if (it == warmup || per > max)
			max = per;
	}
	printf("%s %s %.2f %.2f %.2f %ld %.3f %.2f\n", part_names[p], cpu ? "on" : "off", sum / iterations, min,
	       max, total, (double)cpu_ns / (double)wall, (double)cpu_ns / (double)total);
	fflush(stdout);
}

int main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{ "warmup", required_argument, NULL, 'w' },
		{ "iterations", required_argument, NULL, 'i' },
		{ "time", required_argument, NULL, 'r' },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	struct loop_shape shape = { 3, 5, 1.0 };
	int opt;

	opterr = 0; /* with ':' first: loop_options.h's one-line errors, not getopt's */
	while ((opt = getopt_long(argc, argv, ":w:i:r:h", longopts, NULL)) != -1) {
		int taken = loop_shape_option(&shape, opt, optarg);

		if (taken < 0)
			return loop_bad_value("record-cost", opt, optarg);
		if (taken)
			continue;
		if (opt != 'h')
			return loop_getopt_error("record-cost", opt, argv);
		usage(stdout);
		return 0;
	}
	if (loop_no_operands("record-cost", argc, argv))
		return 2;
	if (jm_thread_cpu_ns() < 0) {
		fprintf(stderr, "record-cost: no CLOCK_THREAD_CPUTIME_ID here\n");
		return 1;
	}
	printf("# part cpu ns_per_op min_iteration_ns max_iteration_ns ops cpu_share cpu_ns_per_op  (%d warm-up + %d x %.3g s)\n",
	       shape.warmup, shape.iterations, shape.seconds);
	bench_one(PART_NOW, 0, shape.warmup, shape.iterations, shape.seconds);
	bench_one(PART_THREAD_CPU, 1, shape.warmup, shape.iterations, shape.seconds);
	for (int cpu = 1; cpu >= 0; cpu--) {
		bench_one(PART_RECORD, cpu, shape.warmup, shape.iterations, shape.seconds);
		bench_one(PART_HELD, cpu, shape.warmup, shape.iterations, shape.seconds);
	}
	return 0;
}
