package org.jmclbench.rtsjcompat;

/**
 * The OutOfMemoryError of an SCJ memory area whose budget was exceeded: names the area,
 * its size and the bytes it needed. On a JVM the excess is detected at the next accounting
 * point of the allocating thread (area exit, end of a release, end of a mission phase),
 * not at the allocation itself.
 */
public final class AreaOverflowError extends OutOfMemoryError {
    private static final long serialVersionUID = 1L;

    private final String areaName;
    private final long size;
    private final long needed;

    /** The overflow of {@code areaName}, of {@code size} bytes, which needed {@code needed}. */
    public AreaOverflowError(String areaName, long size, long needed) {
        super(areaName + " overflowed: needed " + needed + " bytes, size " + size + " bytes");
        this.areaName = areaName;
        this.size = size;
        this.needed = needed;
    }

    /** The area's name. */
    public String areaName() {
        return areaName;
    }

    /** The area's size in bytes. */
    public long size() {
        return size;
    }

    /** The bytes it needed to hold. */
    public long needed() {
        return needed;
    }
}
