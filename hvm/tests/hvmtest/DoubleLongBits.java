package hvmtest;

import vm.VMTest;

/** Patch 06: Double.doubleToRawLongBits and longBitsToDouble keep the IEEE 754 bits. */
public class DoubleLongBits {
    static double x = 1.5; // 0x3FF8000000000000
    static long bits = 0x400921FB54442D18L; // pi

    public static void main(String[] args) {
        VMTest.markResult(!ok());
    }

    // Outside main, so that icecap's -aot (compiled mode) compiles it.
    static boolean ok() {
        return Double.doubleToRawLongBits(x) == 0x3FF8000000000000L
                && Double.longBitsToDouble(bits) == 3.141592653589793
                && Double.longBitsToDouble(Double.doubleToRawLongBits(-x)) == -1.5;
    }
}
