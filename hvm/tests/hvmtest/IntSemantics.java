package hvmtest;

/**
 * Patch 15: Java's int semantics in both modes. Compiled: ishr was logical, shift counts were not
 * masked, i2b and i2c were no-ops, arithmetic was done in the operands' inferred width (8 bits
 * for small constants and bytes), byte fields read zero-extended, array lengths above 32,767 came
 * out negative, wide iinc read the wrong bytes, a constant shift count above 255 stopped the
 * compiler, MIN_VALUE % -1 trapped. Both modes: x / MIN_VALUE looped forever and MIN_VALUE / y
 * gave 0. Interpreted: i2b zero-extended, i2c kept 8 bits. Outside main (icecap -aot).
 */
public class IntSemantics extends PatchCases {
    static int m = -16;
    static int big = 0x12345678;
    static int minus1 = -1;
    static int min = Integer.MIN_VALUE;
    static int five = 5;
    static int seven = 7;
    static int s33 = 33;
    static int s35 = 35;
    static int f40000 = 40000;
    static boolean flag = true;
    static byte b100 = 100;
    static byte bmin = -128;

    public static void main(String[] args) {
        new IntSemantics().run(10);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            return m >> 2 == -4 && m >>> 28 == 15 && (m >> s33) == -8 && (big >> s35) == (big >> 3);
        case 1:
            return (1 << s33) == 2 && (minus1 >>> s33) == 0x7fffffff && (minus1 << s35) == -8;
        case 2:
            return (byte) (big + 0x50) == -56 && (byte) big == 0x78 && (byte) (m * 8) == -128;
        case 3:
            return (char) minus1 == 65535 && (char) big == 0x5678 && (short) f40000 == -25536 && (short) big == 0x5678;
        case 4:
            return min / minus1 == min && min % minus1 == 0 && five / min == 0 && five % min == 5;
        case 5:
            return min / seven == -306783378 && min % seven == -2 && -seven / 2 == -3 && -seven % 3 == -1
                    && seven % -3 == 1 && seven / -3 == -2;
        case 6: {
            int c = (flag ? 100 : 50) + 100;
            int s = b100 + b100;
            int n = -bmin;
            int p = b100 * b100;
            return c == 200 && s == 200 && n == 128 && p == 10000 && big * 16 == 0x23456780;
        }
        case 7:
            return new byte[f40000].length == 40000;
        case 8: {
            int k = five;
            k += 1000; // wide iinc
            k -= 2000;
            return k == -995;
        }
        case 9:
            // a shift count beyond a byte: the compiler stopped ("Illegal consumer size"; found by hvm/difftest.sh)
            return (m << 1000) == -4096 && (minus1 >>> 1000) == 0xffffff && (m >> 1000) == -1;
        default:
            return false;
        }
    }
}
