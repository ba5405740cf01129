package org.jmclbench.tooling.report;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Compares two result sets, metric by metric, with significance. */
@Command(name = "compare", mixinStandardHelpOptions = true, description = "Compares two result sets, metric by metric, with significance.")
public final class CompareCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: compare: not built yet");
        return 1;
    }
}
