/* The workload's command line (docs/FORMATS.md 2), the same as the Java workload's. */
#ifndef JM_OPTIONS_H
#define JM_OPTIONS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "mcl.h"
#include "policy.h"

/* A run's parameters; jm_options_parse fills in every default first. */
typedef struct {
	int particles;
	int number;
	const char *runtime_name;
	const char *out;
	const char *odometry, *laser, *real;
	const char *dataset;
	enum jm_policy policy;
	int ideal;
	int covariance;
	enum jm_memory memory;
	enum jm_estimate estimate;
	enum jm_resample resample;
	enum jm_init init;
	int64_t seed;
	double time_scale;
	double warmup_s;
	int spin_us;
	int gc_log;
	int cpu_time; /* per-job thread CPU time (the cpu_ns column); --no-cpu-time clears it */
	int force;
	int fifo;     /* ask for SCHED_FIFO and mlockall (C only; --no-fifo clears it) */
	int help;
	int version;  /* --version: print the build and exit */
} jm_options;

/*
 * Parses argv (argv[0] the program; an optional leading "run" is skipped). Returns 0, or
 * -1 with err holding "<option>: <problem>".
 */
int jm_options_parse(jm_options *o, int argc, char **argv, char *err, size_t errlen);
/*
 * Rewrites the message s (of capacity cap) as one line: every control character (a newline
 * in an argument or a path) as \xHH, as the Java workload's BadInputException does.
 */
void jm_one_line(char *s, size_t cap);
/* One line per option with its unit and default. */
void jm_options_usage(FILE *f);

const char *jm_memory_name(enum jm_memory m);
const char *jm_estimate_name(enum jm_estimate e);
const char *jm_resample_name(enum jm_resample r);
const char *jm_init_name(enum jm_init i);

#endif
