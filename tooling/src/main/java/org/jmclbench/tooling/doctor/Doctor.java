package org.jmclbench.tooling.doctor;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;
import java.util.stream.Stream;

import org.jmclbench.tooling.runtime.HvmRuntime;
import org.jmclbench.tooling.runtime.IdleStateHold;
import org.jmclbench.tooling.runtime.JmclbenchPaths;
import org.jmclbench.tooling.runtime.ProcessRunner;
import org.jmclbench.tooling.runtime.ProfileComponent;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Checks the machine the way rt-tests' tools and rtcheck do: kernel preemption model, RT throttling,
 * permission for SCHED_FIFO, memlock limit, CPU frequency governor, CPU idle states, isolated CPUs, transparent huge
 * pages, clocksource, virtualisation and steal time, cyclictest. Files are read below {@code root}
 * (the real {@code /} normally; tests pass a fake tree).
 *
 * @param runCommands whether checks may run commands (systemd-detect-virt, cyclictest, the HVM check) and wait; tests do not
 */
public record Doctor(Path root, boolean runCommands) {

    /** This machine. */
    public static Doctor system() {
        return new Doctor(Path.of("/"), true);
    }

    public List<DoctorCheck> run() {
        return List.of(preemptRt(), rtThrottling(), fifoPermission(), memlock(), governor(), cpuIdle(), isolatedCpus(),
                transparentHugePages(), clocksource(), virtualisation(), memory(), stealTime(), cyclictest(), hvm());
    }

    /** The checks as JSON: {@code [{"check","status","value","advice"}]} (stored in machines.doctor_json). */
    public static String toJson(List<DoctorCheck> checks) {
        try {
            return new ObjectMapper().writeValueAsString(checks);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    DoctorCheck preemptRt() {
        String realtime = read("sys/kernel/realtime");
        String version = read("proc/sys/kernel/version");
        if ("1".equals(realtime) || version != null && version.contains("PREEMPT_RT")) {
            return DoctorCheck.pass("preempt-rt", "PREEMPT_RT kernel" + (version == null ? "" : ": " + version));
        }
        return DoctorCheck.warn("preempt-rt", version == null ? "not a PREEMPT_RT kernel" : version,
                "a PREEMPT_RT kernel (e.g. Debian's linux-image-rt-amd64) bounds scheduling latency; results on this kernel show its worst cases");
    }

    DoctorCheck rtThrottling() {
        String v = read("proc/sys/kernel/sched_rt_runtime_us");
        if (v == null) {
            return DoctorCheck.warn("rt-throttling", "unknown (no /proc/sys/kernel/sched_rt_runtime_us)", "");
        }
        if (v.equals("-1")) {
            return DoctorCheck.pass("rt-throttling", "off (sched_rt_runtime_us = -1)");
        }
        String period = read("proc/sys/kernel/sched_rt_period_us");
        return DoctorCheck.warn("rt-throttling", "on: RT tasks get " + v + " us of every " + (period == null ? "1000000" : period) + " us",
                "a SCHED_FIFO run is stopped when it uses its RT budget; to measure without it: echo -1 > /proc/sys/kernel/sched_rt_runtime_us");
    }

    /**
     * Whether the fifo profile can run: its own priority is tried, since an rtprio limit (RLIMIT_RTPRIO)
     * below it permits a lower priority and still refuses the profile's.
     */
    DoctorCheck fifoPermission() {
        List<String> command = List.of("chrt", "-f", Integer.toString(ProfileComponent.FIFO_PRIORITY), "true");
        String chrt = String.join(" ", command);
        if (!runCommands) {
            return DoctorCheck.warn("sched-fifo", "not tried", "try it: " + chrt);
        }
        ProcessRunner.Result r = ProcessRunner.run(command, 10_000);
        if (r.ok()) {
            return DoctorCheck.pass("sched-fifo", "permitted at the fifo profile's priority (" + chrt + " succeeded)");
        }
        return DoctorCheck.fail("sched-fifo", "not permitted at the fifo profile's priority (" + chrt + "): " + firstLine(r.output()),
                "the fifo profile needs CAP_SYS_NICE: run as root, or set an rtprio limit of at least "
                        + ProfileComponent.FIFO_PRIORITY + " in /etc/security/limits.conf");
    }

    DoctorCheck memlock() {
        String limits = read("proc/self/limits");
        if (limits != null) {
            for (String line : limits.split("\n")) {
                if (line.startsWith("Max locked memory")) {
                    String[] f = line.substring("Max locked memory".length()).trim().split("\\s+");
                    String soft = f[0];
                    if (soft.equals("unlimited")) {
                        return DoctorCheck.pass("memlock", "unlimited");
                    }
                    try {
                        long bytes = Long.parseLong(soft);
                        if (bytes >= (1L << 30)) {
                            return DoctorCheck.pass("memlock", bytes / (1 << 20) + " MiB");
                        }
                        return DoctorCheck.warn("memlock", bytes / 1024 + " KiB",
                                "locking the heap (mlockall, -XX:+AlwaysPreTouch with locked pages) needs a bigger limit: ulimit -l unlimited");
                    } catch (NumberFormatException e) {
                        break;
                    }
                }
            }
        }
        return DoctorCheck.warn("memlock", "unknown", "");
    }

    DoctorCheck governor() {
        TreeSet<String> governors = new TreeSet<>();
        Path cpus = root.resolve("sys/devices/system/cpu");
        if (Files.isDirectory(cpus)) {
            try (Stream<Path> s = Files.list(cpus)) {
                for (Path cpu : s.filter(p -> p.getFileName().toString().matches("cpu\\d+")).toList()) {
                    String g = readPath(cpu.resolve("cpufreq/scaling_governor"));
                    if (g != null) {
                        governors.add(g);
                    }
                }
            } catch (IOException ignored) {
                // reported as unknown below
            }
        }
        if (governors.isEmpty()) {
            return DoctorCheck.warn("cpu-governor", "no cpufreq control (a VM, or the driver is not loaded)",
                    "on bare metal, frequency changes show up as latency: cpupower frequency-set -g performance");
        }
        if (governors.size() == 1 && governors.contains("performance")) {
            return DoctorCheck.pass("cpu-governor", "performance");
        }
        return DoctorCheck.warn("cpu-governor", String.join(",", governors),
                "frequency scaling adds latency and drift: cpupower frequency-set -g performance");
    }

    /**
     * Whether an idle CPU may sleep deeply: then a job released to it waits for it to wake, and on a
     * VM a halted vCPU may also run the job slower when it is back. PM QoS ({@code noidle}) works
     * through the cpuidle driver, so without one only the kernel's {@code idle=poll} keeps CPUs awake.
     */
    DoctorCheck cpuIdle() {
        String driver = read("sys/devices/system/cpu/cpuidle/current_driver");
        if (driver == null || driver.isEmpty() || driver.equals("none")) {
            return DoctorCheck.warn("cpu-idle", "no cpuidle driver: an idle CPU halts",
                    "the noidle profile needs a cpuidle driver; idle=poll on the kernel command line keeps the CPUs awake");
        }
        String governor = read("sys/devices/system/cpu/cpuidle/current_governor");
        List<String> deep = new java.util.ArrayList<>();
        boolean anyEnabled = false;
        Path states = root.resolve("sys/devices/system/cpu/cpu0/cpuidle");
        if (Files.isDirectory(states)) {
            try (Stream<Path> s = Files.list(states)) {
                for (Path state : s.filter(p -> p.getFileName().toString().matches("state\\d+")).sorted().toList()) {
                    String name = readPath(state.resolve("name"));
                    if (name != null && !name.equals("POLL")) {
                        deep.add(name);
                        anyEnabled |= !"1".equals(readPath(state.resolve("disable")));
                    }
                }
            } catch (IOException ignored) {
                // no states read: reported with the driver alone
            }
        }
        String value = driver + (governor == null ? "" : " (governor " + governor + ")")
                + (deep.isEmpty() ? "" : ": " + String.join(", ", deep));
        if (!deep.isEmpty() && !anyEnabled) {
            return DoctorCheck.pass("cpu-idle", value + ", all disabled");
        }
        return DoctorCheck.warn("cpu-idle", value,
                "a job released to an idle CPU waits for it to wake: the noidle profile holds " + IdleStateHold.DEVICE
                        + " at 0 during each run, as cyclictest does");
    }

    DoctorCheck isolatedCpus() {
        String iso = read("sys/devices/system/cpu/isolated");
        if (iso != null && !iso.isEmpty()) {
            return DoctorCheck.pass("isolated-cpus", iso + " (the pinned profile uses the last one)");
        }
        return DoctorCheck.warn("isolated-cpus", "none",
                "isolate a CPU for the runtime under test (kernel isolcpus=, nohz_full=, rcu_nocbs=) and use the pinned profile");
    }

    DoctorCheck transparentHugePages() {
        String thp = read("sys/kernel/mm/transparent_hugepage/enabled");
        if (thp == null) {
            return DoctorCheck.pass("transparent-hugepages", "not available");
        }
        int a = thp.indexOf('[');
        int b = thp.indexOf(']');
        String mode = a >= 0 && b > a ? thp.substring(a + 1, b) : thp;
        if (mode.equals("always")) {
            return DoctorCheck.warn("transparent-hugepages", "always",
                    "khugepaged and huge-page faults add latency spikes: echo madvise > /sys/kernel/mm/transparent_hugepage/enabled");
        }
        return DoctorCheck.pass("transparent-hugepages", mode);
    }

    DoctorCheck clocksource() {
        String cs = read("sys/devices/system/clocksource/clocksource0/current_clocksource");
        if (cs == null) {
            return DoctorCheck.warn("clocksource", "unknown", "");
        }
        if (cs.equals("tsc")) {
            return DoctorCheck.pass("clocksource", cs);
        }
        return DoctorCheck.warn("clocksource", cs,
                "tsc is the cheapest and most precise clock; " + cs + " makes every timestamp cost more (check available_clocksource)");
    }

    /** The machine's memory (MemTotal), for the record: an evaluation says what it ran on. */
    DoctorCheck memory() {
        String meminfo = read("proc/meminfo");
        java.util.regex.Matcher m = meminfo == null ? null : java.util.regex.Pattern.compile("(?m)^MemTotal:\\s+(\\d+) kB").matcher(meminfo);
        if (m == null || !m.find()) {
            return DoctorCheck.warn("memory", "unknown", "proc/meminfo has no MemTotal: the machine's memory is not recorded with its results");
        }
        return DoctorCheck.pass("memory", String.format(java.util.Locale.ROOT, "%.1f GiB", Long.parseLong(m.group(1)) / 1048576.0));
    }

    DoctorCheck virtualisation() {
        String virt = null;
        if (runCommands) {
            // --vm: a container shares the host's scheduler; without it, docker on kvm answers "docker"
            ProcessRunner.Result r = ProcessRunner.run(List.of("systemd-detect-virt", "--vm"), 10_000);
            if (!r.timedOut() && r.exitCode() != 127 && !r.stdout().isBlank()) {
                virt = r.stdout().strip();
            }
        }
        if (virt == null) {
            String cpuinfo = read("proc/cpuinfo");
            virt = cpuinfo != null && cpuinfo.matches("(?s).*\\bflags\\s*:.*\\bhypervisor\\b.*") ? "hypervisor flag set" : "none";
        }
        if (virt.equals("none")) {
            return DoctorCheck.pass("virtualisation", "bare metal");
        }
        return DoctorCheck.warn("virtualisation", virt,
                "a virtual machine adds the host's scheduling to every latency (see steal time); measure on bare metal for final numbers");
    }

    DoctorCheck stealTime() {
        long[] a = cpuLine();
        if (a == null) {
            return DoctorCheck.warn("steal-time", "unknown", "");
        }
        long[] b = a;
        if (runCommands) {
            try {
                Thread.sleep(250);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            long[] again = cpuLine();
            if (again != null) {
                b = again;
            }
        }
        boolean sampled = b != a;
        long total = 0;
        long steal;
        if (sampled && sum(b) - sum(a) > 0) {
            total = sum(b) - sum(a);
            steal = b[7] - a[7];
        } else {
            total = sum(a);
            steal = a[7];
        }
        double pct = total == 0 ? 0 : 100.0 * steal / total;
        String v = stealShare(steal, total) + " " + (sampled ? "over 250 ms" : "since boot") + " (" + total + " ticks)";
        if (pct < 1.0) {
            return DoctorCheck.pass("steal-time", v);
        }
        return DoctorCheck.warn("steal-time", v, "the hypervisor is taking CPU time from this machine: expect latency outliers");
    }

    /**
     * {@code steal} ticks of {@code ticks} as a percentage with no more digits than one tick can
     * tell apart (250 ms on 2 CPUs is about 50 ticks: 2% a tick, so "0.00%" claimed a precision it
     * did not have); none is "&lt; one tick", rounded up.
     */
    static String stealShare(long steal, long ticks) {
        if (ticks <= 0) {
            return "unknown";
        }
        double tick = 100.0 / ticks;
        int digits = (int) Math.max(0, Math.min(2, Math.ceil(-Math.log10(tick))));
        if (steal == 0) {
            double scale = Math.pow(10, digits);
            return "< " + String.format(Locale.ROOT, "%." + digits + "f%%", Math.max(Math.ceil(tick * scale - 1e-9), 1) / scale);
        }
        return String.format(Locale.ROOT, "%." + digits + "f%%", tick * steal);
    }

    DoctorCheck cyclictest() {
        String path = System.getenv("PATH");
        if (path != null) {
            for (String dir : path.split(":")) {
                if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, "cyclictest"))) {
                    return DoctorCheck.pass("cyclictest", Path.of(dir, "cyclictest").toString());
                }
            }
        }
        return DoctorCheck.warn("cyclictest", "not found",
                "install rt-tests (apt-get install rt-tests) to compare the dispatcher's lateness with cyclictest's");
    }

    /** Whether the icecap HVM (the hvm runtime, docs/HVM.md) can be built here, and why not. */
    DoctorCheck hvm() {
        if (!runCommands) {
            return DoctorCheck.warn("hvm", "not tried", "hvm/build-hvm.sh --check");
        }
        HvmRuntime.Availability a = HvmRuntime.check(JmclbenchPaths.home());
        if (a.buildable()) {
            return HvmRuntime.sourceGiven() ? DoctorCheck.pass("hvm", a.detail())
                    : DoctorCheck.warn("hvm", a.detail(), "set HVM_SRC to an hvm-scj folder or tarball (docs/HVM.md)");
        }
        return DoctorCheck.warn("hvm", "cannot be built: " + a.detail(),
                "the hvm runtime needs gcc, javac, mvn, patch, pip and HVM_SRC (docs/HVM.md)");
    }

    private long[] cpuLine() {
        String stat = read("proc/stat");
        if (stat == null) {
            return null;
        }
        for (String line : stat.split("\n")) {
            if (line.startsWith("cpu ")) {
                String[] f = line.trim().split("\\s+");
                long[] v = new long[10];
                for (int i = 1; i < f.length && i <= 10; i++) {
                    v[i - 1] = Long.parseLong(f[i]);
                }
                return v;
            }
        }
        return null;
    }

    private static long sum(long[] v) {
        long s = 0;
        for (int i = 0; i < 8; i++) { // guest times are already counted in user
            s += v[i];
        }
        return s;
    }

    private String read(String rel) {
        return readPath(root.resolve(rel));
    }

    private static String readPath(Path p) {
        try {
            // not Files.readString: on procfs (size 0) some JDKs return only the first byte
            try (java.io.InputStream in = Files.newInputStream(p)) {
                return new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).strip();
            }
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    private static String firstLine(String s) {
        String t = s.strip();
        int nl = t.indexOf('\n');
        return nl < 0 ? t : t.substring(0, nl);
    }
}
