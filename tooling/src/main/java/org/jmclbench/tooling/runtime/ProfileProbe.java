package org.jmclbench.tooling.runtime;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;

/**
 * Decides whether a runtime supports a profile: the JVM is asked once per flag set
 * ({@code java <flags> -version}; answers cached in {@code <cache>/probes.properties} by the
 * executable's real path, size, modification time and flags), the OS prefixes ({@code chrt},
 * {@code taskset}) are tried once per process and {@code noidle} needs its device writable. A rejected flag is "unsupported", never a crash.
 */
public final class ProfileProbe {

    /** The answer for one runtime and profile. */
    public record Support(boolean supported, String reason) {
        public static final Support OK = new Support(true, "");

        public static Support no(String reason) {
            return new Support(false, reason);
        }
    }

    private final Path cacheFile;
    private final Properties cache = new Properties();
    private final Map<List<String>, Support> prefixAnswers = new HashMap<>();

    public ProfileProbe(Path cacheFile) {
        this.cacheFile = cacheFile;
        if (cacheFile != null && Files.isRegularFile(cacheFile)) {
            try (InputStream in = Files.newInputStream(cacheFile)) {
                cache.load(in);
            } catch (IOException | IllegalArgumentException e) {
                cache.clear(); // a damaged cache is only a cache: probe again
            }
        }
    }

    /** A probe with the user's cache file. */
    public static ProfileProbe withUserCache() {
        return new ProfileProbe(JmclbenchPaths.cache().resolve("probes.properties"));
    }

    /** Whether {@code runtime} can run {@code profile} with the CPU list {@code pinCpu} for {@code pinned}. */
    public Support check(RuntimeInfo runtime, Profile profile, String pinCpu) {
        Profile effective = profile.effectiveFor(runtime.kind());
        LaunchPlan plan = LaunchPlan.of(runtime, effective, pinCpu);
        if (runtime.isJvm() && effective.has(ProfileComponent.AOT) && runtime.major() < 13) {
            return Support.no("aot: AppCDS dynamic archives need JDK 13 or newer, AOT caches JDK 25");
        }
        if (effective.has(ProfileComponent.NOIDLE)) {
            String why = IdleStateHold.unavailable(IdleStateHold.DEVICE);
            if (why != null) {
                return Support.no(why);
            }
        }
        if (!plan.prefix().isEmpty()) {
            Support s = prefixAnswers.computeIfAbsent(plan.prefix(), ProfileProbe::tryPrefix);
            if (!s.supported()) {
                return s;
            }
        }
        if (runtime.isJvm() && !plan.jvmFlags().isEmpty()) {
            return checkFlags(runtime, plan.jvmFlags());
        }
        return Support.OK;
    }

    /** Whether the JVM starts with {@code flags} (cached). */
    public synchronized Support checkFlags(RuntimeInfo runtime, List<String> flags) {
        String key = cacheKey(runtime.realPath(), flags);
        String cached = key == null ? null : cache.getProperty(key);
        if (cached != null) {
            return cached.equals("ok") ? Support.OK : Support.no(cached);
        }
        List<String> cmd = new ArrayList<>();
        cmd.add(runtime.path().toString());
        cmd.addAll(flags);
        cmd.add("-version");
        ProcessRunner.Result r = ProcessRunner.run(cmd, JvmProber.PROBE_TIMEOUT_MS);
        Support s;
        if (r.ok()) {
            s = Support.OK;
        } else if (r.timedOut()) {
            return Support.no("timed out answering -version with " + String.join(" ", flags)); // not cached: may be load
        } else {
            s = Support.no("rejected " + String.join(" ", flags) + ": " + firstMeaningfulLine(r.output()));
        }
        if (key != null) {
            cache.setProperty(key, s.supported() ? "ok" : s.reason());
            save();
        }
        return s;
    }

    private static Support tryPrefix(List<String> prefix) {
        List<String> cmd = new ArrayList<>(prefix);
        cmd.add("true");
        ProcessRunner.Result r = ProcessRunner.run(cmd, 10_000);
        if (r.ok()) {
            return Support.OK;
        }
        return Support.no(String.join(" ", prefix) + " not permitted here: " + firstMeaningfulLine(r.output()));
    }

    /**
     * The line that says why: HotSpot's generic lines ("Error occurred during initialization of VM",
     * which comes before "Too small maximum heap", and "Could not create the Java Virtual Machine")
     * only when nothing else is said.
     */
    static String firstMeaningfulLine(String output) {
        String generic = null;
        for (String line : output.split("\n")) {
            String l = line.strip();
            if (l.isEmpty() || l.startsWith("OpenJDK 64-Bit Server VM warning: Options -Xverify")) {
                continue;
            }
            if (l.equals("Error occurred during initialization of VM") || l.startsWith("Error: Could not create the Java Virtual Machine")
                    || l.startsWith("Error: A fatal exception has occurred")) {
                generic = generic == null ? l : generic;
                continue;
            }
            return l.length() > 300 ? l.substring(0, 300) : l;
        }
        return generic == null ? "no message" : generic;
    }

    private static String cacheKey(Path real, List<String> flags) {
        try {
            return real + "|" + Files.size(real) + "|" + Files.getLastModifiedTime(real).toMillis() + "|" + String.join(" ", flags);
        } catch (IOException e) {
            return null;
        }
    }

    private void save() {
        if (cacheFile == null) {
            return;
        }
        try {
            Files.createDirectories(cacheFile.getParent());
            Path tmp = Files.createTempFile(cacheFile.getParent(), "probes", ".tmp");
            try (OutputStream out = Files.newOutputStream(tmp)) {
                cache.store(out, "jmclbench: which JVM accepts which flags (delete to probe again)");
            }
            Files.move(tmp, cacheFile, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException ignored) {
            // the cache is an optimisation; the answer is still right
        }
    }
}
