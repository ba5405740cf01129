package org.jmclbench.verification.seeded;

import java.util.function.DoubleUnaryOperator;

/**
 * Seeded bugs for the static allocation check: a release that reaches each kind of
 * allocation, directly, through a helper and through a virtual call. Each line that allocates
 * is marked VIOLATION; the test expects exactly those lines.
 */
public final class AllocatingRelease extends Release {
    private final Step step = new AllocatingStep();
    private double[] particles = new double[4];
    private Object last;

    @Override
    public void handleAsyncEvent() {
        double[] scratch = new double[particles.length]; // VIOLATION newarray
        scratch[0] = helper(particles[0]);
        step.apply(particles);
        last = Double.valueOf(scratch[0]); // VIOLATION boxing
        double[] copy = particles.clone(); // VIOLATION array clone
        last = Mode.values(); // VIOLATION enum values()
        copy[0] = Table.WEIGHTS[0]; // the first use of Table: its initialiser runs in this release
        java.util.Arrays.sort(particles); // VIOLATION a JDK call the rule does not know
        SeededLayer.clear(particles); // the layer's method allocates only an exception it throws: fine
        particles = SeededLayer.snapshot(copy); // VIOLATION a call into the layer that allocates
    }

    /** Its initialiser allocates the constants and their array; values() copies that array. */
    enum Mode { A, B } // VIOLATION

    /** A class whose initialiser allocates, first used by the release. */
    static final class Table {
        static final double[] WEIGHTS = new double[4]; // VIOLATION in the class initialiser
    }

    private double helper(double v) {
        String s = "v=" + v; // VIOLATION string concatenation
        DoubleUnaryOperator f = x -> x + 1; // VIOLATION lambda
        DoubleUnaryOperator g = x -> { // VIOLATION lambda
            double[] box = new double[1]; // VIOLATION in the lambda's body
            box[0] = x;
            return box[0];
        };
        return f.applyAsDouble(g.applyAsDouble(v)) + s.length(); // VIOLATION JDK calls the rule does not know
    }

    /** A step of the job, called virtually. */
    interface Step {
        void apply(double[] p);
    }

    static final class AllocatingStep implements Step {
        @Override
        public void apply(double[] p) {
            Object[] boxes = new Object[p.length]; // VIOLATION anewarray
            boxes[0] = new int[2][2]; // VIOLATION multianewarray
            p[0] = boxes.length;
        }
    }

    /** Not reachable from any release: its allocation is not reported. */
    static Object notARelease() {
        return new Object();
    }
}
