package org.jmclbench.bench;

import java.util.Locale;
import java.util.concurrent.locks.LockSupport;

import javax.realtime.AsynchronouslyInterruptedException;
import javax.realtime.Interruptible;
import javax.realtime.RealtimeThread;

import org.jmclbench.rtsjcompat.Atc;
import org.jmclbench.workload.record.Stats;

/**
 * How long rtsj-compat's asynchronous transfer of control takes to stop a computation, apart from
 * any job: a realtime thread computes in a {@code doInterruptible} with a delivery point
 * ({@link Atc#poll()}, what rtsj-weaver inserts) after every {@code work} steps, and another
 * thread fires the AIE at it 50 to 150 us after it began (both then idle 1 ms, so that SCHED_FIFO's
 * throttling never applies). The latency is from just before {@code fire()} to its
 * {@code interruptAction}. Mode {@code flag} does the same with a volatile flag polled at the same
 * points, the javase and scj engines' cooperative abort, so the two differ by the ATC alone.
 *
 * <p>The engines' abort latency holds this plus the job's gap between delivery points (the static
 * bound) and what the job's frames cost the exception; this isolates the runtime's part.
 *
 * <p>Usage: {@code java -cp benchmarks.jar org.jmclbench.bench.AtcDeliveryLatency atc|flag
 * [ABORTS [WARMUP [WORK]]]}; prints one line of nanosecond statistics over ABORTS aborts after
 * WARMUP unrecorded ones. bench/atc-latency.sh runs both modes.
 */
public final class AtcDeliveryLatency {
    private static final int PRIME_ROUNDS = 20_000;
    /** The computation runs 50 to 150 us before each abort, then both threads idle 1 ms (no RT throttling). */
    private static final long RUN_NS = 50_000L;
    private static final long IDLE_NS = 1_000_000L;

    private static volatile int started = -1;
    private static volatile long firedNs;
    private static volatile long stoppedNs;
    private static volatile boolean abortFlag;
    private static volatile double sink;

    private AtcDeliveryLatency() {
    }

    public static void main(String[] args) throws InterruptedException {
        if (args.length < 1 || args.length > 4 || !(args[0].equals("atc") || args[0].equals("flag"))) {
            System.err.println("usage: AtcDeliveryLatency atc|flag [ABORTS [WARMUP [WORK]]]");
            System.exit(2);
        }
        final boolean useAtc = args[0].equals("atc");
        final int aborts = count(args, 1, 2000);
        if (aborts == 0) {
            System.err.println("AtcDeliveryLatency: ABORTS: at least 1");
            System.exit(2);
        }
        final int warmup = count(args, 2, 200);
        final int work = count(args, 3, 200);
        final int total = warmup + aborts;
        final long[] latency = new long[total];
        final AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
        Atc.prime(PRIME_ROUNDS); // as the rtsj engine does before a run that aborts
        final Interruptible computes = new Interruptible() {
            @Override
            public void run(AsynchronouslyInterruptedException e) throws AsynchronouslyInterruptedException {
                while (true) {
                    step(work);
                    Atc.poll();
                }
            }

            @Override
            public void interruptAction(AsynchronouslyInterruptedException e) {
                stoppedNs = System.nanoTime();
            }
        };
        RealtimeThread target = new RealtimeThread() {
            @Override
            public void run() {
                for (int k = 0; k < total; k++) {
                    LockSupport.parkNanos(IDLE_NS);
                    started = k;
                    if (useAtc) {
                        aie.doInterruptible(computes);
                    } else {
                        while (!abortFlag) {
                            step(work);
                        }
                        abortFlag = false;
                        stoppedNs = System.nanoTime();
                    }
                    latency[k] = stoppedNs - firedNs;
                }
            }
        };
        target.start();
        for (int k = 0; k < total; k++) {
            while (started != k) {
                Thread.yield();
            }
            LockSupport.parkNanos(RUN_NS + (k * 7919L) % (2 * RUN_NS));
            stoppedNs = 0;
            firedNs = System.nanoTime();
            if (useAtc) {
                while (!aie.fire()) { // false until the next doInterruptible has begun
                    Thread.yield();
                    firedNs = System.nanoTime();
                }
            } else {
                abortFlag = true;
            }
            while (stoppedNs == 0) {
                Thread.yield();
            }
        }
        target.join();
        long[] measured = new long[aborts];
        System.arraycopy(latency, warmup, measured, 0, aborts);
        Stats s = Stats.of(measured, aborts);
        System.out.println(String.format(Locale.ROOT, "%-4s aborts %d (after %d) work %d: min %d p50 %d p90 %d p99 %d p99.9 %d max %d ns",
                args[0], aborts, warmup, work, s.min, s.p50, s.p90, s.p99, s.p999, s.max));
    }

    /** {@code n} steps of arithmetic the JIT cannot remove. */
    private static void step(int n) {
        double x = sink;
        for (int i = 0; i < n; i++) {
            x = x * 1.0000001 + 1e-9;
        }
        sink = x;
    }

    private static int count(String[] args, int i, int fallback) {
        if (args.length <= i) {
            return fallback;
        }
        try {
            int n = Integer.parseInt(args[i]);
            if (n >= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // below
        }
        System.err.println("AtcDeliveryLatency: argument " + (i + 1) + ": " + args[i] + ": not a count");
        System.exit(2);
        return fallback;
    }
}
