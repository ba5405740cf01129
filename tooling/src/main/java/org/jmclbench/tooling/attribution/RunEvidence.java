package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.JsonFiles;

/**
 * Everything one run folder says about its jobs and its runtime: the job lines of both tasks,
 * summary.json with its clock, and the runtime's events from the JFR recording or else the
 * GC log (looked for in the run folder, then in its parents, because the runner keeps the
 * recording beside the run tree: {@code runs/<run_key>/recording.jfr}).
 *
 * @param runDir      the run folder (holding summary.json and the job files)
 * @param summary     summary.json
 * @param clock       the run's clock, or null when summary.json has none (events cannot be placed)
 * @param jobs        every job of both tasks
 * @param events      the runtime's events on the run's timeline that the attribution uses ({@link EventSelection});
 *                    empty when none could be read
 * @param eventsRead  how many events were read, used or not
 * @param eventSource where the events came from, e.g. {@code JFR runs/ab12/recording.jfr}, or why there are none
 * @param eventProblem why the run's own event capture could not be read (its recording unreadable, no GC log beside
 *                    it), or null: the attribution then stands on its job lines alone, which explain notes and the
 *                    matrix does not store
 */
public record RunEvidence(Path runDir, JsonNode summary, RunClock clock, List<JobRecord> jobs, List<VmEvent> events,
        long eventsRead, String eventSource, String eventProblem) {

    /** Job file of each task, as FORMATS.md section 3 names them. */
    public static final String PREDICT_FILE = "odoData.txt";
    /** Job file of the update task. */
    public static final String UPDATE_FILE = "laserData.txt";
    /** Levels of the run tree below {@code runs/<run_key>/}: runtime, coverage, particles, policy, repetition. */
    private static final int RUN_TREE_DEPTH = 5;

    /**
     * Loads the run in {@code dir}: either the run folder itself, or a folder holding exactly
     * one run folder somewhere below it (such as the runner's {@code runs/<run_key>/}).
     */
    public static RunEvidence load(Path dir) throws IOException, BadUsageException {
        return load(dir, null);
    }

    /**
     * {@link #load(Path)} with the runtime's events read from {@code eventsFile} (a JFR recording
     * when its name ends in {@code .jfr}, else a GC log) instead of looked for by name; null looks.
     */
    public static RunEvidence load(Path dir, Path eventsFile) throws IOException, BadUsageException {
        if (eventsFile != null && !Files.isRegularFile(eventsFile)) {
            throw BadUsageException.ofOption("--events", eventsFile + ": no such file");
        }
        // Read as a GC log, any other text was a log of no events: the run explained without them, exit 0.
        if (eventsFile != null && !eventsFile.getFileName().toString().endsWith(".jfr") && !isGcLog(eventsFile)) {
            throw BadUsageException.ofOption("--events", eventsFile + ": neither a JFR recording (named .jfr) nor a GC log"
                    + " (no line of it is one a GC log writes)");
        }
        if (!Files.isDirectory(dir)) {
            throw new BadUsageException(dir + ": not a folder");
        }
        Path runDir = findRunDir(dir);
        JsonNode summary = JsonFiles.readObject(runDir.resolve("summary.json"), null);
        List<JobRecord> jobs = new ArrayList<>();
        for (String[] f : new String[][] {{PREDICT_FILE, "predict"}, {UPDATE_FILE, "update"}}) {
            Path p = runDir.resolve(f[0]);
            if (!Files.isRegularFile(p)) {
                throw new BadUsageException(p + ": missing");
            }
            List<JobRecord> task = JobFileReader.read(p, f[1]);
            // one line a released job (docs/FORMATS.md): a file cut at a line end read as a run with fewer jobs
            String mismatch = JobFileReader.releasedMismatch(p, task.size(), summary, f[1]);
            if (mismatch != null) {
                throw new BadUsageException(mismatch + " (a damaged run folder)");
            }
            jobs.addAll(task);
        }
        RunClock clock = RunClock.fromSummary(summary);
        List<VmEvent> events = List.of();
        long read = 0;
        String source;
        String problem = null;
        boolean given = eventsFile != null;
        boolean givenJfr = given && eventsFile.getFileName().toString().endsWith(".jfr");
        Path jfr = given ? (givenJfr ? eventsFile : null) : findUp(runDir, JfrFlags.RECORDING);
        Path gcLog = given ? (givenJfr ? null : eventsFile) : findUp(runDir, JfrFlags.GC_LOG);
        if (jfr == null && gcLog == null) {
            source = "none (no " + JfrFlags.RECORDING + " or " + JfrFlags.GC_LOG + " in the run folder or its parents; "
                    + "--events names another): only os, queued, preemption and compute can be told";
        } else if (clock == null) {
            source = "not used: summary.json has no \"clock\", so the runtime's events cannot be placed on the jobs' timeline";
        } else {
            EventSelection selection = EventSelection.forJobs(jfr != null ? jfr : gcLog, jobs);
            source = jfr != null ? "JFR " + jfr : "GC log " + gcLog;
            if (jfr != null && !readJfr(jfr, clock, selection)) {
                if (givenJfr) {
                    // the user's file, not a run's recording cut short by a crash: the run explained without it, exit 0
                    throw BadUsageException.ofOption("--events", jfr + ": not a JFR recording JFR can read");
                }
                source = "JFR " + jfr + " unreadable (the run may have crashed before dumping it)";
                // with no GC log to read instead, the attribution stands on the job lines alone
                problem = gcLog == null ? source : null;
                source += gcLog != null ? "; GC log " + gcLog : "";
                selection = EventSelection.forJobs(gcLog, jobs);
                jfr = null;
            }
            if (jfr == null && gcLog != null) {
                readGcLog(gcLog, clock, selection);
            }
            events = selection.events();
            read = selection.read();
            source += " (" + read + " events)";
        }
        return new RunEvidence(runDir, summary, clock, List.copyOf(jobs), events, read, source, problem);
    }

    /** The attributions of this run's missed and late jobs. */
    public List<JobAttribution> attribute(Attribution.Settings settings) {
        return Attribution.attribute(jobs, events, settings);
    }

    /**
     * Reads the recording into {@code selection}; false when JFR cannot read it (events read before
     * it stopped are dropped with it: the caller starts afresh).
     *
     * @throws BadUsageException when it holds more events than the harness keeps
     */
    private static boolean readJfr(Path jfr, RunClock clock, EventSelection selection) {
        try {
            JfrEventReader.read(jfr, clock, selection);
            return true;
        } catch (EventSelection.TooManyEvents e) {
            throw new BadUsageException(e.getMessage());
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /** Whether the file named with --events is a GC log; a runaway line before any GC line is bad input naming file:line. */
    private static boolean isGcLog(Path eventsFile) {
        try {
            return GcLogParser.isGcLog(eventsFile);
        } catch (IOException e) {
            throw BadUsageException.ofOption("--events", String.valueOf(e.getMessage()));
        }
    }

    /** Reads the GC log into {@code selection}; a runaway line or too many events is bad input naming file:line. */
    private static void readGcLog(Path gcLog, RunClock clock, EventSelection selection) {
        try {
            GcLogParser.parse(gcLog, clock, selection);
        } catch (IOException e) {
            throw new BadUsageException(String.valueOf(e.getMessage()));
        }
    }

    private static Path findRunDir(Path dir) throws IOException, BadUsageException {
        if (Files.isRegularFile(dir.resolve("summary.json"))) {
            return dir;
        }
        List<Path> found;
        try (Stream<Path> s = Files.find(dir, 8, (p, a) -> a.isRegularFile() && p.getFileName().toString().equals("summary.json"))) {
            found = s.map(Path::getParent).filter(p -> !p.getFileName().toString().endsWith(".partial")).sorted().toList();
        }
        if (found.isEmpty()) {
            throw new BadUsageException(dir + ": no run folder (summary.json) in it");
        }
        if (found.size() > 1) {
            throw new BadUsageException(dir + ": " + found.size() + " run folders in it; name one, e.g. " + found.get(0));
        }
        return found.get(0);
    }

    /**
     * {@code name} in the run folder or one of its five parents: the depth of the run tree below
     * the runner's {@code runs/<run_key>/}, which holds the recording. Whichever folder the user
     * named, the search never goes above that key folder; null when there is none.
     */
    private static Path findUp(Path runDir, String name) {
        Path p = runDir.toAbsolutePath().normalize();
        for (int level = 0; p != null && level <= RUN_TREE_DEPTH; level++, p = p.getParent()) {
            if (Files.isRegularFile(p.resolve(name))) {
                return p.resolve(name);
            }
        }
        return null;
    }
}
