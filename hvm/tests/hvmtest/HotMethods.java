package hvmtest;

/**
 * Patch 22, mode hot: a build that compiles only the methods a list names (HotMethods.methods:
 * the hot ones) and interprets the rest, as the hvm runtime's profile hot builds the mission.
 * The listed methods call unlisted ones and are called by them, passing and returning doubles,
 * longs and references, and an exception crosses the boundary both ways: a mixed build must
 * agree with Java at every crossing. test-patches.sh also checks the compiler's log: the listed
 * methods compiled, the others not. Upstream the compiler ignores the list (hvmc.sh refuses it).
 */
public class HotMethods extends PatchCases {
    static double half = 0.5;
    static long big = 0x123456789abcdefL;

    public static void main(String[] args) {
        new HotMethods().run(4);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            // compiled -> interpreted -> compiled, doubles both ways
            return hotScale(3.0) == 3.0 * (0.25 + 1.5) && coldTwice(hotScale(half)) == 2 * half * (0.25 + 1.5);
        case 1:
            // longs across the boundary, high word first on the VM's stack
            return hotMix(big, 7) == coldMix(big, 7) && hotMix(-1L, 64) == (-1L ^ 64L) * 31 + 5;
        case 2:
            // an exception thrown in interpreted code unwinds a compiled frame, and back
            return hotCatches(0) == -1 && hotCatches(4) == 8 && coldCatches() == 42;
        case 3:
            // a reference and an array element written on one side, read on the other
            double[] a = new double[3];
            hotFill(a, 1.25);
            return coldSum(a) == 1.25 + 2.5 + 3.75;
        default:
            return false;
        }
    }

    /* listed in HotMethods.methods: compiled to C */

    static double hotScale(double x) {
        return x * coldQuarterPlus(1.5);
    }

    static long hotMix(long x, int k) {
        return coldMix(x, k);
    }

    static int hotCatches(int d) {
        try {
            return coldDivide(d);
        } catch (ArithmeticException e) {
            return -1;
        }
    }

    static void hotFill(double[] a, double step) {
        for (int i = 0; i < a.length; i++) {
            a[i] = step * (i + 1);
        }
    }

    static int hotThrows() {
        throw new IllegalStateException("hot");
    }

    /* not listed: interpreted */

    static double coldQuarterPlus(double y) {
        return 0.25 + y;
    }

    static double coldTwice(double x) {
        return 2 * x;
    }

    static long coldMix(long x, int k) {
        return (x ^ (long) k) * 31 + 5;
    }

    static int coldDivide(int d) {
        return 32 / d;
    }

    static int coldCatches() {
        try {
            return hotThrows();
        } catch (IllegalStateException e) {
            return 42;
        }
    }

    static double coldSum(double[] a) {
        double s = 0;
        for (int i = 0; i < a.length; i++) {
            s += a[i];
        }
        return s;
    }
}
