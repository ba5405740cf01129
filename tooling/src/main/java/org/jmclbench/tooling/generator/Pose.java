package org.jmclbench.tooling.generator;

/** A robot pose on the playground: position in metres, heading in radians from +x, counter-clockwise. */
public record Pose(double x, double y, double theta) {
}
