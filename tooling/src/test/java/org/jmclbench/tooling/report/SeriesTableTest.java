package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;

import org.junit.jupiter.api.Test;

/** Series as the runner stores them: columns found by name, nulls and text skipped, peaks kept. */
class SeriesTableTest {

    static final String LATENCY = "{\"columns\":[\"index\",\"releaseS\",\"taskLatencyNs\",\"responseTimeNs\",\"outcome\"],"
            + "\"rows\":[[0,0.0,1000000,1200000,\"done\"],[1,0.05,null,null,\"skipped\"],[2,0.1,9000000,9100000,\"late\"],"
            + "[3,0.15,2000000,2100000,\"done\"],[4,0.2,3000000,3000000,\"done\"]]}";

    @Test
    void columnsByNameIgnoringCaseAndPunctuation() {
        SeriesTable t = SeriesTable.parse(LATENCY);
        assertEquals(2, t.column("latencyNs", "task_latency_ns"));
        assertEquals(0, t.column("INDEX"));
        assertEquals(-1, t.column("nothing"));
        assertNull(SeriesTable.parse("{\"rows\":[]}"));
        assertNull(SeriesTable.parse("not json"));
    }

    @Test
    void peakPointsKeepTheSlowestJobOfEachBucketAndSkipMissingValues() {
        SeriesTable t = SeriesTable.parse(LATENCY);
        List<double[]> all = t.peakPoints(0, 1, 2, 1e-6, 10);
        assertEquals(4, all.size(), "the skipped job has no latency");
        List<double[]> two = t.peakPoints(0, 1, 2, 1e-6, 2);
        assertEquals(2, two.size());
        assertArrayEquals(new double[] {2, 9}, two.get(0), 1e-12, "bucket 0..2 keeps its 9 ms job");
        assertArrayEquals(new double[] {4, 3}, two.get(1), 1e-12);
    }

    @Test
    void roundingKeepsSixSignificantDigits() {
        assertEquals(1.23457, SeriesTable.round(1.234567891), 0);
        assertEquals(0.000123457, SeriesTable.round(0.0001234567), 1e-15);
        assertEquals(0.0, SeriesTable.round(0.0), 0);
    }
}
