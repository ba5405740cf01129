package org.jmclbench.tooling.runner;

import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.load.LoadScenario;

import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeInfo;

/**
 * A matrix resolved against this machine: runtimes found, profiles parsed, datasets read, and the
 * ordered plan of runs for this shard.
 *
 * @param plan        this shard's runs in execution order
 * @param planned     runs of the whole matrix (all shards)
 */
public record ResolvedMatrix(List<RuntimeInfo> runtimes, List<Profile> profiles, List<String> engines,
                             List<String> memory, List<String> policies,
                             List<Integer> particles, List<Dataset> datasets, List<LoadScenario> loads,
                             org.jmclbench.tooling.load.LoadSettings loadSettings, int repeat, long seed, long orderSeed,
                             double timeScale, Double timeoutS, String pinCpu, List<String> workloadArgs, Path db,
                             Path nativeBinary, int[] shard, List<PlannedRun> plan, int planned) {

    /** The timeout of one run: the replay's duration x 3 + 60 s, unless set. */
    public double timeoutFor(PlannedRun r) {
        if (timeoutS != null) {
            return timeoutS;
        }
        return r.dataset().durationS() * timeScale * MatrixDefaults.TIMEOUT_FACTOR + MatrixDefaults.TIMEOUT_SLACK_S;
    }
}
