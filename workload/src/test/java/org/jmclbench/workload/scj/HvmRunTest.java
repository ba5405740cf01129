package org.jmclbench.workload.scj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

import org.jmclbench.workload.WorkloadMain;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code --engine hvm} run (the SCJ mission on the icecap HVM). The tests that run the VM
 * need its tool chain (HVM_SRC, see docs/HVM.md) and are skipped without it; the others do not.
 */
class HvmRunTest {
    /** As IdealCrossCheckTest (Java vs C): a larger difference is a real divergence. */
    private static final double TOL = 1e-9;

    @TempDir
    File tmp;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int main(String... args) {
        out.reset();
        err.reset();
        return WorkloadMain.run(args, new PrintStream(out), new PrintStream(err));
    }

    private String err() {
        return new String(err.toByteArray(), StandardCharsets.UTF_8);
    }

    private static File projectHome() {
        File dir = new File("").getAbsoluteFile();
        while (dir != null && !new File(dir, "hvm/build-mission.sh").isFile()) {
            dir = dir.getParentFile();
        }
        return dir;
    }

    /** Points the workload at the project (for hvm/build-mission.sh) and skips when the tool chain cannot be built here. */
    private static void assumeHvm() throws Exception {
        File home = projectHome();
        Assumptions.assumeTrue(home != null, "no hvm/ folder above the working directory");
        System.setProperty("jmclbench.home", home.getPath());
        Process p = new ProcessBuilder(new File(home, "hvm/build-hvm.sh").getPath(), "--check")
                .redirectErrorStream(true).start();
        String why = new String(readAll(p), StandardCharsets.UTF_8).trim();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "build-hvm.sh --check hung");
        Assumptions.assumeTrue(p.exitValue() == 0 && System.getenv("HVM_SRC") != null,
                "the icecap HVM cannot be built here (set HVM_SRC): " + why);
    }

    @Test
    void anAreaIsNamedByTheSizeIcecapReports() {
        long[] sizes = {1200000, 300000, 4096, 2000, 4096};
        String full = HvmRun.overflow("x\nout of memory: 0x000007D0, 0x00000C84\n", sizes);
        assertEquals("memory area 'update' overflowed on the HVM: an allocation of 3204 bytes did not fit its 2000"
                + " bytes (--area-size AREA=BYTES)", full);
        assertTrue(HvmRun.overflow("out of memory: 0x00001000, 0x00000010", sizes).contains("'predict or sensor'"));
        assertTrue(HvmRun.overflow("out of memory: 0x00000100, 0x00000010", sizes).contains("icecap-internal"));
        assertNull(HvmRun.overflow("warning: unimplemented function executed [0x02EB]", sizes));
    }

    @Test
    void badInputIsRejectedBeforeAnythingIsBuilt() throws Exception {
        // No build script under this home: reaching the build would be a failure (1), not bad input (2).
        System.setProperty("jmclbench.home", tmp.getPath());
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, false);
        File odo = new File(ds, "odometry.txt");
        List<String> lines = Files.readAllLines(odo.toPath(), StandardCharsets.UTF_8);
        int line = 0;
        for (int i = 0, rows = -1; i < lines.size(); i++) {
            if (!lines.get(i).startsWith("#") && ++rows == 10) {
                String[] t = lines.get(i).trim().split("\\s+");
                t[0] = String.format(Locale.ROOT, "%.16e", Double.parseDouble(t[0]) + 0.010);
                lines.set(i, String.join(" ", t));
                line = i + 1;
            }
        }
        Files.write(odo.toPath(), lines, StandardCharsets.UTF_8);
        File o = new File(tmp, "out");
        assertEquals(2, main("run", "--engine", "hvm", "--dataset", ds.getPath(), "-O", o.getPath()), err());
        assertTrue(err().startsWith("jmclbench: " + odo.getPath() + ":" + line + ": odometry is not periodic"), err());
        assertEquals(2, main("run", "--engine", "hvm", "--memory", "allocating", "--dataset", ds.getPath()), err());
        assertEquals(2, main("run", "--engine", "hvm", "--area-size", "nursery=100", "--dataset", ds.getPath()), err());
        assertFalse(o.exists() && o.list().length > 0, "nothing recorded");
    }

    @Test
    void aQueueRunAtLightLoadAgreesWithTheIdealRun() throws Exception {
        assumeHvm();
        // The first 3 s of match-short, replayed 8 times slower: the closest two events (0.29 ms
        // apart) are then more than two of the HVM's 1 ms ticks apart, so releases keep their order.
        File home = projectHome();
        File ds = new File(tmp, "ds");
        ds.mkdirs();
        String[] files = {"odometry.txt", "laser.txt", "real.txt"};
        for (String f : files) {
            List<String> keep = new ArrayList<>();
            for (String l : Files.readAllLines(new File(home, "data/match-short/" + f).toPath())) {
                if (!l.trim().isEmpty() && Double.parseDouble(l.trim().split("\\s+")[0]) <= 3.0) {
                    keep.add(l);
                }
            }
            Files.write(new File(ds, f).toPath(), keep);
        }
        String[] data = {"-odo", new File(ds, files[0]).getPath(), "-laser", new File(ds, files[1]).getPath(),
            "-real", new File(ds, files[2]).getPath()};
        File o = new File(tmp, "out");
        assertEquals(0, main(concat(new String[] {"run", "--ideal", "-p", "50", "-j", "ideal", "-O", o.getPath()}, data)),
                err());
        File ideal = new File(out.toString().trim());
        assertEquals(0, main(concat(new String[] {"run", "--engine", "hvm", "-p", "50", "--policy", "queue",
            "--time-scale", "8", "-O", o.getPath()}, data)), err());
        File hvm = new File(out.toString().trim());
        assertEquals(new File(o, "hvm/nocov/50/QueueTest/1").getPath(), hvm.getPath());
        String summary = new String(Files.readAllBytes(new File(hvm, "summary.json").toPath()), StandardCharsets.UTF_8);
        assertTrue(summary.contains("\"kind\": \"hvm\""), summary);

        // From the job records: until when did the jobs run in release order, each done before the next release?
        List<long[]> jobs = new ArrayList<>(); // release, start, end
        for (String f : new String[] {"odoData.txt", "laserData.txt"}) {
            for (String l : Files.readAllLines(new File(hvm, f).toPath())) {
                if (!l.startsWith("#")) {
                    String[] t = l.trim().split("\\s+");
                    assertEquals("done", t[5], "light load: every job done in time: " + l);
                    jobs.add(new long[] {Long.parseLong(t[1]), Long.parseLong(t[2]), Long.parseLong(t[3])});
                }
            }
        }
        jobs.sort((a, b) -> Long.compare(a[0], b[0]));
        double inOrderUntilS = Double.MAX_VALUE;
        for (int k = 0; k + 1 < jobs.size(); k++) {
            if (jobs.get(k)[2] > jobs.get(k + 1)[1]) {
                inOrderUntilS = jobs.get(k)[0] / 8e9;
                break;
            }
        }
        List<double[]> a = rows(new File(ideal, "position.txt"));
        List<double[]> b = rows(new File(hvm, "position.txt"));
        assertEquals(a.size(), b.size(), "position.txt line counts (ideal, hvm)");
        int compared = 0;
        for (int i = 0; i < a.size() && a.get(i)[0] < inOrderUntilS; i++, compared++) {
            for (int c = 1; c < a.get(i).length; c++) {
                double d = Math.abs(a.get(i)[c] - b.get(i)[c]);
                assertTrue(d <= TOL, "position.txt row " + (i + 1) + " column " + c + ": ideal " + a.get(i)[c]
                        + ", hvm " + b.get(i)[c]);
            }
        }
        assertTrue(compared >= a.size() / 2, "only " + compared + " of " + a.size()
                + " estimates before the first job that overlapped the next release");
    }

    @Test
    void aPrivateMemoryTooSmallFailsWithTheAreaNamed() throws Exception {
        assumeHvm();
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(1, main("run", "--engine", "hvm", "--memory", "scoped", "--area-size", "update=2000", "-p", "400",
                "--policy", "queue", "--dataset", ds.getPath(), "-O", o.getPath()), err());
        assertTrue(err().contains("memory area 'update' overflowed"), err());
        assertFalse(new File(o, "hvm/nocov/400/QueueTest/1/summary.json").exists(), "nothing recorded as valid");
    }

    private static String[] concat(String[] a, String[] b) {
        String[] c = new String[a.length + b.length];
        System.arraycopy(a, 0, c, 0, a.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }

    private static List<double[]> rows(File f) throws IOException {
        List<double[]> rows = new ArrayList<>();
        for (String l : Files.readAllLines(f.toPath())) {
            if (l.trim().isEmpty() || l.startsWith("#")) {
                continue;
            }
            String[] t = l.trim().split("\\s+");
            double[] r = new double[t.length];
            for (int i = 0; i < t.length; i++) {
                r[i] = Double.parseDouble(t[i]);
            }
            rows.add(r);
        }
        return rows;
    }

    private static byte[] readAll(Process p) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        byte[] buf = new byte[4096];
        for (int n; (n = p.getInputStream().read(buf)) > 0;) {
            b.write(buf, 0, n);
        }
        return b.toByteArray();
    }
}
