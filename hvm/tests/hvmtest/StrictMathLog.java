package hvmtest;

import vm.VMTest;

/** Patch 04: Math.log (StrictMath.log underneath) computes the natural logarithm. */
public class StrictMathLog {
    static double x = 1000.0;

    public static void main(String[] args) {
        double d = Math.log(x) - 6.907755278982137;
        boolean ok = d < 1e-12 && d > -1e-12 && Math.log(1.0) == 0.0;
        VMTest.markResult(!ok);
    }
}
