package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;

/** Bad input is one line naming the option or file:line, exit code 2, and nothing run or recorded. */
class BadInputTest extends FakeJvmHome {

    private void assertRejected(String expected, String... args) {
        Fixtures.CliResult r = Fixtures.cli(args);
        assertEquals(2, r.exitCode(), r.out() + r.err());
        String err = r.err().strip();
        assertEquals(1, err.lines().count(), "one line: " + err);
        assertTrue(err.startsWith("jmclbench: "), err);
        assertTrue(err.contains(expected), err + " should contain " + expected);
        assertFalse(Files.exists(db), "nothing may be recorded");
        assertFalse(Files.exists(dir.resolve("out/runs")), "nothing may run");
    }

    /** {@link #assertRejected} for {@code matrix} on the fake JVM, the tiny dataset unless given, and the test's store. */
    private void assertMatrixRejected(String expected, String... options) {
        List<String> args = new ArrayList<>(List.of("matrix", "--java", fake.toString()));
        args.addAll(List.of(options));
        if (!args.contains("--datasets")) {
            args.addAll(List.of("--datasets", "tiny"));
        }
        args.addAll(List.of("--db", db.toString()));
        assertRejected(expected, args.toArray(new String[0]));
    }

    @Test
    void aDatasetWithABadLineIsRefusedBeforeAnythingRuns() throws Exception {
        // every run of the dataset exited 2 and was recorded failed, and the matrix exited 0
        Path bad = dir.resolve("data/bad");
        Files.createDirectories(bad);
        for (String f : new String[] {"odometry.txt", "laser.txt", "real.txt", "dataset.properties"}) {
            Files.copy(dir.resolve("data/tiny").resolve(f), bad.resolve(f));
        }
        List<String> odometry = new ArrayList<>(Files.readAllLines(bad.resolve("odometry.txt")));
        odometry.set(2, "1.0e-01  garbage  0.0");
        Files.write(bad.resolve("odometry.txt"), odometry);
        assertMatrixRejected("--datasets: dataset 'bad': " + bad.resolve("odometry.txt") + ":3: expected 4 columns but found 3",
                "--datasets", "tiny,bad");
    }

    @Test
    void aFileWhereTheRunFoldersGoLeavesNoStoreBehind() throws Exception {
        // the refusal came after the store was created: an empty results.db stayed beside the file
        Files.createDirectories(db.getParent());
        Path runs = Files.writeString(db.resolveSibling("runs"), "a file");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--datasets", "tiny", "--db", db.toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().startsWith("jmclbench: --db: " + db + ": cannot write its run folders in " + db.getParent()), r.err());
        assertFalse(Files.exists(db), "no store left behind");
        assertEquals("a file", Files.readString(runs));
    }

    @Test
    void whatAnIdealRunRefusesIsRefusedByTheMatrixThatPlansOne() {
        // the workload refuses --ideal with a spin or SCJ area sizes (exit 2): each ideal run of the
        // matrix would have been recorded failed
        assertMatrixRejected("--workload-arg: --spin-us: an ideal run has no releases to spin before (--ideal) (the javase"
                + " ideal runs)", "--policies", "skip,ideal", "--workload-arg", "--spin-us 50");
        assertMatrixRejected("--workload-arg: --area-size: an ideal run has no SCJ memory areas (--ideal) (the scj ideal runs)",
                "--policies", "ideal", "--engines", "scj", "--workload-arg", "--area-size=mission=100000");
        assertMatrixRejected("--workload-arg: --spin-us: an ideal run has no releases", "--policies", "ideal",
                "--workload-arg", "--spin-us=+7");
    }

    @Test
    void aWorkloadArgAnEngineRefusesIsRefusedBeforeAnythingRuns() {
        // each run of the engine would have exited 2 and been recorded failed, one by one
        assertMatrixRejected("--workload-arg: --gc-log: the scj engine writes no GC log (only javase does) (the scj skip runs)",
                "--engines", "javase,scj", "--workload-arg", "--gc-log");
        assertMatrixRejected("--workload-arg: --bogus: unknown option (see --help) (the javase skip runs)",
                "--workload-arg", "--bogus");
        assertMatrixRejected("--workload-arg: --warmup: not a number: 'soon'", "--workload-arg", "--warmup soon");
        assertMatrixRejected("--workload-arg: --rtsj-design: chooses the rtsj engine's design: needs --engine rtsj",
                "--workload-arg", "--rtsj-design=atomic");
        // the load scenario is the matrix's: a --load-alloc of the workload's own would run under a load not recorded
        assertMatrixRejected("--workload-arg: '--load-alloc' is set by the runner", "--workload-arg", "--load-alloc 10,1");
    }

    @Test
    void unknownProfile() {
        assertMatrixRejected("--profiles: unknown profile component 'g2'", "--profiles", "g1,g2+fifo");
    }

    @Test
    void conflictingProfile() {
        assertMatrixRejected("two gc settings: g1 and zgc", "--profiles", "g1+zgc");
    }

    @Test
    void unknownRuntime() {
        assertMatrixRejected("--runtimes: unknown runtime 'nosuch-99'", "--runtimes", "nosuch-99");
    }

    @Test
    void pathThatIsNotAJvm() throws Exception {
        Path notJvm = dir.resolve("not-java");
        Files.writeString(notJvm, "#!/bin/sh\necho hello\n");
        notJvm.toFile().setExecutable(true);
        assertRejected("--java: " + notJvm + ": not a JVM", "matrix", "--java", notJvm.toString(),
                "--datasets", "tiny", "--db", db.toString());
        assertRejected("--java: /no/such/java: not a JVM (no such file)", "matrix", "--java", "/no/such/java",
                "--datasets", "tiny", "--db", db.toString());
    }

    @Test
    void badMatrixFileNamesFileAndLine() throws Exception {
        Path m = dir.resolve("m.properties");
        Files.writeString(m, "# a matrix\nprofiles = g1\nparticles = 100, many\n");
        assertMatrixRejected(m + ":3: particles: 'many' is not a positive integer", "--matrix", m.toString());
        Files.writeString(m, "profiles = g1\npolicies = skip,\n");
        assertMatrixRejected(m + ":2: policies: empty item in 'skip,'", "--matrix", m.toString());
        Files.writeString(m, "repeat = 2\nparticles = 100\nparticles = 200\nrepeat = 3\n");
        assertMatrixRejected(m + ":4: repeat: set twice (also at line 1)", "--matrix", m.toString());
        Files.writeString(m, "profiles = g1\n\ncolour = blue\n");
        assertMatrixRejected(m + ":3: unknown key 'colour'", "--matrix", m.toString());
        Files.writeString(m, "java = " + fake + "\nprofiles = g1\nruntimes = fake-21, nosuch-1\ndatasets = tiny\n");
        assertRejected(m + ":3: runtimes: unknown runtime 'nosuch-1'", "matrix", "--matrix", m.toString(),
                "--db", db.toString());
        Files.writeString(m, "java = " + fake + "\nprofiles = g1\nthis line has no equals sign\n");
        assertRejected(m + ":3: expected 'key = value'", "matrix", "--matrix", m.toString(), "--db", db.toString());
        assertRejected("--matrix: " + dir.resolve("missing") + ": cannot read", "matrix", "--matrix",
                dir.resolve("missing").toString(), "--db", db.toString());
    }

    @Test
    void badOptionValues() {
        assertMatrixRejected("--particles: '0' is not a positive integer", "--particles", "100,0");
        // a trailing empty item is as empty as one between commas (',' alone ran the default 400)
        assertMatrixRejected("--particles: empty item in '100,'", "--particles", "100,");
        assertMatrixRejected("--particles: empty item in ','", "--particles", ",");
        assertMatrixRejected("--load-alloc: '100,16,' must be MBPS,LIVEMB", "--load-alloc", "100,16,");
        // planning a repetition count this large never ended (the last one overflowed the loop)
        assertMatrixRejected("--repeat: '2147483647' is more than 10000 repetitions", "--repeat", "2147483647");
        assertMatrixRejected("--policies: unknown policy 'drop'", "--policies", "skip,drop");
        assertMatrixRejected("--shard: '3/2' is not a shard", "--shard", "3/2");
        assertMatrixRejected("--datasets: dataset 'nosuch': no such folder", "--datasets", "nosuch");
        assertMatrixRejected("--workload-arg: empty value", "--workload-arg", " ");
        assertMatrixRejected("--workload-arg: '--seed' is set by the runner", "--workload-arg", "--seed 3");
        // the workload's range, refused before the matrix rather than by each of its runs
        assertMatrixRejected("--time-scale: '1e-9' is out of range [1e-6, 1000]", "--time-scale", "1e-9");
    }

    @Test
    void databaseThatIsNotOne() throws Exception {
        Files.createDirectories(db.getParent());
        Files.writeString(db, "not a database, just text that happens to sit here");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--datasets", "tiny", "--db", db.toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertTrue(r.err().strip().startsWith("jmclbench: --db: " + db + ": not a usable results store"), r.err());
        assertEquals("not a database, just text that happens to sit here", Files.readString(db));
        assertFalse(Files.exists(dir.resolve("out/runs")));
    }

    /**
     * A dry run shows what the run would do: a store the run would refuse (its folder below a file, a
     * file that is no SQLite database, a database without the runs table) is refused by the dry run too,
     * with the run's own line, and nothing is created or changed.
     */
    @Test
    void aDryRunRefusesTheDatabaseTheRunWouldRefuse() throws Exception {
        Path file = Files.writeString(dir.resolve("a-file"), "text");
        Path below = file.resolve("results.db");
        Path text = Files.writeString(dir.resolve("text.db"), "not a database, just text that happens to sit here");
        Path other = dir.resolve("other.db");
        try (java.sql.Connection c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + other);
             java.sql.Statement s = c.createStatement()) {
            s.execute("CREATE TABLE notes (text TEXT)");
        }
        byte[] otherBytes = Files.readAllBytes(other);
        Path m = Files.writeString(dir.resolve("e.txt"), "datasets = tiny\n[a]\nruntimes = native\n");
        String[][] refused = {
            {below.toString(), "--db: " + below + ": cannot write there (" + file + " is a file)"},
            {text.toString(), "--db: " + text + ": not a usable results store ("},
            {other.toString(), "--db: " + other + ": not a usable results store (no runs table)"},
        };
        for (String[] r : refused) {
            Fixtures.CliResult run = Fixtures.cli("matrix", "--java", fake.toString(), "--datasets", "tiny", "--db", r[0]);
            assertEquals(2, run.exitCode(), run.out() + run.err());
            assertTrue(run.err().strip().startsWith("jmclbench: " + r[1]), run.err());
            for (String[] dryRun : List.of(
                    new String[] {"matrix", "--dry-run", "--java", fake.toString(), "--datasets", "tiny", "--db", r[0]},
                    new String[] {"evaluate", "--dry-run", "--matrix", m.toString(), "--db", r[0]})) {
                Fixtures.CliResult dry = Fixtures.cli(dryRun);
                assertEquals(2, dry.exitCode(), dryRun[0] + ": " + dry.out() + dry.err());
                assertEquals(run.err().strip(), dry.err().strip(), dryRun[0] + " --dry-run refuses as the run does");
                assertFalse(dry.out().contains("planned") || dry.out().contains("budget"), "no plan for a refused store: " + dry.out());
            }
        }
        assertEquals("text", Files.readString(file));
        assertEquals("not a database, just text that happens to sit here", Files.readString(text));
        assertArrayEquals(otherBytes, Files.readAllBytes(other), "a dry run changes nothing");
        assertFalse(Files.exists(dir.resolve("out/runs")), "nothing may run");
    }

    /**
     * The hvm runtime on a machine where its tool chain checks out but the mission's executable does
     * not build (stand-in build scripts that write down each build): a dry run plans and builds
     * nothing; a run fails (exit 1, the build's failure is not bad usage) in one line naming where
     * hvm was asked for, with nothing recorded; a build that refuses its input (exit 2) is bad input.
     */
    @Test
    void aDryRunBuildsNoHvmExecutableAndAFailingBuildNamesTheRuntimesOption() throws Exception {
        Path builds = dir.resolve("builds");
        Path hvm = Files.createDirectories(dir.resolve("hvm"));
        script(hvm.resolve("build-hvm.sh"), "echo 'build-hvm: can be built (cached: /c/hvm/toolchain-ab)' >&2\n");
        script(hvm.resolve("build-mission.sh"), "echo \"$*\" >> '" + builds + "'\n"
                + "echo 'build-mission: compiling the mission for the HVM' >&2\n"
                + "echo \"build-mission: the mission does not compile against icecap's SCJ library\" >&2\nexit 1\n");

        Fixtures.CliResult dry = Fixtures.cli("matrix", "--runtimes", "hvm", "--profiles", "default,int", "--datasets", "tiny",
                "--dry-run", "--db", db.toString());
        assertEquals(0, dry.exitCode(), dry.out() + dry.err());
        assertTrue(dry.out().startsWith("2 runs planned"), dry.out());
        assertFalse(Files.exists(builds), "a dry run builds nothing");
        assertFalse(Files.exists(db));

        String failed = ": hvm: the HVM executable (compiled) cannot be built: build-mission: the mission does not compile"
                + " against icecap's SCJ library (./jmclbench doctor; docs/HVM.md)";
        // it was exit 2, as if the user had asked for something wrong
        assertBuildFailed("jmclbench: matrix: --runtimes" + failed, "matrix", "--runtimes", "hvm", "--datasets", "tiny",
                "--db", db.toString());
        assertEquals("--mode compiled", Files.readString(builds).strip(), "the run builds before it records anything");
        Path m = Files.writeString(dir.resolve("m.properties"), "datasets = tiny\nruntimes = hvm\n");
        assertBuildFailed("jmclbench: matrix: " + m + ":2: runtimes" + failed, "matrix", "--matrix", m.toString(),
                "--db", db.toString());

        script(hvm.resolve("build-mission.sh"), "echo 'build-hvm: HVM_SRC=/no/such.tar.gz: no such file or folder' >&2\nexit 2\n");
        assertRejected("jmclbench: --runtimes: hvm: the HVM executable (compiled) cannot be built: build-hvm: HVM_SRC="
                + "/no/such.tar.gz: no such file or folder", "matrix", "--runtimes", "hvm", "--datasets", "tiny", "--db", db.toString());
    }

    /**
     * What the hvm engine refuses beyond the scj engine's checks is refused when a matrix of hvm
     * runs plans, dry or not: a --warmup was planned and each hvm run exited 2, recorded failed.
     */
    @Test
    void whatTheHvmEngineRefusesIsRefusedByTheMatrixThatPlansItsRuns() throws Exception {
        Path hvm = Files.createDirectories(dir.resolve("hvm"));
        script(hvm.resolve("build-hvm.sh"), "echo 'build-hvm: can be built (cached: /c/hvm/toolchain-ab)' >&2\n");
        script(hvm.resolve("build-mission.sh"), "exit 1\n");
        String refused = "jmclbench: --workload-arg: --warmup: the hvm engine has no warm-up (its executable replays"
                + " the dataset once) (the hvm skip runs)";
        assertRejected(refused, "matrix", "--runtimes", "hvm", "--datasets", "tiny", "--workload-arg=--warmup=1",
                "--dry-run", "--db", db.toString());
        assertRejected(refused, "matrix", "--runtimes", "hvm", "--datasets", "tiny", "--workload-arg", "--warmup 0.5",
                "--db", db.toString());
        // the scj engine, which the hvm cells were checked as, has a warm-up: its runs are planned
        Fixtures.CliResult scj = Fixtures.cli("matrix", "--java", fake.toString(), "--engines", "scj", "--datasets", "tiny",
                "--workload-arg=--warmup=0.5", "--dry-run", "--db", db.toString());
        assertEquals(0, scj.exitCode(), scj.out() + scj.err());
    }

    /** The command failed (exit 1) with {@code line} alone on stderr, and nothing ran or was recorded. */
    private void assertBuildFailed(String line, String... args) {
        Fixtures.CliResult r = Fixtures.cli(args);
        assertEquals(1, r.exitCode(), r.out() + r.err());
        assertEquals(line, r.err().strip());
        assertFalse(Files.exists(db), "nothing may be recorded");
        assertFalse(Files.exists(dir.resolve("out/runs")), "nothing may run");
    }

    private static void script(Path file, String body) throws Exception {
        Files.writeString(file, "#!/bin/sh\n" + body);
        Files.setPosixFilePermissions(file, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    @Test
    void aMatrixOfOneRunSaysOneRun() {
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--profiles", "g1", "--particles", "100",
                "--policies", "skip", "--datasets", "tiny", "--dry-run", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().startsWith("1 run planned,"), r.out());
    }

    @Test
    void matrixFileAndCommandLineCombine() throws Exception {
        Path m = dir.resolve("m.properties");
        Files.writeString(m, "java = " + fake + "\nprofiles = g1, zgc\nparticles = 100\nparticles = 200\n"
                + "policies = skip\ndatasets = tiny\nrepeat = 2\n");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--matrix", m.toString(), "--particles", "300", "--dry-run",
                "--db", db.toString());
        assertEquals(0, r.exitCode(), r.err());
        // 2 profiles x 1 size (the command line replaced the file's two) x 2 repetitions
        assertTrue(r.out().startsWith("4 runs planned"), r.out());
        assertTrue(r.out().contains("fake-21 zgc skip 300p tiny #2"), r.out());
        assertFalse(Files.exists(db));
    }
}
