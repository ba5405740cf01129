package org.jmclbench.workload.rtsj;

import javax.realtime.AsynchronouslyInterruptedException;

import org.jmclbench.core.mcl.AbortSignal;

/**
 * The atomic design's abort signal: the MCL loops poll it every poll interval, and each poll
 * calls {@link #deliveryPoint()}, an AI-enabled method (it declares the AIE, so the build weaves a
 * delivery point at its entry). An AIE fired at the job is thrown there and unwinds the localizer,
 * which is not AI-enabled and commits only after its loops: the job leaves the robot unchanged.
 * Between two polls the localizer runs non-AI code, where RTSJ defers the AIE. An AIE that is a
 * {@link Witness} is told when a delivery point threw it, which splits abort latency into
 * noticing and stopping.
 */
final class DeliveryPoints implements AbortSignal {
    static final DeliveryPoints INSTANCE = new DeliveryPoints();

    /** An AIE told, on the job's thread, that a delivery point threw it. */
    interface Witness {
        void delivered();
    }

    private DeliveryPoints() {
    }

    @Override
    public boolean abortRequested() {
        try {
            deliveryPoint();
        } catch (AsynchronouslyInterruptedException e) {
            if (e instanceof Witness) {
                ((Witness) e).delivered();
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
