/* Exact statistics over every job's value, computed after the run. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "stats.h"

static int cmp_i64(const void *a, const void *b)
{
	int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;

	return (x > y) - (x < y);
}

/* The nearest rank's index among n sorted values, q = per_mille / 1000: ceil(q * n) - 1, in [0, n - 1]. */
static long nearest_rank(long n, int per_mille)
{
	/* in integers, so that no rounding of q * n can move the rank */
	long i = (long)((per_mille * (long long)n + 999) / 1000) - 1;

	if (i < 0)
		i = 0;
	if (i > n - 1)
		i = n - 1;
	return i;
}

int64_t jm_percentile(const int64_t *sorted, long n, int per_mille)
{
	return sorted[nearest_rank(n, per_mille)];
}

void jm_stats_compute(jm_stats *s, int64_t *values, long n)
{
	double sum = 0.0, sq = 0.0;
	long i;

	memset(s, 0, sizeof(*s));
	s->count = n;
	if (n == 0)
		return;
	qsort(values, (size_t)n, sizeof(int64_t), cmp_i64);
	for (i = 0; i < n; i++)
		sum += (double)values[i];
	s->mean = sum / (double)n;
	for (i = 0; i < n; i++) {
		double d = (double)values[i] - s->mean;

		sq += d * d;
	}
	s->stdev = sqrt(sq / (double)n);
	s->min = values[0];
	s->max = values[n - 1];
	s->p50 = jm_percentile(values, n, 500);
	s->p90 = jm_percentile(values, n, 900);
	s->p99 = jm_percentile(values, n, 990);
	s->p999 = jm_percentile(values, n, 999);
}

const int jm_released_per_mille[JM_RELEASED_QUANTILES] = { 0, 500, 900, 990, 999, 1000 };
const char *const jm_released_names[JM_RELEASED_QUANTILES] = { "min", "p50", "p90", "p99", "p999", "max" };

static int completed(enum jm_outcome o)
{
	return o == JM_OUTCOME_DONE || o == JM_OUTCOME_LATE;
}

#define JM_SAMPLE_KINDS 7

int jm_task_summary_compute(jm_task_summary *s, const jm_timeline *tl, int task)
{
	/* jitter, latency, response, cpu, abort latency, its noticing and its stopping */
	int64_t *v[JM_SAMPLE_KINDS];
	long nv[JM_SAMPLE_KINDS] = { 0 };
	int k, q, ret = -1;

	memset(s, 0, sizeof(*s));
	for (q = 0; q < JM_SAMPLE_KINDS; q++)
		v[q] = malloc(sizeof(int64_t) * (size_t)(tl->n ? tl->n : 1));
	for (q = 0; q < JM_SAMPLE_KINDS; q++)
		if (!v[q])
			goto out;
	for (k = 0; k < tl->n; k++) {
		const jm_job *j = &tl->jobs[k];

		if (task >= 0 && (int)tl->events[k].task != task)
			continue;
		if (j->outcome == JM_OUTCOME_PENDING)
			continue; /* never released (a run cut short) */
		s->released++;
		s->done += j->outcome == JM_OUTCOME_DONE;
		s->late += j->outcome == JM_OUTCOME_LATE;
		s->skipped += j->outcome == JM_OUTCOME_SKIPPED;
		s->terminated += j->outcome == JM_OUTCOME_TERMINATED;
		if (j->start_ns >= 0 && j->release_ns >= 0)
			v[0][nv[0]++] = j->start_ns - j->release_ns;
		/* latency and response time of completed jobs only: an aborted job's end is no answer */
		if (completed(j->outcome) && j->start_ns >= 0 && j->end_ns >= 0) {
			v[1][nv[1]++] = j->end_ns - j->start_ns;
			if (j->release_ns >= 0)
				v[2][nv[2]++] = j->end_ns - j->release_ns;
		}
		if (j->cpu_ns >= 0)
			v[3][nv[3]++] = j->cpu_ns;
		if (jm_abort_from_ns(j) >= 0) {
			v[4][nv[4]++] = j->end_ns - jm_abort_from_ns(j);
			if (jm_abort_seen_from_ns(j) >= 0) {
				v[5][nv[5]++] = jm_abort_seen_from_ns(j) - jm_abort_from_ns(j);
				v[6][nv[6]++] = j->end_ns - jm_abort_seen_from_ns(j);
			}
			if (completed(j->outcome))
				s->aborts_completed++;
		}
	}
	s->completed = s->done + s->late;
	s->deadline_misses = s->late + s->skipped + s->terminated;
	jm_stats_compute(&s->jitter, v[0], nv[0]);
	jm_stats_compute(&s->latency, v[1], nv[1]);
	jm_stats_compute(&s->response, v[2], nv[2]); /* sorts v[2] */
	for (q = 0; q < JM_RELEASED_QUANTILES && s->released > 0; q++) {
		/* nearest rank among every release; the ranks past the completed ones are +inf */
		long i = nearest_rank(s->released, jm_released_per_mille[q]);

		s->released_response[q] = i < nv[2] ? v[2][i] : JM_NOT_COMPLETED;
	}
	jm_stats_compute(&s->cpu, v[3], nv[3]);
	jm_stats_compute(&s->abort_latency, v[4], nv[4]);
	jm_stats_compute(&s->abort_notice, v[5], nv[5]);
	jm_stats_compute(&s->abort_stop, v[6], nv[6]);
	ret = 0;
out:
	for (q = 0; q < JM_SAMPLE_KINDS; q++)
		free(v[q]);
	return ret;
}

double jm_miss_ratio(const jm_task_summary *s)
{
	return s->released ? (double)s->deadline_misses / (double)s->released : NAN;
}
