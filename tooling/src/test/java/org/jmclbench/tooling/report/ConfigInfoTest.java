package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What the page says of a configuration beside its results: its flags, not the harness's paths. */
class ConfigInfoTest {

    @Test
    void aJvmsFlagsAreItsProfilesWithTheHarnesssRecordingNamedNotItsPaths(@TempDir Path dir) throws Exception {
        Path db = ReportFixtures.write(ReportFixtures.mixed(), dir, "results.db");
        ReportModel model;
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            model = ReportModel.build(store, line -> { });
        }
        ReportModel.ConfigInfo zgc = model.configs.stream().filter(c -> c.id().equals("temurin-25/zgc")).findFirst().orElseThrow();
        // every run records a JFR file of its own: three lines of paths a runtime, the same for all
        assertEquals(List.of("-XX:+UseZGC", "-Xms256m", "-XX:StartFlightRecording (jmclbench's recording, for the causes of misses)"),
                zgc.flags());
        ReportModel.ConfigInfo c = model.configs.stream().filter(x -> x.id().equals("native")).findFirst().orElseThrow();
        assertTrue(c.flags().contains("--seed"), "the C baseline's argv stays whole: " + c.flags());
    }
}
