package org.jmclbench.core.mcl;

/**
 * The project's random generator: xoshiro256** seeded with splitmix64, with the uniform and
 * Gaussian methods of docs/ALGORITHM.md sections 1 and 2. The C baseline implements the same
 * bits; conformance vectors check both. Not thread-safe; its state can be copied so that a
 * terminated job can leave it untouched.
 */
public final class Rng {
    private long s0;
    private long s1;
    private long s2;
    private long s3;

    public Rng(long seed) {
        long sm = seed;
        sm += 0x9E3779B97F4A7C15L;
        s0 = mix(sm);
        sm += 0x9E3779B97F4A7C15L;
        s1 = mix(sm);
        sm += 0x9E3779B97F4A7C15L;
        s2 = mix(sm);
        sm += 0x9E3779B97F4A7C15L;
        s3 = mix(sm);
    }

    private Rng(Rng other) {
        copyFrom(other);
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** The next 64 random bits (an unsigned value in C). */
    public long next() {
        long result = Long.rotateLeft(s1 * 5, 7) * 9;
        long t = s1 << 17;
        s2 ^= s0;
        s3 ^= s1;
        s1 ^= s2;
        s0 ^= s3;
        s2 ^= t;
        s3 = Long.rotateLeft(s3, 45);
        return result;
    }

    /** A double uniform in [0, 1) with 53 random bits. */
    public double uniform() {
        return (next() >>> 11) * 0x1.0p-53;
    }

    /** An approximately standard normal sample: twelve uniforms summed, minus six. */
    public double gaussian() {
        double s = 0.0;
        for (int i = 0; i < 12; i++) {
            s += uniform();
        }
        return s - 6.0;
    }

    /** Makes this generator's state equal to {@code other}'s (no allocation). */
    public void copyFrom(Rng other) {
        s0 = other.s0;
        s1 = other.s1;
        s2 = other.s2;
        s3 = other.s3;
    }

    /** An independent copy with the same state. */
    public Rng copy() {
        return new Rng(this);
    }
}
