package org.jmclbench.workload.output;

/** One memory area of a run for summary.json's {@code memory.areas}: its size, peak use and bytes per release. */
public final class MemoryArea {
    public final String name;
    /** The budget (bytes); for the Java SE heap, the maximum heap size. */
    public final long size;
    /** The most it held at once (bytes); a private area: the largest single release; null where the VM does not tell. */
    public final Long peakBytes;
    /** Mean bytes allocated per release, or null where releases do not apply or were not measured. */
    public final Long bytesPerRelease;

    public MemoryArea(String name, long size, Long peakBytes, Long bytesPerRelease) {
        this.name = name;
        this.size = size;
        this.peakBytes = peakBytes;
        this.bytesPerRelease = bytesPerRelease;
    }
}
