package org.jmclbench.tooling.runner;

/**
 * A value with where it came from ({@code --particles} or {@code matrix.properties:7}), so that a
 * value found bad later (an unknown runtime) is reported at its origin.
 */
public record Sourced<T>(T value, String where) {
}
