package hvmtest;

/**
 * Patch 21, both modes: StrictMath.floor and ceil (Math's delegate to them) are C's floor and
 * ceil, natives instead of JDK 8's floorOrCeil in Java; Java's results at the edges: -0.0, NaN,
 * infinities, values in (-1, 0) and (0, 1), halves, and numbers beyond 2^52 (already integers).
 * Upstream, floorOrCeil gave wrong results (Double.doubleToRawLongBits was a no-op, patch 06).
 */
public class FloorCeil extends PatchCases {
    static double zero = 0.0;
    static double nan = zero / zero;
    static double inf = 1.0 / zero;
    static double big = 4503599627370497.0; // 2^52 + 1

    public static void main(String[] args) {
        new FloorCeil().run(6);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            return Math.floor(2.5) == 2.0 && Math.floor(-2.5) == -3.0 && Math.ceil(2.5) == 3.0 && Math.ceil(-2.5) == -2.0;
        case 1:
            // a value in (-1, 0): floor -1.0, ceil -0.0; in (0, 1): floor +0.0
            return Math.floor(-0.5) == -1.0 && isNegativeZero(Math.ceil(-0.5)) && isPositiveZero(Math.floor(0.5))
                    && Math.ceil(0.5) == 1.0;
        case 2:
            return isNegativeZero(Math.floor(-zero)) && isNegativeZero(Math.ceil(-zero)) && isPositiveZero(Math.floor(zero));
        case 3:
            return Double.isNaN(Math.floor(nan)) && Double.isNaN(Math.ceil(nan)) && Math.floor(inf) == inf
                    && Math.ceil(-inf) == -inf;
        case 4:
            return Math.floor(big) == big && Math.ceil(-big) == -big && Math.floor(1e300) == 1e300
                    && Math.floor(-4.9e-324) == -1.0 && Math.ceil(4.9e-324) == 1.0;
        case 5:
            return StrictMath.floor(-7.25) == -8.0 && StrictMath.ceil(7.25) == 8.0 && Math.floor(1e15 + 0.5) == 1e15;
        default:
            return false;
        }
    }

    static boolean isNegativeZero(double x) {
        return x == 0.0 && 1.0 / x < 0;
    }

    static boolean isPositiveZero(double x) {
        return x == 0.0 && 1.0 / x > 0;
    }
}
