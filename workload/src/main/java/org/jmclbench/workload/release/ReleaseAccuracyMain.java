package org.jmclbench.workload.release;

import java.util.Arrays;
import java.util.Locale;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;

/**
 * The dispatcher alone, for comparison with cyclictest: releases empty jobs at a fixed period
 * through the same engine as a run (dispatcher, handler, skip policy) and prints the
 * distribution of the dispatcher's lateness (wake-up minus requested absolute time, what
 * cyclictest measures) and of the handler's start latency (job start minus release).
 *
 * <pre>java -cp jmclbench-workload.jar org.jmclbench.workload.release.ReleaseAccuracyMain
 *     --period-us 1000 --loops 10000 [--spin-us 0] [--warmup-loops 1000]</pre>
 *
 * Output, one line each, microseconds: {@code dispatcher count=.. min=.. p50=.. p90=.. p99=..
 * p999=.. max=..} and the same for {@code handler}.
 */
public final class ReleaseAccuracyMain {
    private ReleaseAccuracyMain() {
    }

    /** An empty job: the measurement is the release path only. */
    private static final EventJob EMPTY_JOB = new EventJob() {
        @Override
        public boolean run(int k, AbortSignal abort) {
            return true;
        }
    };

    public static void main(String[] args) throws Exception {
        long periodUs = 1000;
        int loops = 10_000;
        long spinUs = 0;
        int warmupLoops = -1;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (i + 1 >= args.length) {
                usage(a + ": needs a value");
            }
            String v = args[++i];
            long value;
            try {
                value = Long.parseLong(v);
            } catch (NumberFormatException e) {
                value = -1;
            }
            if (value < 0 || (value == 0 && !a.equals("--spin-us") && !a.equals("--warmup-loops"))) {
                usage(a + ": not a valid count: " + v);
            }
            switch (a) {
                case "--period-us":
                    periodUs = value;
                    break;
                case "--loops":
                    loops = (int) Math.min(value, 100_000_000L);
                    break;
                case "--spin-us":
                    spinUs = value;
                    break;
                case "--warmup-loops":
                    warmupLoops = (int) Math.min(value, 100_000_000L);
                    break;
                default:
                    usage(a + ": unknown option");
            }
        }
        if (warmupLoops < 0) {
            warmupLoops = (int) Math.min(loops, Math.max(100, 1_000_000 / periodUs)); // about 1 s
        }
        ThreadCpuClock noCpu = ThreadCpuClock.disabled("not measured");
        if (warmupLoops > 0) {
            replay(periodUs, warmupLoops, spinUs, noCpu); // compiles the release path
        }
        JobRecords r = replay(periodUs, loops, spinUs, noCpu);
        long[] lateness = new long[loops];
        long[] startLatency = new long[loops];
        int started = 0;
        for (int k = 0; k < loops; k++) {
            lateness[k] = r.wakeNs[k] - r.releaseNs[k];
            if (r.startNs[k] >= 0) {
                startLatency[started++] = r.startNs[k] - r.releaseNs[k];
            }
        }
        System.out.println(line("dispatcher", lateness, loops));
        System.out.println(line("handler", startLatency, started));
    }

    private static JobRecords replay(long periodUs, int loops, long spinUs, ThreadCpuClock cpu)
            throws InterruptedException {
        long[] release = new long[loops];
        long[] deadline = new long[loops];
        int[] task = new int[loops];
        for (int k = 0; k < loops; k++) {
            release[k] = k * periodUs * 1000L;
            deadline[k] = release[k] + periodUs * 1000L;
        }
        JobRecords records = Records.periodic(loops, periodUs / 1e6);
        new ReleaseEngine(ReleaseSchedule.of(release, deadline, task), PolicyGate.of(OverrunPolicy.SKIP), EMPTY_JOB,
                records, cpu, spinUs * 1000L).run();
        return records;
    }

    /** Nearest-rank percentiles (FORMATS.md section 4), printed in microseconds. */
    static String line(String name, long[] values, int count) {
        long[] v = Arrays.copyOf(values, count);
        Arrays.sort(v);
        StringBuilder sb = new StringBuilder(name).append(" count=").append(count);
        if (count == 0) {
            return sb.toString();
        }
        sb.append(String.format(Locale.ROOT, " min=%.1f", v[0] / 1e3));
        double[] qs = {0.5, 0.9, 0.99, 0.999};
        String[] names = {"p50", "p90", "p99", "p999"};
        for (int i = 0; i < qs.length; i++) {
            int idx = (int) Math.ceil(qs[i] * count) - 1;
            sb.append(String.format(Locale.ROOT, " %s=%.1f", names[i], v[Math.max(0, idx)] / 1e3));
        }
        sb.append(String.format(Locale.ROOT, " max=%.1f", v[count - 1] / 1e3));
        return sb.toString();
    }

    private static void usage(String problem) {
        System.err.println("jmclbench: " + problem);
        System.err.println("usage: ReleaseAccuracyMain --period-us N --loops N [--spin-us N]"
                + " [--warmup-loops N]");
        System.exit(2);
    }
}
