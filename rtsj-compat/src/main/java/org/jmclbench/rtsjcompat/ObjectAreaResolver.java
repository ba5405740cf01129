package org.jmclbench.rtsjcompat;

/**
 * Tells in which area an object lives, for {@code executeInAreaOf} and
 * {@code MemoryArea.getMemoryArea}. A JVM does not record where an object was allocated, so
 * the default knows only the SCJ infrastructure's objects (a handler lives in its mission's
 * memory) and answers null otherwise; a verification listener that tracks allocations can
 * install a complete one.
 */
public interface ObjectAreaResolver {
    /** The area of {@code object}, or null when unknown. */
    Area areaOf(Object object);
}
