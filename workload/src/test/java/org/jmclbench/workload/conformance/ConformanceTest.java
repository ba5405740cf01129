package org.jmclbench.workload.conformance;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.util.HashMap;
import java.util.Map;
import org.jmclbench.workload.conformance.VectorFile.Line;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Angles;
import org.jmclbench.core.mcl.Likelihood;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.mcl.Resampling;
import org.jmclbench.core.mcl.Rng;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The Java workload against the conformance vectors (conformance/README.md): the same files
 * the C baseline is tested against, written by an independent reference of ALGORITHM.md.
 */
class ConformanceTest {
    /** Tolerances stated by the files' headers. */
    private static final double BEARING_TOL = 1e-12;
    private static final double MCL_TOL = 1e-9;

    @Test
    void generatorOutputsAreBitExact() throws IOException {
        Map<Long, Rng> rngs = new HashMap<>();
        Map<Long, Integer> calls = new HashMap<>();
        for (Line l : VectorFile.read("rng.txt").lines) {
            long seed = l.hex64(0);
            int call = l.integer(1);
            Rng r = rngs.computeIfAbsent(seed, Rng::new);
            int done = calls.getOrDefault(seed, 0);
            assertTrue(call >= done, l + ": calls must increase per seed");
            long v = 0;
            for (; done <= call; done++) {
                v = r.next();
            }
            calls.put(seed, done);
            long got = v;
            assertEquals(l.hex64(2), got, () -> l + ": next() = " + Long.toHexString(got));
        }
    }

    @Test
    void uniformsAreBitExact() throws IOException {
        checkDoubles("uniform.txt", false);
    }

    @Test
    void gaussiansAreBitExact() throws IOException {
        checkDoubles("gaussian.txt", true);
    }

    private static void checkDoubles(String file, boolean gaussian) throws IOException {
        Map<Long, Rng> rngs = new HashMap<>();
        Map<Long, Integer> calls = new HashMap<>();
        for (Line l : VectorFile.read(file).lines) {
            long seed = l.hex64(0);
            Rng r = rngs.computeIfAbsent(seed, Rng::new);
            int done = calls.getOrDefault(seed, 0);
            assertEquals(done, l.integer(1), l + ": calls are listed in order, without gaps");
            double v = gaussian ? r.gaussian() : r.uniform();
            calls.put(seed, done + 1);
            assertEquals(l.hex64(2), Double.doubleToRawLongBits(v), () -> l + ": got " + v);
        }
    }

    @Test
    void wrappingIsBitExact() throws IOException {
        int n = 0;
        for (Line l : VectorFile.read("wrap.txt").lines) {
            double a = l.hexDouble(1);
            double v;
            if (l.kind().equals("wrap2pi")) {
                v = Angles.wrap2pi(a);
            } else if (l.kind().equals("wrappi")) {
                v = Angles.wrapPi(a);
            } else {
                throw new AssertionError(l + ": unknown function " + l.kind());
            }
            assertEquals(l.hex64(2), Double.doubleToRawLongBits(v), () -> l + ": " + l.kind() + "(" + a + ") = " + v);
            n++;
        }
        assertTrue(n > 40);
    }

    @Test
    void bearingsAgreeWithin1e12OnTheCircle() throws IOException {
        for (Line l : VectorFile.read("bearing.txt").lines) {
            double v = Angles.bearing(l.dec(0), l.dec(1), l.dec(2), l.dec(3), l.dec(4));
            double expected = l.dec(5);
            assertTrue(v >= 0 && v < Angles.TWO_PI, l + ": bearing out of [0, 2pi): " + v);
            assertTrue(VectorFile.circularDistance(v, expected) <= BEARING_TOL,
                    () -> l + ": bearing " + v + ", expected " + expected);
        }
    }

    @Test
    void likelihoodsAgreeWithinTheirRelativeTolerance() throws IOException {
        Playground p = null;
        int cases = 0;
        for (Line l : VectorFile.read("likelihood.txt").lines) {
            if (l.kind().equals("playground")) {
                int b = l.integer(3);
                double[] bx = new double[b];
                double[] by = new double[b];
                for (int i = 0; i < b; i++) {
                    bx[i] = l.dec(4 + 2 * i);
                    by[i] = l.dec(5 + 2 * i);
                }
                p = new Playground(l.dec(1), l.dec(2), bx, by);
                continue;
            }
            assertEquals("case", l.kind(), l + ": unknown line");
            double v = Likelihood.of(l.dec(1), l.dec(2), l.dec(3), l.dec(4), p);
            double expected = l.dec(5);
            double rtol = l.dec(6);
            assertTrue(Math.abs(v - expected) <= rtol * expected,
                    () -> l + ": likelihood " + v + ", expected " + expected + " (relative " + rtol + ")");
            cases++;
        }
        assertTrue(cases > 20);
    }

    @Test
    void resamplingIndicesAreExact() throws IOException {
        for (Line l : VectorFile.read("resample.txt").lines) {
            int n = l.integer(1);
            double[] w = new double[n];
            for (int i = 0; i < n; i++) {
                w[i] = l.hexDouble(3 + i);
            }
            int[] expected = new int[n];
            for (int i = 0; i < n; i++) {
                expected[i] = l.integer(3 + n + i);
            }
            int[] out = new int[n];
            if (l.kind().equals("systematic")) {
                Resampling.systematic(w, n, l.hexDouble(2), out);
                assertArrayEquals(expected, out, l.toString());
            } else if (l.kind().equals("multinomial")) {
                Rng r = new Rng(l.hex64(2));
                Resampling.multinomial(w, n, r, out);
                assertArrayEquals(expected, out, l.toString());
                assertEquals(l.hex64(3 + 2 * n), r.next(), l + ": the generator's state after the draws");
            } else {
                fail(l + ": unknown method " + l.kind());
            }
        }
    }

    @ParameterizedTest
    @EnumSource(MclConfig.Memory.class)
    void smallFiltersFollowTheReference(MclConfig.Memory memory) throws IOException {
        new MclScenarioRunner(memory).run(VectorFile.read("mcl.txt"));
    }

    /** Replays mcl.txt's scenarios through a {@link Localizer} of one memory style. */
    private static final class MclScenarioRunner {
        private final MclConfig.Memory memory;
        private Localizer loc;
        private int scenarios;

        MclScenarioRunner(MclConfig.Memory memory) {
            this.memory = memory;
        }

        void run(VectorFile f) {
            double[] p = new double[3];
            double[] cov = new double[6];
            for (Line l : f.lines) {
                switch (l.kind()) {
                    case "scenario":
                        MclConfig config = MclConfig.builder()
                                .particles(l.integer(2))
                                .seed(l.hex64(3))
                                .estimate(MclConfig.Estimate.valueOf(l.tokens[4].toUpperCase(java.util.Locale.ROOT)))
                                .resample(MclConfig.Resample.valueOf(l.tokens[5].toUpperCase(java.util.Locale.ROOT)))
                                .init(MclConfig.Init.valueOf(l.tokens[6].toUpperCase(java.util.Locale.ROOT)))
                                .covariance(l.integer(7) == 1)
                                .memory(memory)
                                .build();
                        loc = Localizers.create(config, Playground.thesis(), l.dec(8), l.dec(9), l.dec(10));
                        assertEquals(l.integer(2), loc.particleCount(), l.toString());
                        scenarios++;
                        break;
                    case "init":
                        break;
                    case "predict":
                        assertTrue(loc.predict(l.dec(1), l.dec(2), l.dec(3), AbortSignal.NEVER), l.toString());
                        break;
                    case "update":
                        assertTrue(loc.update(l.dec(1), AbortSignal.NEVER), l.toString());
                        break;
                    case "particle":
                        loc.particle(l.integer(1), p);
                        near(l, "x", l.dec(2), p[0]);
                        near(l, "y", l.dec(3), p[1]);
                        nearAngle(l, "theta", l.dec(4), p[2]);
                        break;
                    case "estimate":
                        near(l, "x", l.dec(1), loc.estimateX());
                        near(l, "y", l.dec(2), loc.estimateY());
                        nearAngle(l, "theta", l.dec(3), loc.estimateTheta());
                        break;
                    case "covariance":
                        loc.covariance(cov);
                        for (int i = 0; i < 6; i++) {
                            near(l, "c" + i, l.dec(1 + i), cov[i]);
                        }
                        break;
                    case "margin":
                    case "end":
                        break;
                    default:
                        fail(l + ": unknown line " + l.kind());
                }
            }
            assertTrue(scenarios >= 3, "mcl.txt has too few scenarios");
        }

        private void near(Line l, String what, double expected, double actual) {
            assertTrue(Math.abs(actual - expected) <= MCL_TOL,
                    () -> l + " (" + memory + "): " + what + " = " + actual + ", expected " + expected);
        }

        private void nearAngle(Line l, String what, double expected, double actual) {
            assertTrue(actual >= 0 && actual < Angles.TWO_PI, l + ": " + what + " out of [0, 2pi): " + actual);
            assertTrue(VectorFile.circularDistance(actual, expected) <= MCL_TOL,
                    () -> l + " (" + memory + "): " + what + " = " + actual + ", expected " + expected);
        }
    }
}
