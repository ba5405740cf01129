package org.jmclbench.tooling.runtime;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Lists the JVMs found on this machine and the profiles each supports. */
@Command(name = "jvms", mixinStandardHelpOptions = true, description = "Lists the JVMs found on this machine and the profiles each supports.")
public final class JvmsCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: jvms: not built yet");
        return 1;
    }
}
