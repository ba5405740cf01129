package org.jmclbench.workload.mcl;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.AbortAt;
import org.jmclbench.core.mcl.AbortSignal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Determinism, the two memory styles' bit-identity and termination (ALGORITHM 8, 9) on a
 * small synthetic dataset.
 */
class LocalizerBehaviourTest {
    @TempDir
    static File tmp;
    static Dataset data;
    static Timeline timeline;

    @BeforeAll
    static void dataset() throws IOException, BadInputException {
        data = DatasetReader.readFolder(SyntheticDataset.write(new File(tmp, "d"), 6.0, 42, true, true));
        timeline = data.timeline();
    }

    /** Every estimate (and covariance) after each event, as raw bits. */
    static long[] trace(MclConfig c) {
        Localizer l = Localizers.create(c, data.playground, data.startX, data.startY, data.startTheta);
        long[] out = new long[timeline.size() * 9];
        double[] cov = new double[6];
        for (int k = 0; k < timeline.size(); k++) {
            assertTrue(job(l, k, AbortSignal.NEVER));
            out[9 * k] = Double.doubleToRawLongBits(l.estimateX());
            out[9 * k + 1] = Double.doubleToRawLongBits(l.estimateY());
            out[9 * k + 2] = Double.doubleToRawLongBits(l.estimateTheta());
            l.covariance(cov);
            for (int i = 0; i < 6; i++) {
                out[9 * k + 3 + i] = Double.doubleToRawLongBits(cov[i]);
            }
        }
        return out;
    }

    static boolean job(Localizer l, int k, AbortSignal abort) {
        int i = timeline.taskIndex(k);
        return timeline.task(k) == Timeline.PREDICT
                ? l.predict(data.odoDx[i], data.odoDy[i], data.odoDtheta[i], abort)
                : l.update(data.laserAngle[i], abort);
    }

    static List<MclConfig> variants(int particles) {
        List<MclConfig> all = new ArrayList<>();
        for (MclConfig.Estimate e : MclConfig.Estimate.values()) {
            for (MclConfig.Resample r : MclConfig.Resample.values()) {
                for (MclConfig.Init i : MclConfig.Init.values()) {
                    all.add(MclConfig.builder().particles(particles).estimate(e).resample(r).init(i)
                            .covariance(true).seed(9).build());
                }
            }
        }
        return all;
    }

    @Test
    void theSameSeedGivesTheSameRun() {
        MclConfig c = MclConfig.builder().particles(300).seed(5).build();
        long[] a = trace(c);
        long[] b = trace(c);
        assertEquals(java.util.Arrays.toString(a), java.util.Arrays.toString(b));
        long[] other = trace(c.toBuilder().seed(6).build());
        assertNotEquals(java.util.Arrays.toString(a), java.util.Arrays.toString(other));
    }

    @Test
    void everyMemoryStyleIsBitIdentical() {
        for (MclConfig c : variants(150)) {
            long[] pre = trace(c.toBuilder().memory(MclConfig.Memory.PREALLOCATED).build());
            for (MclConfig.Memory other : new MclConfig.Memory[] {MclConfig.Memory.ALLOCATING, MclConfig.Memory.SCOPED}) {
                long[] alloc = trace(c.toBuilder().memory(other).build());
                for (int i = 0; i < pre.length; i++) {
                    if (pre[i] != alloc[i]) {
                        throw new AssertionError(c + " " + other + ": value " + i + " (event " + i / 9 + ") differs: "
                                + Double.longBitsToDouble(pre[i]) + " vs " + Double.longBitsToDouble(alloc[i]));
                    }
                }
            }
        }
    }

    @Test
    void theEstimateFollowsTheRobot() {
        // 500 particles from the known start on 6 s of a circle: well under 5 cm on average.
        Localizer l = Localizers.create(MclConfig.of(500), data.playground, data.startX, data.startY, data.startTheta);
        double sum = 0;
        int count = 0;
        int r = 0;
        for (int k = 0; k < timeline.size(); k++) {
            job(l, k, AbortSignal.NEVER);
            while (r < data.realCount() && data.realTime[r] < timeline.time(k)) {
                r++;
            }
            if (timeline.task(k) == Timeline.PREDICT) {
                sum += Math.hypot(l.estimateX() - data.realX[r], l.estimateY() - data.realY[r]);
                count++;
            }
        }
        assertTrue(sum / count < 0.05, "mean xy error " + sum / count);
    }

    /** Aborts at the n-th poll (1-based) of one job. */
    @Test
    void anAbortedJobChangesNothing() {
        int n = 200; // 4 polls per loop over the particles
        for (MclConfig base : variants(n)) {
            for (MclConfig.Memory memory : MclConfig.Memory.values()) {
                MclConfig c = base.toBuilder().memory(memory).build();
                // Abort each event k in 10..15 at every poll it makes, then finish the run;
                // the result must equal the run that never saw the aborted attempt.
                long[] reference = trace(c);
                for (int victim = 10; victim < 16; victim++) {
                    for (int at = 1; at <= 12; at++) {
                        Localizer l = Localizers.create(c, data.playground, data.startX, data.startY,
                                data.startTheta);
                        double[] cov = new double[6];
                        // Fifteen events after the victim suffice to see a disturbed particle set or generator.
                        for (int k = 0; k < victim + 15; k++) {
                            if (k == victim) {
                                double bx = l.estimateX();
                                double by = l.estimateY();
                                double bt = l.estimateTheta();
                                AbortAt signal = new AbortAt(at);
                                boolean completed = job(l, k, signal);
                                if (signal.polls() >= at) {
                                    assertFalse(completed, "aborted at poll " + at);
                                    assertEquals(bx, l.estimateX());
                                    assertEquals(by, l.estimateY());
                                    assertEquals(bt, l.estimateTheta());
                                    assertTrue(job(l, k, AbortSignal.NEVER));
                                } else {
                                    assertTrue(completed, "fewer polls than " + at + ": completes");
                                }
                            } else {
                                assertTrue(job(l, k, AbortSignal.NEVER));
                            }
                            l.covariance(cov);
                            if (Double.doubleToRawLongBits(l.estimateX()) != reference[9 * k]
                                    || Double.doubleToRawLongBits(l.estimateY()) != reference[9 * k + 1]
                                    || Double.doubleToRawLongBits(l.estimateTheta()) != reference[9 * k + 2]
                                    || Double.doubleToRawLongBits(cov[5]) != reference[9 * k + 8]) {
                                throw new AssertionError(c + ": event " + victim + " aborted at poll " + at
                                        + ": event " + k + " differs from the run without the abort");
                            }
                        }
                    }
                }
            }
        }
    }

    /** Counts its polls; never aborts. */
    static final class PollCounter implements AbortSignal {
        int polls;

        @Override
        public boolean abortRequested() {
            polls++;
            return false;
        }
    }

    @Test
    void everyMemoryStylePollsAtTheConfiguredInterval() {
        // MclConfig.pollInterval bounds an abort's notice; the allocating style polled every 64 whatever it said.
        // The styles' loops differ, so their counts do too; each must poll more often at a smaller interval.
        for (MclConfig.Memory memory : MclConfig.Memory.values()) {
            int previous = Integer.MAX_VALUE;
            for (int interval : new int[] {1, 4, 64}) {
                MclConfig c = MclConfig.builder().particles(200).memory(memory).pollInterval(interval).build();
                Localizer l = Localizers.create(c, data.playground, data.startX, data.startY, data.startTheta);
                PollCounter counter = new PollCounter();
                for (int k = 0; k < 20; k++) {
                    assertTrue(job(l, k, counter));
                }
                assertTrue(counter.polls < previous, memory + ": " + counter.polls + " polls at interval " + interval
                        + ", not fewer than " + previous + " at the smaller one");
                previous = counter.polls;
            }
        }
    }
}
