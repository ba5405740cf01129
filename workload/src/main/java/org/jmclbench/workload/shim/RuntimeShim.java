package org.jmclbench.workload.shim;

import java.util.List;

/**
 * The five services the engines need from the real-time layer that are not RTSJ API: whether
 * thread priorities reach the OS, forgetting the previous replay before the next, readying the
 * layer's ATC before a run that fires AIEs, the threads' CPU clock, and ending the event handlers' threads after a
 * replay. The one seam between the rtsj engine and rtsj-compat: on a JVM the layer is rtsj-compat
 * ({@code CompatShim}, present in the Maven build); built for an RTSJ VM by {@code ant rtsj-engine},
 * that class is left out and {@link StandardShim} (RTSJ 1.0.2 API only) takes its place.
 */
public abstract class RuntimeShim {
    private static final String COMPAT = "org.jmclbench.workload.shim.CompatShim";
    private static final RuntimeShim CURRENT = choose();

    /** The shim of this build: rtsj-compat's when it was built in, else the standard one. */
    public static RuntimeShim get() {
        return CURRENT;
    }

    private static RuntimeShim choose() {
        try {
            return (RuntimeShim) Class.forName(COMPAT).getDeclaredConstructor().newInstance();
        } catch (ClassNotFoundException | NoClassDefFoundError e) {
            return new StandardShim();
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot create " + COMPAT, e);
        }
    }

    /** Whether the thread priorities an engine sets are applied by the OS. */
    public abstract boolean prioritiesApplied();

    /** Before a replay: forgets what the layer kept of the previous one; its handlers have ended. */
    public abstract void beforeReplay();

    /**
     * Before any schedulable of a run that will fire AIEs: readies the layer's ATC so that the
     * first deliveries cost what later ones do. Nothing on an RTSJ VM, whose ATC is its own.
     */
    public void beforeAborts() {
    }

    /**
     * After a replay whose events have all ended: ends the event handlers' threads (each after
     * the fires pending now), waits up to {@code timeoutMs} in all and returns the names of those
     * still running (a handler that never ends: the engine's failure).
     */
    public abstract List<String> endHandlers(long timeoutMs);

    /**
     * The per-job CPU clock of a run, probed now (before the measured window): the layer's, or one
     * that is not usable and says why. {@code wanted} is false with {@code --no-cpu-time}: then
     * none is probed or read.
     */
    public abstract CpuClock cpuClock(boolean wanted);

    /** A clock that is never read ({@code cpu_ns} -1), with {@code why} as its status. */
    public static CpuClock noCpuClock(String why) {
        return new NoCpuClock(why);
    }
}
