package org.jmclbench.tooling.doctor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.runtime.ProcessRunner;
import org.jmclbench.tooling.runtime.ProfileComponent;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

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
        write("sys/devices/system/cpu/cpuidle/current_driver", "intel_idle\n");
        cpuIdleState(0, "POLL", false);
        cpuIdleState(1, "C1", true);
        cpuIdleState(2, "C6", true);
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
        write("sys/devices/system/cpu/cpuidle/current_driver", "haltpoll\n");
        write("sys/devices/system/cpu/cpuidle/current_governor", "haltpoll\n");
        cpuIdleState(0, "POLL", false);
        cpuIdleState(1, "haltpoll idle", false);
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

    /**
     * With an rtprio limit between 1 and 79 (and no CAP_SYS_NICE), SCHED_FIFO is permitted at a low
     * priority and refused at the fifo profile's 80: the doctor tries the profile's priority, and says
     * FAIL. Here a stand-in chrt on PATH behaves as chrt does under RLIMIT_RTPRIO = 10.
     */
    @Test
    void anRtprioLimitBelowTheFifoProfilesPriorityFails() throws Exception {
        Path bin = Files.createDirectories(root.resolve("bin"));
        Path chrt = bin.resolve("chrt");
        Files.writeString(chrt, "#!/bin/sh\n# chrt under RLIMIT_RTPRIO = 10, without CAP_SYS_NICE\n"
                + "if [ \"$1\" = -f ] && [ \"$2\" -le 10 ]; then shift 2; exec \"$@\"; fi\n"
                + "echo \"chrt: failed to set pid 0's policy: Operation not permitted\" >&2\nexit 1\n");
        Files.setPosixFilePermissions(chrt, PosixFilePermissions.fromString("rwxr-xr-x"));
        JsonNode fifo = fifoCheckOfAChildDoctor(List.of(), bin + ":" + System.getenv("PATH"));
        assertEquals("FAIL", fifo.get("status").asText(), fifo.toString());
        assertTrue(fifo.get("value").asText().startsWith("not permitted at the fifo profile's priority (chrt -f "
                + ProfileComponent.FIFO_PRIORITY + " true): chrt: failed to set pid 0's policy"), fifo.toString());
        assertTrue(fifo.get("advice").asText().contains("an rtprio limit of at least " + ProfileComponent.FIFO_PRIORITY),
                fifo.toString());
    }

    /**
     * The same with the kernel's own limit, where this machine can set it: prlimit lowers RLIMIT_RTPRIO
     * to 10 and setpriv drops CAP_SYS_NICE for the doctor's process and its children (as root,
     * CAP_SYS_NICE overrides the limit). Skipped unless chrt -f 10 succeeds and chrt -f 80 fails so.
     */
    @Test
    void theKernelsRtprioLimitBelowTheFifoProfilesPriorityFails() throws Exception {
        List<String> limited = List.of("prlimit", "--rtprio=10", "--", "setpriv", "--inh-caps=-sys_nice",
                "--bounding-set=-sys_nice");
        Assumptions.assumeTrue(exitCode(limited, "chrt", "-f", "10", "true") == 0
                        && exitCode(limited, "chrt", "-f", String.valueOf(ProfileComponent.FIFO_PRIORITY), "true") != 0,
                "needs prlimit and setpriv that can lower the rtprio limit and drop CAP_SYS_NICE here");
        JsonNode fifo = fifoCheckOfAChildDoctor(limited, System.getenv("PATH"));
        assertEquals("FAIL", fifo.get("status").asText(), fifo.toString());
    }

    private static int exitCode(List<String> prefix, String... command) {
        List<String> cmd = new ArrayList<>(prefix);
        cmd.addAll(List.of(command));
        return ProcessRunner.run(cmd, 10_000).exitCode();
    }

    /** The sched-fifo check of {@code doctor --json} run in a child JVM behind {@code prefix}, with {@code path} as PATH. */
    private JsonNode fifoCheckOfAChildDoctor(List<String> prefix, String path) throws Exception {
        List<String> cmd = new ArrayList<>(prefix);
        cmd.addAll(Fixtures.childCli(root, "doctor", "--json"));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.DISCARD);
        pb.environment().put("PATH", path);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the doctor hung");
        assertEquals(0, p.exitValue(), out);
        for (JsonNode c : new ObjectMapper().readTree(out)) {
            if (c.get("check").asText().equals("sched-fifo")) {
                return c;
            }
        }
        throw new AssertionError("no sched-fifo check in " + out);
    }

    @Test
    void stealTimeHasThePrecisionOfItsSample() {
        // 250 ms on 2 CPUs: about 50 ticks of 2% each; it printed "0.00%" and "2.00%"
        assertEquals("< 2%", Doctor.stealShare(0, 50));
        assertEquals("2%", Doctor.stealShare(1, 50));
        assertEquals("< 0.3%", Doctor.stealShare(0, 400));
        assertEquals("0.5%", Doctor.stealShare(2, 400));
        assertEquals("< 0.4%", Doctor.stealShare(0, 333)); // 0.3003% a tick, rounded up: "< 0.3%" would claim too little
        // since boot: millions of ticks, two digits at most
        assertEquals("< 0.01%", Doctor.stealShare(0, 12_000_000));
        assertEquals("0.37%", Doctor.stealShare(44_400, 12_000_000));
        assertEquals("unknown", Doctor.stealShare(0, 0));
    }

    /** A KVM guest's idle driver may halt a vCPU; a machine with its deep states disabled passes; no driver, no noidle. */
    @Test
    void idleStatesNameTheDriverAndWhatKeepsTheCpusAwake() throws Exception {
        assertEquals("WARN no cpuidle driver: an idle CPU halts", verdict(new Doctor(root, false).cpuIdle()));
        write("sys/devices/system/cpu/cpuidle/current_driver", "haltpoll\n");
        write("sys/devices/system/cpu/cpuidle/current_governor", "haltpoll\n");
        cpuIdleState(0, "POLL", false);
        cpuIdleState(1, "haltpoll idle", false);
        DoctorCheck vm = new Doctor(root, false).cpuIdle();
        assertEquals("WARN haltpoll (governor haltpoll): haltpoll idle", verdict(vm));
        assertTrue(vm.advice().contains("noidle profile holds /dev/cpu_dma_latency at 0"), vm.advice());
        cpuIdleState(1, "haltpoll idle", true);
        assertEquals("PASS haltpoll (governor haltpoll): haltpoll idle, all disabled", verdict(new Doctor(root, false).cpuIdle()));
    }

    private static String verdict(DoctorCheck c) {
        return c.status() + " " + c.value();
    }

    private void cpuIdleState(int index, String name, boolean disabled) throws Exception {
        write("sys/devices/system/cpu/cpu0/cpuidle/state" + index + "/name", name + "\n");
        write("sys/devices/system/cpu/cpu0/cpuidle/state" + index + "/disable", disabled ? "1\n" : "0\n");
    }

    /** Asserts that each of the machine's checks (all but memory) has {@code status}. */
    private static void assertEvery(String status, Map<String, String> s) {
        for (String c : List.of("preempt-rt", "rt-throttling", "memlock", "cpu-governor", "cpu-idle", "isolated-cpus",
                "transparent-hugepages", "clocksource", "virtualisation", "steal-time")) {
            assertEquals(status, s.get(c), c + " in " + s);
        }
    }

    private static Map<String, String> statuses(List<DoctorCheck> checks) {
        return checks.stream().collect(Collectors.toMap(DoctorCheck::check, DoctorCheck::status));
    }
}
