package org.jmclbench.workload.mcl;

import org.jmclbench.core.mcl.Angles;
import org.jmclbench.core.mcl.MotionModel;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.AbortSignal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Predict (ALGORITHM 6): the noise-free estimate and the particles' noise. */
class MotionModelTest {
    @Test
    void estimateMovesWithoutNoiseInTheRobotFrame() {
        for (MclConfig.Memory memory : MclConfig.Memory.values()) {
            Localizer l = Localizers.create(MclConfig.builder().particles(10).memory(memory).build(),
                    Playground.thesis(), 1.0, 1.0, Math.PI / 2);
            assertTrue(l.predict(0.1, 0.0, 0.0, AbortSignal.NEVER));
            assertEquals(1.0, l.estimateX(), 1e-12);
            assertEquals(1.1, l.estimateY(), 1e-12);
            assertEquals(Math.PI / 2, l.estimateTheta(), 1e-12);
            // Sideways (dy, left of the heading north = west), then a quarter turn.
            assertTrue(l.predict(0.0, 0.2, Math.PI / 2, AbortSignal.NEVER));
            assertEquals(0.8, l.estimateX(), 1e-12);
            assertEquals(1.1, l.estimateY(), 1e-12);
            assertEquals(Math.PI, l.estimateTheta(), 1e-12);
            // Back to the start: forward now means -x.
            assertTrue(l.predict(-0.2, 0.1, Math.PI, AbortSignal.NEVER));
            assertEquals(1.0, l.estimateX(), 1e-12);
            assertEquals(1.0, l.estimateY(), 1e-12);
            assertEquals(0.0, Angles.wrapPi(l.estimateTheta()), 1e-12);
        }
    }

    @Test
    void knownStartSpreadsParticlesBySigmaInit() {
        int n = 20000;
        Localizer l = Localizers.create(MclConfig.of(n), Playground.thesis(), 1.0, 0.5, 0.2);
        double[] p = new double[3];
        Moments x = new Moments();
        Moments theta = new Moments();
        for (int i = 0; i < n; i++) {
            l.particle(i, p);
            x.add(p[0] - 1.0);
            theta.add(Angles.wrapPi(p[2] - 0.2));
        }
        assertEquals(0.0, x.mean(), 0.002);
        assertEquals(MotionModel.INIT_SIGMA, x.rms(), 0.002);
        assertEquals(MotionModel.INIT_SIGMA, theta.rms(), 0.002);
    }

    @Test
    void particleMotionHasTheModelsMeanAndSpread() {
        int n = 20000;
        double dx = 0.1;
        double dy = 0.02;
        double dtheta = 0.3;
        Localizer l = Localizers.create(MclConfig.of(n), Playground.thesis(), 1.0, 0.5, 0.2);
        double[][] before = new double[n][3];
        for (int i = 0; i < n; i++) {
            l.particle(i, before[i]);
        }
        assertTrue(l.predict(dx, dy, dtheta, AbortSignal.NEVER));
        double[] p = new double[3];
        Moments forward = new Moments();
        Moments left = new Moments();
        Moments turn = new Moments();
        for (int i = 0; i < n; i++) {
            l.particle(i, p);
            double c = Math.cos(before[i][2]);
            double s = Math.sin(before[i][2]);
            double ex = p[0] - before[i][0];
            double ey = p[1] - before[i][1];
            // The displacement seen in the particle's own frame before the move.
            forward.add(c * ex + s * ey);
            left.add(-s * ex + c * ey);
            turn.add(Angles.wrapPi(p[2] - before[i][2]));
        }
        double d = Math.sqrt(dx * dx + dy * dy);
        double sigmaXY = MotionModel.ALPHA_XY * d + MotionModel.FLOOR_XY;
        double sigmaT = MotionModel.ALPHA_THETA * dtheta + MotionModel.ALPHA_THETA_XY * d + MotionModel.FLOOR_THETA;
        // Means within 5 standard errors, spreads within 5 percent.
        assertEquals(dx, forward.mean(), 5 * sigmaXY / Math.sqrt(n));
        assertEquals(dy, left.mean(), 5 * sigmaXY / Math.sqrt(n));
        assertEquals(dtheta, turn.mean(), 5 * sigmaT / Math.sqrt(n));
        assertEquals(sigmaXY, forward.spread(), 0.05 * sigmaXY);
        assertEquals(sigmaXY, left.spread(), 0.05 * sigmaXY);
        assertEquals(sigmaT, turn.spread(), 0.05 * sigmaT);
    }

    @Test
    void uniformStartCoversThePlayground() {
        int n = 20000;
        Playground pg = Playground.thesis();
        Localizer l = Localizers.create(MclConfig.builder().particles(n).init(MclConfig.Init.UNIFORM).build(), pg,
                0, 0, 0);
        assertEquals(1.5, l.estimateX());
        assertEquals(1.0, l.estimateY());
        assertEquals(0.0, l.estimateTheta());
        double[] p = new double[3];
        Moments x = new Moments();
        Moments y = new Moments();
        for (int i = 0; i < n; i++) {
            l.particle(i, p);
            assertTrue(p[0] >= 0 && p[0] < 3 && p[1] >= 0 && p[1] < 2 && p[2] >= 0 && p[2] < Angles.TWO_PI);
            x.add(p[0]);
            y.add(p[1]);
        }
        assertEquals(1.5, x.mean(), 0.03);
        assertEquals(1.0, y.mean(), 0.02);
    }

    /** Running sums of a sample, for its mean, its root mean square and its spread about the mean. */
    private static final class Moments {
        private int count;
        private double sum;
        private double sumOfSquares;

        void add(double v) {
            count++;
            sum += v;
            sumOfSquares += v * v;
        }

        double mean() {
            return sum / count;
        }

        double rms() {
            return Math.sqrt(sumOfSquares / count);
        }

        /** The population standard deviation. */
        double spread() {
            double m = mean();
            return Math.sqrt(sumOfSquares / count - m * m);
        }
    }
}
