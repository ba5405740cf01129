package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.store.MachineInfo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Plans: every combination once, native keeps only OS components, shards partition, order from the seed. */
class PlannerTest {

    @TempDir
    Path dir;

    private ResolvedMatrix plan(String... kv) throws Exception {
        MatrixSpec spec = new MatrixSpec();
        for (int i = 0; i < kv.length; i += 2) {
            MatrixOptions.apply(spec, kv[i], kv[i + 1], "--" + kv[i]);
        }
        return MatrixPlanner.resolve(spec, () -> RuntimeDiscovery.discover(List.of(), null), dir, MachineInfo.current());
    }

    @Test
    void nativeKeepsOnlySchedulingAndPinningAndDropsDuplicates() throws Exception {
        Fixtures.home(dir);
        Path nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21);
        ResolvedMatrix m = plan("java", Fixtures.fakeJava(dir, "jvm", "ok", 0, null, 21).toString(),
                "native", nat.toString(), "runtimes", "native", "profiles", "g1,zgc,g1+fifo,zgc+fifo",
                "datasets", "tiny", "particles", "100,400");
        long jvmRuns = m.plan().stream().filter(r -> r.runtime().isJvm()).count();
        List<String> nativeProfiles = m.plan().stream().filter(r -> !r.runtime().isJvm())
                .map(r -> r.profile().name()).distinct().sorted().toList();
        assertEquals(4 * 2, jvmRuns);
        assertEquals(List.of("default", "fifo"), nativeProfiles);
        assertEquals(2 * 2, m.plan().size() - jvmRuns);
    }

    @Test
    void aSpinIsPlannedWhereNoRunIsIdeal() throws Exception {
        Fixtures.home(dir);
        String jvm = Fixtures.fakeJava(dir, "jvm", "ok", 0, null, 21).toString();
        assertEquals(1, plan("java", jvm, "profiles", "g1", "policies", "skip", "datasets", "tiny", "particles", "100",
                "workload-arg", "--spin-us 50").plan().size());
        // a spin of 0 is none: the workload takes it with --ideal
        assertEquals(1, plan("java", jvm, "profiles", "g1", "policies", "ideal", "datasets", "tiny", "particles", "100",
                "workload-arg", "--spin-us 0").plan().size());
    }

    @Test
    void eachCellsWorkloadOptionsAreCheckedAsItsEngineWillCheckThem() throws Exception {
        Fixtures.home(dir);
        String jvm = Fixtures.fakeJava(dir, "jvm", "ok", 0, null, 21).toString();
        String nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21).toString();
        // javase spins before a release, the scj engine refuses to: each scj run would have exited 2, recorded failed
        BadUsageException e = assertThrows(BadUsageException.class, () -> plan("java", jvm, "engines", "javase,scj",
                "datasets", "tiny", "workload-arg", "--spin-us 50"));
        assertEquals("--workload-arg: --spin-us: the scj engine does not spin before a release (only javase does)"
                + " (the scj skip runs)", e.getMessage());
        // the C baseline has no SCJ areas: --area-size is unknown to it, though the scj engine takes it
        e = assertThrows(BadUsageException.class, () -> plan("java", jvm, "native", nat, "runtimes", "native",
                "engines", "scj", "datasets", "tiny", "workload-arg", "--area-size mission=100000"));
        assertEquals("--workload-arg: --area-size: unknown option (see --help) (the native skip runs)", e.getMessage());
        e = assertThrows(BadUsageException.class, () -> plan("java", jvm, "policies", "skip,queue", "datasets", "tiny",
                "workload-arg", "--resample", "workload-arg", "stratified"));
        assertEquals("--workload-arg: --resample: 'stratified' is not one of systematic|multinomial (the javase skip runs)",
                e.getMessage());
        // what every engine takes is planned; so is a memory style an engine lacks, recorded unsupported when run
        assertEquals(3, plan("java", jvm, "native", nat, "runtimes", "native", "engines", "javase,scj", "datasets", "tiny",
                "workload-arg", "--no-cpu-time --resample=multinomial").plan().size());
        assertEquals(2, plan("java", jvm, "engines", "javase,scj", "memory", "allocating", "datasets", "tiny",
                "workload-arg", "--init uniform").plan().size());
    }

    @Test
    void aWarmupIsCheckedAgainstEachDatasetAsTheWorkloadWillCheckIt() throws Exception {
        Fixtures.home(dir);
        String jvm = Fixtures.fakeJava(dir, "jvm", "ok", 0, null, 21).toString();
        String nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21).toString();
        // tiny's last event is at 19 * 0.05 s (its dataset.properties says 1.0): a warm-up of 0.96 s leaves none after
        // it, and every run, Java and C, would have exited 2, recorded failed
        BadUsageException e = assertThrows(BadUsageException.class, () -> plan("java", jvm, "native", nat,
                "runtimes", "all", "datasets", "tiny", "workload-arg", "--warmup 0.96"));
        assertEquals("--workload-arg: --warmup: reaches the last time of " + dir.resolve("data/tiny/odometry.txt")
                + ": a warm-up replays the data before it and must leave an event after it (the javase skip runs)",
                e.getMessage());
        assertEquals(4, plan("java", jvm, "native", nat, "runtimes", "all", "datasets", "tiny", "policies", "skip,ideal",
                "workload-arg", "--warmup=0.9").plan().size());
    }

    @Test
    void shardsPartitionTheMatrixAndTheOrderFollowsTheSeed() throws Exception {
        Fixtures.home(dir);
        String jvm = Fixtures.fakeJava(dir, "jvm", "ok", 0, null, 21).toString();
        String[] base = {"java", jvm, "profiles", "g1,zgc,serial", "policies", "skip,terminate", "particles", "100,400",
                "datasets", "tiny", "repeat", "2", "order-seed", "42"};
        ResolvedMatrix whole = plan(base);
        assertEquals(3 * 2 * 2 * 2, whole.plan().size());
        Set<String> union = new HashSet<>();
        int total = 0;
        for (int k = 1; k <= 3; k++) {
            String[] withShard = java.util.Arrays.copyOf(base, base.length + 2);
            withShard[base.length] = "shard";
            withShard[base.length + 1] = k + "/3";
            ResolvedMatrix part = plan(withShard);
            total += part.plan().size();
            part.plan().forEach(r -> union.add(r.runKey()));
        }
        assertEquals(whole.plan().size(), total);
        assertEquals(whole.plan().size(), union.size());
        // repetition rounds in order, shuffled within
        int firstRep2 = whole.plan().indexOf(whole.plan().stream().filter(r -> r.repetition() == 2).findFirst().orElseThrow());
        assertEquals(12, firstRep2);
        assertTrue(whole.plan().subList(0, 12).stream().allMatch(r -> r.repetition() == 1));
        assertEquals(whole.plan(), plan(base).plan(), "same seed, same order");
        String[] other = base.clone();
        other[other.length - 1] = "43";
        assertNotEquals(whole.plan().stream().map(PlannedRun::runKey).toList(),
                plan(other).plan().stream().map(PlannedRun::runKey).toList());
    }
}
