package org.jmclbench.rtsjcompat;

/**
 * Argument checks that javax.realtime and javax.safetycritical constructors share, in one place
 * so that their messages (which tests compare) are worded once. Not on any release path.
 */
public final class Arguments {
    private Arguments() {
    }

    /** {@code value}, or IllegalArgumentException "{@code name} is negative: value". */
    public static long nonNegative(long value, String name) {
        if (value < 0) {
            throw new IllegalArgumentException(name + " is negative: " + value);
        }
        return value;
    }

    /** A copy of {@code items}, or IllegalArgumentException {@code nullMessage} when an element is null. */
    public static <T> T[] copyWithoutNulls(T[] items, String nullMessage) {
        for (T item : items) {
            if (item == null) {
                throw new IllegalArgumentException(nullMessage);
            }
        }
        return items.clone();
    }
}
