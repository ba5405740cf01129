/* Run folder writer: job files, position and deviation series, data.txt and summary.json. */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <ftw.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "angles.h"
#include "json.h"
#include "output.h"
#include "stats.h"

#ifndef JM_CFLAGS
#define JM_CFLAGS ""
#endif

static const char *test_name(const jm_options *o)
{
	return o->ideal ? "IdealTest" : jm_policy_folder(o->policy);
}

int jm_run_dir(const jm_options *o, char *buf, size_t len)
{
	const char *p;
	size_t k = 0;
	int n;

	/* the output root as Java's File writes it (no repeated or trailing '/', but "/" itself), so
	 * that both print and record the same path: -O out/ is out/native/..., not out//native/... */
	for (p = o->out; *p && k + 1 < len; p++)
		if (!(*p == '/' && k > 0 && buf[k - 1] == '/'))
			buf[k++] = *p;
	if (*p)
		return -1;
	if (k > 1 && buf[k - 1] == '/')
		k--;
	n = snprintf(buf + k, len - k, "%s%s/%s/%d/%s/%d", buf[k - 1] == '/' ? "" : "/", o->runtime_name,
		     o->covariance ? "cov" : "nocov", o->particles, test_name(o), o->number);
	return n < 0 || (size_t)n >= len - k ? -1 : 0;
}

int jm_mkdirs(const char *dir)
{
	char path[PATH_MAX];
	char *p;

	if (snprintf(path, sizeof(path), "%s", dir) >= (int)sizeof(path)) {
		errno = ENAMETOOLONG;
		return -1;
	}
	for (p = path + 1; *p; p++) {
		if (*p != '/')
			continue;
		*p = '\0';
		if (mkdir(path, 0777) && errno != EEXIST)
			return -1;
		*p = '/';
	}
	if (mkdir(path, 0777) && errno != EEXIST)
		return -1;
	return 0;
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
	(void)st;
	(void)flag;
	(void)ftw;
	return remove(path);
}

int jm_remove_tree(const char *dir)
{
	return nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

static const char *outcome_name(enum jm_outcome o)
{
	switch (o) {
	case JM_OUTCOME_DONE:
		return "done";
	case JM_OUTCOME_LATE:
		return "late";
	case JM_OUTCOME_SKIPPED:
		return "skipped";
	case JM_OUTCOME_TERMINATED:
		return "terminated";
	default:
		return "pending";
	}
}

static int completed(enum jm_outcome o)
{
	return o == JM_OUTCOME_DONE || o == JM_OUTCOME_LATE;
}

/* Opens dir/name for writing; on failure sets err. */
static FILE *open_out(const char *dir, const char *name, char *path, size_t pathlen, char *err,
		      size_t errlen)
{
	FILE *f;

	snprintf(path, pathlen, "%s/%s", dir, name);
	f = fopen(path, "w");
	if (!f)
		snprintf(err, errlen, "%s: cannot write: %s", path, strerror(errno));
	return f;
}

static int close_out(FILE *f, const char *path, char *err, size_t errlen)
{
	int bad = ferror(f);

	if (fclose(f) || bad) {
		snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
		return -1;
	}
	return 0;
}

static int write_jobs(const jm_run *r, const char *dir, const char *name, enum jm_task task,
		      char *err, size_t errlen)
{
	char path[PATH_MAX + 64];
	FILE *f = open_out(dir, name, path, sizeof(path), err, errlen);
	int k;

	if (!f)
		return -1;
	fputs("# index release_ns start_ns end_ns deadline_ns outcome cpu_ns abort_ns seen_ns\n", f);
	for (k = 0; k < r->tl->n; k++) {
		const jm_event *e = &r->tl->events[k];
		const jm_job *j = &r->tl->jobs[k];

		if (e->task != task)
			continue;
		fprintf(f, "%d %lld %lld %lld %lld %s %lld %lld %lld\n", e->index, (long long)j->release_ns,
			(long long)j->start_ns, (long long)j->end_ns, (long long)j->deadline_ns,
			outcome_name(j->outcome), (long long)j->cpu_ns, (long long)jm_abort_from_ns(j),
			(long long)jm_abort_seen_from_ns(j));
	}
	return close_out(f, path, err, errlen);
}

/* Deviation of the estimate from the ground truth at each real-position time (ALGORITHM.md 10). */
struct deviation {
	double sum[4], max[4]; /* |ex|, |ey|, exy, |et| */
	long n;
};

static int write_positions(const jm_run *r, const char *dir, struct deviation *dev, char *err,
			   size_t errlen)
{
	char ppath[PATH_MAX + 64], dpath[PATH_MAX + 64];
	const jm_series *real = &r->ds->real;
	FILE *pf, *df;
	double x = r->init_x, y = r->init_y, th = r->init_theta;
	int i, k = 0, ret;

	memset(dev, 0, sizeof(*dev));
	pf = open_out(dir, "position.txt", ppath, sizeof(ppath), err, errlen);
	if (!pf)
		return -1;
	df = open_out(dir, "positionDeviation.txt", dpath, sizeof(dpath), err, errlen);
	if (!df) {
		fclose(pf);
		return -1;
	}
	fputs("# time x y theta\n", pf);
	fputs("# time dx dy dxy dtheta\n", df);
	for (i = 0; i < real->n; i++) {
		const double *rr = JM_ROW(real, i);
		double ex, ey, exy, et, a[4];
		int q;

		/* the estimate committed by the latest completed job at or before this time */
		while (k < r->tl->n && r->tl->events[k].time <= rr[0]) {
			const jm_job *j = &r->tl->jobs[k];

			if (completed(j->outcome)) {
				x = j->ex;
				y = j->ey;
				th = j->et;
			}
			k++;
		}
		ex = x - rr[1];
		ey = y - rr[2];
		exy = sqrt(ex * ex + ey * ey);
		et = jm_wrappi(th - rr[3]);
		fprintf(pf, "%.16e  %.16e  %.16e  %.16e\n", rr[0], x, y, th);
		fprintf(df, "%.16e  %.16e  %.16e  %.16e  %.16e\n", rr[0], ex, ey, exy, et);
		a[0] = fabs(ex);
		a[1] = fabs(ey);
		a[2] = exy;
		a[3] = fabs(et);
		for (q = 0; q < 4; q++) {
			dev->sum[q] += a[q];
			if (a[q] > dev->max[q])
				dev->max[q] = a[q];
		}
		dev->n++;
	}
	ret = close_out(pf, ppath, err, errlen);
	if (close_out(df, dpath, err, errlen))
		ret = -1;
	return ret;
}

static int write_covariance(const jm_run *r, const char *dir, char *err, size_t errlen)
{
	char path[PATH_MAX + 64];
	FILE *f = open_out(dir, "covariance.txt", path, sizeof(path), err, errlen);
	int k, q;

	if (!f)
		return -1;
	fputs("# time cxx cxy cxt cyy cyt ctt\n", f);
	for (k = 0; k < r->tl->n; k++) {
		const jm_job *j = &r->tl->jobs[k];

		if (r->tl->events[k].task != JM_TASK_UPDATE || !completed(j->outcome))
			continue;
		fprintf(f, "%.16e", r->tl->events[k].time);
		for (q = 0; q < 6; q++)
			fprintf(f, "  %.16e", j->cov[q]);
		fputc('\n', f);
	}
	return close_out(f, path, err, errlen);
}

/* One task's summary (or both tasks': task < 0) and the thesis's missCount, which depends on the policy. */
struct task_summary {
	jm_task_summary s;
	long miss;
};

static int summarise(const jm_run *r, int task, struct task_summary *t)
{
	const jm_task_summary *s = &t->s;

	if (jm_task_summary_compute(&t->s, r->tl, task))
		return -1;
	if (r->opt->ideal)
		t->miss = 0;
	else
		t->miss = jm_policy_misses(r->opt->policy, s->late, s->skipped, s->terminated);
	return 0;
}

static void json_stats(jm_json *j, const char *key, const jm_stats *s)
{
	static const char *const quantile_keys[] = { "min", "p50", "p90", "p99", "p999", "max" };
	const int64_t quantiles[] = { s->min, s->p50, s->p90, s->p99, s->p999, s->max };
	size_t q;

	jm_json_open(j, key, '{');
	jm_json_i64(j, "count", s->count);
	/* an empty sample has no statistics, each one null (jm_json_double writes NaN as null) */
	jm_json_double(j, "mean", s->count ? s->mean : NAN);
	jm_json_double(j, "stdev", s->count ? s->stdev : NAN);
	for (q = 0; q < sizeof(quantiles) / sizeof(quantiles[0]); q++) {
		if (s->count)
			jm_json_i64(j, quantile_keys[q], quantiles[q]);
		else
			jm_json_null(j, quantile_keys[q]);
	}
	jm_json_close(j, '}');
}

static void json_task(jm_json *j, const char *key, const struct task_summary *t)
{
	const jm_task_summary *s = &t->s;
	int q;

	jm_json_open(j, key, '{');
	jm_json_i64(j, "released", s->released);
	jm_json_i64(j, "completed", s->completed);
	jm_json_i64(j, "done", s->done);
	jm_json_i64(j, "late", s->late);
	jm_json_i64(j, "skipped", s->skipped);
	jm_json_i64(j, "terminated", s->terminated);
	jm_json_i64(j, "missCount", t->miss);
	json_stats(j, "releaseJitterNs", &s->jitter);
	json_stats(j, "taskLatencyNs", &s->latency);
	json_stats(j, "responseTimeNs", &s->response);
	json_stats(j, "cpuNs", &s->cpu);
	json_stats(j, "abortLatencyNs", &s->abort_latency);
	json_stats(j, "abortNoticeNs", &s->abort_notice);
	json_stats(j, "abortStopNs", &s->abort_stop);
	jm_json_i64(j, "abortsCompleted", s->aborts_completed);
	jm_json_i64(j, "deadlineMisses", s->deadline_misses);
	jm_json_double(j, "missRatio", jm_miss_ratio(s)); /* NAN, written null, when nothing was released */
	jm_json_open(j, "responseTimeReleasedNs", '{');
	jm_json_i64(j, "count", s->released);
	jm_json_i64(j, "completed", s->response.count);
	for (q = 0; q < JM_RELEASED_QUANTILES; q++) {
		if (s->released == 0)
			jm_json_null(j, jm_released_names[q]);
		else if (s->released_response[q] == JM_NOT_COMPLETED)
			jm_json_str(j, jm_released_names[q], "inf");
		else
			jm_json_i64(j, jm_released_names[q], s->released_response[q]);
	}
	jm_json_close(j, '}');
	jm_json_close(j, '}');
}

static const char *nonempty(const char *s)
{
	return s && *s ? s : NULL;
}

static void json_parameters(jm_json *j, const jm_run *r)
{
	const jm_options *o = r->opt;

	jm_json_open(j, "parameters", '{');
	jm_json_str(j, "runtimeName", o->runtime_name);
	jm_json_str(j, "engine", "native");
	jm_json_i64(j, "particles", o->particles);
	jm_json_i64(j, "number", o->number);
	jm_json_str(j, "policy", jm_policy_name(o->policy));
	jm_json_bool(j, "ideal", o->ideal);
	jm_json_str(j, "memory", jm_memory_name(o->memory));
	jm_json_str(j, "estimate", jm_estimate_name(o->estimate));
	jm_json_str(j, "resample", jm_resample_name(o->resample));
	jm_json_str(j, "init", jm_init_name(o->init));
	jm_json_i64(j, "seed", o->seed);
	jm_json_bool(j, "covariance", o->covariance);
	jm_json_double(j, "timeScale", o->time_scale);
	jm_json_double(j, "warmupS", o->warmup_s);
	jm_json_i64(j, "spinUs", o->spin_us);
	jm_json_bool(j, "cpuTime", o->cpu_time);
	jm_json_bool(j, "gcLog", o->gc_log);
	jm_json_open(j, "dataset", '{');
	if (r->ds->dir[0])
		jm_json_str(j, "path", r->ds->dir);
	else
		jm_json_null(j, "path");
	jm_json_str(j, "name", nonempty(r->ds->name));
	jm_json_str(j, "scenario", nonempty(r->ds->scenario));
	jm_json_str(j, "odometry", r->ds->odometry_path);
	jm_json_str(j, "laser", r->ds->laser_path);
	jm_json_str(j, "real", r->ds->real_path);
	jm_json_close(j, '}');
	jm_json_close(j, '}');
}

static void json_environment(jm_json *j, const jm_run *r)
{
	const jm_env *env = r->env;
	const jm_sched_info *s = r->sched;
	int i;

	jm_json_open(j, "environment", '{');
	jm_json_open(j, "runtime", '{');
	jm_json_str(j, "language", "c");
	jm_json_str(j, "name", "jmclbench-native");
#if defined(__clang__)
	jm_json_str(j, "vendor", "clang");
#elif defined(__GNUC__)
	jm_json_str(j, "vendor", "gcc");
#else
	jm_json_null(j, "vendor");
#endif
	jm_json_str(j, "version", __VERSION__);
	jm_json_null(j, "vmName");
	jm_json_open(j, "inputArguments", '[');
	for (i = 0; i < r->argc; i++)
		jm_json_str(j, NULL, r->argv[i]);
	jm_json_close(j, ']');
	jm_json_open(j, "gcNames", '[');
	jm_json_close(j, ']');
#if defined(__clang__)
	jm_json_str(j, "compiler", "clang " __VERSION__);
#elif defined(__GNUC__)
	jm_json_str(j, "compiler", "gcc " __VERSION__);
#else
	jm_json_str(j, "compiler", __VERSION__);
#endif
	jm_json_str(j, "cflags", JM_CFLAGS);
	jm_json_close(j, '}');
	jm_json_open(j, "os", '{');
	jm_json_str(j, "name", nonempty(env->os_name));
	jm_json_str(j, "arch", nonempty(env->arch));
	jm_json_str(j, "kernel", nonempty(env->kernel));
	jm_json_close(j, '}');
	jm_json_open(j, "cpu", '{');
	jm_json_str(j, "model", nonempty(env->cpu_model));
	jm_json_i64(j, "processors", env->processors);
	jm_json_close(j, '}');
	jm_json_open(j, "scheduling", '{');
	jm_json_str(j, "policy", s->policy_name ? s->policy_name : "SCHED_OTHER");
	jm_json_i64(j, "priority", s->dispatcher_priority);
	jm_json_i64(j, "handlerPriority", s->handler_priority);
	jm_json_bool(j, "fifoRequested", s->fifo_requested);
	jm_json_bool(j, "mlockall", s->mlocked);
	if (!s->mlocked && s->mlock_note)
		jm_json_str(j, "mlockallNote", s->mlock_note);
	jm_json_close(j, '}');
	jm_json_str(j, "clocksource", nonempty(env->clocksource));
	jm_json_str(j, "hostname", nonempty(env->hostname));
	jm_json_str(j, "startedAt", nonempty(env->started_at));
	jm_json_close(j, '}');
}

/*
 * The engine (its kind in every run) and, in real-time runs, the facts of the release engine:
 * how far the numbers can be trusted (FORMATS.md 4).
 */
static void json_engine(jm_json *j, const jm_run *r)
{
	const jm_sched_info *s = r->sched;

	jm_json_open(j, "engine", '{');
	jm_json_str(j, "kind", "native");
	if (r->opt->ideal) {
		jm_json_close(j, '}');
		return;
	}
	jm_json_i64(j, "dispatcherPriority", s->dispatcher_priority);
	jm_json_i64(j, "handlerPriority", s->handler_priority);
	jm_json_bool(j, "prioritiesApplied", s->fifo);
	jm_json_str(j, "cpuTime", r->opt->cpu_time ? "used (CLOCK_THREAD_CPUTIME_ID)" : "off (--no-cpu-time)");
	jm_json_str(j, "gcLog", r->opt->gc_log ? "none: the native runtime has no garbage collector" : NULL);
	jm_json_i64(j, "warmupEvents", s->warmup_events);
	jm_json_null(j, "allocatedBytes"); /* not counted in C; --memory allocating mallocs per job */
	jm_json_close(j, '}');
}

/* The mean of deviation q over the real-position times; NaN when there were none. */
static double deviation_mean(const struct deviation *d, int q)
{
	return d->n ? d->sum[q] / (double)d->n : NAN;
}

static void json_deviation(jm_json *j, const char *key, const struct deviation *d, int q)
{
	jm_json_open(j, key, '{');
	jm_json_double(j, "mean", deviation_mean(d, q));
	jm_json_double(j, "max", d->n ? d->max[q] : NAN);
	jm_json_close(j, '}');
}

/*
 * The fewest of 15 to 17 significant digits that read back as v (NaN when there is no value), as
 * Java's shortest digits; in printf's %g notation, not Java's (1e-05 where Java writes 1.0E-5).
 */
static const char *shortest(char buf[40], double v)
{
	int prec;

	if (isnan(v))
		return "NaN";
	for (prec = 15; prec <= 17; prec++) {
		snprintf(buf, 40, "%.*g", prec, v);
		if (strtod(buf, NULL) == v)
			break;
	}
	if (!strpbrk(buf, ".eEn"))
		strcat(buf, ".0");
	return buf;
}

/* The mean of a sample in milliseconds; NaN when it is empty. */
static double mean_ms(const jm_stats *s)
{
	return s->count ? s->mean / 1e6 : NAN;
}

int jm_output_write(const jm_run *r, const char *dir, char *err, size_t errlen)
{
	char path[PATH_MAX + 64];
	struct task_summary t[3];
	struct deviation dev;
	jm_stats lateness;
	int64_t *wake = NULL;
	long nwake = 0;
	char num[40];
	jm_json j;
	FILE *f;
	int k, ret = -1;

	if (write_jobs(r, dir, "odoData.txt", JM_TASK_PREDICT, err, errlen) ||
	    write_jobs(r, dir, "laserData.txt", JM_TASK_UPDATE, err, errlen) ||
	    write_positions(r, dir, &dev, err, errlen) ||
	    (r->opt->covariance && write_covariance(r, dir, err, errlen)))
		return -1;
	if (summarise(r, JM_TASK_PREDICT, &t[0]) || summarise(r, JM_TASK_UPDATE, &t[1]) ||
	    summarise(r, -1, &t[2])) {
		snprintf(err, errlen, "%s: out of memory", dir);
		return -1;
	}
	wake = malloc(sizeof(int64_t) * (size_t)(r->tl->n ? r->tl->n : 1));
	if (!wake) {
		snprintf(err, errlen, "%s: out of memory", dir);
		return -1;
	}
	for (k = 0; k < r->tl->n; k++)
		if (r->tl->jobs[k].wake_ns >= 0)
			wake[nwake++] = r->tl->jobs[k].wake_ns - r->tl->events[k].release_ns;
	jm_stats_compute(&lateness, wake, nwake);

	f = open_out(dir, "data.txt", path, sizeof(path), err, errlen);
	if (!f)
		goto out;
	fprintf(f, "deviationXY %s\n", shortest(num, deviation_mean(&dev, 2)));
	fprintf(f, "deviationX %s\n", shortest(num, deviation_mean(&dev, 0)));
	fprintf(f, "deviationY %s\n", shortest(num, deviation_mean(&dev, 1)));
	fprintf(f, "deviationAngle %s\n", shortest(num, deviation_mean(&dev, 3)));
	fprintf(f, "missCount %ld\n", t[2].miss);
	fprintf(f, "averageReleaseJitter %s\n", shortest(num, mean_ms(&t[2].s.jitter)));
	fprintf(f, "averageTaskTime %s\n", shortest(num, mean_ms(&t[2].s.latency)));
	if (close_out(f, path, err, errlen))
		goto out;

	f = open_out(dir, "summary.json", path, sizeof(path), err, errlen);
	if (!f)
		goto out;
	jm_json_init(&j, f);
	jm_json_open(&j, NULL, '{');
	jm_json_str(&j, "schema", "jmclbench-run/1");
	jm_json_str(&j, "status", "complete");
	json_parameters(&j, r);
	json_environment(&j, r);
	jm_json_double(&j, "durationS", (double)r->sched->duration_ns / 1e9);
	jm_json_i64(&j, "missCount", t[2].miss);
	jm_json_open(&j, "tasks", '{');
	json_task(&j, "predict", &t[0]);
	json_task(&j, "update", &t[1]);
	json_task(&j, "all", &t[2]);
	jm_json_close(&j, '}');
	json_stats(&j, "dispatcherLatenessNs", &lateness);
	json_engine(&j, r);
	/* no memory areas: C has one heap and the tooling compares areas of the Java engines only */
	jm_json_open(&j, "memory", '{');
	jm_json_open(&j, "areas", '[');
	jm_json_close(&j, ']');
	jm_json_close(&j, '}');
	jm_json_open(&j, "deviation", '{');
	json_deviation(&j, "xy", &dev, 2);
	json_deviation(&j, "x", &dev, 0);
	json_deviation(&j, "y", &dev, 1);
	json_deviation(&j, "angle", &dev, 3);
	jm_json_close(&j, '}');
	jm_json_close(&j, '}');
	if (close_out(f, path, err, errlen))
		goto out;
	ret = 0;
out:
	free(wake);
	return ret;
}
