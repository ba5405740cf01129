package org.jmclbench.tooling.runner;

import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeInfo;

/** One run of a matrix: a configuration, its repetition number and the key that identifies it in the store. */
public record PlannedRun(RuntimeInfo runtime, Profile profile, String policy, int particles, Dataset dataset,
                         int repetition, long seed, LoadScenario load, String runKey) {

    /** {@code temurin-25 g1 skip 400p match-short #2} (and {@code load=cpu} under a load), for progress lines. */
    public String label() {
        return runtime.name() + " " + profile.name() + " " + policy + " " + particles + "p " + dataset.label()
                + (load == LoadScenario.NONE ? "" : " load=" + load.label()) + " #" + repetition;
    }
}
