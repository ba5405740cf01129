package org.jmclbench.verification.toy;

/** One seeded bug per property, plugged into {@link ToyMission} (NONE: the correct program). */
public enum ToyFault {
    NONE,
    /** P1: the dispatcher takes the records' lock, then the robot's; the handler the other way. */
    LOCK_INVERSION,
    /** P2: the dispatcher reads the robot's estimate without its lock. */
    UNGUARDED_READ,
    /** P3: the job writes the live particles before it polls the abort request. */
    COMMIT_BEFORE_POLL,
    /** P4: the job polls every two poll intervals. */
    WIDE_POLL,
    /** P5: a release that finds the queue non-empty is dropped. */
    LOST_RELEASE,
    /** P6: the release allocates a scratch array. */
    STRAY_ALLOCATION
}
