package org.jmclbench.scj;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The update handler's release queue at and around its capacity (one slot per laser event): a
 * queue run whose update jobs all wait fills it, and every event comes out once, in release
 * order, also after the indices wrap around.
 */
class ReleaseQueueTest {

    @Test
    void filledToItsCapacityItGivesEveryEventOnceInOrder() {
        ReleaseQueue q = new ReleaseQueue(4);
        for (int k : new int[] {3, 7, 8, 12}) {
            q.offer(k);
        }
        assertEquals(3, q.take());
        assertEquals(7, q.take());
        assertEquals(8, q.take());
        assertEquals(12, q.take());
        assertEquals(-1, q.take(), "empty");
    }

    @Test
    void offersAndTakesInterleavedPastTheEndOfItsArray() {
        ReleaseQueue q = new ReleaseQueue(3);
        int next = 0;
        int expected = 0;
        for (int round = 0; round < 5; round++) {
            for (int i = 0; i < 3; i++) { // full again each round, the slots reused
                q.offer(next++);
            }
            for (int i = 0; i < 3; i++) {
                assertEquals(expected++, q.take());
            }
            assertEquals(-1, q.take());
        }
    }
}
