/* Summary statistics of a timing sample (docs/FORMATS.md 4, STATS). */
#ifndef JM_STATS_H
#define JM_STATS_H

#include <stdint.h>

#include "engine.h"

/* count, mean, population stdev, min, nearest-rank percentiles, max; count 0 means all null. */
typedef struct {
	long count;
	double mean, stdev;
	int64_t min, p50, p90, p99, p999, max;
} jm_stats;

/* Computes s over values[0..n-1]; sorts values in place. */
void jm_stats_compute(jm_stats *s, int64_t *values, long n);
/* The nearest-rank percentile of a sorted sample, q = per_mille / 1000: index ceil(q * n) - 1. */
int64_t jm_percentile(const int64_t *sorted, long n, int per_mille);

/* Stands for +infinity among the released quantiles: a release whose job never completed. */
#define JM_NOT_COMPLETED INT64_MAX
/* The quantiles of the response time over every release: min p50 p90 p99 p999 max. */
#define JM_RELEASED_QUANTILES 6
extern const int jm_released_per_mille[JM_RELEASED_QUANTILES];
extern const char *const jm_released_names[JM_RELEASED_QUANTILES];

/*
 * One task's jobs (or both tasks') for summary.json: the deadline accounting of every release
 * (pending jobs were never released and count nowhere) and its timing samples.
 */
typedef struct {
	long released, completed, done, late, skipped, terminated;
	long deadline_misses; /* late + skipped + terminated, under every policy */
	jm_stats jitter, latency, response, cpu;
	jm_stats abort_latency; /* end - jm_abort_from_ns of the jobs an abort took hold of */
	jm_stats abort_notice;  /* of those that saw it: jm_abort_seen_from_ns - jm_abort_from_ns */
	jm_stats abort_stop;    /* and end - jm_abort_seen_from_ns */
	long aborts_completed;  /* of those, the ones that completed all the same */
	/* response time at jm_released_per_mille over every release, JM_NOT_COMPLETED = +inf;
	 * meaningful when released > 0 */
	int64_t released_response[JM_RELEASED_QUANTILES];
} jm_task_summary;

/* Summarises the jobs of task (< 0: both tasks). 0, or -1 out of memory. */
int jm_task_summary_compute(jm_task_summary *s, const jm_timeline *tl, int task);
/* deadline_misses / released; NAN when nothing was released. */
double jm_miss_ratio(const jm_task_summary *s);

#endif
