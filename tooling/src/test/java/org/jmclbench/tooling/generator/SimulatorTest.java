package org.jmclbench.tooling.generator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.jmclbench.core.mcl.Angles;
import org.junit.jupiter.api.Test;

class SimulatorTest {
    private static final Playground FIELD = Playground.thesis();

    private static SimulatedRun run(String scenario, SensorNoise noise, long seed, double seconds) {
        return new Simulator(FIELD, noise).run(Scenario.byName(scenario), seed, (int) Math.round(seconds * 20));
    }

    @Test
    void sameSeedGivesTheSameRunAndAnotherSeedAnother() {
        SimulatedRun a = run("match", SensorNoise.DEFAULT, 7, 20);
        SimulatedRun b = run("match", SensorNoise.DEFAULT, 7, 20);
        SimulatedRun c = run("match", SensorNoise.DEFAULT, 8, 20);
        assertArrayEquals(a.odometry(), b.odometry());
        assertArrayEquals(a.laser(), b.laser());
        assertArrayEquals(a.real(), b.real());
        assertFalse(java.util.Arrays.deepEquals(a.odometry(), c.odometry()));
        // The route does not depend on the seed, only the sensors do.
        assertArrayEquals(a.real(), c.real());
    }

    @Test
    void shorterRunIsAPrefixOfTheLongerOne() {
        SimulatedRun shortRun = run("match-short", SensorNoise.DEFAULT, 1, 20);
        SimulatedRun longRun = run("match", SensorNoise.DEFAULT, 1, 90);
        for (int i = 0; i < shortRun.odometry().length; i++) {
            assertArrayEquals(longRun.odometry()[i], shortRun.odometry()[i]);
            assertArrayEquals(longRun.real()[i], shortRun.real()[i]);
        }
        for (int i = 0; i < shortRun.laser().length; i++) {
            assertArrayEquals(longRun.laser()[i], shortRun.laser()[i]);
        }
    }

    @Test
    void timesAreOnTheOdometryGridAndSorted() {
        SimulatedRun r = run("figure8", SensorNoise.DEFAULT, 3, 10);
        for (int i = 0; i < r.odometry().length; i++) {
            assertEquals((i + 1) * 0.05, r.odometry()[i][0], 1e-12);
            assertEquals(r.odometry()[i][0], r.real()[i][0]);
        }
        double previous = 0;
        for (double[] l : r.laser()) {
            assertTrue(l[0] > previous && l[0] <= 10.0);
            assertTrue(l[1] >= 0 && l[1] < Angles.TWO_PI);
            previous = l[0];
        }
    }

    /** With perfect sensors, at each reported time the turret points exactly at a beacon. */
    @Test
    void laserTimesAreTheBeamCrossings() {
        for (String scenario : List.of("match-short", "figure8", "kidnap")) {
            SimulatedRun r = run(scenario, SensorNoise.NONE, 5, 40);
            assertTrue(r.laser().length > 0);
            for (double[] l : r.laser()) {
                double turret = r.turretAngle(l[0]);
                Pose pose = r.trajectory().poseAt(l[0]);
                double best = Double.POSITIVE_INFINITY;
                for (double[] b : FIELD.beacons()) {
                    double bearing = Angles.wrap2pi(StrictMath.atan2(b[1] - pose.y(), b[0] - pose.x()) - pose.theta());
                    best = Math.min(best, Math.abs(Angles.wrapPi(turret - bearing)));
                }
                assertTrue(best < 1e-6, scenario + " t=" + l[0] + ": turret " + best + " rad off every beacon");
                assertTrue(Math.abs(Angles.wrapPi(l[1] - turret)) < 1e-6, scenario + " t=" + l[0]);
            }
        }
    }

    /**
     * No crossing is lost or invented: an independent count from the ground truth file alone
     * (poses linearly interpolated between the 50 ms lines, scanned every 0.5 ms) finds the
     * same crossings for every beacon, at times within a millisecond.
     */
    @Test
    void everyBeamCrossingIsReportedOnce() {
        SimulatedRun r = run("match", SensorNoise.NONE, 2, 30);
        double[][] real = r.real();
        List<Double> expected = new ArrayList<>();
        for (double[] b : FIELD.beacons()) {
            double previous = Double.NaN;
            for (int k = 0; k <= 60000; k++) {
                double t = k * 0.0005;
                double[] p = interpolate(r.scenario().start(), real, t);
                double bearing = StrictMath.atan2(b[1] - p[1], b[0] - p[0]) - p[2];
                double offset = Angles.wrapPi(r.turretAngle(t) - bearing);
                if (previous < 0 && offset >= 0 && offset - previous < 1) {
                    expected.add(t);
                }
                previous = offset;
            }
        }
        expected.sort(null);
        assertEquals(expected.size(), r.laser().length);
        for (int i = 0; i < expected.size(); i++) {
            assertEquals(expected.get(i), r.laser()[i][0], 1e-3);
        }
    }

    /** Pose at t from the start pose and the real.txt lines, linear in between (theta unwrapped). */
    private static double[] interpolate(Pose start, double[][] real, double t) {
        int i = (int) Math.floor(t / 0.05);
        double[] a = i == 0 ? new double[] {0, start.x(), start.y(), start.theta()} : real[Math.min(i, real.length) - 1];
        double[] b = real[Math.min(i, real.length - 1)];
        double f = i >= real.length ? 1 : (t - a[0]) / (b[0] - a[0]);
        double dth = Angles.wrapPi(b[3] - a[3]);
        return new double[] {a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]), a[3] + f * dth};
    }

    /** The thesis: seen from the corner (0, 0), S2 and S3 are about 34 degrees apart, about 32 ms of turret. */
    @Test
    void gapBetweenS2AndS3SeenFromNearTheCornerMatchesTheThesis() {
        Pose corner = new Pose(0.15, 0.15, 0.0);
        Scenario standing = Scenario.byName("stay").withStart(corner);
        SimulatedRun r = new Simulator(FIELD, SensorNoise.NONE).run(standing, 1, 60);
        double minGap = Double.POSITIVE_INFINITY;
        for (int i = 1; i < r.laser().length; i++) {
            minGap = Math.min(minGap, r.laser()[i][0] - r.laser()[i - 1][0]);
        }
        double s2 = StrictMath.atan2(0 - corner.y(), 3 - corner.x());
        double s3 = StrictMath.atan2(2 - corner.y(), 3 - corner.x());
        double geometric = (s3 - s2) / (3 * Angles.TWO_PI);
        assertEquals(geometric, minGap, 1e-6);
        assertTrue(minGap > 0.030 && minGap < 0.034, "S2-S3 gap " + minGap + " s");
        // 9 crossings a second: three beacons, three turns.
        assertEquals(27, r.laser().length, 1);
    }

    /** With perfect odometry, chaining the increments rebuilds real.txt (and the kidnapping is the one gap). */
    @Test
    void noiseFreeOdometryIntegratesToTheGroundTruth() {
        for (Scenario s : Scenario.all()) {
            SimulatedRun r = new Simulator(FIELD, SensorNoise.NONE).run(s, 1, 1200);
            double x = s.start().x();
            double y = s.start().y();
            double th = s.start().theta();
            List<Double> jumps = new ArrayList<>();
            for (int i = 0; i < r.odometry().length; i++) {
                double[] o = r.odometry()[i];
                double c = Math.cos(th);
                double sn = Math.sin(th);
                x += o[1] * c - o[2] * sn;
                y += o[1] * sn + o[2] * c;
                th += o[3];
                double[] truth = r.real()[i];
                double err = Math.hypot(x - truth[1], y - truth[2]) + Math.abs(Angles.wrapPi(th - truth[3]));
                if (err > 1e-9) {
                    jumps.add(truth[0]);
                    x = truth[1];
                    y = truth[2];
                    th = truth[3];
                }
            }
            if (s.kidnap() == null) {
                assertEquals(List.of(), jumps, s.name());
            } else {
                assertEquals(1, jumps.size(), s.name());
                assertEquals(s.kidnap().time() + 0.05, jumps.get(0), 1e-9);
            }
        }
    }

    @Test
    void kidnapJumpsInTheGroundTruthButNotInTheOdometry() {
        SimulatedRun r = run("kidnap", SensorNoise.DEFAULT, 1, 60);
        int jumps = 0;
        for (int i = 1; i < r.real().length; i++) {
            double moved = Math.hypot(r.real()[i][1] - r.real()[i - 1][1], r.real()[i][2] - r.real()[i - 1][2]);
            double odo = Math.hypot(r.odometry()[i][1], r.odometry()[i][2]);
            assertTrue(odo < 0.03, "odometry increments stay small");
            if (moved > 0.5) {
                jumps++;
                assertEquals(30.05, r.real()[i][0], 1e-9);
            } else {
                assertTrue(moved < 0.03);
            }
        }
        assertEquals(1, jumps);
    }

    /** Every scenario keeps the robot 0.15 m inside the field, within its speed and acceleration limits. */
    @Test
    void robotStaysInsideTheMarginsAndMovesSmoothly() {
        for (Scenario s : Scenario.all()) {
            SimulatedRun r = new Simulator(FIELD, SensorNoise.NONE).run(s, 1, (int) Math.round(s.defaultDuration() * 20));
            Trajectory tr = r.trajectory();
            double kidnapAt = s.kidnap() == null ? Double.NaN : s.kidnap().time();
            for (int i = 0; i < tr.size(); i++) {
                Trajectory.Piece piece = tr.piece(i);
                for (double t : new double[] {piece.start(), 0.5 * (piece.start() + piece.end()), piece.end()}) {
                    Pose p = tr.poseIn(i, t);
                    double margin = Math.min(Math.min(p.x(), 3 - p.x()), Math.min(p.y(), 2 - p.y()));
                    assertTrue(margin >= 0.15, s.name() + " at t=" + t + ": " + p);
                }
                assertTrue(Math.abs(piece.speed()) <= RouteFollower.V_MAX + 1e-12);
                assertTrue(Math.abs(piece.turnRate()) <= RouteFollower.W_MAX + 1e-12);
                if (i > 0 && !(Math.abs(piece.start() - kidnapAt) < 1e-9)) {
                    Trajectory.Piece before = tr.piece(i - 1);
                    double dt = piece.end() - piece.start();
                    assertTrue(Math.abs(piece.speed() - before.speed()) <= RouteFollower.ACCEL * dt + 1e-12);
                    assertTrue(Math.abs(piece.turnRate() - before.turnRate()) <= RouteFollower.ANGULAR_ACCEL * dt + 1e-12);
                }
            }
            if (!s.name().equals("stay")) {
                double travelled = 0;
                for (int i = 0; i < tr.size(); i++) {
                    travelled += Math.abs(tr.piece(i).speed()) * (tr.piece(i).end() - tr.piece(i).start());
                }
                assertTrue(travelled > 0.1 * s.defaultDuration(), s.name() + " travels " + travelled + " m");
            }
        }
    }

    /** The sensors are noisy as configured: increments scatter around the truth and about 5 % of crossings are missed. */
    @Test
    void noiseIsPresentAndOfTheConfiguredSize() {
        SimulatedRun clean = run("match", SensorNoise.NONE, 4, 90);
        SimulatedRun noisy = run("match", SensorNoise.DEFAULT, 4, 90);
        double sumSq = 0;
        double sumVar = 0;
        for (int i = 0; i < clean.odometry().length; i++) {
            double[] c = clean.odometry()[i];
            double e = noisy.odometry()[i][1] - c[1];
            double d = Math.hypot(c[1], c[2]);
            double sigma = SensorNoise.DEFAULT.alphaXY() * d + SensorNoise.DEFAULT.floorXY();
            sumSq += e * e;
            sumVar += sigma * sigma;
        }
        double ratio = sumSq / sumVar; // 1 for noise of exactly the configured size
        assertTrue(ratio > 0.8 && ratio < 1.2, "odometry noise ratio " + ratio);
        double kept = (double) noisy.laser().length / clean.laser().length;
        assertTrue(kept > 0.92 && kept < 0.98, "kept " + kept + " of the crossings");
        double sumAngle = 0;
        int j = 0;
        for (double[] l : noisy.laser()) {
            while (clean.laser()[j][0] != l[0]) {
                j++;
            }
            double e = Angles.wrapPi(l[1] - clean.laser()[j][1]);
            sumAngle += e * e;
        }
        double rms = Math.sqrt(sumAngle / noisy.laser().length);
        assertEquals(SensorNoise.DEFAULT.laserSigma(), rms, 0.002);
    }
}
