package hvmtest;

import vm.VMTest;

/** Patch 01: dsub and ddiv take the operand pushed first as minuend and dividend. */
public class DoubleSubDiv {
    // Fields, not constants, so that javac cannot fold the arithmetic away.
    static double a = 7.0;
    static double b = 2.0;

    public static void main(String[] args) {
        VMTest.markResult(!ok());
    }

    // Outside main, so that icecap's -aot (compiled mode) compiles it.
    static boolean ok() {
        return a - b == 5.0 && a / b == 3.5 && b - a == -5.0 && b / a == 2.0 / 7.0;
    }
}
