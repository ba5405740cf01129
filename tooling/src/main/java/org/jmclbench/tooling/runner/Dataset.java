package org.jmclbench.tooling.runner;

import java.io.IOException;
import java.io.InputStream;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.data.DatasetMetadata;
import org.jmclbench.workload.data.DatasetReader;

/**
 * A dataset folder given to a matrix by name ({@code match-short}: the project's {@code data/})
 * or by path, with what the runner needs of it: a label, its duration (for the timeout) and a
 * digest of its content (part of the run key, so that changed data is a new configuration).
 */
public record Dataset(String label, Path dir, double durationS, String digest) {

    static final String[] FILES = {"odometry.txt", "laser.txt", "real.txt"};

    /** Resolves {@code nameOrPath} against {@code home/data}; {@code where} names the option or file:line. */
    public static Dataset resolve(String nameOrPath, Path home, String where) {
        boolean isName = !nameOrPath.contains("/") && !nameOrPath.equals(".") && !nameOrPath.equals("..");
        Path dir = isName ? home.resolve("data").resolve(nameOrPath) : Path.of(nameOrPath).toAbsolutePath().normalize();
        if (!Files.isDirectory(dir)) {
            throw new BadUsageException(where + ": dataset '" + nameOrPath + "': no such folder " + dir);
        }
        for (String f : FILES) {
            if (!Files.isRegularFile(dir.resolve(f))) {
                throw new BadUsageException(where + ": dataset '" + nameOrPath + "': missing " + dir.resolve(f));
            }
        }
        try {
            // read here, once, as the workload and the native baseline read it (one grammar, docs/FORMATS.md 1):
            // a bad line would otherwise fail every run of the dataset, each recorded failed, and the matrix exit 0
            DatasetReader.readFolder(dir.toFile());
        } catch (BadInputException e) {
            throw new BadUsageException(where + ": dataset '" + nameOrPath + "': " + e.getMessage());
        }
        String label = dir.getFileName().toString();
        return new Dataset(label, dir, duration(dir), digest(dir));
    }

    /** {@code duration} of dataset.properties, else the last odometry time. */
    static double duration(Path dir) {
        Path props = dir.resolve("dataset.properties");
        if (Files.isRegularFile(props)) {
            // the workload's reader (docs/FORMATS.md 1.2): one grammar for the file everywhere
            try (InputStream in = Files.newInputStream(props)) {
                String d = DatasetMetadata.read(in, props.toString()).properties.getProperty("duration");
                if (d != null) {
                    double v = Double.parseDouble(d.strip());
                    if (v > 0 && Double.isFinite(v)) {
                        return v;
                    }
                }
            } catch (IOException | BadInputException | NumberFormatException ignored) {
                // fall back to the data itself; the workload reports a bad file
            }
        }
        return lastTime(dir.resolve("odometry.txt"));
    }

    private static double lastTime(Path file) {
        try (RandomAccessFile f = new RandomAccessFile(file.toFile(), "r")) {
            long len = f.length();
            long from = Math.max(0, len - 4096);
            byte[] tail = new byte[(int) (len - from)];
            f.seek(from);
            f.readFully(tail);
            String[] lines = new String(tail, StandardCharsets.UTF_8).split("\n");
            for (int i = lines.length - 1; i >= 0; i--) {
                String l = lines[i].strip();
                if (!l.isEmpty() && !l.startsWith("#")) {
                    return Math.max(0, Double.parseDouble(l.split("\\s+")[0]));
                }
            }
        } catch (IOException | NumberFormatException ignored) {
            // the workload will report the bad file itself
        }
        return 0;
    }

    private static String digest(Path dir) {
        try {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            for (String f : FILES) {
                md.update(Files.readAllBytes(dir.resolve(f)));
            }
            return HexFormat.of().formatHex(md.digest()).substring(0, 16);
        } catch (IOException | NoSuchAlgorithmException e) {
            throw new BadUsageException("dataset " + dir + ": cannot read (" + e.getMessage() + ")");
        }
    }
}
