package javax.realtime;

/**
 * A scoped memory whose allocation time is linear in the object size (RTSJ). On this layer a
 * measured budget of its maximum size; see {@link ScopedMemory}. Named {@code LTMemory#n} in
 * reports, n its creation order.
 */
public class LTMemory extends ScopedMemory {

    /** A scope of {@code size} bytes. */
    public LTMemory(long size) {
        this(size, size);
    }

    /** A scope that may grow from {@code initial} to {@code maximum} bytes (the budget is the maximum). */
    public LTMemory(long initial, long maximum) {
        super("LTMemory", check(initial, maximum));
    }

    private static long check(long initial, long maximum) {
        if (initial < 0 || maximum < initial) {
            throw new IllegalArgumentException("need 0 <= initial <= maximum: " + initial + ", " + maximum);
        }
        return maximum;
    }
}
