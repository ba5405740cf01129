/*
 * The command line the C timing loops share (kernel_jobs.c, record_cost.c): the iteration shape
 * JMH's -wi, -i and -r give (bench/options.sh's c_loop_shape passes them), and the one-line
 * errors of getopt run with ':' first and opterr 0, so that a missing value or an unknown option
 * is one line of ours, exit 2, not getopt's message and the whole usage on stderr.
 */
#ifndef JM_BENCH_LOOP_OPTIONS_H
#define JM_BENCH_LOOP_OPTIONS_H

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Warm-up iterations, measured iterations and the seconds of each. */
struct loop_shape {
	int warmup;
	int iterations;
	double seconds;
};

/*
 * Option opt of the shape ('w', 'i' or 'r') with value arg into s: 1 when taken, -1 when its value
 * is bad, 0 when opt is not one of them.
 */
static inline int loop_shape_option(struct loop_shape *s, int opt, const char *arg)
{
	char *end = NULL;

	switch (opt) {
	case 'w':
		s->warmup = (int)strtol(arg, &end, 10);
		return *arg && !*end && s->warmup >= 0 && s->warmup <= 1000000 ? 1 : -1;
	case 'i':
		s->iterations = (int)strtol(arg, &end, 10);
		return *arg && !*end && s->iterations >= 1 && s->iterations <= 1000000 ? 1 : -1;
	case 'r':
		/* finite: an infinite iteration would never end */
		s->seconds = strtod(arg, &end);
		return *arg && !*end && s->seconds > 0 && isfinite(s->seconds) ? 1 : -1;
	default:
		return 0;
	}
}

/* Prints the one line for getopt's ':' (a missing value) or '?' (an unknown option); returns 2. */
static inline int loop_getopt_error(const char *prog, int opt, char **argv)
{
	if (opt == ':')
		fprintf(stderr, "%s: %s: needs a value\n", prog, argv[optind - 1]);
	else if (optopt)
		fprintf(stderr, "%s: -%c: unknown option (see --help)\n", prog, optopt);
	else
		fprintf(stderr, "%s: %s: unknown option (see --help)\n", prog, argv[optind - 1]);
	return 2;
}

/* Prints the one line for a bad value of option opt; returns 2. */
static inline int loop_bad_value(const char *prog, int opt, const char *arg)
{
	fprintf(stderr, "%s: -%c: bad value '%s'\n", prog, opt, arg);
	return 2;
}

/* 2 with one line when an argument is left after the options, else 0. */
static inline int loop_no_operands(const char *prog, int argc, char **argv)
{
	if (optind < argc) {
		fprintf(stderr, "%s: %s: unexpected argument (see --help)\n", prog, argv[optind]);
		return 2;
	}
	return 0;
}

#endif
