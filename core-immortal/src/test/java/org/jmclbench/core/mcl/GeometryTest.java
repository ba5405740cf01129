package org.jmclbench.core.mcl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Bearings and angle wrapping (ALGORITHM 3) on the thesis's playground. */
class GeometryTest {
    private static final double EPS = 1e-12;

    @Test
    void bearingsFromTheOriginMatchTheThesisFigures() {
        Playground p = Playground.thesis();
        double s1 = Angles.bearing(0, 0, 0, p.beaconX[0], p.beaconY[0]);
        double s2 = Angles.bearing(0, 0, 0, p.beaconX[1], p.beaconY[1]);
        double s3 = Angles.bearing(0, 0, 0, p.beaconX[2], p.beaconY[2]);
        assertEquals(Math.PI / 2, s1, EPS);
        assertEquals(0.0, s2, EPS);
        assertEquals(Math.atan2(2, 3), s3, EPS);
        // The gap S1 -> S2 counter-clockwise is 270 degrees, S2 -> S3 about 34 degrees.
        assertEquals(270.0, Math.toDegrees(Angles.wrap2pi(s2 - s1)), 1e-9);
        assertEquals(33.69, Math.toDegrees(Angles.wrap2pi(s3 - s2)), 0.01);
    }

    @Test
    void bearingIsRelativeToTheHeadingAndInZeroToTwoPi() {
        // Heading north, a beacon due east is seen at -90 degrees, i.e. 270.
        assertEquals(3 * Math.PI / 2, Angles.bearing(1, 1, Math.PI / 2, 2, 1), EPS);
        // Heading east, a beacon behind is at 180.
        assertEquals(Math.PI, Angles.bearing(1, 1, 0, 0, 1), EPS);
        for (double th = -10; th < 10; th += 0.37) {
            double b = Angles.bearing(0.3, 0.7, th, 3, 2);
            assertTrue(b >= 0 && b < Angles.TWO_PI, "bearing " + b);
        }
    }

    @Test
    void wrap2piKeepsHeadingsInZeroToTwoPi() {
        assertEquals(0.0, Angles.wrap2pi(0.0));
        assertEquals(0.0, Angles.wrap2pi(Angles.TWO_PI));
        assertEquals(Math.PI, Angles.wrap2pi(-Math.PI), EPS);
        assertEquals(1.0, Angles.wrap2pi(1.0 + 3 * Angles.TWO_PI), 1e-12);
        assertEquals(Angles.TWO_PI - 1.0, Angles.wrap2pi(-1.0), EPS);
        // A tiny negative angle must not come out as exactly 2pi (the >= 2pi rule).
        double r = Angles.wrap2pi(-1e-18);
        assertTrue(r >= 0 && r < Angles.TWO_PI, "wrapped " + r);
    }

    @Test
    void wrapPiKeepsDifferencesInMinusPiToPi() {
        assertEquals(-Math.PI, Angles.wrapPi(Math.PI), EPS);
        assertEquals(-Math.PI, Angles.wrapPi(-Math.PI), EPS);
        assertEquals(0.5, Angles.wrapPi(0.5 + Angles.TWO_PI), 1e-12);
        assertEquals(-0.5, Angles.wrapPi(Angles.TWO_PI - 0.5), 1e-12);
        for (double a = -20; a < 20; a += 0.113) {
            double w = Angles.wrapPi(a);
            assertTrue(w >= -Math.PI && w < Math.PI, "wrapped " + w);
            assertEquals(0.0, Math.sin(w - a), 1e-9);
        }
    }
}
