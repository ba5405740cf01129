package org.jmclbench.workload.output;

/** One memory area of a run for summary.json's {@code memory.areas}: its size, peak use, bytes per release and releases that allocated. */
public final class MemoryArea {
    public final String name;
    /** The budget (bytes); for the Java SE heap, the maximum heap size. */
    public final long size;
    /** The most it held at once (bytes); a private area: the largest single release; null where the VM does not tell. */
    public final Long peakBytes;
    /** Mean bytes allocated per release, or null where releases do not apply or were not measured. */
    public final Long bytesPerRelease;
    /** Releases measured in the area (a handler's private memory), or null where releases do not apply or were not counted. */
    public final Long releases;
    /**
     * How many of those releases allocated anything, or null: tells a release style that always
     * allocates from a one-off (on HotSpot, a JIT compile request; rtsj-compat/README.md).
     */
    public final Long allocatingReleases;

    public MemoryArea(String name, long size, Long peakBytes, Long bytesPerRelease) {
        this(name, size, peakBytes, bytesPerRelease, null, null);
    }

    public MemoryArea(String name, long size, Long peakBytes, Long bytesPerRelease, Long releases, Long allocatingReleases) {
        this.name = name;
        this.size = size;
        this.peakBytes = peakBytes;
        this.bytesPerRelease = bytesPerRelease;
        this.releases = releases;
        this.allocatingReleases = allocatingReleases;
    }
}
