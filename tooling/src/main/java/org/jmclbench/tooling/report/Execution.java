package org.jmclbench.tooling.report;

import org.jmclbench.tooling.runtime.RuntimeKind;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * What runs where, for one configuration (the evaluation's "what runs where" table): how the
 * code executes, how it is scheduled and whether its priorities took effect, what its memory
 * areas are, and how jobs are released. Read from a run's summary.json where the run records it
 * (scheduling, priorities, the HVM's mode, the VM's name, the clock source); the rest follows
 * from the engine and runtime kind, as docs/RUNNER.md and docs/HVM.md describe them.
 */
public record Execution(String execution, String scheduling, String priorities, String memory, String release) {
    /** {@link #priorities} of a run that asked for thread priorities the OS did not apply. */
    private static final String IGNORED = "not applied (the OS ignored them)";

    /** The configuration's facts from one completed run's summary (a missing field reads "not recorded"). */
    static Execution of(RuntimeKind kind, String engine, String memoryStyle, JsonNode summary) {
        JsonNode env = summary.path("environment");
        JsonNode sched = env.path("scheduling");
        String scheduling = sched.hasNonNull("policy")
                ? sched.get("policy").asText() + (sched.hasNonNull("priority") ? " " + sched.get("priority").asText() : "")
                : "not recorded";
        JsonNode applied = summary.at("/engine/prioritiesApplied");
        String priorities = applied.isBoolean() ? (applied.asBoolean() ? "applied" : IGNORED)
                : kind == RuntimeKind.HVM ? "the HVM's own scheduler (green threads)" : "not recorded";
        String clock = env.hasNonNull("clocksource") ? ", clocksource " + env.get("clocksource").asText() : "";
        return switch (kind) {
            case NATIVE -> new Execution("C, compiled ahead of time (gcc)", scheduling, priorities,
                    "static arrays; no allocation after start",
                    "a dispatcher thread sleeping to absolute CLOCK_MONOTONIC release times (clock_nanosleep TIMER_ABSTIME), "
                            + "handing each event to its task's thread" + clock);
            case HVM -> new Execution("icecap HVM, " + hvmMode(summary), scheduling, priorities,
                    "real SCJ memory areas (" + memoryStyle + "), no garbage collector",
                    "handlers as green threads on one OS thread, released on the HVM's 1 ms clock tick; the VM busy-waits when idle"
                            + clock);
            case JVM -> new Execution(jvm(env), scheduling, priorities, jvmMemory(engine, memoryStyle),
                    jvmRelease(engine) + clock);
        };
    }

    /** Whether the run asked for thread priorities and the OS did not apply them (every thread at one priority). */
    boolean prioritiesIgnored() {
        return IGNORED.equals(priorities);
    }

    private static String hvmMode(JsonNode summary) {
        String mode = summary.at("/engine/mode").asText("");
        return switch (mode) {
            case "compiled" -> "Java compiled to C ahead of time";
            case "interpreted" -> "interpreter";
            case "hot" -> "hot methods compiled to C, the rest interpreted";
            case "" -> "mode not recorded";
            default -> mode;
        };
    }

    private static String jvm(JsonNode env) {
        String vm = env.at("/runtime/vmName").asText("");
        return (vm.isEmpty() ? "a JVM" : vm) + ", JIT-compiled";
    }

    private static String jvmMemory(String engine, String style) {
        if ("scj".equals(engine)) {
            return "SCJ areas (" + style + ") kept as budgets on the JVM's garbage-collected heap (rtsj-compat)";
        }
        if (engine != null && engine.startsWith("rtsj")) {
            return "the garbage-collected heap (RTSJ areas are not used by this engine)";
        }
        return "the garbage-collected heap" + ("allocating".equals(style) ? ", temporaries allocated per job" : ", jobs allocation-free");
    }

    private static String jvmRelease(String engine) {
        if ("scj".equals(engine)) {
            return "SCJ handlers on Java threads, released by rtsj-compat's dispatcher sleeping to absolute times";
        }
        if (engine != null && engine.startsWith("rtsj")) {
            return "RTSJ async event handlers fired by a dispatcher thread sleeping to absolute times";
        }
        return "a dispatcher thread sleeping to absolute release times (LockSupport.parkNanos)";
    }
}
