/*
 * The overrun policies (SPEC section 4): what happens to an event released while a job works
 * on the robot. The C baseline's one definition, with the codes, labels and thesis test names
 * of the Java one (core-immortal, org.jmclbench.core.policy.OverrunPolicy); a test compares
 * the two.
 */
#ifndef JM_POLICY_H
#define JM_POLICY_H

#include <stddef.h>

/* The stable codes, the same as Java's OverrunPolicy.code. */
enum jm_policy { JM_POLICY_SKIP = 0, JM_POLICY_TERMINATE = 1, JM_POLICY_QUEUE = 2 };

/* The option values, '|'-separated in code order (the n-th label is code n). */
#define JM_POLICY_LABELS "skip|terminate|queue"

/* The option value and summary.json name of a policy. */
static inline const char *jm_policy_name(enum jm_policy p)
{
	switch (p) {
	case JM_POLICY_TERMINATE:
		return "terminate";
	case JM_POLICY_QUEUE:
		return "queue";
	default:
		return "skip";
	}
}

/* The thesis's test name: the run path's folder (SkipTest, TermTest, QueueTest). */
static inline const char *jm_policy_folder(enum jm_policy p)
{
	switch (p) {
	case JM_POLICY_TERMINATE:
		return "TermTest";
	case JM_POLICY_QUEUE:
		return "QueueTest";
	default:
		return "SkipTest";
	}
}

#endif
