/*
 * Command-line parsing by table. Not getopt_long: the thesis's flags (-odo, -laser, -real)
 * are multi-letter options after a single dash, which getopt_long cannot parse; and both it and
 * getopt_long_only, which could, accept abbreviations (--part for --particles) the Java workload
 * does not.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dataset.h"
#include "options.h"
#include "grammar.h"

enum opt_id {
	OPT_PARTICLES, OPT_NUMBER, OPT_RUNTIME, OPT_OUT, OPT_ODO, OPT_LASER, OPT_REAL, OPT_DATASET,
	OPT_T, OPT_POLICY, OPT_IDEAL, OPT_COV, OPT_MEMORY, OPT_ESTIMATE, OPT_RESAMPLE, OPT_INIT,
	OPT_SEED, OPT_TIME_SCALE, OPT_WARMUP, OPT_SPIN, OPT_GC_LOG, OPT_NO_CPU_TIME, OPT_FORCE, OPT_NO_FIFO, OPT_VERSION, OPT_HELP,
};

struct opt {
	const char *dash;     /* single-dash name, or NULL */
	const char *dashdash; /* long name, or NULL */
	const char *arg;      /* argument name, or NULL for a flag */
	const char *help;
	enum opt_id id;
};

#define JM_MAX_PARTICLES 100000000

static const struct opt options[] = {
	{ "-p", "--particles", "N", "particle count (default 400)", OPT_PARTICLES },
	{ "-n", "--number", "N", "number of the test, the last folder of the run path (default 1)", OPT_NUMBER },
	{ "-j", "--runtime-name", "NAME", "runtime name in the output path (default native)", OPT_RUNTIME },
	{ "-O", "--out", "DIR", "output root (default results)", OPT_OUT },
	{ "-odo", "--odo", "FILE", "thesis-format odometry file: time dx dy dtheta (with -laser, -real)", OPT_ODO },
	{ "-laser", "--laser", "FILE", "thesis-format laser file: time angle (with -odo, -real)", OPT_LASER },
	{ "-real", "--real", "FILE", "thesis-format ground truth: time x y theta (with -odo, -laser)", OPT_REAL },
	{ NULL, "--dataset", "DIR", "dataset folder (default data/match-short under $JMCLBENCH_HOME)", OPT_DATASET },
	{ "-T", NULL, NULL, "shorthand for --policy terminate", OPT_T },
	{ NULL, "--policy", "P", JM_POLICY_LABELS ": an event released while a job runs (default skip)", OPT_POLICY },
	{ NULL, "--ideal", NULL, "one thread, no timing: the infinitely fast computer (default off)", OPT_IDEAL },
	{ "-c", "--covariance", NULL, "compute and write the covariance after each update (default off)", OPT_COV },
	{ NULL, "--memory", "M", "preallocated|allocating: malloc/free per job or not (default preallocated)", OPT_MEMORY },
	{ NULL, "--estimate", "E", "mean|best: weighted mean or best particle (default mean)", OPT_ESTIMATE },
	{ NULL, "--resample", "R", "systematic|multinomial (default systematic)", OPT_RESAMPLE },
	{ NULL, "--init", "I", "known|uniform: around the start pose or over the field (default known)", OPT_INIT },
	{ NULL, "--seed", "N", "generator seed, a signed 64-bit integer (default 1)", OPT_SEED },
	{ NULL, "--time-scale", "F", "multiplies event times and deadlines; 0.5 = twice as fast (1e-6 to 1000, default 1.0)", OPT_TIME_SCALE },
	{ NULL, "--warmup", "S", "first replay the first S seconds and discard them, seconds (default 0)", OPT_WARMUP },
	{ NULL, "--spin-us", "N", "sleep until N microseconds before each release, then spin, us (default 0)", OPT_SPIN },
	{ NULL, "--gc-log", NULL, "keep the runtime's GC log (accepted; C has no GC) (default off)", OPT_GC_LOG },
	{ NULL, "--no-cpu-time", NULL, "no per-job CPU time (cpu_ns -1), two clock reads per job fewer (default: measured)", OPT_NO_CPU_TIME },
	{ NULL, "--force", NULL, "overwrite a complete run folder (default off)", OPT_FORCE },
	{ NULL, "--no-fifo", NULL, "do not ask for SCHED_FIFO and mlockall (C only) (default: ask)", OPT_NO_FIFO },
	{ NULL, "--version", NULL, "print the build (compiler and flags) on one line and exit", OPT_VERSION },
	{ "-h", "--help", NULL, "this help", OPT_HELP },
};

#define NOPTIONS (sizeof(options) / sizeof(options[0]))

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

void jm_one_line(char *s, size_t cap)
{
	size_t i, n = 0, len = strlen(s);
	char *tmp = malloc(len + 1);

	if (!tmp)
		return;
	memcpy(tmp, s, len);
	for (i = 0; i < len && n + 5 < cap; i++) {
		unsigned char c = (unsigned char)tmp[i];

		if (c < 0x20 || c == 0x7f)
			n += (size_t)snprintf(s + n, cap - n, "\\x%02x", c);
		else
			s[n++] = (char)c;
	}
	s[n] = '\0';
	free(tmp);
}

static int fail(char *err, size_t errlen, const char *name, const char *problem, const char *value)
{
	if (value)
		snprintf(err, errlen, "%s: %s: '%s'", name, problem, value);
	else
		snprintf(err, errlen, "%s: %s", name, problem);
	return -1;
}

/* An integer in [lo, hi], with the Java workload's messages. */
static int int_in(const char *name, const char *s, long long lo, long long hi, long long *out, char *err,
		  size_t errlen)
{
	const char *d = s + (*s == '+' || *s == '-');
	char *end;
	long long v;

	/* [+-]?digits and nothing else, as the Java workload: no blanks, no other digits */
	if (!*d || strspn(d, "0123456789") != strlen(d))
		return fail(err, errlen, name, "not an integer", s);
	errno = 0;
	v = strtoll(s, &end, 10);
	if (errno == ERANGE)
		return fail(err, errlen, name, "not an integer", s);
	if (v < lo || v > hi) {
		snprintf(err, errlen, "%s: %lld is out of range [%lld, %lld]", name, v, lo, hi);
		return -1;
	}
	*out = v;
	return 0;
}

/* A finite number > 0 (or >= 0 when zero_ok). */
static int double_in(const char *name, const char *s, int zero_ok, double *out, char *err, size_t errlen)
{
	double v;

	/* the data files' number grammar, as the Java workload: no hex, no inf or nan words, no blanks */
	if (!jm_plain_decimal(s, strlen(s)))
		return fail(err, errlen, name, "not a number", s);
	v = strtod(s, NULL);
	if (!isfinite(v) || v < 0.0 || (!zero_ok && v == 0.0)) {
		snprintf(err, errlen, "%s: '%s' must be a finite number %s", name, s, zero_ok ? ">= 0" : "> 0");
		return -1;
	}
	*out = v;
	return 0;
}

/* Which of the '|'-separated labels v is (its index), or -1 with err set. */
static int choice(const char *name, const char *v, const char *labels, char *err, size_t errlen)
{
	const char *p = labels;
	int i = 0;

	for (;;) {
		const char *bar = strchr(p, '|');
		size_t len = bar ? (size_t)(bar - p) : strlen(p);

		if (strlen(v) == len && !strncmp(v, p, len))
			return i;
		if (!bar)
			break;
		p = bar + 1;
		i++;
	}
	snprintf(err, errlen, "%s: '%s' is not one of %s", name, v, labels);
	return -1;
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
		if (o->dashdash) {
			len = strlen(o->dashdash);
			if (!strncmp(arg, o->dashdash, len) && arg[len] == '=') {
				*inline_value = arg + len + 1;
				return o;
			}
		}
	}
	return NULL;
}

/* A folder of the run path: letters, digits and . _ + - only, so it cannot escape the output root. */
static int runtime_name_ok(const char *s)
{
	const char *p;

	if (!*s || !strcmp(s, ".") || !strcmp(s, ".."))
		return 0;
	for (p = s; *p; p++)
		if (!isalnum((unsigned char)*p) && !strchr("._+-", *p))
			return 0;
	return 1;
}

static int parse(jm_options *o, int argc, char **argv, char *err, size_t errlen);

int jm_options_parse(jm_options *o, int argc, char **argv, char *err, size_t errlen)
{
	int r = parse(o, argc, argv, err, errlen);

	if (r)
		jm_one_line(err, errlen);
	return r;
}

static int parse(jm_options *o, int argc, char **argv, char *err, size_t errlen)
{
	int i = 1, terminate_flag = 0, policy_given = 0;

	memset(o, 0, sizeof(*o));
	o->particles = 400;
	o->number = 1;
	o->runtime_name = "native";
	o->out = "results";
	o->policy = JM_POLICY_SKIP;
	o->seed = 1;
	o->time_scale = 1.0;
	o->fifo = 1;
	o->cpu_time = 1;

	if (argc > 1 && !strcmp(argv[1], "run"))
		i = 2;
	for (; i < argc; i++) {
		const char *arg = argv[i], *value = NULL, *name;
		const struct opt *opt = find(arg, &value);
		long long n;
		double d;
		int c;

		if (!opt) {
			const char *eq = strchr(arg, '=');

			if (arg[0] == '-' && arg[1] == '-' && eq) {
				char head[128];

				snprintf(head, sizeof(head), "%.*s", (int)(eq - arg), arg);
				return fail(err, errlen, head, "unknown option (see --help)", NULL);
			}
			if (arg[0] == '-')
				return fail(err, errlen, arg, "unknown option (see --help)", NULL);
			return fail(err, errlen, arg, "unexpected argument (see --help)", NULL);
		}
		name = value ? opt->dashdash : arg;
		if (!opt->arg && value)
			return fail(err, errlen, name, "takes no value", NULL);
		if (opt->arg && !value) {
			if (i + 1 >= argc)
				return fail(err, errlen, name, "needs a value", NULL);
			value = argv[++i];
		}
		switch (opt->id) {
		case OPT_PARTICLES:
			if (int_in(name, value, 1, JM_MAX_PARTICLES, &n, err, errlen))
				return -1;
			o->particles = (int)n;
			break;
		case OPT_NUMBER:
			if (int_in(name, value, 0, INT_MAX, &n, err, errlen))
				return -1;
			o->number = (int)n;
			break;
		case OPT_RUNTIME:
			if (!runtime_name_ok(value)) {
				snprintf(err, errlen, "%s: '%s' must be letters, digits, '.', '_', '+' or '-'", name, value);
				return -1;
			}
			o->runtime_name = value;
			break;
		case OPT_OUT:
		case OPT_ODO:
		case OPT_LASER:
		case OPT_REAL:
		case OPT_DATASET:
			if (!*value)
				return fail(err, errlen, name, "must not be empty", NULL);
			if (opt->id == OPT_OUT)
				o->out = value;
			else if (opt->id == OPT_ODO)
				o->odometry = value;
			else if (opt->id == OPT_LASER)
				o->laser = value;
			else if (opt->id == OPT_REAL)
				o->real = value;
			else
				o->dataset = value;
			break;
		case OPT_T:
			terminate_flag = 1;
			break;
		case OPT_POLICY:
			if ((c = choice(name, value, JM_POLICY_LABELS, err, errlen)) < 0)
				return -1;
			o->policy = (enum jm_policy)c;
			policy_given = 1;
			break;
		case OPT_IDEAL:
			o->ideal = 1;
			break;
		case OPT_COV:
			o->covariance = 1;
			break;
		case OPT_MEMORY:
			if ((c = choice(name, value, "preallocated|allocating", err, errlen)) < 0)
				return -1;
			o->memory = (enum jm_memory)c;
			break;
		case OPT_ESTIMATE:
			if ((c = choice(name, value, "mean|best", err, errlen)) < 0)
				return -1;
			o->estimate = (enum jm_estimate)c;
			break;
		case OPT_RESAMPLE:
			if ((c = choice(name, value, "systematic|multinomial", err, errlen)) < 0)
				return -1;
			o->resample = (enum jm_resample)c;
			break;
		case OPT_INIT:
			if ((c = choice(name, value, "known|uniform", err, errlen)) < 0)
				return -1;
			o->init = (enum jm_init)c;
			break;
		case OPT_SEED:
			if (int_in(name, value, LLONG_MIN, LLONG_MAX, &n, err, errlen))
				return -1;
			o->seed = (int64_t)n;
			break;
		case OPT_TIME_SCALE:
			if (double_in(name, value, 0, &d, err, errlen))
				return -1;
			/* as the Java workload: below, a deadline rounds to its release; above, the
			 * scaled times leave the clock's range */
			if (d < 1e-6 || d > 1e3) {
				snprintf(err, errlen, "%s: '%s' is out of range [1e-6, 1000]", name, value);
				return -1;
			}
			o->time_scale = d;
			break;
		case OPT_WARMUP:
			if (double_in(name, value, 1, &d, err, errlen))
				return -1;
			o->warmup_s = d;
			break;
		case OPT_SPIN:
			if (int_in(name, value, 0, 1000000, &n, err, errlen))
				return -1;
			o->spin_us = (int)n;
			break;
		case OPT_GC_LOG:
			o->gc_log = 1;
			break;
		case OPT_NO_CPU_TIME:
			o->cpu_time = 0;
			break;
		case OPT_FORCE:
			o->force = 1;
			break;
		case OPT_NO_FIFO:
			o->fifo = 0;
			break;
		case OPT_VERSION:
			o->version = 1;
			break;
		case OPT_HELP:
			o->help = 1;
			break;
		}
	}
	if (o->help || o->version)
		return 0;
	if (terminate_flag) {
		if (policy_given && o->policy != JM_POLICY_TERMINATE) {
			snprintf(err, errlen, "-T: contradicts --policy %s", jm_policy_name(o->policy));
			return -1;
		}
		o->policy = JM_POLICY_TERMINATE;
	}
	if ((o->odometry || o->laser || o->real) && !(o->odometry && o->laser && o->real))
		return fail(err, errlen, !o->odometry ? "-odo" : !o->laser ? "-laser" : "-real",
			    "missing: -odo, -laser and -real go together", NULL);
	if (o->dataset && o->odometry)
		return fail(err, errlen, "--dataset", "cannot be combined with -odo/-laser/-real", NULL);
	/* not recorded among the parameters as if it had been applied (the Java workload's IdealEngine) */
	if (o->ideal && o->spin_us > 0)
		return fail(err, errlen, "--spin-us", "an ideal run has no releases to spin before (--ideal)", NULL);
	return 0;
}
