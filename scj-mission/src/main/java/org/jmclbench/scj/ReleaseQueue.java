package org.jmclbench.scj;

/**
 * The laser events released to the update handler and not yet taken, in release order: the
 * sensor offers, the update handler takes one per release. Sized for every laser event, so it
 * never fills; allocation-free after construction.
 */
final class ReleaseQueue {
    private final int[] events;
    private int head;
    private int tail;

    ReleaseQueue(int capacity) {
        events = new int[Math.max(1, capacity)];
    }

    synchronized void offer(int k) {
        events[tail % events.length] = k;
        tail++;
    }

    /** The oldest event offered and not taken, or -1 when there is none. */
    synchronized int take() {
        if (head == tail) {
            return -1;
        }
        int k = events[head % events.length];
        head++;
        return k;
    }
}
