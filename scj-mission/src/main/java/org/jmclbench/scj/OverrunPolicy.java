package org.jmclbench.scj;

/** What happens to an event released while a job works on the robot (SPEC section 4). */
public enum OverrunPolicy {
    /** The new event is dropped (the thesis's SkipTest). */
    SKIP,
    /** The job in progress is asked to abort, polled every poll interval, and the new event runs (TermTest). */
    TERMINATE,
    /** Every event is processed in release order; one completed after its deadline is late (QueueTest). */
    QUEUE
}
