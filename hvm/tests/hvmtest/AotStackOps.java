package hvmtest;

/**
 * Patch 14: the compiled code's pop2 (a discarded long or double result), dup2_x1 (a long
 * assigned to a field inside an expression) and dup2_x2 (a long or double assigned to an array
 * element inside an expression): "unsupported byte code" before. Outside main (icecap -aot).
 */
public class AotStackOps extends PatchCases {
    static long big = 0x123456789ABCDEFL;
    static double d = 2.75;
    static int calls;
    long field;
    double dfield;

    public static void main(String[] args) {
        new AotStackOps().run(4);
    }

    static long countedLong() {
        calls++;
        return big;
    }

    static double countedDouble() {
        calls++;
        return d;
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0: {
            calls = 0;
            countedLong(); // pop2
            countedDouble(); // pop2
            return calls == 2;
        }
        case 1: {
            AotStackOps o = new AotStackOps();
            long r = (o.field = big + 1); // dup2_x1
            double s = (o.dfield = d * 2); // dup2_x1
            return r == 0x123456789ABCDF0L && o.field == r && s == 5.5 && o.dfield == 5.5;
        }
        case 2: {
            long[] a = new long[3];
            long r = a[1] = big; // dup2_x2
            return r == big && a[1] == big && a[0] == 0 && a[2] == 0;
        }
        case 3: {
            double[] a = new double[3];
            double r = a[2] = d; // dup2_x2
            return r == 2.75 && a[2] == 2.75 && a[1] == 0.0;
        }
        default:
            return false;
        }
    }
}
