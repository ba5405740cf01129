package org.jmclbench.tooling.generator;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * Writes a simulated run as a dataset folder (docs/FORMATS.md section 1). The files are
 * written into a hidden temporary folder beside the target and moved into place only when
 * all are complete, so no half dataset is ever left under the target's name.
 */
public final class DatasetWriter {
    /** The files a dataset folder consists of. */
    public static final Set<String> FILES = Set.of("odometry.txt", "laser.txt", "real.txt", "dataset.properties");
    /** The metadata's format tag. */
    public static final String FORMAT = "jmclbench-dataset/1";
    /** The generator's version tag; bump it when the same inputs would give other files. */
    public static final String GENERATOR = "jmclbench-generator/1";

    private DatasetWriter() {
    }

    /**
     * Writes the dataset into {@code out}. An existing non-empty {@code out} is replaced only
     * with {@code force}, and only when it holds nothing but dataset files.
     */
    public static void write(SimulatedRun run, Path out, boolean force) throws BadUsageException, IOException {
        Path target = out.toAbsolutePath().normalize();
        Path parent = target.getParent();
        if (parent == null) {
            throw BadUsageException.ofOption("--out", "cannot write a dataset at " + out);
        }
        if (target.equals(Path.of("").toAbsolutePath().normalize())) {
            // an empty --out or '.' names the working folder: replacing it leaves the caller's shell in a deleted folder
            throw BadUsageException.ofOption("--out", "'" + out + "' is the working folder; name the dataset's folder (e.g. data/NAME)");
        }
        checkTarget(target, out, force);
        Files.createDirectories(parent);
        Path partial = newFolder(parent, "." + target.getFileName() + ".partial-");
        try {
            writeFiles(run, partial);
            if (Files.exists(target)) {
                Path old = Files.createTempDirectory(parent, "." + target.getFileName() + ".old-");
                Files.delete(old);
                Files.move(target, old, StandardCopyOption.ATOMIC_MOVE);
                Files.move(partial, target, StandardCopyOption.ATOMIC_MOVE);
                deleteTree(old);
            } else {
                Files.move(partial, target, StandardCopyOption.ATOMIC_MOVE);
            }
        } finally {
            if (Files.exists(partial)) {
                deleteTree(partial);
            }
        }
    }

    /**
     * A new uniquely named folder with the permissions any new folder gets (the umask's), not the owner-only
     * ones of a temporary directory: the dataset is read by whoever runs the workload.
     */
    private static Path newFolder(Path parent, String prefix) throws IOException {
        java.util.Random random = new java.security.SecureRandom();
        while (true) {
            try {
                return Files.createDirectory(parent.resolve(prefix + Long.toUnsignedString(random.nextLong(), 36)));
            } catch (java.nio.file.FileAlreadyExistsException e) {
                // that name is taken: draw another
            }
        }
    }

    private static void checkTarget(Path target, Path shown, boolean force) throws BadUsageException, IOException {
        if (!Files.exists(target)) {
            return;
        }
        if (!Files.isDirectory(target)) {
            throw BadUsageException.ofOption("--out", shown + " exists and is not a folder");
        }
        boolean empty = true;
        boolean onlyDataset = true;
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(target)) {
            for (Path p : entries) {
                empty = false;
                if (!FILES.contains(p.getFileName().toString()) || !Files.isRegularFile(p)) {
                    onlyDataset = false;
                }
            }
        }
        if (empty) {
            return;
        }
        if (!force) {
            throw BadUsageException.ofOption("--out", shown + " is not empty (--force replaces a dataset folder)");
        }
        if (!onlyDataset) {
            throw BadUsageException.ofOption("--out", shown + " holds files that are not a dataset's; not replacing it");
        }
    }

    /** Writes the four files of the dataset into an existing folder. */
    public static void writeFiles(SimulatedRun run, Path dir) throws IOException {
        writeTable(dir.resolve("odometry.txt"), run.odometry());
        writeTable(dir.resolve("laser.txt"), run.laser());
        writeTable(dir.resolve("real.txt"), run.real());
        StringBuilder sb = new StringBuilder();
        sb.append("# jmclbench dataset, see docs/FORMATS.md section 1\n");
        for (Map.Entry<String, String> e : metadata(run).entrySet()) {
            sb.append(e.getKey()).append('=').append(e.getValue()).append('\n');
        }
        Files.writeString(dir.resolve("dataset.properties"), sb.toString(), StandardCharsets.UTF_8);
    }

    /** The metadata keys and values, in the order they are written. */
    public static Map<String, String> metadata(SimulatedRun run) {
        Scenario s = run.scenario();
        SensorNoise n = run.noise();
        Map<String, String> m = new LinkedHashMap<>();
        m.put("format", FORMAT);
        m.put("scenario", s.name());
        m.put("seed", Long.toString(run.seed()));
        m.put("generator", GENERATOR);
        m.put("duration", Double.toString(run.duration()));
        m.put("playground.width", Double.toString(run.playground().width()));
        m.put("playground.height", Double.toString(run.playground().height()));
        m.put("beacons", run.playground().beaconsProperty());
        m.put("start.x", Double.toString(s.start().x()));
        m.put("start.y", Double.toString(s.start().y()));
        m.put("start.theta", number(s.start().theta()));
        m.put("odometry.period", Double.toString(1.0 / Simulator.ODOMETRY_RATE));
        m.put("odometry.noise.alphaXY", Double.toString(n.alphaXY()));
        m.put("odometry.noise.floorXY", Double.toString(n.floorXY()));
        m.put("odometry.noise.alphaTheta", Double.toString(n.alphaTheta()));
        m.put("odometry.noise.alphaThetaXY", Double.toString(n.alphaThetaXY()));
        m.put("odometry.noise.floorTheta", Double.toString(n.floorTheta()));
        m.put("laser.rps", Double.toString(Simulator.LASER_RPS));
        m.put("laser.phase", number(run.turretPhase()));
        m.put("laser.noise", Double.toString(n.laserSigma()));
        m.put("laser.missProbability", Double.toString(n.missProbability()));
        m.put("simulation.step", Double.toString(1.0 / (Simulator.ODOMETRY_RATE * Simulator.STEPS_PER_ODOMETRY)));
        // only a kidnapping the data contain: one at or after the end never happened in them
        if (s.kidnap() != null && s.kidnap().time() < run.duration()) {
            m.put("kidnap.time", Double.toString(s.kidnap().time()));
            m.put("kidnap.x", Double.toString(s.kidnap().pose().x()));
            m.put("kidnap.y", Double.toString(s.kidnap().pose().y()));
            m.put("kidnap.theta", number(s.kidnap().pose().theta()));
        }
        return m;
    }

    /** A number as every data file writes it: {@code %.16e}, locale-independent. */
    public static String number(double v) {
        return String.format(Locale.ROOT, "%.16e", v);
    }

    private static void writeTable(Path file, double[][] rows) throws IOException {
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            StringBuilder sb = new StringBuilder(128);
            for (double[] row : rows) {
                sb.setLength(0);
                for (int i = 0; i < row.length; i++) {
                    if (i > 0) {
                        sb.append("  ");
                    }
                    sb.append(number(row[i]));
                }
                sb.append('\n');
                out.write(sb.toString());
            }
        }
    }

    private static void deleteTree(Path root) throws IOException {
        try (Stream<Path> walk = Files.walk(root)) {
            walk.sorted(Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.delete(p);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }
}
