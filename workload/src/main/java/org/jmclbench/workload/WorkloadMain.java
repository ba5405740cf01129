package org.jmclbench.workload;

/** Entry point of the workload process: one test, configured by its command line. */
public final class WorkloadMain {
    private WorkloadMain() {
    }

    public static void main(String[] args) {
        System.err.println("jmclbench: run: not built yet");
        System.exit(1);
    }
}
