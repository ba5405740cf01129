package org.jmclbench.workload.output;

import java.io.BufferedReader;
import java.io.File;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * What the run ran on (summary.json's "environment"): runtime, OS, kernel, CPU, the
 * thread's scheduling policy, clocksource, host. Read from java.lang.management and /proc
 * only (no child process), before the measured window.
 */
public final class Environment {
    public final String runtimeName;
    public final String vendor;
    public final String version;
    public final String vmName;
    public final List<String> inputArguments;
    public final List<String> gcNames;
    public final String osName;
    public final String osArch;
    public final String kernel;
    public final String cpuModel;
    public final int processors;
    public final String schedulingPolicy;
    public final int schedulingPriority;
    public final String clocksource;
    public final String hostname;
    public final String startedAt;

    private Environment() {
        runtimeName = System.getProperty("java.runtime.name", System.getProperty("java.vm.name", "java"));
        vendor = System.getProperty("java.vendor", "");
        version = System.getProperty("java.runtime.version", System.getProperty("java.version", ""));
        vmName = System.getProperty("java.vm.name", "");
        List<String> args;
        try {
            args = new ArrayList<>(ManagementFactory.getRuntimeMXBean().getInputArguments());
        } catch (RuntimeException e) {
            args = new ArrayList<>();
        }
        inputArguments = Collections.unmodifiableList(args);
        List<String> gcs = new ArrayList<>();
        for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            gcs.add(gc.getName());
        }
        gcNames = Collections.unmodifiableList(gcs);
        osName = System.getProperty("os.name", "");
        osArch = System.getProperty("os.arch", "");
        String k = firstLine("/proc/sys/kernel/osrelease");
        kernel = k != null ? k : System.getProperty("os.version", "");
        cpuModel = cpuModel();
        processors = Runtime.getRuntime().availableProcessors();
        int[] sched = scheduling();
        schedulingPolicy = sched == null ? "unknown" : policyName(sched[0]);
        schedulingPriority = sched == null ? -1 : sched[1];
        String cs = firstLine("/sys/devices/system/clocksource/clocksource0/current_clocksource");
        clocksource = cs != null ? cs : "unknown";
        hostname = hostname();
        startedAt = Instant.now().truncatedTo(ChronoUnit.SECONDS).toString();
    }

    /** Reads the environment now (call before the measured window). */
    public static Environment capture() {
        return new Environment();
    }

    /** Writes the "environment" object's content as a JSON value. */
    public void writeTo(Json j) {
        j.beginObject();
        j.name("runtime").beginObject();
        j.name("language").value("java");
        j.name("name").value(runtimeName);
        j.name("vendor").value(vendor);
        j.name("version").value(version);
        j.name("vmName").value(vmName);
        j.name("inputArguments").beginArray();
        for (String a : inputArguments) {
            j.value(a);
        }
        j.endArray();
        j.name("gcNames").beginArray();
        for (String g : gcNames) {
            j.value(g);
        }
        j.endArray();
        j.endObject();
        j.name("os").beginObject().name("name").value(osName).name("arch").value(osArch).name("kernel").value(kernel)
                .endObject();
        j.name("cpu").beginObject().name("model").value(cpuModel).name("processors").value(processors).endObject();
        j.name("scheduling").beginObject().name("policy").value(schedulingPolicy).name("priority")
                .value(schedulingPriority).endObject();
        j.name("clocksource").value(clocksource);
        j.name("hostname").value(hostname);
        j.name("startedAt").value(startedAt);
        j.endObject();
    }

    /** Linux's names for sched_setscheduler policies (the value of /proc/.../stat field 41). */
    static String policyName(int policy) {
        switch (policy) {
            case 0:
                return "SCHED_OTHER";
            case 1:
                return "SCHED_FIFO";
            case 2:
                return "SCHED_RR";
            case 3:
                return "SCHED_BATCH";
            case 5:
                return "SCHED_IDLE";
            case 6:
                return "SCHED_DEADLINE";
            default:
                return "policy-" + policy;
        }
    }

    /** {policy, rt_priority} of the calling thread from /proc/thread-self/stat (fields 41 and 40), or null. */
    static int[] scheduling() {
        String stat = firstLine("/proc/thread-self/stat");
        if (stat == null) {
            stat = firstLine("/proc/self/stat");
        }
        return stat == null ? null : parseStat(stat);
    }

    /** Fields 41 (policy) and 40 (rt_priority) of a stat line; the command (field 2) may hold spaces and parentheses. */
    static int[] parseStat(String stat) {
        int close = stat.lastIndexOf(')');
        if (close < 0) {
            return null;
        }
        String[] f = stat.substring(close + 1).trim().split("\\s+");
        // f[0] is field 3, so field m is f[m - 3].
        if (f.length < 39) {
            return null;
        }
        try {
            return new int[] {Integer.parseInt(f[41 - 3]), Integer.parseInt(f[40 - 3])};
        } catch (NumberFormatException e) {
            return null;
        }
    }

    private static String cpuModel() {
        File f = new File("/proc/cpuinfo");
        if (f.canRead()) {
            try (BufferedReader r = new BufferedReader(
                    new InputStreamReader(new FileInputStream(f), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    if (line.startsWith("model name") && line.indexOf(':') > 0) {
                        return line.substring(line.indexOf(':') + 1).trim();
                    }
                }
            } catch (IOException e) {
                // fall through
            }
        }
        return "unknown";
    }

    private static String hostname() {
        String h = firstLine("/proc/sys/kernel/hostname");
        if (h != null && !h.isEmpty()) {
            return h;
        }
        try {
            return InetAddress.getLocalHost().getHostName();
        } catch (IOException e) {
            return "unknown";
        }
    }

    private static String firstLine(String path) {
        File f = new File(path);
        if (!f.canRead()) {
            return null;
        }
        try (BufferedReader r = new BufferedReader(
                new InputStreamReader(new FileInputStream(f), StandardCharsets.UTF_8))) {
            String line = r.readLine();
            return line == null ? null : line.trim();
        } catch (IOException e) {
            return null;
        }
    }
}
