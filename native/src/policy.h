/*
 * The overrun policies (SPEC section 4): what happens to an event released while a job works
 * on the robot. The C baseline's one definition, with the codes, labels and thesis test names
 * of the Java one (core-immortal, org.jmclbench.core.policy.OverrunPolicy); a test compares
 * the two. Each policy's rule is here too (jm_policy_release, jm_policy_misses): the engine
 * (engine.c) and the writers (output.c) name no policy, so a new policy is this file (its code,
 * its row, its cases, which -Wswitch -Werror asks for) and its tests.
 */
#ifndef JM_POLICY_H
#define JM_POLICY_H

#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "job.h"
#include "mcl.h"

/* The stable codes, the same as Java's OverrunPolicy.code. */
enum jm_policy { JM_POLICY_SKIP = 0, JM_POLICY_TERMINATE = 1, JM_POLICY_QUEUE = 2 };

/* The option values, '|'-separated in code order (the n-th label is code n). */
#define JM_POLICY_LABELS "skip|terminate|queue"

/*
 * Per policy, by code: the option value and summary.json name, and the thesis's test name (the
 * run path's folder). A new policy is one row here, its code above and its cases below.
 */
static const struct jm_policy_names {
	const char *name;
	const char *folder;
} jm_policy_table[] = {
	[JM_POLICY_SKIP] = { "skip", "SkipTest" },
	[JM_POLICY_TERMINATE] = { "terminate", "TermTest" },
	[JM_POLICY_QUEUE] = { "queue", "QueueTest" },
};

/* The row of a policy; a code out of range reads as skip's, as code 0. */
static inline const struct jm_policy_names *jm_policy_row(enum jm_policy p)
{
	size_t i = (size_t)p;

	return &jm_policy_table[i < sizeof(jm_policy_table) / sizeof(jm_policy_table[0]) ? i : 0];
}

/* The option value and summary.json name of a policy. */
static inline const char *jm_policy_name(enum jm_policy p)
{
	return jm_policy_row(p)->name;
}

/* The thesis's test name: the run path's folder (SkipTest, TermTest, QueueTest). */
static inline const char *jm_policy_folder(enum jm_policy p)
{
	return jm_policy_row(p)->folder;
}

/*
 * What the policies decide on, in the real-time engine, changed only under its lock: the events
 * released and waiting for the robot, and the one whose job is on it. Under every policy the robot
 * runs one job at a time, the oldest waiting event first (jm_robot_next); a policy decides, as each
 * event is released, what waits (jm_policy_release).
 */
struct jm_robot {
	int *fifo;       /* released events waiting, in release order; room for every event */
	int head, tail;  /* the waiting ones: fifo[head] to fifo[tail - 1] */
	int running;     /* event whose job is on the robot, or -1 */
	int latest;      /* the event released last, or -1 */
	jm_job *jobs;    /* the run's records, by event: outcomes and abort requests */
	jm_abort abort;  /* the job on the robot is asked to stop */
};

/* An idle robot, nothing released yet; fifo has room for every event of the run. */
static inline void jm_robot_init(struct jm_robot *r, int *fifo, jm_job *jobs)
{
	r->fifo = fifo;
	r->head = r->tail = 0;
	r->running = r->latest = -1;
	r->jobs = jobs;
	atomic_init(&r->abort.requested, 0);
	r->abort.seen_ns = -1;
}

/* The event whose job may start now (the robot free, the oldest waiting one), or -1. */
static inline int jm_robot_next(const struct jm_robot *r)
{
	return r->running < 0 && r->head < r->tail ? r->fifo[r->head] : -1;
}

/* Puts the next event's job on the robot (jm_robot_next must not be -1); its event. */
static inline int jm_robot_start(struct jm_robot *r)
{
	r->running = r->fifo[r->head++];
	atomic_store_explicit(&r->abort.requested, 0, memory_order_relaxed);
	r->abort.seen_ns = -1;
	return r->running;
}

/* The job on the robot has ended: the robot is free. */
static inline void jm_robot_end(struct jm_robot *r)
{
	r->running = -1;
}

/*
 * The rule of policy p for event k, released at now_ns (ns from the run start). Events of one
 * release instant come one call each, in timeline order, before any of them starts.
 */
static inline void jm_policy_release(enum jm_policy p, struct jm_robot *r, int k, int64_t now_ns)
{
	switch (p) {
	case JM_POLICY_SKIP:
		/* a job on the robot, or one released and about to start: drop the new event */
		if (r->running >= 0 || r->head < r->tail)
			r->jobs[k].outcome = JM_OUTCOME_SKIPPED;
		else
			r->fifo[r->tail++] = k;
		break;
	case JM_POLICY_TERMINATE:
		if (r->running >= 0)
			atomic_store_explicit(&r->abort.requested, 1, memory_order_relaxed);
		/* the request of the superseded event's job (running, waiting or ended), as Java's gates */
		if (r->latest >= 0 && r->jobs[r->latest].abort_ns < 0)
			r->jobs[r->latest].abort_ns = now_ns;
		/* a released event superseded before it could start never will: terminated */
		while (r->head < r->tail)
			r->jobs[r->fifo[r->head++]].outcome = JM_OUTCOME_TERMINATED;
		r->fifo[r->tail++] = k;
		break;
	case JM_POLICY_QUEUE:
		r->fifo[r->tail++] = k;
		break;
	}
	r->latest = k;
}

/* The thesis's missCount of a real-time run under p, from its job counts. */
static inline long jm_policy_misses(enum jm_policy p, long late, long skipped, long terminated)
{
	switch (p) {
	case JM_POLICY_QUEUE:
		return late; /* it drops nothing; a miss is a completion after the deadline */
	case JM_POLICY_SKIP:
	case JM_POLICY_TERMINATE:
		break;
	}
	return skipped + terminated;
}

#endif
