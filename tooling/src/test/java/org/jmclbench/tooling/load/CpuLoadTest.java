package org.jmclbench.tooling.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Load processes never outlive their run: closed, crashed or killed hard. Wide margins, no timing. */
class CpuLoadTest {

    @Test
    void closeEndsStressNgAndItsWorkers() throws Exception {
        assumeTrue(CpuLoad.onPath("stress-ng").isPresent(), "stress-ng is not installed");
        List<Long> pids = new ArrayList<>();
        try (CpuLoad load = CpuLoad.start(2, Duration.ofSeconds(600))) {
            assertEquals("stress-ng", load.tool());
            pids.addAll(load.pids());
            assertTrue(ProcessHandle.of(pids.get(0)).map(ProcessHandle::isAlive).orElse(false));
            for (int i = 0; i < 200 && descendants(pids.get(0)).size() < 2; i++) {
                Thread.sleep(50);
            }
            pids.addAll(descendants(pids.get(0)));
        }
        assertAllGone(pids, 30);
    }

    @Test
    void ourOwnHogsStopWithCloseToo() throws Exception {
        List<Long> pids;
        try (CpuLoad load = CpuLoad.start(1, Duration.ofSeconds(600), false)) {
            assertEquals("busy-loop", load.tool());
            pids = load.pids();
            assertTrue(ProcessHandle.of(pids.get(0)).isPresent());
        }
        assertAllGone(pids, 30);
    }

    @Test
    void theLoadSessionPassesTheAllocPartToTheWorkload() throws Exception {
        try (LoadSession s = LoadSession.start(LoadScenario.ALLOC, new LoadSettings(1, 200, 32), Duration.ofSeconds(60))) {
            assertEquals(List.of("--load-name", "alloc", "--load-alloc", "200,32"), s.workloadArgs());
            assertEquals(List.of(), s.cpuPids());
            assertEquals("alloc: alloc 200 MB/s, 32 MB live", s.description());
        }
        try (LoadSession s = LoadSession.start(LoadScenario.NONE, LoadSettings.defaults(), Duration.ofSeconds(60))) {
            assertEquals(List.of("--load-name", "none"), s.workloadArgs());
        }
    }

    /**
     * The process that started the load dies (an uncaught exception: shutdown hook; SIGKILL:
     * the kernel's parent-death signal). The hogs' own time limit is 600 s, so their end within
     * 60 s is not the backstop at work.
     */
    @ParameterizedTest
    @CsvSource({"crash,stress-ng", "kill,stress-ng", "crash,busy-loop", "kill,busy-loop"})
    void loadEndsWhenItsOwnerDies(String how, String tool) throws Exception {
        assumeTrue(!tool.equals("stress-ng") || CpuLoad.onPath("stress-ng").isPresent(), "stress-ng is not installed");
        String java = ProcessHandle.current().info().command().orElse("java");
        Process owner = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                LoadChildProcess.class.getName(), how.equals("kill") ? "wait" : "crash", tool)
                .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        List<Long> pids = new ArrayList<>();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(owner.getInputStream(), StandardCharsets.UTF_8))) {
            String line = r.readLine();
            assertTrue(line != null && line.startsWith("PIDS "), "the owner reported its load: " + line);
            Arrays.stream(line.substring(5).trim().split(" ")).map(Long::parseLong).forEach(pids::add);
            assertTrue(pids.size() >= (tool.equals("stress-ng") ? 3 : 2), "hogs and workers: " + pids);
            if (how.equals("kill")) {
                owner.destroyForcibly(); // SIGKILL: no shutdown hook runs
            }
            assertTrue(owner.waitFor(60, TimeUnit.SECONDS), "the owner ended");
        } finally {
            owner.destroyForcibly();
        }
        assertAllGone(pids, 60);
    }

    private static List<Long> descendants(long pid) {
        return ProcessHandle.of(pid).map(h -> h.descendants().map(ProcessHandle::pid).toList()).orElse(List.of());
    }

    private static void assertAllGone(List<Long> pids, int seconds) throws InterruptedException {
        long deadline = System.nanoTime() + seconds * 1_000_000_000L;
        List<Long> alive = pids;
        while (System.nanoTime() < deadline) {
            alive = pids.stream().filter(p -> ProcessHandle.of(p).map(ProcessHandle::isAlive).orElse(false)).toList();
            if (alive.isEmpty()) {
                return;
            }
            Thread.sleep(100);
        }
        // Leave nothing behind even when failing.
        alive.forEach(p -> ProcessHandle.of(p).ifPresent(ProcessHandle::destroyForcibly));
        throw new AssertionError("still running after " + seconds + " s: " + alive);
    }
}
