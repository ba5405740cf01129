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
    }

    private double helper(double v) {
        String s = "v=" + v; // VIOLATION string concatenation
        DoubleUnaryOperator f = x -> x + 1; // VIOLATION lambda
        return f.applyAsDouble(v) + s.length();
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
