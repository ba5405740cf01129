package org.jmclbench.tooling.store;

/**
 * One row of {@code runs}: a finished run (ok or not) with its configuration and outcome.
 *
 * @param status ok | failed | timeout | unsupported
 * @param runDir the run's folder relative to the database's folder (null when nothing ran)
 * @param engine javase | scj | native (later hvm): what ran the workload
 * @param memory the memory style: preallocated | allocating | scoped
 * @param codeVersion the jmclbench commit that made the run ({@link org.jmclbench.tooling.cli.CodeVersion}); null when unknown
 */
public record RunRow(String runKey, String matrixId, String machineId, String runtime, String runtimeVersion,
                        String profile, String policy, int particles, String dataset, String load, int repetition,
                        String status, Integer exitCode, String failure, String stderrTail, String startedAt,
                        String endedAt, Double wallS, String runDir, String summaryJson, long seed, String commandJson,
                        String engine, String memory, String codeVersion) {

    public static final String OK = "ok";
    public static final String FAILED = "failed";
    public static final String TIMEOUT = "timeout";
    public static final String UNSUPPORTED = "unsupported";
}
