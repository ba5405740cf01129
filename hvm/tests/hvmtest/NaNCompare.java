package hvmtest;

/**
 * Patch 17, both modes: dcmpl/dcmpg gave 0 for a NaN operand (so x != x was false and
 * Double.isNaN failed); d2i did not saturate (C's conversion is undefined out of range) nor map NaN
 * to 0. Outside main (icecap -aot).
 */
public class NaNCompare extends PatchCases {
    static double nan = zero() / zero();
    static double one = 1.0;
    static double big = 1e20;

    static double zero() {
        return 0.0;
    }

    public static void main(String[] args) {
        new NaNCompare().run(5);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            return nan != nan && !(nan == nan) && one == one;
        case 1:
            return !(nan < one) && !(nan > one) && !(nan <= one) && !(nan >= one) && !(one < nan) && !(one >= nan);
        case 2:
            return Double.isNaN(nan) && !Double.isNaN(one);
        case 3:
            return (int) nan == 0 && (int) big == Integer.MAX_VALUE && (int) -big == Integer.MIN_VALUE
                    && (int) (one * -2.5) == -2;
        case 4:
            return (int) (one * 2147483647.5) == Integer.MAX_VALUE && (int) (one * -2147483648.5) == Integer.MIN_VALUE;
        default:
            return false;
        }
    }
}
