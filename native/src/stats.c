/* Exact statistics over every job's value, computed after the run. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stats.h"

static int cmp_i64(const void *a, const void *b)
{
	int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;

	return (x > y) - (x < y);
}

int64_t jm_percentile(const int64_t *sorted, long n, int per_mille)
{
	/* ceil(q * n) - 1 in integers, so that no rounding of q * n can move the rank */
	long i = (long)((per_mille * (long long)n + 999) / 1000) - 1;

	if (i < 0)
		i = 0;
	if (i > n - 1)
		i = n - 1;
	return sorted[i];
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
