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

/*
 * Per policy, by code: the option value and summary.json name, and the thesis's test name (the
 * run path's folder). A new policy is one row here (and its code above).
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

#endif
