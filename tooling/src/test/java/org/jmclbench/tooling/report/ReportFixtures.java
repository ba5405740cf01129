package org.jmclbench.tooling.report;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** The fixture databases shared by the report's tests. */
final class ReportFixtures {

    /** A runtime name that would run script if the page ever put it into HTML unescaped. */
    static final String XSS_RUNTIME = "<script>alert(1)</script>";

    private ReportFixtures() {
    }

    /**
     * Four runtimes with completed runs (native, two JVMs, one hostile name), one whose flag is
     * not supported, one that crashed; skip and terminate; 100/400/1600 particles; 3 repetitions.
     */
    static FixtureDb mixed() {
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(List.of(
                new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("temurin-17", "g1", "17.0.15+6", 1.3, "ok"),
                new FixtureDb.Config("temurin-25", "zgc", "25+36", 1.15, "ok"),
                new FixtureDb.Config(XSS_RUNTIME, "g1", "<img src=x onerror=alert(3)>", 1.4, "ok"),
                new FixtureDb.Config("temurin-11", "shenandoah", "11.0.25", 1.2, "unsupported"),
                new FixtureDb.Config("crashy", "", "1.0", 1.2, "failed")));
        f.repetitions = 3;
        f.durationS = 12;
        return f;
    }

    /** One run: the first runtime of the default fixture, skip, 400 particles, one repetition. */
    static FixtureDb oneRun() {
        FixtureDb f = new FixtureDb();
        f.configs = List.of(f.configs.get(0));
        f.policies = List.of("skip");
        f.particles = List.of(400);
        f.repetitions = 1;
        return f;
    }

    /** The labels of {@link #engines()}: the engine and memory style are part of each JVM row's name. */
    static final String JAVASE = "temurin-25/g1 / javase preallocated";
    static final String JAVASE_ALLOCATING = "temurin-25/g1 / javase allocating";
    static final String SCJ = "temurin-25/g1 / scj preallocated";
    static final String SCJ_SCOPED = "temurin-25/g1 / scj scoped";
    static final String NATIVE = "native / preallocated";

    /**
     * The memory-model experiment: one JVM with the Java SE engine (preallocated, allocating) and
     * the SCJ engine (preallocated, scoped), and native; skip; 100 and 400 particles; 2 repetitions.
     */
    static FixtureDb engines() {
        FixtureDb f = new FixtureDb();
        f.configs = memoryModels("g1");
        f.policies = List.of("skip");
        f.particles = List.of(100, 400);
        f.repetitions = 2;
        f.durationS = 6;
        return f;
    }

    /**
     * A breakdown search's store: the default runtimes under queue at 10, 100 and 400 particles,
     * 3 repetitions; every runtime has a late job at some count, some in one repetition only.
     */
    static FixtureDb breakdown() {
        FixtureDb f = new FixtureDb();
        f.policies = List.of("queue");
        f.particles = List.of(10, 100, 400);
        f.durationS = 6;
        return f;
    }

    /**
     * native, and temurin-25 under {@code profile} with both engines and their four memory
     * styles (Java SE preallocated and allocating, SCJ preallocated and scoped).
     */
    static List<FixtureDb.Config> memoryModels(String profile) {
        return new ArrayList<>(List.of(
                new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("temurin-25", profile, "25+36", 1.15, "ok", "javase", "preallocated"),
                new FixtureDb.Config("temurin-25", profile, "25+36", 1.3, "ok", "javase", "allocating"),
                new FixtureDb.Config("temurin-25", profile, "25+36", 1.2, "ok", "scj", "preallocated"),
                new FixtureDb.Config("temurin-25", profile, "25+36", 1.25, "ok", "scj", "scoped")));
    }

    static Path write(FixtureDb f, Path dir, String name) throws Exception {
        Path db = dir.resolve(name);
        f.write(db);
        return db;
    }
}
