package org.jmclbench.hvm.launcher;

import java.io.File;

import org.jmclbench.workload.engine.EngineFacts;
import org.jmclbench.workload.output.Json;

/** summary.json's {@code engine} object of an hvm run (docs/FORMATS.md section 4): which executable ran, and how long. */
final class HvmFacts implements EngineFacts {
    private final File executable;
    private final long processWallNs;

    HvmFacts(File executable, long processWallNs) {
        this.executable = executable;
        this.processWallNs = processWallNs;
    }

    @Override
    public void writeTo(Json j) {
        String mode = mode(executable);
        j.name("vm").value("icecap HVM (" + ("compiled".equals(mode) ? "compiled to C, icecap -aot"
                : "hot".equals(mode) ? "hot methods compiled to C, hvm/mission/hot-methods.txt" : "interpreter")
                + "), github.com/scj-devel/hvm-scj, with jmclbench's patches (hvm/patches)");
        j.name("mode").value(mode);
        j.name("level").value(1);
        j.name("executable").value(executable.getPath());
        j.name("executableBytes").value(executable.length());
        j.name("toolchain").value(executable.getParentFile().getParentFile().getName());
        j.name("clock").value("CLOCK_MONOTONIC read to the ns; releases on a 1 ms tick");
        j.name("timeSource").value("clock_gettime(CLOCK_MONOTONIC)");
        j.name("warmupEvents").value(0);
        j.name("processWallNs").value(processWallNs);
    }

    /** interpreted, compiled or hot. */
    String mode() {
        return mode(executable);
    }

    /** The executable's mode, from the MODE file build-mission.sh writes beside it (interpreted when absent: built before modes). */
    static String mode(File executable) {
        File f = new File(executable.getParentFile(), "MODE");
        try {
            String m = new String(java.nio.file.Files.readAllBytes(f.toPath()), java.nio.charset.StandardCharsets.UTF_8).trim();
            return m.isEmpty() ? "interpreted" : m;
        } catch (java.io.IOException e) {
            return "interpreted";
        }
    }
}
