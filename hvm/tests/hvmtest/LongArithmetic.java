package hvmtest;

/**
 * Patch 16: 64-bit arithmetic. Both modes: lshr shifted logically. Compiled: ladd, lsub, lmul,
 * land, lor, lxor, lneg, lcmp and the shifts are emitted as C 64-bit operations (they were helper
 * calls on 32-bit halves). Outside main (icecap -aot).
 */
public class LongArithmetic extends PatchCases {
    static long x = -16L;
    static long p = 0x123456789L;
    static long q = 0x987654321L;
    static long one = 1;
    static long mone = -1;
    static long max = Long.MAX_VALUE;
    static int s2 = 2;
    static int s65 = 65;
    static int minus5 = -5;

    public static void main(String[] args) {
        new LongArithmetic().run(8);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            return x >> s2 == -4L && (x >>> 60) == 15L && (mone >> 63) == -1L && (Long.MIN_VALUE >> 63) == -1L;
        case 1:
            return (one << s65) == 2L && (mone >>> s65) == Long.MAX_VALUE && (x >> s65) == -8L;
        case 2:
            return p * q == -0x28828BD331E7CC57L && max * 2 == -2L && x * x == 256L;
        case 3:
            return max + one == Long.MIN_VALUE && Long.MIN_VALUE - one == max && -Long.MIN_VALUE == Long.MIN_VALUE
                    && -p == -0x123456789L && p - q == -0x8641FDB98L;
        case 4:
            return p < q && q > p && x < one && mone < 0 && Long.MIN_VALUE < one && max > mone && p == 0x123456789L
                    && p != q;
        case 5:
            return (p & q) == 0x103454301L && (p | q) == 0x9A76567A9L && (p ^ q) == 0x8A42024A8L;
        case 6:
            return (int) p == 0x23456789 && (long) minus5 == -5L && (int) (x >>> 32) == -1;
        case 7: {
            long seed = 42;
            for (int k = 0; k < 10; k++) {
                seed = (seed * 0x5DEECE66DL + 0xBL) & ((1L << 48) - 1);
            }
            return seed == 120421598792892L;
        }
        default:
            return false;
        }
    }
}
