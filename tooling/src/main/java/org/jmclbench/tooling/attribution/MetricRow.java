package org.jmclbench.tooling.attribution;

/** One row of the store's {@code metrics} table (docs/FORMATS.md section 5). */
public record MetricRow(String task, String metric, String stat, double value) {
}
