package hvmtest;

import vm.VMTest;

/** Patch 03: long division and remainder of numbers above 2^62 end, with Java's results. */
public class LongDivRem {
    static long x = 0x7000000000000007L; // 8070450532247928839 > 2^62
    static long y = 10;
    static long minusOne = -1;

    public static void main(String[] args) {
        VMTest.markResult(!ok());
    }

    // Outside main, so that icecap's -aot (compiled mode) compiles it.
    static boolean ok() {
        return x / y == 807045053224792883L
                && x % y == 9L
                && -x / y == -807045053224792883L
                && -x % y == -9L
                && Long.MIN_VALUE / minusOne == Long.MIN_VALUE
                && Long.MIN_VALUE % minusOne == 0L
                && 1000000007L / y == 100000000L;
    }
}
