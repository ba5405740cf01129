package org.jmclbench.tooling.runner;

import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeInfo;

/**
 * One run of a matrix: a configuration, its repetition number and the key that identifies it in the store.
 *
 * @param engine {@code javase} or {@code scj} on a JVM, {@code native} for the native baseline ({@link Engines})
 * @param memory the memory style ({@code preallocated}, {@code allocating}, {@code scoped})
 */
public record PlannedRun(RuntimeInfo runtime, Profile profile, String engine, String memory, String policy, int particles,
                         Dataset dataset, int repetition, long seed, LoadScenario load, String runKey) {

    /**
     * {@code temurin-25 g1 skip 400p match-short #2}, with the engine when it is not the runtime's
     * first ({@code scj}), the memory style when not preallocated and {@code load=cpu} under a load,
     * for progress lines.
     */
    public String label() {
        return runtime.name() + " " + profile.name()
                + (engine.equals(Engines.JAVASE) || engine.equals(Engines.NATIVE) ? "" : " " + engine)
                + (memory.equals(Engines.PREALLOCATED) ? "" : " " + memory) + " " + policy + " " + particles + "p " + dataset.label()
                + (load == LoadScenario.NONE ? "" : " load=" + load.label()) + " #" + repetition;
    }
}
