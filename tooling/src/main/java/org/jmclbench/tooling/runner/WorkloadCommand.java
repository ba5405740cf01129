package org.jmclbench.tooling.runner;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.runtime.JmclbenchPaths;
import org.jmclbench.tooling.runtime.LaunchPlan;
import org.jmclbench.tooling.runtime.ProfileComponent;
import org.jmclbench.tooling.runtime.RuntimeInfo;

/** Builds the command line of one workload process (docs/FORMATS.md section 2), as an argument list. */
public final class WorkloadCommand {

    /** The workload's entry point in the workload jar. */
    public static final String MAIN_CLASS = "org.jmclbench.workload.WorkloadMain";

    private WorkloadCommand() {
    }

    /**
     * {@code [prefix] <java> <flags> -Djmclbench.home=H -cp JAR WorkloadMain run <args>} for a JVM,
     * {@code [prefix] <native> run <args>} for the native baseline, and for the HVM
     * {@code [prefix] <tool java> -Djmclbench.home=H -cp JAR WorkloadMain run --engine hvm <args>}.
     * The engine and memory style are passed only when they are not the defaults (javase,
     * preallocated), so that a workload older than them still runs the default configuration; the
     * runtime name gets the engine's suffix ({@code -scj}, {@code -rtsj-atomic}: {@link Engines#runtimeSuffix}),
     * as the workload's own default name does.
     */
    public static List<String> build(PlannedRun run, LaunchPlan plan, List<String> extraJvmFlags, Path home, Path jar,
                                     Path out, double timeScale, List<String> workloadArgs) {
        List<String> cmd = new ArrayList<>(plan.prefix());
        RuntimeInfo rt = run.runtime();
        cmd.add(rt.path().toString());
        if (rt.kind() == RuntimeKind.HVM) {
            // the HVM launcher on this JVM validates, builds and drives the HVM executable
            cmd.add("-Djmclbench.home=" + home);
            cmd.add("-cp");
            cmd.add(JmclbenchPaths.hvmLauncherClassPath());
            cmd.add(MAIN_CLASS);
        } else if (rt.isJvm()) {
            cmd.addAll(plan.jvmFlags());
            cmd.addAll(extraJvmFlags);
            cmd.add("-Djmclbench.home=" + home);
            cmd.add("-cp");
            cmd.add(jar.toString());
            cmd.add(MAIN_CLASS);
        }
        cmd.addAll(workloadOptions(run, out, timeScale, workloadArgs));
        return cmd;
    }

    /**
     * The workload's own command line within {@link #build}'s: {@code run} and the options, as the
     * workload parses them (docs/FORMATS.md section 2); the planner checks them with the workload's
     * parser before anything runs.
     */
    static List<String> workloadOptions(PlannedRun run, Path out, double timeScale, List<String> workloadArgs) {
        RuntimeInfo rt = run.runtime();
        List<String> cmd = new ArrayList<>();
        cmd.add("run");
        if (rt.kind() == RuntimeKind.HVM) {
            cmd.addAll(List.of("--engine", "hvm"));
        }
        cmd.addAll(List.of("-p", String.valueOf(run.particles()), "-n", String.valueOf(run.repetition()),
                "-j", rt.name() + (rt.isJvm() ? Engines.runtimeSuffix(run.engine()) : ""), "-O", out.toString(), "--dataset", run.dataset().dir().toString()));
        if (run.policy().equals("ideal")) {
            cmd.add("--ideal");
        } else {
            cmd.addAll(List.of("--policy", run.policy()));
        }
        cmd.addAll(List.of("--seed", String.valueOf(run.seed())));
        if (rt.isJvm()) {
            cmd.addAll(Engines.workloadArgs(run.engine()));
        }
        if (!run.memory().equals(Engines.PREALLOCATED)) {
            cmd.addAll(List.of("--memory", run.memory()));
        }
        if (timeScale != 1.0) {
            cmd.addAll(List.of("--time-scale", String.format(Locale.ROOT, "%s", timeScale)));
        }
        if (rt.kind() == RuntimeKind.NATIVE && !run.profile().has(ProfileComponent.FIFO)) {
            // the C program raises itself to SCHED_FIFO when permitted; without the fifo profile it
            // must run under the same scheduling as the JVMs it is compared with
            cmd.add("--no-fifo");
        }
        cmd.addAll(workloadArgs);
        return cmd;
    }
}
