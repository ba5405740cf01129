package org.jmclbench.tooling.load;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * The load of one run, started just before it and ended with it (use try-with-resources
 * around the run, on the thread that waits for the run: see {@link CpuLoad}).
 *
 * <p>The {@code cpu} part runs beside the runtime under test; the {@code alloc} part runs inside
 * it, switched on by {@link #workloadArgs()} ({@code --load-alloc}). The scenario's name goes to
 * the workload too ({@code --load-name}), which records it in summary.json's
 * {@code parameters.load}; the runner records it in {@code runs.load}.
 *
 * @param cpu the CPU hogs, or null when the scenario has no cpu part
 */
public record LoadSession(LoadScenario scenario, LoadSettings settings, CpuLoad cpu) implements AutoCloseable {

    /**
     * Starts the out-of-process part of {@code scenario}.
     *
     * @param maxRunTime the run's own timeout: the CPU hogs stop by themselves a little after it
     */
    public static LoadSession start(LoadScenario scenario, LoadSettings settings, Duration maxRunTime) throws IOException {
        CpuLoad cpu = scenario.cpu() ? CpuLoad.start(settings.cpuWorkers(), maxRunTime.plusSeconds(30)) : null;
        return new LoadSession(scenario, settings, cpu);
    }

    /** The workload options that switch the in-runtime part on and record the scenario (Java workload only). */
    public List<String> workloadArgs() {
        List<String> args = new ArrayList<>(List.of("--load-name", scenario.label()));
        if (scenario.alloc()) {
            args.add("--load-alloc");
            args.add(settings.allocMbPerS() + "," + settings.allocLiveMb());
        }
        return args;
    }

    /** A one-line description, e.g. {@code mixed: stress-ng --cpu 2; alloc 100 MB/s, 16 MB live}. */
    public String description() {
        List<String> parts = new ArrayList<>();
        if (cpu != null) {
            parts.add(cpu.tool() + " --cpu " + settings.cpuWorkers());
        }
        if (scenario.alloc()) {
            parts.add("alloc " + LoadSettings.allocText(settings.allocMbPerS(), settings.allocLiveMb()));
        }
        return scenario.label() + (parts.isEmpty() ? "" : ": " + String.join("; ", parts));
    }

    /** The CPU hogs' process ids (empty without a cpu part). */
    public List<Long> cpuPids() {
        return cpu == null ? List.of() : cpu.pids();
    }

    /** Ends the CPU hogs; the alloc part ends with the workload's process. */
    @Override
    public void close() {
        if (cpu != null) {
            cpu.close();
        }
    }
}
