package org.jmclbench.workload.scj;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.MotionModel;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.rtsjcompat.ScjLauncher;
import org.jmclbench.scj.MclSafelet;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.scj.MissionSizes;
import org.jmclbench.scj.Periodicity;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.workload.output.MemoryArea;

/**
 * The {@code --engine scj} run on Java SE: checks that the odometry has a period, launches the
 * SCJ mission at Level 1 through rtsj-compat (a warm-up mission, or one or two short
 * class-loading missions, first, so that class loading stays out of the measured releases), and turns the compat layer's report into the run's
 * memory areas and engine facts. An overflowing area or any other mission failure is a
 * {@link RunFailure} naming it.
 */
public final class ScjRun {
    /** Events of the class-loading mission run before the measured one (when there is no warm-up). */
    static final int PRELOAD_EVENTS = 4;

    private ScjRun() {
    }

    /** Runs the mission of the options on the dataset (checked by {@link ScjEngine#validate}). */
    static EngineResult run(RunOptions options, Dataset dataset) throws RunFailure {
        MissionConfiguration config = configuration(options, options.mclConfig(), options.timeScale, true);

        // Class loading allocates (some 30 KB, charged to whatever area is current): a short
        // mission of the same kind first, so that no measured release pays for it.
        int warmupEvents = 0;
        if (options.warmupS > 0) {
            DatasetInput warm = DatasetInput.before(dataset, options.warmupS);
            warmupEvents = warm.odometryCount() + warm.laserCount();
            launch(new MclSafelet(roomy(configuration(options, options.mclConfig(), options.timeScale, false), warm),
                    warm, new RecordCapture()), "the warm-up mission");
        } else {
            MclConfig small = options.mclConfig().toBuilder()
                    .particles(Math.min(options.particles, 2 * MotionModel.ABORT_BLOCK)).build();
            DatasetInput first = new DatasetInput(dataset, Math.min(PRELOAD_EVENTS, dataset.odometryCount()),
                    Math.min(PRELOAD_EVENTS, dataset.laserCount()));
            // Under skip or terminate a slow first mission (an interpreter, a loaded machine) may drop
            // or abort every job of a task, leaving its classes to load in a measured release: queue
            // runs every job to its end, then the run's own policy loads what only its gate touches.
            for (OverrunPolicy policy : preloadPolicies(options.policy)) {
                launch(new MclSafelet(roomy(configuration(options, small, policy, 0.1, false), first), first,
                        new RecordCapture()), "the class-loading mission");
            }
        }

        RecordCapture output = new RecordCapture();
        MclSafelet safelet = new MclSafelet(config, new DatasetInput(dataset), output);
        ScjLauncher mission = launch(safelet, "the mission");
        JobRecords records = output.records();
        if (records == null) {
            throw new RunFailure("the mission ended without handing over its records");
        }
        for (int k = 0; k < records.size(); k++) {
            if (records.outcome[k] == JobRecords.PENDING) {
                throw new RunFailure("event " + k + " never ended (the mission terminated early)");
            }
        }
        return new EngineResult(records, areas(mission), new ScjFacts(warmupEvents, mission, outOfOrder(records)));
    }

    /**
     * Jobs that started before a job of an earlier event: the two handlers contend for the robot
     * on its monitor only (SCJ Level 1 has no wait/notify), so under overload a later event of one
     * task can overtake an earlier one of the other; 0 when the machine kept up.
     */
    static int outOfOrder(JobRecords r) {
        int count = 0;
        long latest = Long.MIN_VALUE;
        for (int k = 0; k < r.size(); k++) {
            if (r.startNs[k] < 0) {
                continue;
            }
            if (r.startNs[k] < latest) {
                count++;
            }
            latest = Math.max(latest, r.startNs[k]);
        }
        return count;
    }

    /** The mission's configuration for the options, with a filter (the run's, or a smaller one) and a time scale. */
    public static MissionConfiguration configuration(RunOptions o, MclConfig mcl, double timeScale, boolean areaSizes) {
        return configuration(o, mcl, o.policy, timeScale, areaSizes);
    }

    /** The policies of the class-loading missions: queue (every job computes), then the run's own. */
    static OverrunPolicy[] preloadPolicies(OverrunPolicy policy) {
        return policy == OverrunPolicy.QUEUE ? new OverrunPolicy[] {policy}
                : new OverrunPolicy[] {OverrunPolicy.QUEUE, policy};
    }

    private static MissionConfiguration configuration(RunOptions o, MclConfig mcl, OverrunPolicy policy,
            double timeScale, boolean areaSizes) {
        MissionConfiguration c = new MissionConfiguration(mcl, policy, timeScale);
        if (areaSizes) {
            for (Map.Entry<String, Long> e : o.areaSizes.entrySet()) {
                c.areaSize(MissionSizes.areaIndex(e.getKey()), e.getValue());
            }
        }
        return c;
    }

    /**
     * Extra room in every area of the warm-up and class-loading missions: loading classes allocates
     * there, and more under a Java agent that rewrites classes as they load (a profiler's, or Jazzer's
     * in the test JVM after a fuzz test: 8.4 MiB were needed where 8 were given). The areas are budgets
     * counted on the heap, not reserved memory, so the room costs nothing.
     */
    static final long LOADING_ROOM = 64L << 20;

    /** The configuration with every area {@link #LOADING_ROOM} larger than the workload needs. */
    private static MissionConfiguration roomy(MissionConfiguration c, DatasetInput input) {
        MissionSizes sizes = new MissionSizes(c, input.odometryCount(), input.laserCount());
        for (int a = 0; a < MissionSizes.AREA_COUNT; a++) {
            c.areaSize(a, sizes.size(a) + LOADING_ROOM);
        }
        return c;
    }

    private static ScjLauncher launch(MclSafelet safelet, String what) throws RunFailure {
        ScjLauncher mission = ScjLauncher.launch(safelet);
        if (mission == null) {
            throw new RunFailure(what + " did not run (no report from rtsj-compat)");
        }
        if (!mission.succeeded()) {
            int a = mission.overflowedArea();
            if (a >= 0) {
                String area = areaName(mission.areaName(a));
                throw new RunFailure("memory area '" + area + "' overflowed in " + what + ": it needed "
                        + mission.overflowBytesNeeded() + " bytes, its size is " + mission.areaSize(a)
                        + " bytes (--area-size " + area + "=BYTES)");
            }
            throw new RunFailure(what + " failed: " + mission.failureMessage());
        }
        return mission;
    }

    /**
     * The compat layer's areas under the mission's names (immortal, mission, the handlers' names).
     * On a JVM with no allocation counter every figure of use is 0 whatever the area held: null then
     * (not measured), never a made-up 0 bytes per release.
     */
    static List<MemoryArea> areas(ScjLauncher mission) {
        List<MemoryArea> out = new ArrayList<>();
        boolean measured = mission.allocationMeasured();
        for (int a = 0; a < mission.areaCount(); a++) {
            boolean released = mission.areaIsPrivate(a) && mission.areaReleases(a) > 0;
            Long peak = measured ? mission.areaPeakBytes(a) : null;
            Long perRelease = released && measured ? Math.round(mission.areaBytesPerRelease(a)) : null;
            Long allocating = released && measured ? mission.areaAllocatingReleases(a) : null;
            out.add(new MemoryArea(areaName(mission.areaName(a)), mission.areaSize(a), peak, perRelease,
                    released ? mission.areaReleases(a) : null, allocating));
        }
        return out;
    }

    /** ImmortalMemory -> immortal, MissionMemory -> mission, PrivateMemory:NAME -> NAME. */
    static String areaName(String compatName) {
        if (compatName.equals("ImmortalMemory")) {
            return "immortal";
        }
        if (compatName.equals("MissionMemory")) {
            return "mission";
        }
        int colon = compatName.indexOf(':');
        return colon >= 0 ? compatName.substring(colon + 1) : compatName.toLowerCase(Locale.ROOT);
    }

    /** A PeriodicEventHandler needs a period: odometry a reading of which is off its periodic release by more than the tolerance is bad input. */
    public static void checkPeriodic(Dataset d) throws BadInputException {
        int i = Periodicity.firstIrregular(d.odoTime);
        if (i < 0) {
            return;
        }
        throw BadInputException.atLine(d.odometryFile.getPath(), dataLine(d.odometryFile, i),
                String.format(Locale.ROOT, "odometry is not periodic: the reading at %.6f s is more than %.3f s from its"
                        + " periodic release %.6f s (first reading + %d * mean interval %.6f s); the scj engine's"
                        + " PeriodicEventHandler needs a period", d.odoTime[i], Periodicity.TOLERANCE_S,
                        Periodicity.periodicRelease(d.odoTime, i), i, Periodicity.period(d.odoTime)));
    }

    /** The file line (1-based) of data row i, skipping blank and comment lines as the reader does. */
    static int dataLine(File f, int row) {
        try (BufferedReader r = new BufferedReader(new InputStreamReader(Files.newInputStream(f.toPath()),
                StandardCharsets.UTF_8))) {
            int lineNo = 0;
            int rows = -1;
            String line;
            while ((line = r.readLine()) != null) {
                lineNo++;
                String s = line.trim();
                if (s.isEmpty() || s.charAt(0) == '#') {
                    continue;
                }
                if (++rows == row) {
                    return lineNo;
                }
            }
        } catch (IOException e) {
            // fall through: the row number is still a fair pointer
        }
        return row + 1;
    }
}
