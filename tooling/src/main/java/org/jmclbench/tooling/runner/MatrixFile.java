package org.jmclbench.tooling.runner;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * Reads a matrix file: one {@code key = value} a line, the keys being the long options of
 * {@code matrix} without their dashes ({@link MatrixOptions#SETTINGS});
 * list values are comma-separated and a repeated list key adds to the list; {@code #} starts a comment.
 * Errors name {@code file:line}.
 *
 * <pre>
 * # two JVMs and C, three sizes, three repetitions
 * runtimes  = temurin-25, native
 * profiles  = g1, zgc+pretouch
 * engines   = javase, scj
 * policies  = skip, terminate
 * particles = 100, 400, 1600
 * datasets  = match-short
 * repeat    = 3
 * </pre>
 */
public final class MatrixFile {
    private MatrixFile() {
    }

    /** Adds the file's settings to {@code spec}. */
    public static void read(Path file, MatrixSpec spec) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new BadUsageException("--matrix: " + file + ": cannot read (" + e.getClass().getSimpleName() + ")");
        }
        int n = 0;
        java.util.Map<String, Integer> oneValue = new java.util.HashMap<>(); // key -> its line
        for (String raw : lines) {
            n++;
            String where = file + ":" + n;
            String line = raw.strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            Setting s = Setting.parse(line, where, "'key = value'");
            MatrixOptions.apply(spec, s.key(), s.value(), where);
            // a second value would silently replace the first, where the command line refuses it
            boolean list = MatrixOptions.SETTINGS.stream().anyMatch(x -> x.key().equals(s.key()) && x.list());
            Integer first = list ? null : oneValue.putIfAbsent(s.key(), n);
            if (first != null) {
                throw new BadUsageException(where + ": " + s.key() + ": set twice (also at line " + first + ")");
            }
        }
    }

    /** One {@code key = value} line of a matrix file, and where it stands (file:line) for messages. */
    record Setting(String key, String value, String where) {
        /**
         * The stripped line {@code line} as a setting, or bad usage naming {@code where}: no key, or
         * an empty value ({@code expected} says what the file's lines may be).
         */
        static Setting parse(String line, String where, String expected) {
            int eq = line.indexOf('=');
            if (eq <= 0) {
                throw new BadUsageException(where + ": expected " + expected);
            }
            String key = line.substring(0, eq).strip();
            String value = line.substring(eq + 1).strip();
            if (value.isEmpty()) {
                throw new BadUsageException(where + ": " + key + ": empty value");
            }
            return new Setting(key, value, where);
        }
    }
}
