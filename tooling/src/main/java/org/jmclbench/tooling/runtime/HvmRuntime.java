package org.jmclbench.tooling.runtime;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * The icecap HVM as a runtime under test (docs/HVM.md): whether its tool chain can be built on
 * this machine, building the mission's executable ahead of a matrix, and its {@link RuntimeInfo}.
 * Its runs are driven by the workload on the tool's own JVM ({@code run --engine hvm}).
 */
public final class HvmRuntime {
    /** The runtime's name in results, matrices and the report. */
    public static final String NAME = "hvm";
    /** The icecap source the scripts pin (hvm/build-hvm.sh). */
    static final String VERSION = "hvm-scj 4d31e23 + jmclbench patches";
    /** The variable hvm/build-mission.sh (and so the hvm engine) reads the mode from: compiled or interpreted. */
    public static final String MODE_VARIABLE = "JMCLBENCH_HVM_MODE";
    /** Building the tool chain and the mission takes about 70 s on a quiet machine. */
    static final long BUILD_TIMEOUT_MS = 15 * 60 * 1000L;
    /** The hvm scripts' exit code for bad input (hvm/script-options.sh); 1 is a failed build. */
    static final int BAD_INPUT_EXIT = 2;

    private HvmRuntime() {
    }

    /** Whether the tool chain can be built here, and the reason when not. */
    public record Availability(boolean buildable, String detail) {
    }

    /** Whether HVM_SRC names the icecap source (the user's explicit choice of the HVM). */
    public static boolean sourceGiven() {
        String s = System.getenv("HVM_SRC");
        return s != null && !s.isEmpty();
    }

    /** Asks {@code hvm/build-hvm.sh --check} (builds nothing). */
    public static Availability check(Path home) {
        Path script = home.resolve("hvm/build-hvm.sh");
        if (!Files.isExecutable(script)) {
            return new Availability(false, "no " + script);
        }
        ProcessRunner.Result r = ProcessRunner.run(List.of(script.toString(), "--check"), 60_000);
        return availability(r.ok(), r.exitCode(), r.output(), sourceGiven());
    }

    /**
     * What {@code build-hvm.sh --check} said, for a reader: without HVM_SRC, a tool chain not
     * cached yet will be cloned from GitHub; a cached one (the pinned commit's) needs nothing.
     */
    static Availability availability(boolean ok, int exitCode, String output, boolean sourceGiven) {
        String detail = output.trim().replace("build-hvm: ", "");
        if (ok && !sourceGiven && !detail.contains("(cached:")) {
            detail += "; HVM_SRC is not set: the source will be cloned from GitHub (needs network)";
        }
        return new Availability(ok, detail.isEmpty() ? "exit status " + exitCode : detail);
    }

    /**
     * Builds (or finds cached) the mission's executable in each mode ({@link Profile#hvmMode}), so
     * that no run pays for it, naming {@code where} the hvm runtime was asked for (an option, or a
     * matrix file's line) when it cannot.
     *
     * @throws BadUsageException when the build refuses its input (build-mission.sh's exit 2: a bad HVM_SRC)
     * @throws IOException when the build fails (its exit 1, or its timeout): the machine's failure, not the user's
     */
    public static void prepare(Path home, List<String> modes, String where) throws IOException {
        for (String mode : modes) {
            ProcessRunner.Result r = ProcessRunner.run(List.of(home.resolve("hvm/build-mission.sh").toString(),
                    "--mode", mode), BUILD_TIMEOUT_MS);
            if (r.ok()) {
                continue;
            }
            String why = where + ": " + NAME + ": the HVM executable (" + mode + ") cannot be built: "
                    + (r.timedOut() ? "no end after " + BUILD_TIMEOUT_MS / 60_000 + " min" : ProcessRunner.lastLine(r.output()))
                    + " (./jmclbench doctor; docs/HVM.md)";
            if (!r.timedOut() && r.exitCode() == BAD_INPUT_EXIT) {
                throw new BadUsageException(why);
            }
            throw new IOException(why);
        }
    }

    /** The environment of an hvm run of {@code profile}: the mode its executable is built in. */
    public static java.util.Map<String, String> environment(Profile profile) {
        return java.util.Map.of(MODE_VARIABLE, profile.hvmMode());
    }

    /** The runtime: its program is the tool's own JVM, which runs the workload that drives the executable. */
    public static RuntimeInfo runtime() {
        Path java = Path.of(ProcessHandle.current().info().command().orElse("java"));
        Path real;
        try {
            real = java.toRealPath();
        } catch (java.io.IOException e) {
            real = java;
        }
        return new RuntimeInfo(NAME, RuntimeKind.HVM, "icecap", VERSION, 0, java, real);
    }
}
