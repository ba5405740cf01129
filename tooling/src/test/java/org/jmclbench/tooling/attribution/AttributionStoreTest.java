package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AttributionStoreTest {

    @Test
    void storesRowsCauseCountsWarmupMetricsAndPauses(@TempDir Path tmp) throws Exception {
        Path run = ExplainCommandTest.runnerStyleRun(tmp, true);
        AttributionData data = AttributionData.of(run);
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + tmp.resolve("results.db"));
             Statement s = c.createStatement()) {
            s.execute("CREATE TABLE metrics (run_key TEXT, task TEXT, metric TEXT, stat TEXT, value REAL,"
                    + " PRIMARY KEY (run_key, task, metric, stat))");
            s.execute("CREATE TABLE series (run_key TEXT, name TEXT, json TEXT, PRIMARY KEY (run_key, name))");
            AttributionStore.write(c, "ab12", data);
            try (ResultSet rs = s.executeQuery("SELECT count(*) FROM attributions WHERE run_key = 'ab12'")) {
                assertEquals(data.rows().size(), rs.getInt(1));
            }
            try (ResultSet rs = s.executeQuery("SELECT value FROM metrics WHERE task = 'run' AND metric = 'cause.jobs'")) {
                assertEquals(data.rows().size(), rs.getInt(1));
            }
            try (ResultSet rs = s.executeQuery("SELECT value FROM metrics WHERE task = 'run' AND metric = 'cause.gc' AND stat = 'count'")) {
                assertTrue(rs.next() && rs.getInt(1) > 0);
            }
            try (ResultSet rs = s.executeQuery("SELECT sum(value) FROM metrics WHERE task = 'run' AND metric LIKE 'cause.%' AND stat = 'primary'")) {
                assertEquals(data.rows().size(), rs.getInt(1), "primary causes partition the attributed jobs");
            }
            try (ResultSet rs = s.executeQuery("SELECT value FROM metrics WHERE task = 'all' AND metric = 'missedOrLate.warm'")) {
                assertTrue(rs.next());
            }
            try (ResultSet rs = s.executeQuery("SELECT causes_json FROM attributions WHERE task = 'predict' AND job_index = 40")) {
                JsonNode j = new ObjectMapper().readTree(rs.getString(1));
                assertTrue(j.path("causes").toString().contains("\"kind\":\"compute\""), j.toString());
            }
            try (ResultSet rs = s.executeQuery("SELECT json FROM series WHERE name = 'pauses'")) {
                JsonNode j = new ObjectMapper().readTree(rs.getString(1));
                assertEquals("start", j.path("columns").get(0).asText());
                assertTrue(j.path("rows").size() > 10);
                boolean gc = false;
                for (JsonNode row : j.path("rows")) {
                    gc |= row.get(2).asText().equals("gc") && row.get(1).asDouble() >= row.get(0).asDouble();
                }
                assertTrue(gc, "GC pauses in the series");
            }
        }
    }
}
