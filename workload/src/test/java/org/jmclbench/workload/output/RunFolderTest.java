package org.jmclbench.workload.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.WorkloadMain;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The run folder (FORMATS 3): layout, files and columns, .partial staging, no overwrite without --force. */
class RunFolderTest {
    @TempDir
    File tmp;

    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int main(String... args) {
        err.reset();
        return WorkloadMain.run(args, new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
    }

    private String err() {
        return new String(err.toByteArray(), StandardCharsets.UTF_8);
    }

    private static List<String[]> rows(File f) throws IOException {
        List<String[]> rows = new ArrayList<>();
        for (String line : Files.readAllLines(f.toPath(), StandardCharsets.UTF_8)) {
            if (!line.startsWith("#")) {
                rows.add(line.trim().split("\\s+"));
            }
        }
        return rows;
    }

    @Test
    void anIdealRunWritesEveryFileWithItsColumns() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 4.0, 3, true, true);
        File out = new File(tmp, "out");
        assertEquals(0, main("run", "--ideal", "-p", "200", "--dataset", ds.getPath(), "-O", out.getPath(), "-j",
                "test-jvm", "-n", "4", "-c"), err());
        File dir = new File(out, "test-jvm/cov/200/IdealTest/4");
        assertTrue(dir.isDirectory());
        assertFalse(new File(out, "test-jvm/cov/200/IdealTest/4.partial").exists());
        Dataset d = DatasetReader.readFolder(ds);
        Timeline t = d.timeline();

        List<String[]> odo = rows(new File(dir, "odoData.txt"));
        assertEquals("# index release_ns start_ns end_ns deadline_ns outcome cpu_ns abort_ns seen_ns",
                Files.readAllLines(new File(dir, "odoData.txt").toPath()).get(0));
        assertEquals(t.predictCount(), odo.size());
        long previousEnd = -1;
        for (int i = 0; i < odo.size(); i++) {
            String[] r = odo.get(i);
            assertEquals(9, r.length);
            assertEquals(Integer.toString(i), r[0]);
            assertEquals("-1", r[7], "no abort in an ideal run");
            assertEquals("-1", r[8], "nothing to see in an ideal run");
            assertEquals("done", r[5]);
            assertEquals("-1", r[4]);
            long start = Long.parseLong(r[2]);
            long end = Long.parseLong(r[3]);
            assertTrue(start >= 0 && end >= start && start >= previousEnd, "times of the single thread");
            previousEnd = end;
        }
        List<String[]> laser = rows(new File(dir, "laserData.txt"));
        assertEquals(t.updateCount(), laser.size());
        assertEquals(9, laser.get(0).length);

        List<String[]> pos = rows(new File(dir, "position.txt"));
        assertEquals(d.realCount(), pos.size());
        assertEquals(4, pos.get(0).length);
        List<String[]> dev = rows(new File(dir, "positionDeviation.txt"));
        assertEquals(d.realCount(), dev.size());
        assertEquals(5, dev.get(0).length);
        double sum = 0;
        for (String[] r : dev) {
            double dx = Double.parseDouble(r[1]);
            double dy = Double.parseDouble(r[2]);
            assertEquals(Math.hypot(dx, dy), Double.parseDouble(r[3]), 1e-12);
            sum += Double.parseDouble(r[3]);
        }
        List<String[]> cov = rows(new File(dir, "covariance.txt"));
        assertEquals(t.updateCount(), cov.size());
        assertEquals(7, cov.get(0).length);
        assertTrue(Double.parseDouble(cov.get(5)[1]) >= 0, "cxx is a variance");

        List<String[]> data = rows(new File(dir, "data.txt"));
        String[] keys = {"deviationXY", "deviationX", "deviationY", "deviationAngle", "missCount",
            "averageReleaseJitter", "averageTaskTime"};
        assertEquals(keys.length, data.size());
        for (int i = 0; i < keys.length; i++) {
            assertEquals(keys[i], data.get(i)[0]);
            assertEquals(2, data.get(i).length);
        }
        assertEquals(sum / dev.size(), Double.parseDouble(data.get(0)[1]), 1e-12);
        assertEquals("0", data.get(4)[1]);

        String json = new String(Files.readAllBytes(new File(dir, "summary.json").toPath()), StandardCharsets.UTF_8);
        assertTrue(json.contains("\"schema\": \"jmclbench-run/1\""), json);
        assertTrue(json.contains("\"status\": \"complete\""));
        assertTrue(json.contains("\"ideal\": true"));
        assertTrue(json.contains("\"particles\": 200"));
        assertTrue(json.contains("\"released\": " + t.predictCount()));
        assertTrue(json.contains("\"released\": " + t.updateCount()));
        assertTrue(json.contains("\"released\": " + t.size()));
        assertTrue(json.contains("\"scenario\": \"synthetic\""));
        assertTrue(json.contains("\"dispatcherLatenessNs\": {\n    \"count\": 0,\n    \"mean\": null"), json);
        assertTrue(json.contains("\"p999\""));
    }

    @Test
    void thesisFilesWorkAndACompleteFolderIsNotOverwrittenWithoutForce() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "bare"), 2.0, 4, false, false);
        File out = new File(tmp, "out");
        String[] args = {"run", "--ideal", "-p", "100", "-odo", new File(ds, "odometry.txt").getPath(), "-laser",
            new File(ds, "laser.txt").getPath(), "-real", new File(ds, "real.txt").getPath(), "-O", out.getPath(),
            "-j", "jvm"};
        assertEquals(0, main(args), err());
        File dir = new File(out, "jvm/nocov/100/IdealTest/1");
        File summary = new File(dir, "summary.json");
        assertTrue(summary.isFile());
        assertFalse(new File(dir, "covariance.txt").exists());
        long written = summary.lastModified();
        Files.write(new File(dir, "marker").toPath(), new byte[0]);

        assertEquals(2, main(args));
        assertEquals("jmclbench: " + dir.getPath() + ": a complete run folder exists (use --force to overwrite)\n",
                err().replace("\r", ""));
        assertTrue(new File(dir, "marker").exists(), "left untouched");
        assertEquals(written, summary.lastModified());

        String[] forced = java.util.Arrays.copyOf(args, args.length + 1);
        forced[args.length] = "--force";
        assertEquals(0, main(forced), err());
        assertTrue(summary.isFile());
        assertFalse(new File(dir, "marker").exists(), "replaced by the new run");
        assertFalse(new File(dir.getParentFile(), "1.partial").exists());
        assertFalse(new File(dir.getParentFile(), "1.replaced.partial").exists());
    }

    @Test
    void aRunIsStagedInPartialUntilCommitted() throws Exception {
        File dir = new File(tmp, "o/rt/nocov/10/SkipTest/2");
        RunFolder f = new RunFolder(dir, false);
        File partial = f.begin();
        assertEquals(new File(tmp, "o/rt/nocov/10/SkipTest/2.partial"), partial);
        Files.write(new File(partial, "odoData.txt").toPath(), "x".getBytes(StandardCharsets.UTF_8));
        // A failure here leaves only the .partial folder: nothing complete-looking.
        assertFalse(dir.exists());
        // A new attempt starts from an empty .partial.
        File again = new RunFolder(dir, false).begin();
        assertEquals(0, again.list().length);
        Files.write(new File(again, "data.txt").toPath(), "y".getBytes(StandardCharsets.UTF_8));
        new RunFolder(dir, false).commit();
        assertTrue(new File(dir, "data.txt").isFile());
        assertFalse(partial.exists());
        assertThrows(BadInputException.class, () -> new RunFolder(dir, false).begin());
    }

    @Test
    void aFailingRunLeavesNoCompleteFolder() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds2"), 1.0, 5, false, true);
        File out = new File(tmp, "out2");
        // The output root is a file: the run cannot write (bad usage, exit 2), and nothing appears.
        Files.write(out.toPath(), new byte[0]);
        int code = main("run", "--ideal", "-p", "10", "--dataset", ds.getPath(), "-O", out.getPath());
        assertEquals(2, code, err());
        assertTrue(err().startsWith("jmclbench: -O: cannot create "), err());
        assertEquals(1, err().trim().split("\n").length, err());
        assertTrue(out.isFile());
    }

    @Test
    void warmupDoesNotChangeTheIdealRunsResult() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds3"), 3.0, 6, true, true);
        File out = new File(tmp, "out3");
        assertEquals(0, main("run", "--ideal", "-p", "150", "--dataset", ds.getPath(), "-O", out.getPath(), "-j",
                "j", "-n", "1"), err());
        assertEquals(0, main("run", "--ideal", "-p", "150", "--dataset", ds.getPath(), "-O", out.getPath(), "-j",
                "j", "-n", "2", "--warmup", "2", "--gc-log"), err());
        // JDK 9+ turns the GC log on at run time; the tests run on 17 or later.
        assertTrue(new File(out, "j/nocov/150/IdealTest/2/gc.log").isFile());
        File a = new File(out, "j/nocov/150/IdealTest/1/position.txt");
        File b = new File(out, "j/nocov/150/IdealTest/2/position.txt");
        assertEquals(Files.readAllLines(a.toPath()), Files.readAllLines(b.toPath()));
        String summary = new String(Files.readAllBytes(new File(out, "j/nocov/150/IdealTest/2/summary.json")
                .toPath()), StandardCharsets.UTF_8);
        assertTrue(summary.contains("\"warmupS\": 2.0"), summary);
    }
}
