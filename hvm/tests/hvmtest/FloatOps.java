package hvmtest;

/**
 * Patch 18: float. The compiler leaves a method that handles floats to the interpreter (its
 * compiled float code converted floats through int variables; frem and f2l were missing); the
 * interpreter lacked frem, f2l and l2f, and fcmpl/fcmpg gave 0 for NaN, f2i did not saturate
 * (patch 17). "Handles floats": a float bytecode, parameter or result, float field access or call
 * passing a float; check 7 relays floats through a method with no float bytecode. Outside main
 * (icecap -aot).
 */
public class FloatOps extends PatchCases {
    static float f = 2.5f;
    static float g = -1.25f;
    static float fnan = fzero() / fzero();
    static long lv = (1L << 40) + 1;

    static float fzero() {
        return 0.0f;
    }

    public static void main(String[] args) {
        new FloatOps().run(8);
    }

    @Override
    boolean check(int i) {
        switch (i) {
        case 0:
            return f + g == 1.25f && f * g == -3.125f && f / g == -2.0f && f - g == 3.75f && g - f == -3.75f;
        case 1:
            return -f == -2.5f && f % 2f == 0.5f && -f % 2f == -0.5f;
        case 2:
            return fnan != fnan && !(fnan < f) && !(fnan > f) && !(fnan <= f) && !(fnan >= f);
        case 3:
            return (int) fnan == 0 && (int) (f * 1e19f) == Integer.MAX_VALUE && (int) (g * 1e19f) == Integer.MIN_VALUE
                    && (int) g == -1;
        case 4:
            return (long) (f * 4e11f) == 999999995904L && (long) fnan == 0L && (long) (g * 1e30f) == Long.MIN_VALUE;
        case 5:
            return (float) lv == 1099511627776.0f && (float) -lv == -1099511627776.0f;
        case 6:
            return (double) f == 2.5 && (float) (f * 0.1) == 0.25f && (float) lv * 2 == 2199023255552.0f;
        case 7:
            return relay();
        default:
            return false;
        }
    }

    static float passed;
    static Holder holder = new Holder();

    static final class Holder {
        float value;
    }

    /**
     * No float bytecode here, but floats cross it: a float field is read and passed to a method,
     * a float result is stored in fields (compiled code must move the bits, not convert them).
     */
    static boolean relay() {
        passed = half(f);
        holder.value = half(g);
        return isValue(passed, 1.25) && isValue(holder.value, -0.625) && isValue(half(holder.value), -0.3125);
    }

    static float half(float x) {
        return x / 2;
    }

    static boolean isValue(float x, double expected) {
        return x == expected;
    }
}
