package org.jmclbench.tooling.runtime;

import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * What ran a stored run: a JVM, the native C baseline or the icecap HVM (an SCJ VM), decided once
 * from the run's stored facts so that the report, the evaluation and compare agree on it.
 */
public enum RuntimeKind {
    /** A JVM: the javase or scj engine on HotSpot (or another JVM). */
    JVM,
    /** The C baseline: its own engine, the reference every Java runtime is compared with. */
    NATIVE,
    /** The icecap HVM running the SCJ mission: not a JVM, and not the C baseline either. */
    HVM;

    /** The engine name a run of this kind carries when the runtime is its own engine ({@code native}, {@code hvm}). */
    public String engine() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * The kind from the stored facts: the HVM by its engine, its summary's engine kind or its
     * runtime name ({@code hvm}, {@code hvm-*}); the C baseline by its engine, its runtime name or
     * the language its summary reports; a JVM otherwise. The HVM is asked first: it is compiled C,
     * but it is not the baseline.
     *
     * @param summary the run's summary.json (a missing node when there is none)
     */
    public static RuntimeKind of(String runtime, String engine, JsonNode summary) {
        String name = runtime == null ? "" : runtime;
        if (HVM.engine().equals(engine) || HVM.engine().equals(summary.at("/engine/kind").asText())
                || name.equals(HVM.engine()) || name.startsWith(HVM.engine() + "-")) {
            return HVM;
        }
        if (NATIVE.engine().equals(engine) || name.equals(NATIVE.engine())
                || "c".equalsIgnoreCase(summary.at("/environment/runtime/language").asText())) {
            return NATIVE;
        }
        return JVM;
    }
}
