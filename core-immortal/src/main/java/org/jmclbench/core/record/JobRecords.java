package org.jmclbench.core.record;

import org.jmclbench.core.timeline.Timeline;

/**
 * Every job's timestamps, outcome and committed estimate, in arrays allocated before the run
 * and indexed by the merged event k, so that recording a job is a few array stores: no
 * allocation and no I/O while measuring. Written out after the run by the run writer.
 */
public final class JobRecords {
    public static final byte PENDING = 0;
    public static final byte DONE = 1;
    public static final byte LATE = 2;
    public static final byte SKIPPED = 3;
    public static final byte TERMINATED = 4;

    /** The timeline the records belong to. */
    public final Timeline timeline;
    /** Scheduled release (ns from the run start); in ideal runs the moment the thread takes the job. */
    public final long[] releaseNs;
    /** Job start (ns from the run start), -1 if it never started. */
    public final long[] startNs;
    /** Job end (completion or abort), -1 if it never started. */
    public final long[] endNs;
    /** Absolute deadline (ns from the run start), -1 in ideal runs. */
    public final long[] deadlineNs;
    /** CPU time of the handler thread in the job, -1 where unknown. */
    public final long[] cpuNs;
    /** When the dispatcher woke up to release the event, -1 where there is no dispatcher. */
    public final long[] wakeNs;
    /**
     * When an abort of event k's job was first requested (terminate: a later release, the gate's
     * request or an AIE fired at it), ns from the run start; -1 never. Raw: see {@link #abortFromNs}.
     */
    public final long[] abortNs;
    /**
     * When event k's job saw the abort request: its poll answered true, or its delivery point
     * threw the AIE; ns from the run start; -1 never, or an engine that does not record it.
     * Splits the abort latency into noticing (bounded by the gap between two polls) and stopping.
     */
    public final long[] abortSeenNs;
    /** One of PENDING, DONE, LATE, SKIPPED, TERMINATED. */
    public final byte[] outcome;
    /** Estimate committed by the job (valid when DONE or LATE). */
    public final double[] estX;
    public final double[] estY;
    public final double[] estTheta;
    /** Covariance after each completed update, 6 per event (cxx cxy cxt cyy cyt ctt), or null. */
    public final double[] cov;
    /** The estimate before any job (the initialisation's), for deviations before the first completed job. */
    public double initialX;
    public double initialY;
    public double initialTheta;
    /** Wall time of the measured window (ns), set by the run. */
    public long durationNs = -1;

    public JobRecords(Timeline t, boolean covariance) {
        int n = t.size();
        timeline = t;
        releaseNs = new long[n];
        startNs = new long[n];
        endNs = new long[n];
        deadlineNs = new long[n];
        cpuNs = new long[n];
        wakeNs = new long[n];
        abortNs = new long[n];
        abortSeenNs = new long[n];
        outcome = new byte[n];
        estX = new double[n];
        estY = new double[n];
        estTheta = new double[n];
        cov = covariance ? new double[6 * n] : null;
        clear();
    }

    /** Back to the state before a run (every time -1, every outcome PENDING), without allocating. */
    public void clear() {
        // plain loops: no java.util in code an SCJ VM runs
        for (int k = 0; k < outcome.length; k++) {
            releaseNs[k] = -1;
            startNs[k] = -1;
            endNs[k] = -1;
            deadlineNs[k] = -1;
            cpuNs[k] = -1;
            wakeNs[k] = -1;
            abortNs[k] = -1;
            abortSeenNs[k] = -1;
            outcome[k] = PENDING;
            estX[k] = Double.NaN;
            estY[k] = Double.NaN;
            estTheta[k] = Double.NaN;
        }
        if (cov != null) {
            for (int i = 0; i < cov.length; i++) {
                cov[i] = Double.NaN;
            }
        }
        durationNs = -1;
    }

    /** The number of events. */
    public int size() {
        return outcome.length;
    }

    /** Whether event k's job completed (DONE or LATE) and so committed an estimate. */
    public boolean completed(int k) {
        return outcome[k] == DONE || outcome[k] == LATE;
    }

    /**
     * When the abort of event k's job took hold, the abort_ns of the job files: the request, or
     * the job's start when it was requested before the job started; -1 when the job never started
     * or no abort was requested before its end (a request at or after the end asked nothing of
     * it). The abort latency is {@code endNs[k] - abortFromNs(k)}, positive where defined.
     */
    public long abortFromNs(int k) {
        long a = abortNs[k];
        long s = startNs[k];
        long e = endNs[k];
        if (a < 0 || s < 0 || e < 0) {
            return -1;
        }
        long from = a > s ? a : s;
        return from < e ? from : -1;
    }

    /**
     * When event k's job saw the abort that took hold of it (the seen_ns of the job files), or -1:
     * no abort took hold ({@link #abortFromNs}), or the engine did not record it. Noticing takes
     * {@code abortSeenFromNs(k) - abortFromNs(k)}, stopping {@code endNs[k] - abortSeenFromNs(k)}.
     */
    public long abortSeenFromNs(int k) {
        long from = abortFromNs(k);
        long seen = abortSeenNs[k];
        return from >= 0 && seen >= from && seen <= endNs[k] ? seen : -1;
    }

    /** Records that event k's job saw its abort request at {@code ns}, unless it saw it earlier. */
    public void abortSeen(int k, long ns) {
        if (abortSeenNs[k] < 0) {
            abortSeenNs[k] = ns;
        }
    }

    /** Records an abort request of event k's job at {@code ns}, unless an earlier one is recorded. */
    public void requestAbort(int k, long ns) {
        if (abortNs[k] < 0 || ns < abortNs[k]) {
            abortNs[k] = ns;
        }
    }

    /** Records the initialisation's estimate. */
    public void setInitialEstimate(double x, double y, double theta) {
        initialX = x;
        initialY = y;
        initialTheta = theta;
    }

    /** The outcome's name as written in the job files: done, late, skipped, terminated or pending. */
    public static String outcomeName(byte outcome) {
        switch (outcome) {
            case DONE:
                return "done";
            case LATE:
                return "late";
            case SKIPPED:
                return "skipped";
            case TERMINATED:
                return "terminated";
            default:
                return "pending";
        }
    }
}
