/* Monotonic and per-thread CPU clocks in nanoseconds. */
#ifndef JM_CLOCK_H
#define JM_CLOCK_H

#include <stdint.h>
#include <time.h>

static inline int64_t jm_ts_ns(const struct timespec *ts)
{
	return (int64_t)ts->tv_sec * 1000000000LL + ts->tv_nsec;
}

/* CLOCK_MONOTONIC, the clock every release and timestamp of a run uses. */
static inline int64_t jm_now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return jm_ts_ns(&ts);
}

/* CPU time of the calling thread. */
static inline int64_t jm_thread_cpu_ns(void)
{
	struct timespec ts;

	if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts))
		return -1;
	return jm_ts_ns(&ts);
}

#endif
