package org.jmclbench.core.mcl;

/** The field the robot moves on: its size and the beacons the laser sees, in a fixed order. */
public final class Playground {
    /** Size along x (m); the field is [0, width] x [0, height]. */
    public final double width;
    /** Size along y (m). */
    public final double height;
    /** Beacon x coordinates (m), in the order the likelihood sums them. */
    public final double[] beaconX;
    /** Beacon y coordinates (m). */
    public final double[] beaconY;

    public Playground(double width, double height, double[] beaconX, double[] beaconY) {
        if (!(width > 0) || !(height > 0) || Double.isInfinite(width) || Double.isInfinite(height)) {
            throw new IllegalArgumentException("playground size must be positive and finite");
        }
        if (beaconX.length != beaconY.length || beaconX.length == 0) {
            throw new IllegalArgumentException("beacons need as many x as y coordinates, at least one");
        }
        this.width = width;
        this.height = height;
        this.beaconX = beaconX.clone();
        this.beaconY = beaconY.clone();
    }

    /** The thesis's field: 3 m x 2 m, beacons S1 (0, 1), S2 (3, 0), S3 (3, 2). */
    public static Playground thesis() {
        return new Playground(3.0, 2.0, new double[] {0.0, 3.0, 3.0}, new double[] {1.0, 0.0, 2.0});
    }

    /** The number of beacons. */
    public int beaconCount() {
        return beaconX.length;
    }

    /** The beacons as written in dataset.properties: {@code x,y;x,y;...}. */
    public String beaconsText() {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < beaconX.length; i++) {
            if (i > 0) {
                b.append(';');
            }
            b.append(beaconX[i]).append(',').append(beaconY[i]);
        }
        return b.toString();
    }

    @Override
    public String toString() {
        return "Playground[" + width + " x " + height + ", beacons " + beaconsText() + "]";
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof Playground)) {
            return false;
        }
        Playground p = (Playground) o;
        return p.width == width && p.height == height && sameValues(p.beaconX, beaconX)
                && sameValues(p.beaconY, beaconY);
    }

    @Override
    public int hashCode() {
        return Double.hashCode(width) * 31 + Double.hashCode(height) * 17 + beaconX.length;
    }

    private static boolean sameValues(double[] a, double[] b) {
        if (a.length != b.length) {
            return false;
        }
        for (int i = 0; i < a.length; i++) {
            if (Double.doubleToLongBits(a[i]) != Double.doubleToLongBits(b[i])) {
                return false;
            }
        }
        return true;
    }
}
