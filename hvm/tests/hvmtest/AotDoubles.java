package hvmtest;

/**
 * Patch 13: the compiled code's double opcodes. dsub and ddiv in order, drem, dastore (stored
 * nothing) and daload (missing), l2d (missing), d2l of values beyond 32 bits (wrote 0 as the
 * high word). The checks are outside main: icecap's -aot compiles every method but main.
 */
public class AotDoubles extends PatchCases {
    static double a = 7.5;
    static double b = 2.0;
    static long big = (1L << 40) + 3;
    static double[] shared = new double[3];

    public static void main(String[] args) {
        new AotDoubles().run(8);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            return a - b == 5.5 && b - a == -5.5 && a / b == 3.75 && b / a == 2.0 / 7.5;
        case 1:
            return a % b == 1.5 && -a % b == -1.5 && a * b == 15.0 && a + b == 9.5;
        case 2: {
            double[] d = new double[4];
            for (int k = 0; k < d.length; k++) {
                d[k] = a * k + 0.25;
            }
            return d[0] == 0.25 && d[3] == 22.75 && sum(d) == 46.0;
        }
        case 3:
            shared[1] += a; // dup2, daload, dadd, dastore
            shared[1] += a;
            return shared[1] == 15.0 && shared[0] == 0.0 && shared[2] == 0.0;
        case 4:
            return (double) big == 1099511627779.0 && (double) -big == -1099511627779.0 && (double) (big >> 20) == 1048576.0;
        case 5:
            return (long) (a * 1e12) == 7500000000000L && (long) -a == -7L && (long) (b * 1.5e9) == 3000000000L;
        case 6:
            return (int) a == 7 && (int) -a == -7 && (int) (a * 1e6) == 7500000;
        case 7:
            return half(a) == 3.75 && half(-b) == -1.0;
        default:
            return false;
        }
    }

    static double sum(double[] d) {
        double s = 0;
        for (int k = 0; k < d.length; k++) {
            s += d[k];
        }
        return s;
    }

    static double half(double x) {
        return x / 2;
    }
}
