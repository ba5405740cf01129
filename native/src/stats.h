/* Summary statistics of a timing sample (docs/FORMATS.md 4, STATS). */
#ifndef JM_STATS_H
#define JM_STATS_H

#include <stdint.h>

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

#endif
