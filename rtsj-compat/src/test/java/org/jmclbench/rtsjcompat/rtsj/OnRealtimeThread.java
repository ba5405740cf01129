package org.jmclbench.rtsjcompat.rtsj;

import static org.junit.jupiter.api.Assertions.assertFalse;

import java.time.Duration;
import javax.realtime.RealtimeThread;
import org.junit.jupiter.api.Assertions;

/** Runs a test body on a {@link RealtimeThread} (doInterruptible needs a schedulable) and rethrows its failure. */
final class OnRealtimeThread {
    interface Body {
        void run(RealtimeThread self) throws Exception;
    }

    private OnRealtimeThread() {
    }

    static void run(Body body) {
        Throwable[] failure = new Throwable[1];
        RealtimeThread t = new RealtimeThread() {
            @Override
            public void run() {
                try {
                    body.run(this);
                } catch (Throwable e) {
                    failure[0] = e;
                }
            }
        };
        Assertions.assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            t.start();
            t.join();
        });
        assertFalse(t.isAlive());
        if (failure[0] instanceof AssertionError) {
            throw (AssertionError) failure[0];
        }
        if (failure[0] != null) {
            throw new AssertionError("the real-time thread failed", failure[0]);
        }
    }
}
