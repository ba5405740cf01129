package org.jmclbench.workload.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The engine driving a Localizer whose job cost is controlled: each completed job increments
 * the estimate, an aborted one changes nothing, so the committed estimates must count the
 * completed jobs exactly.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class FakeLocalizerTest {
    /** Busy-spins costNs per job, polling the abort request every ~20 us like core's 64-particle blocks. */
    static final class FakeLocalizer implements Localizer {
        final long costNs;
        double committed;

        FakeLocalizer(long costNs) {
            this.costNs = costNs;
        }

        private boolean job(AbortSignal abort) {
            long end = System.nanoTime() + costNs;
            while (System.nanoTime() < end) {
                long poll = System.nanoTime() + 20_000;
                while (System.nanoTime() < poll) {
                    // spin
                }
                if (abort.abortRequested()) {
                    return false;
                }
            }
            committed++;
            return true;
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            return job(abort);
        }

        @Override
        public boolean update(double angle, AbortSignal abort) {
            return job(abort);
        }

        @Override
        public double estimateX() {
            return committed;
        }

        @Override
        public double estimateY() {
            return -committed;
        }

        @Override
        public double estimateTheta() {
            return 0;
        }

        @Override
        public void covariance(double[] out) {
            java.util.Arrays.fill(out, 0, 6, committed);
        }

        @Override
        public int particleCount() {
            return 1;
        }

        @Override
        public void particle(int i, double[] out) {
            out[0] = committed;
        }
    }

    @Test
    void committedEstimatesCountCompletedJobsUnderEveryPolicy() throws Exception {
        for (String policy : new String[] {"skip", "terminate", "queue"}) {
            Timeline t = ReleaseEngineTest.periodicTimeline(24, 10_000_000L);
            double[] zeros = new double[t.size()];
            JobRecords r = new JobRecords(t, true);
            FakeLocalizer fake = new FakeLocalizer(25_000_000L);
            EventJob job = new LocalizerJob(zeros, zeros, zeros, zeros, t, fake, r);
            ReleaseSchedule s = ReleaseEngineTest.periodicSchedule(t, 10_000_000L);
            new ReleaseEngine(s, PolicyGate.of(OverrunPolicy.ofLabel(policy)), job, r, ThreadCpuClock.probe(), 0).run();
            ReleaseEngineTest.assertAccountedOnce(r, t.size());
            int completed = 0;
            for (int k = 0; k < t.size(); k++) {
                if (r.completed(k)) {
                    completed++;
                    assertEquals(completed, r.estX[k], 0.0, policy + " event " + k);
                    assertEquals(-completed, r.estY[k], 0.0, policy + " event " + k);
                    if (t.task(k) == Timeline.UPDATE) {
                        assertEquals(completed, r.cov[6 * k + 5], 0.0, policy + " event " + k);
                    }
                } else {
                    assertTrue(Double.isNaN(r.estX[k]), policy + " event " + k + " has an estimate");
                }
            }
            assertEquals(completed, (int) fake.committed, policy);
            assertTrue(completed < t.size() || policy.equals("queue"), policy + ": nothing missed under overload");
        }
    }
}
