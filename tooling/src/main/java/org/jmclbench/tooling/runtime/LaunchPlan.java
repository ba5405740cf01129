package org.jmclbench.tooling.runtime;

import java.util.ArrayList;
import java.util.List;

/**
 * What a profile means for one runtime: a command prefix ({@code chrt}, {@code taskset}) and the JVM
 * flags that go before the class path. AOT cache flags are added by the runner once the cache is trained.
 *
 * @param prefix   command words before the runtime's executable
 * @param jvmFlags JVM options (empty for native)
 */
public record LaunchPlan(List<String> prefix, List<String> jvmFlags) {

    /** The launch plan of {@code profile} on {@code runtime}; {@code pinCpu} is the CPU list for {@code pinned}. */
    public static LaunchPlan of(RuntimeInfo runtime, Profile profile, String pinCpu) {
        List<String> prefix = new ArrayList<>();
        if (profile.has(ProfileComponent.FIFO)) {
            prefix.addAll(List.of("chrt", "-f", String.valueOf(ProfileComponent.FIFO_PRIORITY)));
        }
        if (profile.has(ProfileComponent.PINNED)) {
            prefix.addAll(List.of("taskset", "-c", pinCpu));
        }
        List<String> flags = new ArrayList<>();
        if (runtime.isJvm()) {
            int heapMb = profile.heapMb(); // a profile's heap size wins over Epsilon's default
            for (ProfileComponent c : profile.components()) {
                if ((c == ProfileComponent.ZGC || c == ProfileComponent.SHENANDOAH) && runtime.major() > 0 && runtime.major() < 15) {
                    flags.add("-XX:+UnlockExperimentalVMOptions"); // experimental before JDK 15
                }
                flags.addAll(c.flags());
                if (c == ProfileComponent.EPSILON && heapMb == 0) {
                    heapMb = ProfileComponent.EPSILON_HEAP_MB;
                }
            }
            if (profile.has(ProfileComponent.PRETOUCH)) {
                int mb = heapMb > 0 ? heapMb : ProfileComponent.PRETOUCH_HEAP_MB;
                flags.add("-Xms" + mb + "m");
                flags.add("-Xmx" + mb + "m");
            } else if (heapMb > 0) {
                flags.add("-Xmx" + heapMb + "m");
            }
        }
        return new LaunchPlan(List.copyOf(prefix), List.copyOf(flags));
    }

    /** The CPU a pinned run uses: the last isolated CPU if any (isolcpus), else the last CPU. */
    public static String defaultPinCpu() {
        try {
            String iso = ProcessRunner.readText(java.nio.file.Path.of("/sys/devices/system/cpu/isolated")).trim();
            if (!iso.isEmpty()) {
                List<Integer> cpus = CpuList.parse(iso);
                if (!cpus.isEmpty()) {
                    return String.valueOf(cpus.get(cpus.size() - 1));
                }
            }
        } catch (java.io.IOException | IllegalArgumentException ignored) {
            // no isolation information: fall back to the last CPU
        }
        return String.valueOf(Runtime.getRuntime().availableProcessors() - 1);
    }
}
