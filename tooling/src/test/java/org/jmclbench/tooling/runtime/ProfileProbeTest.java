package org.jmclbench.tooling.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.cli.BadUsageException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A flag the JVM rejects makes the profile unsupported (cached), never a crash. */
class ProfileProbeTest {

    @TempDir
    Path dir;

    @Test
    void fakeJvmRejectingShenandoahMarksOnlyThatUnsupported() throws Exception {
        Path java = Fixtures.fakeJava(dir, "jvm", "ok", 0, "-XX:+UseShenandoahGC", 21);
        RuntimeInfo rt = JvmProber.probe(java, new String[1]).orElseThrow();
        Path cache = dir.resolve("probes.properties");
        ProfileProbe probe = new ProfileProbe(cache);
        ProfileProbe.Support shen = probe.check(rt, Profile.parse("shenandoah+pretouch", "t"), "0");
        assertFalse(shen.supported());
        assertTrue(shen.reason().contains("Unrecognized VM option 'UseShenandoahGC'"), shen.reason());
        assertTrue(probe.check(rt, Profile.parse("g1", "t"), "0").supported());
        assertTrue(probe.check(rt, Profile.parse("zgc+pretouch", "t"), "0").supported());
        // the answers are cached on disk: a new probe does not ask again
        assertTrue(Files.readString(cache).contains("UseShenandoahGC"));
        ProfileProbe again = new ProfileProbe(cache);
        assertFalse(again.check(rt, Profile.parse("shenandoah+pretouch", "t"), "0").supported());
    }

    @Test
    void realJvmRejectsABogusFlag() {
        Path java = Path.of(ProcessHandle.current().info().command().orElseThrow());
        RuntimeInfo rt = JvmProber.probe(java, new String[1]).orElseThrow();
        assertEquals(Runtime.version().feature(), rt.major());
        ProfileProbe probe = new ProfileProbe(dir.resolve("p.properties"));
        ProfileProbe.Support bogus = probe.checkFlags(rt, List.of("-XX:+UseJmclbenchBogusFlag"));
        assertFalse(bogus.supported());
        assertTrue(bogus.reason().contains("UseJmclbenchBogusFlag"), bogus.reason());
        assertTrue(probe.checkFlags(rt, List.of("-XX:+UseSerialGC")).supported());
    }

    @Test
    void unsupportedProfileIsRecordedAsUnsupportedInTheMatrix() throws Exception {
        Fixtures.home(dir);
        Path fake = Fixtures.fakeJava(dir, "jvm", "ok", 0, "-XX:+UseShenandoahGC", 21);
        Path db = dir.resolve("out/r.db");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--profiles", "g1,shenandoah",
                "--datasets", "tiny", "--particles", "100", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("1 ok, 0 failed, 0 timed out, 1 unsupported"), r.out());
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + db); var s = c.createStatement();
             var rs = s.executeQuery("SELECT status, failure, run_dir FROM runs WHERE profile = 'shenandoah'")) {
            assertTrue(rs.next());
            assertEquals("unsupported", rs.getString(1));
            assertTrue(rs.getString(2).contains("UseShenandoahGC"));
        }
    }

    @Test
    void profilesParseAndBuildTheirFlags() {
        Profile p = Profile.parse("epsilon+pretouch+fifo+pinned", "--profiles");
        RuntimeInfo jvm = new RuntimeInfo("x-21", RuntimeKind.JVM, "x", "21", 21, Path.of("/j"), Path.of("/j"));
        LaunchPlan plan = LaunchPlan.of(jvm, p, "1");
        assertEquals(List.of("chrt", "-f", "80", "taskset", "-c", "1"), plan.prefix());
        assertEquals(List.of("-XX:+UnlockExperimentalVMOptions", "-XX:+UseEpsilonGC", "-XX:+AlwaysPreTouch",
                "-Xms2048m", "-Xmx2048m"), plan.jvmFlags());
        assertEquals(List.of("-XX:TieredStopAtLevel=1", "-XX:+AlwaysPreTouch", "-Xms512m", "-Xmx512m"),
                LaunchPlan.of(jvm, Profile.parse("c1+pretouch", "t"), "0").jvmFlags());
        RuntimeInfo jdk11 = new RuntimeInfo("x-11", RuntimeKind.JVM, "x", "11", 11, Path.of("/j"), Path.of("/j"));
        assertEquals(List.of("-XX:+UnlockExperimentalVMOptions", "-XX:+UseZGC"),
                LaunchPlan.of(jdk11, Profile.parse("zgc", "t"), "0").jvmFlags());
        assertEquals("fifo+pinned", p.effectiveFor(RuntimeKind.NATIVE).name());
        assertEquals("default", Profile.parse("g1+int", "t").effectiveFor(RuntimeKind.NATIVE).name());
        // the HVM keeps the OS components and int (its interpreter); compiled to C is its default
        Profile g1IntFifo = Profile.parse("g1+int+fifo", "t");
        assertEquals("int+fifo", g1IntFifo.effectiveFor(RuntimeKind.HVM).name());
        assertEquals("interpreted", g1IntFifo.effectiveFor(RuntimeKind.HVM).hvmMode());
        assertEquals("compiled", Profile.parse("g1+c1+pinned", "t").effectiveFor(RuntimeKind.HVM).hvmMode());
        assertEquals("pinned", Profile.parse("g1+c1+pinned", "t").effectiveFor(RuntimeKind.HVM).name());
        assertEquals("g1+int+fifo", g1IntFifo.effectiveFor(RuntimeKind.JVM).name());
        // hot (the hot methods compiled, the rest interpreted) is the HVM's alone: a JVM drops it
        Profile hot = Profile.parse("hot+pinned", "t");
        assertEquals("hot", hot.effectiveFor(RuntimeKind.HVM).hvmMode());
        assertEquals("hot+pinned", hot.effectiveFor(RuntimeKind.HVM).name());
        assertEquals("pinned", hot.effectiveFor(RuntimeKind.JVM).name());
        assertEquals("pinned", hot.effectiveFor(RuntimeKind.NATIVE).name());
        assertThrows(BadUsageException.class, () -> Profile.parse("int+hot", "t"), "two modes of the one JIT category");
        RuntimeInfo hvm = new RuntimeInfo("hvm", RuntimeKind.HVM, "icecap", "1", 0, Path.of("/j"), Path.of("/j"));
        assertEquals(List.of(), LaunchPlan.of(hvm, g1IntFifo.effectiveFor(RuntimeKind.HVM), "0").jvmFlags());
        assertThrows(BadUsageException.class, () -> Profile.parse("int+c1", "t"));
        assertThrows(BadUsageException.class, () -> Profile.parse("g1+", "t"));
        assertThrows(BadUsageException.class, () -> Profile.parse("fifo+fifo", "t"));
        assertEquals("zgc+fifo", Profile.parse(" zgc + fifo ", "t").name());
    }

    /** noidle is an OS setting: every runtime kind keeps it, and it adds no flag and no prefix. */
    @Test
    void noidleIsKeptByEveryRuntimeAndLaunchesNothingOfItsOwn() {
        Profile p = Profile.parse("g1+fifo+noidle", "t");
        assertEquals("fifo+noidle", p.effectiveFor(RuntimeKind.NATIVE).name());
        assertEquals("fifo+noidle", p.effectiveFor(RuntimeKind.HVM).name());
        RuntimeInfo jvm = new RuntimeInfo("x-21", RuntimeKind.JVM, "x", "21", 21, Path.of("/j"), Path.of("/j"));
        LaunchPlan plan = LaunchPlan.of(jvm, p, "1");
        assertEquals(List.of("chrt", "-f", "80"), plan.prefix());
        assertEquals(List.of("-XX:+UseG1GC"), plan.jvmFlags());
        assertThrows(BadUsageException.class, () -> Profile.parse("noidle+noidle", "t"));
    }
    @Test
    void heapSizeIsAProfileComponentOfJvmsOnly() {
        RuntimeInfo jvm = new RuntimeInfo("x-21", RuntimeKind.JVM, "x", "21", 21, Path.of("/j"), Path.of("/j"));
        assertEquals(List.of("-XX:+UseZGC", "-Xmx256m"), LaunchPlan.of(jvm, Profile.parse("zgc+heap256m", "t"), "0").jvmFlags());
        // with pretouch the heap is fixed at that size; Epsilon's 2048 MB gives way to the asked one
        assertEquals(List.of("-XX:+AlwaysPreTouch", "-Xms4096m", "-Xmx4096m"),
                LaunchPlan.of(jvm, Profile.parse("heap4g+pretouch", "t"), "0").jvmFlags());
        assertEquals(List.of("-XX:+UnlockExperimentalVMOptions", "-XX:+UseEpsilonGC", "-Xmx8192m"),
                LaunchPlan.of(jvm, Profile.parse("epsilon+heap8g", "t"), "0").jvmFlags());
        Profile p = Profile.parse("g1+heap1024m+fifo", "t");
        assertEquals("g1+heap1g+fifo", p.name(), "one size, one name");
        assertEquals(1024, p.heapMb());
        assertEquals("g1+heap1g+fifo", p.effectiveFor(RuntimeKind.JVM).name());
        assertEquals("fifo", p.effectiveFor(RuntimeKind.NATIVE).name());
        assertEquals(0, p.effectiveFor(RuntimeKind.NATIVE).heapMb());
        assertEquals("default", Profile.parse("heap64m", "t").effectiveFor(RuntimeKind.HVM).name());
        // a heap the JVM refuses is unsupported with HotSpot's reason, not its generic first line
        assertEquals("Too small maximum heap",
                ProfileProbe.firstMeaningfulLine("Error occurred during initialization of VM\nToo small maximum heap\n"));
        assertEquals("Error occurred during initialization of VM",
                ProfileProbe.firstMeaningfulLine("\nError occurred during initialization of VM\n"));
        for (String bad : List.of("heap1g+heap2g", "heap0m", "heap2000g", "heap9999999g", "heap512", "heap1t")) {
            BadUsageException e = assertThrows(BadUsageException.class, () -> Profile.parse(bad, "--profiles"), bad);
            assertTrue(e.getMessage().startsWith("--profiles: "), e.getMessage());
        }
    }
}
