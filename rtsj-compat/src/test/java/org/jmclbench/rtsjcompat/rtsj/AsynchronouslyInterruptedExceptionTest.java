package org.jmclbench.rtsjcompat.rtsj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import javax.realtime.AsynchronouslyInterruptedException;
import javax.realtime.Interruptible;
import org.jmclbench.rtsjcompat.Atc;
import org.jmclbench.rtsjcompat.AtcState;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * RTSJ's AIE rules on this layer, with explicit delivery points ({@code Atc.poll()}, what the
 * weaver inserts): fire, delivery, deferral where there is no delivery point, catching without
 * clearing, clear/happened, enable/disable, nesting, the generic AIE, and that an AIE never
 * escapes doInterruptible.
 */
class AsynchronouslyInterruptedExceptionTest {
    private final List<String> log = new ArrayList<>();

    @AfterEach
    void nothingLeftPending() {
        assertEquals(0, Atc.pendingThreads(), "an AIE stayed pending after its doInterruptible");
    }

    /** An Interruptible from two lambdas; interruptAction is logged. */
    private Interruptible task(String name, ThrowingRun body) {
        return new Interruptible() {
            @Override
            public void run(AsynchronouslyInterruptedException e) throws AsynchronouslyInterruptedException {
                body.run(e);
                log.add(name + " completed");
            }

            @Override
            public void interruptAction(AsynchronouslyInterruptedException e) {
                log.add(name + " interruptAction");
            }
        };
    }

    interface ThrowingRun {
        void run(AsynchronouslyInterruptedException e) throws AsynchronouslyInterruptedException;
    }

    @Test
    void aPendingAieIsClearedWhenTheLogicEndsWithAnotherThrowable() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            IllegalStateException failure = new IllegalStateException("the job failed");
            IllegalStateException thrown = assertThrows(IllegalStateException.class, () -> aie.doInterruptible(task("t", e -> {
                assertTrue(e.fire());
                throw failure; // leaves run(AIE) with the AIE pending
            })));
            assertSame(failure, thrown);
            assertFalse(aie.clear(), "left pending on the thread: delivered in its next doInterruptible");
            assertTrue(new AsynchronouslyInterruptedException().doInterruptible(task("next", e -> Atc.poll())));
            assertEquals(Collections.singletonList("next completed"), log);
        });
    }

    @Test
    void primingTheAtcLeavesNothingPendingAndAieWorkAfterwardsAsBefore() {
        Atc.prime(500);
        assertEquals(0, Atc.pendingThreads());
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            assertTrue(aie.doInterruptible(task("t", e -> {
                Atc.poll(); // nothing pending here after the priming: returns
                log.add("not interrupted");
            })));
            assertEquals(Arrays.asList("not interrupted", "t completed"), log);
        });
    }

    @Test
    void fireWithoutADoInterruptibleInProgressReturnsFalse() {
        assertFalse(new AsynchronouslyInterruptedException().fire());
    }

    @Test
    void doInterruptibleNeedsASchedulable() {
        AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
        assertThrows(IllegalThreadStateException.class, () -> aie.doInterruptible(task("t", e -> { })));
    }

    @Test
    void aFiredAieIsDeliveredAtTheNextDeliveryPointAndHandledByInterruptAction() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            assertTrue(aie.doInterruptible(task("t", e -> {
                Atc.poll(); // nothing pending: returns
                assertTrue(e.fire());
                log.add("fired");
                Atc.poll();
                log.add("after the delivery point");
            })));
            assertEquals(Arrays.asList("fired", "t interruptAction"), log);
            assertFalse(aie.clear(), "cleared by doInterruptible");
            assertFalse(aie.fire(), "no doInterruptible in progress any more");
        });
    }

    @Test
    void withoutADeliveryPointTheRunCompletesAndThePendingAieIsCleared() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            aie.doInterruptible(task("t", e -> {
                assertTrue(e.fire());
                assertSame(e, AtcState.current().pending());
            }));
            assertEquals(Arrays.asList("t completed"), log);
            assertEquals(null, AtcState.current().pending());
        });
    }

    @Test
    void catchingTheAieDoesNotClearItButHappenedDoes() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            aie.doInterruptible(task("t", e -> {
                e.fire();
                try {
                    Atc.poll();
                    fail("not delivered");
                } catch (AsynchronouslyInterruptedException caught) {
                    assertSame(e, caught);
                }
                try {
                    Atc.poll();
                    fail("a caught AIE must stay pending");
                } catch (AsynchronouslyInterruptedException again) {
                    assertTrue(again.happened(true));
                }
                Atc.poll(); // cleared: no delivery
                log.add("went on");
            }));
            assertEquals(Arrays.asList("went on", "t completed"), log);
        });
    }

    @Test
    void aDisabledAieIsHeldPendingUntilEnabled() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            assertFalse(aie.disable(), "outside its doInterruptible");
            aie.doInterruptible(task("t", e -> {
                assertTrue(e.disable());
                assertFalse(e.isEnabled());
                assertFalse(e.fire(), "disabled: fire answers false");
                Atc.poll();
                log.add("deferred while disabled");
                assertTrue(e.enable());
                Atc.poll();
                log.add("not reached");
            }));
            assertEquals(Arrays.asList("deferred while disabled", "t interruptAction"), log);
        });
    }

    @Test
    void anAieDisabledAfterItsFireIsHeldUntilEnabledAgain() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            aie.doInterruptible(task("t", e -> {
                assertTrue(e.fire(), "enabled: pending and deliverable");
                assertTrue(e.disable());
                Atc.poll();
                log.add("deferred once disabled");
                assertTrue(e.enable());
                Atc.poll();
                log.add("not reached");
            }));
            assertEquals(Arrays.asList("deferred once disabled", "t interruptAction"), log);
        });
    }

    @Test
    void anOuterAieUnwindsTheInnerDoInterruptibleAndIsDeliveredInTheOuter() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException outer = new AsynchronouslyInterruptedException();
            AsynchronouslyInterruptedException inner = new AsynchronouslyInterruptedException();
            outer.doInterruptible(task("outer", o -> {
                inner.doInterruptible(task("inner", i -> {
                    assertTrue(o.fire());
                    assertFalse(i.fire(), "an enclosing AIE is already pending");
                    Atc.poll();
                }));
                log.add("inner returned");
                Atc.poll();
            }));
            assertEquals(Arrays.asList("inner returned", "outer interruptAction"), log);
        });
    }

    @Test
    void anInnerAieIsHandledByItsOwnDoInterruptible() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException outer = new AsynchronouslyInterruptedException();
            AsynchronouslyInterruptedException inner = new AsynchronouslyInterruptedException();
            outer.doInterruptible(task("outer", o -> {
                inner.doInterruptible(task("inner", i -> {
                    assertTrue(i.fire());
                    Atc.poll();
                }));
                Atc.poll();
            }));
            assertEquals(Arrays.asList("inner interruptAction", "outer completed"), log);
        });
    }

    @Test
    void aDoInterruptibleAlreadyInProgressReturnsFalse() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            aie.doInterruptible(task("t", e -> assertFalse(e.doInterruptible(task("again", x -> { })))));
            assertEquals(Arrays.asList("t completed"), log);
        });
    }

    @Test
    void theGenericAieOfInterruptIsDeliveredAndClearedByTheInnermostDoInterruptible() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            aie.doInterruptible(task("t", e -> {
                self.interrupt();
                assertSame(AsynchronouslyInterruptedException.getGeneric(), AtcState.current().pending());
                Atc.poll();
            }));
            assertEquals(Arrays.asList("t interruptAction"), log);
            assertEquals(null, AtcState.current().pending());
            Thread.interrupted();
        });
    }

    @Test
    void anotherThreadsFireIsDeliveredToTheSchedulableRunningTheDoInterruptible() {
        OnRealtimeThread.run(self -> {
            AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
            boolean[] fired = new boolean[1];
            aie.doInterruptible(task("t", e -> {
                Thread firer = new Thread(() -> fired[0] = e.fire());
                firer.start();
                try {
                    firer.join();
                } catch (InterruptedException x) {
                    fail(x);
                }
                Atc.poll();
            }));
            assertTrue(fired[0]);
            assertEquals(Arrays.asList("t interruptAction"), log);
        });
    }
}
