/* The native of hvmtest.ClockTick: CLOCK_MONOTONIC, independent of the VM's tick. */
#include <stdint.h>
#include <time.h>
#include "ostypes.h"

int16 n_hvmtest_ClockTick_monotonicNanos(int32 *sp)
{
	struct timespec t;
	int64_t ns;
	clock_gettime(CLOCK_MONOTONIC, &t);
	ns = (int64_t) t.tv_sec * 1000000000 + t.tv_nsec;
	sp[0] = (int32) (uint32_t) ((uint64_t) ns >> 32); /* a long: most significant word first */
	sp[1] = (int32) (uint32_t) (uint64_t) ns;
	return -1;
}
