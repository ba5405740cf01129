package org.jmclbench.workload.scj;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunOptions;

/**
 * The options the hvm engine refuses beyond the scj engine's checks: its executable replays the
 * dataset once (no warm-up), releases on the HVM's own 1 ms tick (no spin) and has no GC log;
 * given, they were recorded in summary.json's parameters as if they had been applied. Part of the
 * launch contract rather than of hvm/launcher, which nothing may depend on: the hvm engine
 * (hvm/launcher's HvmEngine) applies them first, and the matrix checks an hvm cell's options with
 * them when it plans, without the HVM launcher on its class path.
 */
public final class HvmOptionRules {
    private HvmOptionRules() {
    }

    /** Refuses what the hvm engine cannot apply, naming the option; the scj engine's checks come after. */
    public static void check(RunOptions o) throws BadInputException {
        if (o.warmupS > 0) {
            throw BadInputException.ofOption("--warmup", "the hvm engine has no warm-up (its executable replays the dataset once)");
        }
        if (o.spinUs > 0) {
            throw BadInputException.ofOption("--spin-us", "the hvm engine releases on the HVM's own clock tick, with no spin");
        }
        if (o.gcLog) {
            throw BadInputException.ofOption("--gc-log", "the hvm engine has no GC log (the HVM's memory is SCJ areas)");
        }
    }
}
