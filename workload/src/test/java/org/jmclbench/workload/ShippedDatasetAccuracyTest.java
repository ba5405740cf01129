package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;

import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.record.Deviation;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.release.ThreadCpuClock;
import org.junit.jupiter.api.Test;

/**
 * Localisation accuracy of the ideal run on the datasets shipped in {@code data/}. Bounds
 * have wide margins over the measured figures (in comments) because the filter is chaotic:
 * a last-bit difference of a JVM's sin/cos/exp may send it on another, equally valid path.
 */
class ShippedDatasetAccuracyTest {
    static File datasets() {
        for (File d = new File(System.getProperty("user.dir")).getAbsoluteFile(); d != null; d = d.getParentFile()) {
            File candidate = new File(d, "data");
            if (new File(candidate, "match").isDirectory()) {
                return candidate;
            }
        }
        throw new AssertionError("the shipped data/ folder was not found above " + System.getProperty("user.dir"));
    }

    static Deviation idealRun(String name, MclConfig c) throws BadInputException {
        Dataset d = DatasetReader.readFolder(new File(datasets(), name));
        Timeline t = d.timeline();
        JobRecords r = new JobRecords(t, false);
        IdealRun.run(d, t, Localizers.create(c, d.playground, d.startX, d.startY, d.startTheta), r,
                ThreadCpuClock.disabled("not measured"));
        return d.deviation(t, r);
    }

    /** The time after which the xy error stays below the bound (0 when always below). */
    static double settledAfter(Deviation v, double bound) {
        double last = 0;
        for (int i = 0; i < v.size(); i++) {
            if (v.dxy[i] >= bound) {
                last = v.time[i];
            }
        }
        return last;
    }

    @Test
    void matchWithAThousandParticlesFromTheKnownStartStaysWithinFiveCentimetres() throws BadInputException {
        // Measured (seeds 1-5): mean xy 0.95-1.15 cm, max 2.6-3.4 cm; mean angle 0.011 rad.
        // (The allocating style gives bit-identical estimates, tested elsewhere: not repeated here.)
        for (long seed = 1; seed <= 3; seed++) {
            Deviation v = idealRun("match", MclConfig.builder().particles(1000).seed(seed).build());
            assertTrue(v.meanXY() < 0.05, "seed " + seed + ": mean xy " + v.meanXY());
            assertTrue(v.meanAbsTheta() < 0.05, "seed " + seed + ": mean angle " + v.meanAbsTheta());
        }
    }

    @Test
    void theOtherTrackingScenariosStayWithinFiveCentimetres() throws BadInputException {
        // Measured with 1000 particles (seeds 1-5): figure8 1.2-1.3 cm, stay 0.4 cm, match-short 0.6 cm.
        for (String name : new String[] {"figure8", "stay", "match-short"}) {
            Deviation v = idealRun(name, MclConfig.of(1000));
            assertTrue(v.meanXY() < 0.05, name + ": mean xy " + v.meanXY());
        }
    }

    @Test
    void kidnapIsTrackedUntilTheKidnap() throws BadInputException {
        // Before the kidnap at 30 s: under 1 cm; after it this filter (no particle injection)
        // stays lost: 0.2 to 2.7 m, which the kidnap scenario is there to show.
        Deviation v = idealRun("kidnap", MclConfig.of(1000));
        int before = 0;
        while (before < v.size() && v.time[before] < 30.0) {
            before++;
        }
        double meanBefore = Deviation.meanAbs(v.dxy, 0, before);
        double meanAfter = Deviation.meanAbs(v.dxy, before, v.size());
        assertTrue(meanBefore < 0.05, "before the kidnap: " + meanBefore);
        assertTrue(meanAfter > 0.2, "after the kidnap: " + meanAfter);
    }

    @Test
    void stayFromAUniformStartConvergesWithinTenCentimetresInUnderTenSeconds() throws BadInputException {
        // Measured settle times (error below 10 cm from then on), seeds 1-10:
        //   4000 particles: 0.55 6.10 6.75 3.55 0.40 10.40 6.70 2.10 9.05 0.70 s
        //   1000 particles: 27.45 6.20 15.10 6.85 0.25 20.20 6.40 7.05 23.75 16.75 s
        // Standing still, particles move only by the motion-noise floor (2 mm a step), so the
        // time is set by how near the truth the closest initial particles fall: 1000 uniform
        // particles do not reliably converge in 10 s; 4000 do, but for one seed in ten.
        int settled = 0;
        StringBuilder times = new StringBuilder();
        for (long seed = 1; seed <= 5; seed++) {
            Deviation v = idealRun("stay",
                    MclConfig.builder().particles(4000).init(MclConfig.Init.UNIFORM).seed(seed).build());
            double t = settledAfter(v, 0.10);
            times.append(' ').append(t);
            if (t < 10.0) {
                settled++;
            }
        }
        assertTrue(settled >= 4, "settle times (s):" + times);
    }
}
