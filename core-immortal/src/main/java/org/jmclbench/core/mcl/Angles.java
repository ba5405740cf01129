package org.jmclbench.core.mcl;

/** Angle arithmetic of docs/ALGORITHM.md section 3: headings in [0, 2pi), differences in [-pi, pi). */
public final class Angles {
    /** 2pi, the literal both languages use. */
    public static final double TWO_PI = 2 * Math.PI;

    private Angles() {
    }

    /** The angle wrapped to [0, 2pi). */
    public static double wrap2pi(double a) {
        double r = a - TWO_PI * Math.floor(a / TWO_PI);
        return r >= TWO_PI ? 0.0 : r;
    }

    /** The angle wrapped to [-pi, pi). */
    public static double wrapPi(double a) {
        return wrap2pi(a + Math.PI) - Math.PI;
    }

    /** The angle at which a robot at (px, py) heading ptheta sees the point (bx, by), in [0, 2pi). */
    public static double bearing(double px, double py, double ptheta, double bx, double by) {
        return wrap2pi(Math.atan2(by - py, bx - px) - ptheta);
    }
}
