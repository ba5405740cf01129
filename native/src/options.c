/*
 * Command-line parsing by table. Not getopt_long: the thesis's flags (-odo, -laser, -real)
 * are multi-letter options after a single dash, which getopt_long cannot parse, and
 * getopt_long_only would accept abbreviations the Java workload does not.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

enum opt_id {
	OPT_PARTICLES, OPT_NUMBER, OPT_RUNTIME, OPT_OUT, OPT_ODO, OPT_LASER, OPT_REAL, OPT_DATASET,
	OPT_T, OPT_POLICY, OPT_IDEAL, OPT_COV, OPT_MEMORY, OPT_ESTIMATE, OPT_RESAMPLE, OPT_INIT,
	OPT_SEED, OPT_TIME_SCALE, OPT_WARMUP, OPT_SPIN, OPT_GC_LOG, OPT_FORCE, OPT_NO_FIFO, OPT_HELP,
};

struct opt {
	const char *dash;     /* single-dash name, or NULL */
	const char *dashdash; /* long name, or NULL */
	const char *arg;      /* argument name, or NULL for a flag */
	const char *help;
	enum opt_id id;
};

#define JM_MAX_PARTICLES 10000000

static const struct opt options[] = {
	{ "-p", "--particles", "N", "particle count (default 400)", OPT_PARTICLES },
	{ "-n", "--number", "N", "number of the test, the last folder of the run path (default 1)", OPT_NUMBER },
	{ "-j", "--runtime-name", "NAME", "runtime name in the output path (default native)", OPT_RUNTIME },
	{ "-O", "--out", "DIR", "output root (default results)", OPT_OUT },
	{ "-odo", NULL, "FILE", "thesis-format odometry file: time dx dy dtheta (with -laser, -real)", OPT_ODO },
	{ "-laser", NULL, "FILE", "thesis-format laser file: time angle (with -odo, -real)", OPT_LASER },
	{ "-real", NULL, "FILE", "thesis-format ground truth: time x y theta (with -odo, -laser)", OPT_REAL },
	{ NULL, "--dataset", "DIR", "dataset folder (default datasets/match-short under $JMCLBENCH_HOME)", OPT_DATASET },
	{ "-T", NULL, NULL, "shorthand for --policy terminate", OPT_T },
	{ NULL, "--policy", "P", "skip|terminate|queue: an event released while a job runs (default skip)", OPT_POLICY },
	{ NULL, "--ideal", NULL, "one thread, no timing: the infinitely fast computer (default off)", OPT_IDEAL },
	{ "-c", "--covariance", NULL, "compute and write the covariance after each update (default off)", OPT_COV },
	{ NULL, "--memory", "M", "preallocated|allocating: malloc/free per job or not (default preallocated)", OPT_MEMORY },
	{ NULL, "--estimate", "E", "mean|best: weighted mean or best particle (default mean)", OPT_ESTIMATE },
	{ NULL, "--resample", "R", "systematic|multinomial (default systematic)", OPT_RESAMPLE },
	{ NULL, "--init", "I", "known|uniform: around the start pose or over the field (default known)", OPT_INIT },
	{ NULL, "--seed", "N", "generator seed, a signed 64-bit integer (default 1)", OPT_SEED },
	{ NULL, "--time-scale", "F", "multiplies event times and deadlines; 0.5 = twice as fast (default 1.0)", OPT_TIME_SCALE },
	{ NULL, "--warmup", "S", "first replay the first S seconds and discard them, seconds (default 0)", OPT_WARMUP },
	{ NULL, "--spin-us", "N", "sleep until N microseconds before each release, then spin, us (default 0)", OPT_SPIN },
	{ NULL, "--gc-log", NULL, "keep the runtime's GC log (accepted; C has no GC) (default off)", OPT_GC_LOG },
	{ NULL, "--force", NULL, "overwrite a complete run folder (default off)", OPT_FORCE },
	{ NULL, "--no-fifo", NULL, "do not ask for SCHED_FIFO and mlockall (C only) (default: ask)", OPT_NO_FIFO },
	{ "-h", "--help", NULL, "this help", OPT_HELP },
};

#define NOPTIONS (sizeof(options) / sizeof(options[0]))

const char *jm_policy_name(enum jm_policy p)
{
	return p == JM_POLICY_TERMINATE ? "terminate" : p == JM_POLICY_QUEUE ? "queue" : "skip";
}

const char *jm_memory_name(enum jm_memory m)
{
	return m == JM_MEMORY_ALLOCATING ? "allocating" : "preallocated";
}

const char *jm_estimate_name(enum jm_estimate e)
{
	return e == JM_ESTIMATE_BEST ? "best" : "mean";
}

const char *jm_resample_name(enum jm_resample r)
{
	return r == JM_RESAMPLE_MULTINOMIAL ? "multinomial" : "systematic";
}

const char *jm_init_name(enum jm_init i)
{
	return i == JM_INIT_UNIFORM ? "uniform" : "known";
}

void jm_options_usage(FILE *f)
{
	size_t i;

	fprintf(f, "usage: jmclbench-native [run] [options]\n"
		   "Replays a dataset on its real timeline through the MCL particle filter and writes\n"
		   "<out>/<runtime>/<cov|nocov>/<particles>/<SkipTest|TermTest|QueueTest|IdealTest>/<n>/.\n\n");
	for (i = 0; i < NOPTIONS; i++) {
		const struct opt *o = &options[i];
		char names[64];

		snprintf(names, sizeof(names), "%s%s%s%s%s", o->dash ? o->dash : "",
			 o->dash && o->dashdash ? ", " : "", o->dashdash ? o->dashdash : "",
			 o->arg ? " " : "", o->arg ? o->arg : "");
		fprintf(f, "  %-24s %s\n", names, o->help);
	}
	fprintf(f, "\nExit codes: 0 success, 2 bad usage or bad input, 1 a failure of the benchmark.\n");
}

static int fail(char *err, size_t errlen, const char *name, const char *problem, const char *value)
{
	if (value)
		snprintf(err, errlen, "%s: %s: %s", name, problem, value);
	else
		snprintf(err, errlen, "%s: %s", name, problem);
	return -1;
}

static int parse_long(const char *s, long long lo, long long hi, long long *out)
{
	char *end;
	long long v;

	errno = 0;
	v = strtoll(s, &end, 10);
	if (end == s || *end != '\0' || errno == ERANGE || v < lo || v > hi)
		return -1;
	*out = v;
	return 0;
}

static int parse_double(const char *s, double *out)
{
	char *end;
	double v = strtod(s, &end);

	if (end == s || *end != '\0' || !isfinite(v))
		return -1;
	*out = v;
	return 0;
}

static const struct opt *find(const char *arg, const char **inline_value)
{
	size_t i;

	*inline_value = NULL;
	for (i = 0; i < NOPTIONS; i++) {
		const struct opt *o = &options[i];
		size_t len;

		if ((o->dash && !strcmp(arg, o->dash)) || (o->dashdash && !strcmp(arg, o->dashdash)))
			return o;
		if (o->dashdash && o->arg) {
			len = strlen(o->dashdash);
			if (!strncmp(arg, o->dashdash, len) && arg[len] == '=') {
				*inline_value = arg + len + 1;
				return o;
			}
		}
	}
	return NULL;
}

static int runtime_name_ok(const char *s)
{
	const char *p;

	if (!*s || !strcmp(s, ".") || !strcmp(s, "..") || strlen(s) > 100)
		return 0;
	for (p = s; *p; p++)
		if (*p == '/' || (unsigned char)*p < 0x20 || *p == 0x7f)
			return 0;
	return 1;
}

int jm_options_parse(jm_options *o, int argc, char **argv, char *err, size_t errlen)
{
	int i = 1;

	memset(o, 0, sizeof(*o));
	o->particles = 400;
	o->number = 1;
	o->runtime_name = "native";
	o->out = "results";
	o->policy = JM_POLICY_SKIP;
	o->seed = 1;
	o->time_scale = 1.0;
	o->fifo = 1;

	if (argc > 1 && !strcmp(argv[1], "run"))
		i = 2;
	for (; i < argc; i++) {
		const char *arg = argv[i], *value = NULL, *name;
		const struct opt *opt = find(arg, &value);
		long long n;
		double d;

		if (!opt) {
			if (arg[0] == '-')
				return fail(err, errlen, arg, "unknown option (see --help)", NULL);
			return fail(err, errlen, arg, "unexpected argument (see --help)", NULL);
		}
		name = value ? opt->dashdash : arg;
		if (opt->arg && !value) {
			if (i + 1 >= argc)
				return fail(err, errlen, name, "needs a value", opt->arg);
			value = argv[++i];
		}
		switch (opt->id) {
		case OPT_PARTICLES:
			if (parse_long(value, 1, JM_MAX_PARTICLES, &n))
				return fail(err, errlen, name, "not an integer in 1..10000000", value);
			o->particles = (int)n;
			break;
		case OPT_NUMBER:
			if (parse_long(value, 0, INT_MAX, &n))
				return fail(err, errlen, name, "not a non-negative integer", value);
			o->number = (int)n;
			break;
		case OPT_RUNTIME:
			if (!runtime_name_ok(value))
				return fail(err, errlen, name, "not usable as a folder name", value);
			o->runtime_name = value;
			break;
		case OPT_OUT:
			if (!*value)
				return fail(err, errlen, name, "empty path", NULL);
			o->out = value;
			break;
		case OPT_ODO:
			o->odometry = value;
			break;
		case OPT_LASER:
			o->laser = value;
			break;
		case OPT_REAL:
			o->real = value;
			break;
		case OPT_DATASET:
			if (!*value)
				return fail(err, errlen, name, "empty path", NULL);
			o->dataset = value;
			break;
		case OPT_T:
			o->policy = JM_POLICY_TERMINATE;
			break;
		case OPT_POLICY:
			if (!strcmp(value, "skip"))
				o->policy = JM_POLICY_SKIP;
			else if (!strcmp(value, "terminate"))
				o->policy = JM_POLICY_TERMINATE;
			else if (!strcmp(value, "queue"))
				o->policy = JM_POLICY_QUEUE;
			else
				return fail(err, errlen, name, "expected skip, terminate or queue, got", value);
			break;
		case OPT_IDEAL:
			o->ideal = 1;
			break;
		case OPT_COV:
			o->covariance = 1;
			break;
		case OPT_MEMORY:
			if (!strcmp(value, "preallocated"))
				o->memory = JM_MEMORY_PREALLOCATED;
			else if (!strcmp(value, "allocating"))
				o->memory = JM_MEMORY_ALLOCATING;
			else
				return fail(err, errlen, name, "expected preallocated or allocating, got", value);
			break;
		case OPT_ESTIMATE:
			if (!strcmp(value, "mean"))
				o->estimate = JM_ESTIMATE_MEAN;
			else if (!strcmp(value, "best"))
				o->estimate = JM_ESTIMATE_BEST;
			else
				return fail(err, errlen, name, "expected mean or best, got", value);
			break;
		case OPT_RESAMPLE:
			if (!strcmp(value, "systematic"))
				o->resample = JM_RESAMPLE_SYSTEMATIC;
			else if (!strcmp(value, "multinomial"))
				o->resample = JM_RESAMPLE_MULTINOMIAL;
			else
				return fail(err, errlen, name, "expected systematic or multinomial, got", value);
			break;
		case OPT_INIT:
			if (!strcmp(value, "known"))
				o->init = JM_INIT_KNOWN;
			else if (!strcmp(value, "uniform"))
				o->init = JM_INIT_UNIFORM;
			else
				return fail(err, errlen, name, "expected known or uniform, got", value);
			break;
		case OPT_SEED:
			if (parse_long(value, LLONG_MIN, LLONG_MAX, &n))
				return fail(err, errlen, name, "not a 64-bit integer", value);
			o->seed = (int64_t)n;
			break;
		case OPT_TIME_SCALE:
			if (parse_double(value, &d) || d <= 0.0 || d > 1000.0)
				return fail(err, errlen, name, "not a number in (0, 1000]", value);
			o->time_scale = d;
			break;
		case OPT_WARMUP:
			if (parse_double(value, &d) || d < 0.0)
				return fail(err, errlen, name, "not a non-negative number of seconds", value);
			o->warmup_s = d;
			break;
		case OPT_SPIN:
			if (parse_long(value, 0, 1000000, &n))
				return fail(err, errlen, name, "not an integer in 0..1000000 (microseconds)", value);
			o->spin_us = (int)n;
			break;
		case OPT_GC_LOG:
			o->gc_log = 1;
			break;
		case OPT_FORCE:
			o->force = 1;
			break;
		case OPT_NO_FIFO:
			o->fifo = 0;
			break;
		case OPT_HELP:
			o->help = 1;
			return 0;
		}
	}
	if (o->dataset && (o->odometry || o->laser || o->real))
		return fail(err, errlen, "--dataset", "cannot be combined with -odo, -laser, -real", NULL);
	if ((o->odometry || o->laser || o->real) && !(o->odometry && o->laser && o->real))
		return fail(err, errlen, !o->odometry ? "-odo" : !o->laser ? "-laser" : "-real",
			    "missing: -odo, -laser and -real go together", NULL);
	return 0;
}
