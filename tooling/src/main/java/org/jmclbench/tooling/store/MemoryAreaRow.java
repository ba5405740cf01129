package org.jmclbench.tooling.store;

/**
 * One {@code memory_areas} row: a memory area of a run (summary.json {@code memory.areas}); null
 * where the engine does not tell. For a handler's private memory {@code peakBytes} is one release's peak.
 */
public record MemoryAreaRow(String name, Long size, Long peakBytes, Double bytesPerRelease) {
}
