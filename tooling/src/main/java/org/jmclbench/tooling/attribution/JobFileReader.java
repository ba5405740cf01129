package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.BoundedLineReader;

import com.fasterxml.jackson.databind.JsonNode;

/** Reads job lines ({@code odoData.txt}, {@code laserData.txt}: docs/FORMATS.md section 3). */
public final class JobFileReader {
    private static final Set<String> OUTCOMES = Set.of("done", "late", "skipped", "terminated");

    private JobFileReader() {
    }

    /**
     * Why {@code task}'s job file, of {@code lines} job lines, disagrees with summary.json's count of
     * its released jobs (one line a released job), or null when it agrees or the summary has no
     * count: a file cut short, or a summary claiming jobs no line backs.
     */
    public static String releasedMismatch(Path file, int lines, JsonNode summary, String task) {
        JsonNode released = summary.path("tasks").path(task).path("released");
        return !released.canConvertToLong() || released.asLong() == lines ? null
                : file + ": " + lines + " job lines, but summary.json says " + released.asLong() + " " + task
                        + " jobs were released";
    }

    /** The jobs of one task from its job file; a malformed line is a {@link BadUsageException} naming file:line. */
    public static List<JobRecord> read(Path file, String task) throws IOException, BadUsageException {
        List<JobRecord> jobs = new ArrayList<>();
        // bounded lines: a runaway job file without line ends is refused at its line, not read whole
        try (BoundedLineReader r = new BoundedLineReader(file)) {
            String line;
            while ((line = readLine(r)) != null) {
                int n = r.lineNumber();
                String t = line.trim();
                if (t.isEmpty() || t.startsWith("#")) {
                    continue;
                }
                String[] f = t.split("\\s+");
                if (f.length < 7 || f.length > 9) {
                    throw BadUsageException.atLine(file.toString(), n, "expected 7 to 9 columns (index release_ns start_ns end_ns deadline_ns outcome cpu_ns [abort_ns [seen_ns]]), found " + f.length);
                }
                if (!OUTCOMES.contains(f[5])) {
                    throw BadUsageException.atLine(file.toString(), n, "unknown outcome '" + f[5] + "'");
                }
                try {
                    jobs.add(new JobRecord(task, Integer.parseInt(f[0]), Long.parseLong(f[1]), Long.parseLong(f[2]),
                            Long.parseLong(f[3]), Long.parseLong(f[4]), f[5], Long.parseLong(f[6])));
                } catch (NumberFormatException e) {
                    throw BadUsageException.atLine(file.toString(), n, "not an integer: " + e.getMessage());
                }
            }
        }
        return jobs;
    }

    private static String readLine(BoundedLineReader r) throws IOException {
        try {
            return r.readLine();
        } catch (IOException e) {
            // the line too long: bad input like any other malformed line (its message names file:line)
            throw new BadUsageException(e.getMessage());
        }
    }
}
