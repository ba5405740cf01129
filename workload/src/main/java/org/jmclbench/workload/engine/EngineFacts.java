package org.jmclbench.workload.engine;

import org.jmclbench.workload.output.Json;

/**
 * What an engine tells about how it ran, beyond its kind: summary.json's {@code engine} object
 * (docs/FORMATS.md section 4). Each engine has its own typed value class, filled in one place
 * and written by itself in a fixed order.
 */
public interface EngineFacts {
    /** No facts beyond the kind (the ideal run). */
    EngineFacts NONE = j -> {
    };

    /** Writes the facts as members of the open {@code engine} object (its {@code kind} is written already). */
    void writeTo(Json j);
}
