package hvmtest;

/**
 * Patch 19, both modes: an array index outside 0..length-1 throws ArrayIndexOutOfBoundsException
 * and reads or writes nothing. Compiled code had no check at all (it read and wrote past the
 * array); the interpreter let a negative index through and threw NullPointerException for one at
 * or above the length. Outside main (icecap -aot).
 */
public class ArrayBounds extends PatchCases {
    static int[] ints = new int[4];
    static double[] doubles = new double[3];
    static byte[] bytes = new byte[5];
    static long[] longs = new long[2];
    static Object[] objects = new Object[2];
    static short[] shorts = new short[3];
    static char[] chars = new char[3];
    /* allocated after the others: a store past their end would land here */
    static int[] guard = { 7, 7, 7, 7 };
    static int four = 4, three = 3, minus1 = -1, big = 70000, min = Integer.MIN_VALUE;
    static long sink;

    public static void main(String[] args) {
        new ArrayBounds().run(10);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            return loadInt(ints, four) && loadInt(ints, minus1) && loadInt(ints, big) && loadInt(ints, min)
                    && !loadInt(ints, three);
        case 1:
            return storeDouble(doubles, three) && storeDouble(doubles, minus1) && !storeDouble(doubles, 2);
        case 2:
            return storeByte(bytes, 5) && storeByte(bytes, minus1) && loadByte(bytes, 5) && !loadByte(bytes, 4);
        case 3:
            return loadLong(longs, 2) && loadLong(longs, minus1) && !loadLong(longs, 1);
        case 4:
            return storeObject(objects, 2) && storeObject(objects, minus1) && !storeObject(objects, 1);
        case 5:
            return storeShort(shorts, three) && storeChar(chars, three) && storeShort(shorts, minus1)
                    && !storeShort(shorts, 2) && !storeChar(chars, 2);
        case 6:
            // nothing was written past any array by the stores above
            return guard[0] == 7 && guard[1] == 7 && guard[2] == 7 && guard[3] == 7 && guard.length == 4;
        case 7:
            // thrown in a callee without a handler, caught by the caller's
            try {
                sink = ints[four + 1];
                return false;
            } catch (ArrayIndexOutOfBoundsException e) {
                return nested(ints) == 2;
            }
        case 8:
            // in-bounds accesses still read what was written
            ints[three] = 42;
            doubles[2] = 2.5;
            longs[1] = 0x123456789L;
            bytes[4] = -3;
            return ints[three] == 42 && doubles[2] == 2.5 && longs[1] == 0x123456789L && bytes[4] == -3;
        case 9:
            // an index computed as a byte or short is sign-extended before the check
            return loadInt(ints, (byte) 0xff) && loadInt(ints, (short) 0xffff) && !loadInt(ints, (byte) 3);
        default:
            return false;
        }
    }

    static int nested(int[] a) {
        int caught = 0;
        try {
            outOfBounds(a);
        } catch (ArrayIndexOutOfBoundsException e) {
            caught++;
        }
        try {
            outOfBounds(a);
        } catch (RuntimeException e) {
            caught++;
        }
        return caught;
    }

    static void outOfBounds(int[] a) {
        a[a.length] = 1;
    }

    static boolean loadInt(int[] a, int i) {
        try {
            sink = a[i];
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }

    static boolean storeDouble(double[] a, int i) {
        try {
            a[i] = 1.5;
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }

    static boolean storeByte(byte[] a, int i) {
        try {
            a[i] = 1;
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }

    static boolean loadByte(byte[] a, int i) {
        try {
            sink = a[i];
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }

    static boolean loadLong(long[] a, int i) {
        try {
            sink = a[i];
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }

    static boolean storeObject(Object[] a, int i) {
        try {
            a[i] = a;
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }

    static boolean storeShort(short[] a, int i) {
        try {
            a[i] = 1;
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }

    static boolean storeChar(char[] a, int i) {
        try {
            a[i] = 'x';
            return false;
        } catch (ArrayIndexOutOfBoundsException e) {
            return true;
        }
    }
}
