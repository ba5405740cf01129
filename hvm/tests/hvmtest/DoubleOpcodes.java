package hvmtest;

import vm.VMTest;

/** Patch 02: dneg, drem, l2d and d2l, with Java's rounding and saturation. */
public class DoubleOpcodes {
    static double a = 7.5;
    static double b = 2.0;
    static long big = (1L << 40) + 3;
    static double huge = 1e30;
    static double nan = 0.0 / zero();

    static double zero() {
        return 0.0;
    }

    public static void main(String[] args) {
        VMTest.markResult(!ok());
    }

    // Outside main, so that icecap's -aot (compiled mode) compiles it.
    static boolean ok() {
        return -a == -7.5
                && a % b == 1.5
                && -a % b == -1.5
                && (double) big == 1099511627779.0
                && (double) -big == -1099511627779.0
                && (long) (a * 1e12) == 7500000000000L
                && (long) -a == -7L
                && (long) huge == Long.MAX_VALUE
                && (long) -huge == Long.MIN_VALUE
                && (long) nan == 0L;
    }
}
