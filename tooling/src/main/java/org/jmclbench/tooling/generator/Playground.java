package org.jmclbench.tooling.generator;

import java.util.List;

/** The field the robot drives on: its size and the laser reflectors (beacons), in a fixed order. */
public record Playground(double width, double height, List<double[]> beacons) {

    /** The thesis's playground: 3 m x 2 m, beacons S1 = (0, 1), S2 = (3, 0), S3 = (3, 2). */
    public static Playground thesis() {
        return new Playground(3.0, 2.0, List.of(new double[] {0.0, 1.0}, new double[] {3.0, 0.0},
                new double[] {3.0, 2.0}));
    }

    /** The beacons as the metadata writes them: {@code x,y;x,y;...}. */
    public String beaconsProperty() {
        StringBuilder sb = new StringBuilder();
        for (double[] b : beacons) {
            if (sb.length() > 0) {
                sb.append(';');
            }
            sb.append(b[0]).append(',').append(b[1]);
        }
        return sb.toString();
    }
}
