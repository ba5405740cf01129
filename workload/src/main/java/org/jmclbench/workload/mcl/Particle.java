package org.jmclbench.workload.mcl;

/** One particle of the {@code allocating} memory style: a pose hypothesis, as in the thesis's Robot class. */
final class Particle {
    final double x;
    final double y;
    final double theta;

    Particle(double x, double y, double theta) {
        this.x = x;
        this.y = y;
        this.theta = theta;
    }
}
