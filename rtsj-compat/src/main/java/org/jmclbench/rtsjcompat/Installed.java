package org.jmclbench.rtsjcompat;

/**
 * A process-wide seam of the layer (the time source, the allocation meter): chosen at first use
 * (from its system property), or installed by tests and verification before a launch. Reading it
 * allocates nothing once it is chosen.
 */
abstract class Installed<T> {
    private volatile T current;

    /** The seam to use when none was installed (called once, on first use). */
    abstract T choose();

    /** The installed seam, chosen at first use. */
    final T get() {
        T t = current;
        if (t == null) {
            synchronized (this) {
                if (current == null) {
                    current = choose();
                }
                t = current;
            }
        }
        return t;
    }

    /** Installs {@code value} ({@code what} names it when null); call it before a launch, not during one. */
    final void install(T value, String what) {
        if (value == null) {
            throw new IllegalArgumentException(what + " is null");
        }
        synchronized (this) {
            current = value;
        }
    }
}
