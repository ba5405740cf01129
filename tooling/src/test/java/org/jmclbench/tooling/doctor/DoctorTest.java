package org.jmclbench.tooling.doctor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.jmclbench.tooling.runtime.ProcessRunner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The doctor reads the kernel's files; a fake tree shows each verdict. */
class DoctorTest {

    @TempDir
    Path root;

    private void write(String rel, String text) throws Exception {
        Path p = root.resolve(rel);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
    }

    @Test
    void goodRealTimeMachine() throws Exception {
        write("sys/kernel/realtime", "1\n");
        write("proc/sys/kernel/version", "#1 SMP PREEMPT_RT Debian 6.1.0-rt\n");
        write("proc/sys/kernel/sched_rt_runtime_us", "-1\n");
        write("proc/self/limits", "Limit Soft Hard Units\nMax locked memory         unlimited            unlimited            bytes\n");
        write("sys/devices/system/cpu/cpu0/cpufreq/scaling_governor", "performance\n");
        write("sys/devices/system/cpu/cpu1/cpufreq/scaling_governor", "performance\n");
        write("sys/devices/system/cpu/isolated", "1\n");
        write("sys/kernel/mm/transparent_hugepage/enabled", "always madvise [never]\n");
        write("sys/devices/system/clocksource/clocksource0/current_clocksource", "tsc\n");
        write("proc/cpuinfo", "processor : 0\nflags : fpu vme sse\n");
        write("proc/stat", "cpu  100 0 100 1000 0 0 0 0 0 0\n");
        write("proc/meminfo", "MemTotal:       24596796 kB\nMemFree:        1000 kB\n");
        List<DoctorCheck> all = new Doctor(root, false).run();
        Map<String, String> s = statuses(all);
        assertEquals("23.5 GiB", all.stream().filter(c -> c.check().equals("memory")).findFirst().orElseThrow().value());
        assertEvery("PASS", s);
    }

    @Test
    void ordinaryVirtualMachine() throws Exception {
        write("proc/sys/kernel/version", "#1 SMP PREEMPT_DYNAMIC\n");
        write("proc/sys/kernel/sched_rt_runtime_us", "950000\n");
        write("proc/self/limits", "Max locked memory         8388608              8388608              bytes\n");
        write("sys/devices/system/cpu/isolated", "\n");
        write("sys/kernel/mm/transparent_hugepage/enabled", "[always] madvise never\n");
        write("sys/devices/system/clocksource/clocksource0/current_clocksource", "kvm-clock\n");
        write("proc/cpuinfo", "processor : 0\nflags : fpu vme hypervisor sse\n");
        write("proc/stat", "cpu  100 0 100 1000 0 0 0 50 0 0\n");
        List<DoctorCheck> checks = new Doctor(root, false).run();
        Map<String, String> s = statuses(checks);
        assertEvery("WARN", s);
        assertTrue(checks.stream().filter(c -> c.status().equals("WARN")).allMatch(c -> !c.advice().isEmpty()),
                "every warning says what to do");
        String json = Doctor.toJson(checks);
        assertTrue(json.startsWith("[{\"check\":\"preempt-rt\",\"status\":\"WARN\""), json);
    }

    @Test
    void inAContainerTheVirtualisationIsTheMachinesNotTheContainers() {
        // in docker on kvm, systemd-detect-virt alone answers "docker": a container, which adds no scheduling layer
        ProcessRunner.Result container = ProcessRunner.run(List.of("systemd-detect-virt", "--container"), 10_000);
        org.junit.jupiter.api.Assumptions.assumeTrue(container.exitCode() == 0 && !container.stdout().isBlank(),
                "runs only in a container that systemd-detect-virt recognises");
        DoctorCheck virt = Doctor.system().virtualisation();
        assertTrue(!virt.value().equals(container.stdout().strip()), virt.value());
    }

    /** Asserts that each of the machine's checks (all but memory) has {@code status}. */
    private static void assertEvery(String status, Map<String, String> s) {
        for (String c : List.of("preempt-rt", "rt-throttling", "memlock", "cpu-governor", "isolated-cpus",
                "transparent-hugepages", "clocksource", "virtualisation", "steal-time")) {
            assertEquals(status, s.get(c), c + " in " + s);
        }
    }

    private static Map<String, String> statuses(List<DoctorCheck> checks) {
        return checks.stream().collect(Collectors.toMap(DoctorCheck::check, DoctorCheck::status));
    }
}
