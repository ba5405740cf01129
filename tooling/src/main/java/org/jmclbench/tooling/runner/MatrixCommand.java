package org.jmclbench.tooling.runner;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Runs a matrix of runtimes x profiles x policies x particles x datasets x repetitions. */
@Command(name = "matrix", mixinStandardHelpOptions = true, description = "Runs a matrix of runtimes x profiles x policies x particles x datasets x repetitions.")
public final class MatrixCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: matrix: not built yet");
        return 1;
    }
}
