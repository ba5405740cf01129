package org.jmclbench.workload.rtsj;

import javax.realtime.AsynchronouslyInterruptedException;

import org.jmclbench.core.mcl.AbortSignal;

/**
 * The atomic design's abort signal: the MCL loops poll it every poll interval, and each poll
 * calls {@link #deliveryPoint()}, an AI-enabled method (it declares the AIE, so the build weaves a
 * delivery point at its entry). An AIE fired at the job is thrown there and unwinds the localizer,
 * which is not AI-enabled and commits only after its loops: the job leaves the robot unchanged.
 * Between two polls the localizer runs non-AI code, where RTSJ defers the AIE. A
 * {@link WitnessedInterrupt} notes when a delivery point threw it, which splits abort latency
 * into noticing and stopping.
 */
final class DeliveryPoints implements AbortSignal {
    static final DeliveryPoints INSTANCE = new DeliveryPoints();

    /**
     * An AIE that notes when one of these delivery points first threw it, in
     * {@code System.nanoTime()}. The catch that notes it calls no method: a JIT inlines it into
     * every job loop, where it is cold, and HotSpot resolves a cold call there at that loop's first
     * delivery (a call to the RTSJ clock or to a witness method was measured costing 27 to 36 us
     * in the rtsj engine, where the delivery itself took 0.1 us).
     */
    static final class WitnessedInterrupt extends AsynchronouslyInterruptedException {
        private static final long serialVersionUID = 1L;
        // written and read by the job's thread only
        boolean delivered;
        long deliveredNanoTime;

        /** Forgets the last delivery (a new job). */
        void reset() {
            delivered = false;
            deliveredNanoTime = 0;
        }
    }

    private DeliveryPoints() {
    }

    @Override
    public boolean abortRequested() {
        try {
            deliveryPoint();
        } catch (AsynchronouslyInterruptedException e) {
            if (e instanceof WitnessedInterrupt) {
                WitnessedInterrupt w = (WitnessedInterrupt) e;
                if (!w.delivered) {
                    w.deliveredNanoTime = System.nanoTime();
                    w.delivered = true;
                }
            }
            // Passed on unchanged: AbortSignal cannot declare the AIE, the JVM does not care.
            throw DeliveryPoints.<RuntimeException>passOn(e);
        }
        return false;
    }

    /** A delivery point of its own: woven with a poll at its entry. */
    static void deliveryPoint() throws AsynchronouslyInterruptedException {
    }

    @SuppressWarnings("unchecked")
    private static <T extends Throwable> T passOn(Throwable e) throws T {
        throw (T) e;
    }
}
