package org.jmclbench.tooling.generator;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Generates a dataset with the robot simulator. */
@Command(name = "generate", mixinStandardHelpOptions = true, description = "Generates a dataset with the robot simulator.")
public final class GenerateCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: generate: not built yet");
        return 1;
    }
}
