package org.jmclbench.tooling.runner;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Runs the default comparison: every JVM and native, skip and terminate, 100/400/1600 particles. */
@Command(name = "quick", mixinStandardHelpOptions = true, description = "Runs the default comparison: every JVM and native, skip and terminate, 100/400/1600 particles.")
public final class QuickCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: quick: not built yet");
        return 1;
    }
}
