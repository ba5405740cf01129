package org.jmclbench.bench;

import java.io.File;
import java.io.IOException;
import java.util.concurrent.TimeUnit;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.core.mcl.MclConfig;
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
 * Time per job of the MCL kernel (SPEC section 11): one odometry job ({@code predict}) or one
 * laser job ({@code update}: likelihood, normalisation, estimate, systematic resampling), on
 * the events of a shipped dataset replayed in order and wrapped around, exactly as
 * native/bench/kernel_jobs.c replays them, so the two times can be divided.
 *
 * <p>Each benchmark replays only its own task's events: the predict jobs never see an update
 * and the update jobs never move the particles. The arithmetic per job is what a run does
 * (the same particle count, the same functions on similar arguments), which is what the
 * Java/C comparison needs; the localisation quality of such a replay is irrelevant here.
 *
 * <p>Run: {@code java -jar bench/target/benchmarks.jar KernelBenchmark -prof gc}, or
 * {@code bench/kernel-ratio.sh} for the comparison with C.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class KernelBenchmark {
    @Param({"1000", "4000"})
    int particles;

    @Param({"preallocated", "allocating"})
    String memory;

    /** Dataset folder; empty for data/match-short found upwards from the working directory. */
    @Param("")
    String dataset;

    private Localizer localizer;
    private double[] odoDx;
    private double[] odoDy;
    private double[] odoDtheta;
    private double[] laser;
    private int nextOdometry;
    private int nextLaser;

    @Setup(Level.Trial)
    public void setUp() throws IOException, BadInputException {
        Dataset d = DatasetReader.readFolder(dataset.isEmpty() ? findDefault() : new File(dataset));
        MclConfig config = MclConfig.builder()
                .particles(particles)
                .memory(MclConfig.Memory.valueOf(memory.toUpperCase(java.util.Locale.ROOT)))
                .seed(1)
                .build();
        localizer = Localizers.create(config, d.playground, d.startX, d.startY, d.startTheta);
        odoDx = d.odoDx;
        odoDy = d.odoDy;
        odoDtheta = d.odoDtheta;
        laser = d.laserAngle;
    }

    private static File findDefault() throws IOException {
        File dir = new File("").getAbsoluteFile();
        while (dir != null) {
            File c = new File(dir, "data/match-short");
            if (new File(c, DatasetReader.ODOMETRY).isFile()) {
                return c;
            }
            dir = dir.getParentFile();
        }
        throw new IOException("data/match-short not found above " + new File("").getAbsolutePath()
                + "; pass -p dataset=DIR");
    }

    /** One odometry job. */
    @Benchmark
    public double predict() {
        int k = nextOdometry;
        nextOdometry = k + 1 == odoDx.length ? 0 : k + 1;
        localizer.predict(odoDx[k], odoDy[k], odoDtheta[k], AbortSignal.NEVER);
        return localizer.estimateX();
    }

    /** One laser job: likelihood of every particle, normalisation, estimate, resampling. */
    @Benchmark
    public double update() {
        int k = nextLaser;
        nextLaser = k + 1 == laser.length ? 0 : k + 1;
        localizer.update(laser[k], AbortSignal.NEVER);
        return localizer.estimateX();
    }
}
