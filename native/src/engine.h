/* The release engine: the merged event timeline, the per-job records and the two ways to run it. */
#ifndef JM_ENGINE_H
#define JM_ENGINE_H

#include <stdint.h>

#include "dataset.h"
#include "job.h"
#include "mcl.h"
#include "options.h"

enum jm_task { JM_TASK_PREDICT = 0, JM_TASK_UPDATE = 1 };

#define JM_PREDICT_DEADLINE_S 0.050
#define JM_LAST_UPDATE_DEADLINE_S 0.250

/* One event of the merged timeline: its data and its scheduled release and deadline. */
typedef struct {
	double time;          /* seconds, as in the dataset */
	enum jm_task task;
	int index;            /* counts this task's events from 0 */
	double arg[3];        /* dx dy dtheta, or the laser angle */
	int64_t release_ns;   /* from the run start, time-scaled */
	int64_t deadline_ns;  /* absolute from the run start */
} jm_event;

/* Events in release order (odometry before laser at equal times) and their job records. */
typedef struct {
	int n;
	int ntask[2];
	jm_event *events;
	jm_job *jobs;
} jm_timeline;

/* Builds the timeline of the events with time <= until_s, or < until_s when not inclusive
 * (all events when until_s < 0). */
int jm_timeline_build(jm_timeline *tl, const jm_dataset *ds, double time_scale, double until_s,
		      int inclusive);
void jm_timeline_free(jm_timeline *tl);

/*
 * When the abort of a job took hold, the job files' abort_ns (Java's JobRecords.abortFromNs): its
 * first abort request, or its start when requested before it started; -1 when it never started or
 * nothing was requested before its end. The abort latency is end_ns minus this.
 */
int64_t jm_abort_from_ns(const jm_job *j);

/*
 * When the job saw the abort that took hold of it, the job files' seen_ns (Java's
 * JobRecords.abortSeenFromNs): -1 when none took hold or the job never saw it. Noticing is this
 * minus jm_abort_from_ns, stopping end_ns minus this.
 */
int64_t jm_abort_seen_from_ns(const jm_job *j);

/* How the real-time engine ran: the scheduling it actually got. */
typedef struct {
	int fifo_requested;
	int fifo;                /* SCHED_FIFO granted to the threads */
	int dispatcher_priority; /* 0 under SCHED_OTHER */
	int handler_priority;
	const char *policy_name; /* policy of the dispatcher thread */
	int mlocked;
	const char *mlock_note;  /* why not, when not */
	int64_t duration_ns;     /* run start to the end of the last job */
	int warmup_events;       /* events replayed by the warm-up before the measured run */
} jm_sched_info;

/*
 * The infinitely fast computer: every event in order in this thread. 0, or -1 out of memory.
 * cpu_time: read the thread CPU clock per job (cpu_ns), else cpu_ns is -1 (--no-cpu-time).
 */
int jm_run_ideal(jm_mcl *m, jm_timeline *tl, int cpu_time, jm_sched_info *info);
/*
 * Replays the timeline in real time: a dispatcher thread releasing each event at its
 * absolute time and one handler thread per task, with the policy deciding what happens to an
 * event released while a job is on the robot. 0, or -1 (out of memory, no threads).
 */
int jm_run_realtime(jm_mcl *m, jm_timeline *tl, enum jm_policy policy, int spin_us, int fifo,
		    int cpu_time, jm_sched_info *info);

/* Locks the process's memory when permitted (never under AddressSanitizer); sets info. */
void jm_lock_memory(jm_sched_info *info);

#endif
