/*
 * How a thread records its jobs (Java's JobRecorder): the start and end times (CLOCK_MONOTONIC,
 * stored as ns from the run start), the thread's CPU time over the job and the outcome. Per job:
 * jm_recorder_start just before the job, jm_recorder_end just after it, then, once the robot has
 * been handed on, jm_recorder_record. The CPU clock (CLOCK_THREAD_CPUTIME_ID, a system call: no
 * vDSO has it) is read in start and record, so the next job does not wait for the second read;
 * the CPU time so includes the time stamps and the hand-over. Without cpu (--no-cpu-time) neither
 * read happens and cpu_ns is -1. bench/record-cost.sh measures exactly this code
 * (native/bench/record_cost.c).
 */
#ifndef JM_RECORD_H
#define JM_RECORD_H

#include <stdint.h>

#include "clock.h"
#include "engine.h"

typedef struct {
	int cpu;           /* read the thread CPU clock */
	int64_t t0;        /* CLOCK_MONOTONIC of the run's time 0 */
	int64_t cpu_start; /* -1 when not read or not readable */
	int64_t start, end;
} jm_recorder;

static inline void jm_recorder_init(jm_recorder *r, int cpu, int64_t t0)
{
	r->cpu = cpu;
	r->t0 = t0;
	r->cpu_start = r->start = r->end = -1;
}

/* Just before the job: the CPU clock, then the start time. */
static inline void jm_recorder_start(jm_recorder *r)
{
	r->cpu_start = r->cpu ? jm_thread_cpu_ns() : -1;
	r->start = jm_now_ns();
}

/* Just after the job, before anything else: the end time. */
static inline void jm_recorder_end(jm_recorder *r)
{
	r->end = jm_now_ns();
}

/*
 * After jm_recorder_end (and the robot's release): the job's start, end, CPU time and outcome,
 * terminated unless it completed, else done by its deadline (or with none, -1) or late.
 */
static inline void jm_recorder_record(const jm_recorder *r, jm_job *j, int completed)
{
	int64_t cpu_end = r->cpu_start >= 0 ? jm_thread_cpu_ns() : -1;

	j->start_ns = r->start - r->t0;
	j->end_ns = r->end - r->t0;
	j->cpu_ns = r->cpu_start >= 0 && cpu_end >= 0 ? cpu_end - r->cpu_start : -1;
	if (!completed)
		j->outcome = JM_OUTCOME_TERMINATED;
	else
		j->outcome = j->deadline_ns < 0 || j->end_ns <= j->deadline_ns ? JM_OUTCOME_DONE : JM_OUTCOME_LATE;
}

#endif
