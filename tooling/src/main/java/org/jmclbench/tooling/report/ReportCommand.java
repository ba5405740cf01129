package org.jmclbench.tooling.report;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Builds the HTML report from the results database. */
@Command(name = "report", mixinStandardHelpOptions = true, description = "Builds the HTML report from the results database.")
public final class ReportCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: report: not built yet");
        return 1;
    }
}
