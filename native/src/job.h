/*
 * One event's job record and its outcomes: what the engines fill in during a run and the writers
 * read after it. Its own header so that the policies' rules (policy.h) can write outcomes without
 * the engine's header, which needs the options, which need the policies.
 */
#ifndef JM_JOB_H
#define JM_JOB_H

#include <stdint.h>

enum jm_outcome { JM_OUTCOME_PENDING, JM_OUTCOME_DONE, JM_OUTCOME_LATE, JM_OUTCOME_SKIPPED,
		  JM_OUTCOME_TERMINATED };

/* What happened to one event's job; preallocated, filled during the run, written after it. */
typedef struct {
	int64_t start_ns, end_ns, cpu_ns; /* -1 where there is no such time */
	int64_t wake_ns;                  /* dispatcher wake-up for this release; -1 in ideal runs */
	int64_t abort_ns;                 /* first abort request (terminate), -1 never; see jm_abort_from_ns */
	int64_t seen_ns;                  /* when the job's poll first saw it, -1 never; see jm_abort_seen_from_ns */
	int64_t release_ns, deadline_ns;  /* as recorded (ideal: release = start, deadline -1) */
	enum jm_outcome outcome;
	double ex, ey, et;                /* estimate committed by a completed job */
	double cov[6];                    /* covariance committed by a completed update */
} jm_job;

#endif
