/*
 * jmclbench-native: the C baseline of the jmclbench workload. Same command line, data
 * formats, algorithm, policies and run folder as the Java workload (docs/FORMATS.md,
 * docs/ALGORITHM.md): what a C programmer would get on this machine.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdnoreturn.h>
#include <string.h>
#include <limits.h>
#include <sys/stat.h>

#include "dataset.h"
#include "engine.h"
#include "env.h"
#include "mcl.h"
#include "options.h"
#include "output.h"

#ifndef JM_CFLAGS
#define JM_CFLAGS ""
#endif
#if defined(__clang__)
#define JM_COMPILER "clang " __VERSION__
#elif defined(__GNUC__)
#define JM_COMPILER "gcc " __VERSION__
#else
#define JM_COMPILER __VERSION__
#endif

#define EXIT_BAD_INPUT 2
#define EXIT_BENCH_FAILURE 1

/* One line on stderr and the exit code: 2 for bad usage or input, 1 for our own failure. */
static noreturn void die(int code, const char *fmt, ...)
{
	char msg[PATH_MAX + 512];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	jm_one_line(msg, sizeof(msg));
	fprintf(stderr, "jmclbench: %s\n", msg);
	exit(code);
}

static void mcl_config(jm_mcl_config *c, const jm_options *o, const jm_dataset *ds)
{
	memset(c, 0, sizeof(*c));
	c->particles = o->particles;
	c->memory = o->memory;
	c->estimate = o->estimate;
	c->resample = o->resample;
	c->init = o->init;
	c->covariance = o->covariance;
	c->seed = (uint64_t)o->seed;
	c->start_x = ds->start_x;
	c->start_y = ds->start_y;
	c->start_theta = ds->start_theta;
}

/* --gc-log: the file the run folder promises, saying why it holds no log. */
static int write_gc_note(const char *dir)
{
	char path[PATH_MAX + 64];
	FILE *f;

	snprintf(path, sizeof(path), "%s/gc.log", dir);
	f = fopen(path, "w");
	if (!f)
		return -1;
	fputs("# no GC log: the native runtime has no garbage collector\n", f);
	return fclose(f);
}

static int run_timeline(jm_mcl *m, jm_timeline *tl, const jm_options *o, jm_sched_info *info)
{
	if (o->ideal)
		return jm_run_ideal(m, tl, o->cpu_time, info);
	return jm_run_realtime(m, tl, o->policy, o->spin_us, o->fifo, o->cpu_time, info);
}

int main(int argc, char **argv)
{
	char err[PATH_MAX + 256], final_dir[PATH_MAX], partial[PATH_MAX + 16], replaced[PATH_MAX + 32] = "";
	char default_dataset[PATH_MAX];
	jm_options opt;
	jm_dataset ds;
	jm_mcl mcl;
	jm_mcl_config cfg;
	jm_timeline tl = { 0 };
	jm_sched_info sched = { 0 };
	jm_env env;
	jm_run run;
	struct stat st;
	const char *dataset_dir = NULL, *home;
	int ret = EXIT_BENCH_FAILURE;

	if (jm_options_parse(&opt, argc, argv, err, sizeof(err)))
		die(EXIT_BAD_INPUT, "%s", err);
	if (opt.help) {
		jm_options_usage(stdout);
		return 0;
	}
	if (opt.version) {
		printf("jmclbench-native %s (%s)\n", JM_COMPILER, JM_CFLAGS);
		return 0;
	}
	/*
	 * -j becomes one folder of the run path: a name longer than a folder name may be would fail
	 * later as "-O: path too long" or "-O: cannot create", blaming the output root for it.
	 */
	if (strlen(opt.runtime_name) > NAME_MAX)
		die(EXIT_BAD_INPUT, "-j: %zu characters, longer than a folder name may be (%d)",
		    strlen(opt.runtime_name), NAME_MAX);
	if (!opt.odometry) {
		dataset_dir = opt.dataset;
		if (!dataset_dir) {
			home = getenv("JMCLBENCH_HOME");
			snprintf(default_dataset, sizeof(default_dataset), "%s%sdata/match-short",
				 home && *home ? home : "", home && *home ? "/" : "");
			dataset_dir = default_dataset;
		}
	}
	if (jm_dataset_load(&ds, dataset_dir, opt.odometry, opt.laser, opt.real, err, sizeof(err)) ||
	    jm_dataset_check_time_scale(&ds, opt.time_scale, err, sizeof(err)) ||
	    jm_dataset_check_warmup(&ds, opt.warmup_s, err, sizeof(err)))
		die(EXIT_BAD_INPUT, "%s", err);

	if (jm_run_dir(&opt, final_dir, sizeof(final_dir)))
		die(EXIT_BAD_INPUT, "-O: path too long: %s", opt.out);
	snprintf(partial, sizeof(partial), "%s.partial", final_dir);
	if (stat(final_dir, &st) == 0 && !opt.force)
		die(EXIT_BAD_INPUT, "%s: a complete run folder exists (use --force to overwrite)", final_dir);
	/* the empty <n>.partial/ now, so that a place that cannot be written fails before the run */
	if (stat(partial, &st) == 0 && jm_remove_tree(partial))
		die(EXIT_BENCH_FAILURE, "%s: cannot remove what an earlier attempt left: %s", partial, strerror(errno));
	if (jm_mkdirs(partial))
		die(EXIT_BAD_INPUT, "-O: cannot create %s: %s", partial, strerror(errno));

	jm_env_read(&env);
	mcl_config(&cfg, &opt, &ds);
	if (!opt.ideal && opt.fifo)
		jm_lock_memory(&sched);
	else
		sched.mlock_note = opt.ideal ? "ideal run" : "not requested";

	if (opt.warmup_s > 0.0) {
		/*
		 * As the Java workload: the first seconds on a throwaway filter, then start afresh;
		 * ideal runs replay the events up to that time, real-time runs those released before
		 * it through the same engine.
		 */
		if (jm_mcl_init(&mcl, &cfg, &ds.pg) ||
		    jm_timeline_build(&tl, &ds, opt.time_scale, opt.warmup_s, opt.ideal))
			die(EXIT_BENCH_FAILURE, "out of memory");
		if (run_timeline(&mcl, &tl, &opt, &sched))
			die(EXIT_BENCH_FAILURE, "the warm-up failed (out of memory or no threads)");
		sched.warmup_events = tl.n;
		jm_timeline_free(&tl);
		jm_mcl_free(&mcl);
	}
	if (jm_mcl_init(&mcl, &cfg, &ds.pg) || jm_timeline_build(&tl, &ds, opt.time_scale, -1.0, 1))
		die(EXIT_BENCH_FAILURE, "out of memory");
	memset(&run, 0, sizeof(run));
	jm_mcl_estimate(&mcl, &run.init_x, &run.init_y, &run.init_theta);
	if (run_timeline(&mcl, &tl, &opt, &sched)) {
		fprintf(stderr, "jmclbench: the run failed (out of memory or no threads)\n");
		goto out;
	}

	run.opt = &opt;
	run.ds = &ds;
	run.tl = &tl;
	run.sched = &sched;
	run.env = &env;
	run.argc = argc;
	run.argv = argv;
	if (opt.gc_log && write_gc_note(partial)) {
		fprintf(stderr, "jmclbench: %s/gc.log: cannot write: %s\n", partial, strerror(errno));
		goto out;
	}
	if (jm_output_write(&run, partial, err, sizeof(err))) {
		fprintf(stderr, "jmclbench: %s\n", err);
		goto out;
	}
	if (stat(final_dir, &st) == 0) {
		if (!opt.force) {
			/* another process completed the same run meanwhile: keep its folder */
			jm_remove_tree(partial);
			fprintf(stderr, "jmclbench: %s: a complete run folder exists (use --force to overwrite)\n",
				final_dir);
			ret = EXIT_BAD_INPUT;
			goto out;
		}
		/* the old folder aside first, so that the new one appears in one rename */
		snprintf(replaced, sizeof(replaced), "%s.replaced.partial", final_dir);
		if ((stat(replaced, &st) == 0 && jm_remove_tree(replaced)) || rename(final_dir, replaced)) {
			fprintf(stderr, "jmclbench: %s: cannot move aside: %s\n", final_dir, strerror(errno));
			goto out;
		}
	}
	if (rename(partial, final_dir)) {
		fprintf(stderr, "jmclbench: %s: cannot rename to %s: %s\n", partial, final_dir, strerror(errno));
		goto out;
	}
	if (replaced[0] && jm_remove_tree(replaced))
		fprintf(stderr, "jmclbench: %s: cannot remove: %s\n", replaced, strerror(errno));
	/* the complete run folder, the one line a script needs */
	printf("%s\n", final_dir);
	ret = 0;
out:
	jm_timeline_free(&tl);
	jm_mcl_free(&mcl);
	jm_dataset_free(&ds);
	return ret;
}
