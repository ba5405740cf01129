package org.jmclbench.bench;

import java.util.concurrent.TimeUnit;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.release.JobRecorder;
import org.jmclbench.workload.release.ThreadCpuClock;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The cost of recording one job (SPEC section 11: "well under a microsecond"), as the javase
 * handlers and the ideal run record it: the engines' own {@link JobRecorder} around an empty job,
 * into {@link JobRecords} of {@value #EVENTS} events written in turn, with the thread CPU clock
 * ({@code cpuTime=on}, the default of a run) or without it ({@code off}, {@code --no-cpu-time}).
 * Beside it the parts: one read of each clock, and the share of the recording done while the
 * job holds the robot ({@link #held}: {@code start} and {@code end}; {@code record} follows the
 * robot's release). native/bench/record_cost.c measures the C engines' record.h the same way;
 * {@code bench/record-cost.sh} runs both and prints the table.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class RecordCostBenchmark {
    /** Records of this many events, written in turn, as a run writes them (more than the caches' lines hold). */
    static final int EVENTS = 4096;

    /** {@code on}: the thread CPU clock is read per job, as in a run's default; {@code off}: --no-cpu-time. */
    @Param({"on", "off"})
    String cpuTime;

    private ThreadCpuClock clock;
    private JobRecords records;
    private JobRecorder recorder;
    private int next;

    @Setup(Level.Trial)
    public void setUp() {
        boolean on = "on".equals(cpuTime);
        clock = ThreadCpuClock.forRun(on);
        if (on && !clock.usable()) {
            throw new IllegalStateException("no thread CPU clock on this JVM: " + clock.status());
        }
        double[] times = new double[EVENTS];
        for (int k = 0; k < EVENTS; k++) {
            times[k] = k * 0.001;
        }
        records = new JobRecords(Timeline.merge(times, new double[0]), false);
        for (int k = 0; k < EVENTS; k++) {
            records.deadlineNs[k] = Long.MAX_VALUE / 2; // done, as most jobs of a run are
        }
        recorder = new JobRecorder(records, clock, System.nanoTime());
    }

    private int nextEvent() {
        int k = next;
        next = k + 1 == EVENTS ? 0 : k + 1;
        return k;
    }

    /** Recording one (empty) job: start, end, then the stores and the outcome. */
    @Benchmark
    public void record() {
        int k = nextEvent();
        recorder.start();
        recorder.end();
        recorder.record(k, true, -1);
    }

    /** The part of {@link #record} done while the job holds the robot: start and end. */
    @Benchmark
    public void held() {
        recorder.start();
        recorder.end();
    }

    /** One read of the monotonic clock (System.nanoTime). */
    @Benchmark
    public long nanoTime() {
        return System.nanoTime();
    }

    /** One read of the thread CPU clock as the engines read it (-1 without one). */
    @Benchmark
    public long cpuClock() {
        return clock.now();
    }
}
