package org.jmclbench.rtsjcompat.rtsj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import javax.realtime.ImmortalMemory;
import javax.realtime.LTMemory;
import javax.realtime.RealtimeThread;
import org.jmclbench.rtsjcompat.AllocationMeter;
import org.jmclbench.rtsjcompat.AreaOverflowError;
import org.jmclbench.rtsjcompat.AreaUsage;
import org.jmclbench.rtsjcompat.RtsjRuntime;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** RTSJ scoped and immortal memory as measured budgets, with SCJ's accounting. */
class ScopedMemoryTest {
    static volatile Object sink;

    @BeforeEach
    void measured() {
        assumeTrue(AllocationMeter.current().measures(), "this JVM has no per-thread allocation counter");
        RtsjRuntime.reset();
    }

    private static AreaUsage usage(String name) {
        return RtsjRuntime.areas().stream().filter(a -> a.name().equals(name)).findFirst()
                .orElseThrow(() -> new AssertionError("no area " + name));
    }

    @Test
    void aScopeIsChargedWhatItsThreadsAllocateAndEmptiedWhenTheLastLeaves() {
        OnRealtimeThread.run(self -> {
            LTMemory scope = new LTMemory(64 * 1024);
            for (int i = 0; i < 3; i++) {
                scope.enter(() -> {
                    sink = new byte[10000];
                    assertEquals(RealtimeThread.getCurrentMemoryArea(), scope);
                    assertEquals(1, scope.getReferenceCount());
                });
            }
            assertEquals(0, scope.getReferenceCount());
            AreaUsage u = usage(scope.toString());
            assertEquals("scoped", u.kind());
            assertTrue(u.peakBytes() >= 10000 && u.peakBytes() < 11000, "peak " + u.peakBytes());
            assertTrue(u.totalBytes() >= 30000, "total " + u.totalBytes());
            assertEquals(3, u.cycles());
        });
    }

    @Test
    void aScopeThatOverflowsRaisesAnOutOfMemoryErrorNamingIt() {
        OnRealtimeThread.run(self -> {
            LTMemory scope = new LTMemory(1000, 2000);
            AreaOverflowError e = assertThrows(AreaOverflowError.class, () -> scope.enter(() -> sink = new byte[5000]));
            assertEquals(scope.toString(), e.areaName());
            assertTrue(scope.toString().startsWith("LTMemory#"));
        });
    }

    @Test
    void immortalMemoryOutsideAnScjLaunchIsMeasured() {
        OnRealtimeThread.run(self -> {
            ImmortalMemory.instance().enter(() -> sink = new long[1000]);
            assertTrue(usage("ImmortalMemory").totalBytes() >= 8000);
        });
    }
}
