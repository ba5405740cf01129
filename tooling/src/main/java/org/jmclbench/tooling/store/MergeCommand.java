package org.jmclbench.tooling.store;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Merges result databases from several machines. */
@Command(name = "merge", mixinStandardHelpOptions = true, description = "Merges result databases from several machines.")
public final class MergeCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: merge: not built yet");
        return 1;
    }
}
