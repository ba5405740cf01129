package org.jmclbench.tooling.runner;

import java.nio.file.Path;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * How one forked run ended, as the host saw it.
 *
 * @param status      ok | failed | timeout | unsupported
 * @param exitCode    the process's exit code (null when it never ran or was killed on timeout)
 * @param failure     one line saying what went wrong (null when ok)
 * @param stderrTail  the last lines of the run's stderr
 * @param leaf        the complete run folder (ok runs)
 * @param summaryText the run's summary.json verbatim (ok runs)
 */
public record ForkOutcome(String status, Integer exitCode, String failure, String stderrTail, double wallS,
                         Path leaf, String summaryText, JsonNode summary) {
}
