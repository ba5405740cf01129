package org.jmclbench.hvm.launcher;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.File;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;
import org.jmclbench.workload.scj.ScjRun;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.workload.output.MemoryArea;

/**
 * The {@code --engine hvm} run: the SCJ mission compiled by the icecap HVM into a native
 * executable (hvm/build-mission.sh, cached). This side validates the options and dataset as
 * the scj engine does (before anything is built or started), writes them as a run file of
 * 64-bit words, runs the executable under a timeout, and reads its job records back from a
 * result file; doubles cross as raw IEEE 754 bits both ways. A crash, a hang, an overflowing
 * memory area or missing records is that run's {@link RunFailure}. Layouts: docs/HVM.md.
 */
public final class HvmRun {
    /**
     * The hang timeout is this many times the replay's length plus {@link #TIMEOUT_MARGIN_S}: an
     * overloaded queue run ends after its backlog, and the VM's single thread shares the CPU
     * with the machine's other work (a loaded 2-core VM ran a 20 s replay for over 80 s).
     */
    static final long TIMEOUT_FACTOR = 4;
    /** Beyond the replay itself: start-up and write-out (the executable is built before). */
    static final long TIMEOUT_MARGIN_S = 120;
    /** Sets another margin (seconds): a slower machine may need more, a test of a hang less. */
    static final String TIMEOUT_MARGIN_PROPERTY = "jmclbench.hvm.marginS";
    /** How much of each end of hvm.log is read back (the file itself stays whole in the run folder). */
    static final int LOG_END_BYTES = 256 * 1024;
    // icecap's message when an area cannot hold an allocation: "out of memory: 0x<area size>, 0x<bytes>"
    private static final Pattern OUT_OF_MEMORY = Pattern.compile("out of memory: 0x([0-9A-Fa-f]+), 0x([0-9A-Fa-f]+)");

    private HvmRun() {
    }

    /** Builds (or takes from the cache) the executable, runs the mission on the dataset and returns its records. */
    static EngineResult run(RunOptions options, Dataset dataset, File runFolder, PrintStream err)
            throws RunFailure, IOException {
        MissionConfiguration config = ScjRun.configuration(options, options.mclConfig(), options.timeScale, true);
        long[] sizes = areaSizes(config, dataset);
        File exe = build(err);

        File work = Files.createTempDirectory("jmclbench-hvm").toFile();
        try {
            File in = new File(work, "run.bin");
            File out = new File(work, "result.bin");
            File log = new File(runFolder, "hvm.log");
            writeInput(in, options, config, dataset);
            long timeoutS = (long) Math.ceil(TIMEOUT_FACTOR * dataset.duration() * options.timeScale)
                    + Long.getLong(TIMEOUT_MARGIN_PROPERTY, TIMEOUT_MARGIN_S);
            ProcessBuilder pb = new ProcessBuilder(exe.getPath());
            pb.environment().put("JMCLBENCH_HVM_INPUT", in.getPath());
            pb.environment().put("JMCLBENCH_HVM_OUTPUT", out.getPath());
            pb.redirectErrorStream(true).redirectOutput(log);
            long started = System.nanoTime();
            Process p = pb.start();
            boolean ended;
            try {
                ended = p.waitFor(timeoutS, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                p.destroyForcibly();
                Thread.currentThread().interrupt();
                throw new RunFailure("interrupted while the HVM ran");
            }
            if (!ended) {
                p.destroyForcibly();
                throw new RunFailure("the HVM executable did not end within " + timeoutS + " s (hung); log: " + log);
            }
            long wallNs = System.nanoTime() - started;
            String output = logEnds(log);
            String overflow = overflow(output, sizes);
            if (overflow != null) {
                throw new RunFailure(overflow);
            }
            if (p.exitValue() != 0 || !out.isFile()) {
                throw new RunFailure("the HVM executable failed (exit status " + p.exitValue() + "): "
                        + lastLines(output, 3) + " (log: " + log + ")");
            }
            HvmResultFile.AreaUse use = new HvmResultFile.AreaUse();
            JobRecords records = readRecords(out, dataset, options.covariance, use);
            List<MemoryArea> areas = new ArrayList<>();
            for (int a = 0; a < MissionSizes.AREA_COUNT; a++) {
                areas.add(use.area(a, sizes[a]));
            }
            return new EngineResult(records, areas, new HvmFacts(exe, wallNs));
        } finally {
            deleteTree(work);
        }
    }

    /**
     * The sizes the executable gives icecap: the mission's, plus icecap's own infrastructure in
     * immortal memory and the handlers' stacks in mission memory (unless set with --area-size).
     */
    static long[] areaSizes(MissionConfiguration config, Dataset d) {
        return MissionRunFile.icecapSizes(config, new MissionSizes(config, d.odometryCount(), d.laserCount()));
    }

    /** The area icecap reported full, named by its size; null when no area overflowed. */
    static String overflow(String output, long[] sizes) {
        Matcher m = OUT_OF_MEMORY.matcher(output);
        if (!m.find()) {
            return null;
        }
        long size = Long.parseLong(m.group(1), 16);
        long needed = Long.parseLong(m.group(2), 16);
        StringBuilder names = new StringBuilder();
        for (int a = 0; a < sizes.length; a++) {
            if (sizes[a] == size) {
                names.append(names.length() == 0 ? "" : " or ").append(MissionSizes.AREA_NAMES[a]);
            }
        }
        String area = names.length() == 0 ? "of " + size + " bytes (an icecap-internal area)" : "'" + names + "'";
        return "memory area " + area + " overflowed on the HVM: an allocation of " + needed
                + " bytes did not fit its " + size + " bytes (--area-size AREA=BYTES)";
    }

    /**
     * HVM_SRC as {@code hvm/build-hvm.sh --check} judges it, before the run folder is begun: one
     * that is not an hvm-scj folder or tarball is bad input (the script's exit 2, its line the
     * message), not the run's failure. A machine that cannot build the tool chain (exit 1) is left
     * to {@link #build}, as is a home without the script.
     */
    static void checkSource() throws BadInputException {
        String home = System.getProperty("jmclbench.home", ".");
        File script = new File(new File(home, "hvm"), "build-hvm.sh");
        if (!script.isFile()) {
            return;
        }
        try {
            Process p = new ProcessBuilder(script.getPath(), "--check").redirectErrorStream(true).start();
            String out;
            try (InputStream s = p.getInputStream()) {
                out = new String(readAll(s), StandardCharsets.UTF_8).trim();
            }
            if (p.waitFor() == 2) {
                String line = out.substring(out.lastIndexOf('\n') + 1);
                throw new BadInputException(line.startsWith("build-hvm: ") ? line.substring("build-hvm: ".length()) : line);
            }
        } catch (IOException e) {
            // the build runs the script again and reports what stops it
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static File build(PrintStream err) throws RunFailure, IOException {
        String home = System.getProperty("jmclbench.home", ".");
        File script = new File(new File(home, "hvm"), "build-mission.sh");
        if (!script.isFile()) {
            throw new RunFailure("no " + script + " (the hvm engine needs the jmclbench source tree)");
        }
        ProcessBuilder pb = new ProcessBuilder(script.getPath()).redirectError(ProcessBuilder.Redirect.INHERIT);
        Process p = pb.start();
        String path;
        try (InputStream s = p.getInputStream()) {
            path = new String(readAll(s), StandardCharsets.UTF_8).trim();
        }
        int status;
        try {
            status = p.waitFor();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RunFailure("interrupted while building the HVM executable");
        }
        if (status != 0 || path.isEmpty() || !new File(path).canExecute()) {
            throw new RunFailure("cannot build the HVM executable (hvm/build-mission.sh exit status " + status
                    + "; HVM_SRC=" + System.getenv("HVM_SRC") + ")");
        }
        return new File(path);
    }

    /** The run file: filter, policy, time scale, area sizes set, then the dataset (docs/HVM.md). */
    static void writeInput(File f, RunOptions o, MissionConfiguration config, Dataset d) throws IOException {
        MclConfig mcl = config.mcl;
        try (OutputStream os = new BufferedOutputStream(new FileOutputStream(f))) {
            LittleEndian w = new LittleEndian(os);
            // In the word order of MissionRunFile's positions, MAGIC_WORD to TIME_SCALE.
            w.word(MissionRunFile.INPUT_MAGIC);
            w.word(MissionRunFile.VERSION);
            w.word(mcl.particles);
            w.word(MissionRunFile.code(mcl.estimate));
            w.word(MissionRunFile.code(mcl.resample));
            w.word(MissionRunFile.code(mcl.init));
            w.word(MissionRunFile.code(mcl.memory));
            w.word(mcl.seed);
            w.word(mcl.covariance ? 1 : 0);
            w.word(mcl.pollInterval);
            w.word(config.policy.code);
            w.real(config.timeScale);
            for (int a = 0; a < MissionSizes.AREA_COUNT; a++) {
                w.word(config.areaSize(a));
            }
            w.word(d.odometryCount());
            w.word(d.laserCount());
            w.real(d.playground.width);
            w.real(d.playground.height);
            w.word(d.playground.beaconCount());
            for (double x : d.playground.beaconX) {
                w.real(x);
            }
            for (double y : d.playground.beaconY) {
                w.real(y);
            }
            w.real(d.startX);
            w.real(d.startY);
            w.real(d.startTheta);
            for (double[] column : new double[][] {d.odoTime, d.odoDx, d.odoDy, d.odoDtheta, d.laserTime, d.laserAngle}) {
                for (double v : column) {
                    w.real(v);
                }
            }
        }
    }

    /** The result file's records (docs/HVM.md), checked by {@link HvmResultFile}; each area's use into {@code use}. */
    static JobRecords readRecords(File f, Dataset d, boolean covariance, HvmResultFile.AreaUse use) throws RunFailure, IOException {
        try (InputStream is = new BufferedInputStream(new FileInputStream(f))) {
            return HvmResultFile.read(is, f.getPath(), d.timeline(), covariance, use);
        }
    }

    /**
     * The log's first and last {@link #LOG_END_BYTES} (all of it when shorter), what lies between
     * said in a line: icecap's overflow message and the lines a failure quotes stand at the end,
     * and an executable that floods its output must not take the run's JVM with it.
     */
    static String logEnds(File log) throws IOException {
        try (RandomAccessFile f = new RandomAccessFile(log, "r")) {
            long size = f.length();
            if (size <= 2L * LOG_END_BYTES) {
                return new String(read(f, 0, (int) size), StandardCharsets.UTF_8);
            }
            return new String(read(f, 0, LOG_END_BYTES), StandardCharsets.UTF_8) + "\n[" + (size - 2L * LOG_END_BYTES)
                    + " bytes of hvm.log left out]\n" + new String(read(f, size - LOG_END_BYTES, LOG_END_BYTES), StandardCharsets.UTF_8);
        }
    }

    private static byte[] read(RandomAccessFile f, long from, int length) throws IOException {
        byte[] b = new byte[length];
        f.seek(from);
        f.readFully(b);
        return b;
    }

    /**
     * The last {@code n} lines that say something, joined by " | ": blank lines and control
     * characters (the NUL padding of a log written past a hole) are passed over.
     */
    private static String lastLines(String s, int n) {
        Deque<String> said = new ArrayDeque<>();
        String[] lines = s.split("\n");
        for (int i = lines.length - 1; i >= 0 && said.size() < n; i--) {
            String line = lines[i].replaceAll("\\p{Cntrl}", "").trim();
            if (!line.isEmpty()) {
                said.addFirst(line);
            }
        }
        return said.isEmpty() ? "(no output)" : String.join(" | ", said);
    }

    private static byte[] readAll(InputStream s) throws IOException {
        java.io.ByteArrayOutputStream b = new java.io.ByteArrayOutputStream();
        byte[] buf = new byte[8192];
        for (int n; (n = s.read(buf)) > 0;) {
            b.write(buf, 0, n);
        }
        return b.toByteArray();
    }

    private static void deleteTree(File f) {
        File[] children = f.listFiles();
        if (children != null) {
            for (File c : children) {
                deleteTree(c);
            }
        }
        f.delete();
    }

    /** 64-bit little-endian words; a double as its raw bits. */
    static final class LittleEndian {
        private final DataOutputStream out;

        LittleEndian(OutputStream os) {
            out = new DataOutputStream(os);
        }

        void word(long v) throws IOException {
            out.writeLong(Long.reverseBytes(v));
        }

        void real(double v) throws IOException {
            word(Double.doubleToRawLongBits(v));
        }
    }
}
