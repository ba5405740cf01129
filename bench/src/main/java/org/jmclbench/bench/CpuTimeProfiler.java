package org.jmclbench.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.util.Collection;
import java.util.Collections;
import java.util.HashMap;
import java.util.Map;
import org.openjdk.jmh.infra.BenchmarkParams;
import org.openjdk.jmh.infra.IterationParams;
import org.openjdk.jmh.profile.InternalProfiler;
import org.openjdk.jmh.results.AggregationPolicy;
import org.openjdk.jmh.results.IterationResult;
import org.openjdk.jmh.results.Result;
import org.openjdk.jmh.results.ScalarResult;

/**
 * JMH profiler reporting the CPU time the benchmark's worker threads spent per operation
 * ({@code cpu.time.norm}, ns/op): unlike the wall time it excludes waiting for a CPU, so on a
 * machine shared with other work it still compares with the C loop's own CPU clock.
 * Use: {@code -prof org.jmclbench.bench.CpuTimeProfiler}.
 */
public final class CpuTimeProfiler implements InternalProfiler {
    private final ThreadMXBean mx = ManagementFactory.getThreadMXBean();
    private final Map<Long, Long> before = new HashMap<>();

    @Override
    public String getDescription() {
        return "CPU time of the JMH worker threads per operation";
    }

    @Override
    public void beforeIteration(BenchmarkParams benchmarkParams, IterationParams iterationParams) {
        before.clear();
        if (mx.isThreadCpuTimeSupported()) {
            for (long id : workers()) {
                before.put(id, mx.getThreadCpuTime(id));
            }
        }
    }

    @Override
    public Collection<? extends Result> afterIteration(BenchmarkParams benchmarkParams,
            IterationParams iterationParams, IterationResult result) {
        long ops = result.getMetadata().getMeasuredOps();
        long cpu = 0;
        int seen = 0;
        for (long id : workers()) {
            Long b = before.get(id);
            long now = mx.getThreadCpuTime(id);
            if (b != null && b >= 0 && now >= 0) {
                cpu += now - b;
                seen++;
            }
        }
        // The workers start with the first iteration: nothing to report until they are known.
        if (seen == 0 || ops <= 0) {
            return Collections.emptyList();
        }
        return Collections.singletonList(
                new ScalarResult("cpu.time.norm", cpu / (double) ops, "ns/op", AggregationPolicy.AVG));
    }

    private long[] workers() {
        long[] ids = mx.getAllThreadIds();
        ThreadInfo[] infos = mx.getThreadInfo(ids);
        long[] out = new long[ids.length];
        int n = 0;
        for (ThreadInfo t : infos) {
            if (t != null && t.getThreadName().contains("-jmh-worker-")) {
                out[n++] = t.getThreadId();
            }
        }
        return java.util.Arrays.copyOf(out, n);
    }
}
