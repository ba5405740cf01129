package org.jmclbench.tooling.runtime;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** Lists the runtimes found on this machine and the profiles each supports. */
@Command(name = "jvms", mixinStandardHelpOptions = true,
        header = "Lists the runtimes found here and the profiles each supports.",
        description = {"Lists the runtimes found on this machine (JAVA_HOME, PATH, /usr/lib/jvm, SDKMAN, ~/.jdks, JDKs "
                + "installed by `jvm install`, the native baseline) and the profile components each supports. "
                + "Each JVM is asked once per flag set (`java <flags> -version`); answers are cached."})
public final class JvmsCommand implements Callable<Integer> {

    @Option(names = "--java", paramLabel = "PATH", description = "also list this JVM (repeatable)")
    List<String> javas = new ArrayList<>();

    @Option(names = "--no-probe", description = "do not probe profile support (faster)")
    boolean noProbe;

    @Option(names = "--json", description = "print JSON")
    boolean json;

    @Override
    public Integer call() throws Exception {
        RuntimeDiscovery d = RuntimeDiscovery.discover();
        for (String j : javas) {
            d.addJava(j);
        }
        ProfileProbe probe = ProfileProbe.withUserCache();
        String pin = LaunchPlan.defaultPinCpu();
        List<Map<String, Object>> rows = new ArrayList<>();
        List<RuntimeInfo> all = new ArrayList<>(d.all());
        HvmRuntime.Availability hvm = HvmRuntime.check(JmclbenchPaths.home());
        if (hvm.buildable()) {
            all.add(HvmRuntime.runtime());
        }
        for (RuntimeInfo r : all) {
            List<String> supported = new ArrayList<>();
            Map<String, String> unsupported = new LinkedHashMap<>();
            if (!noProbe) {
                supported.add(Profile.DEFAULT);
                for (ProfileComponent c : ProfileComponent.values()) {
                    if (!c.appliesTo(r.kind())) {
                        continue;
                    }
                    ProfileProbe.Support s = probe.check(r, Profile.parse(c.id(), "jvms"), pin);
                    if (s.supported()) {
                        supported.add(c.id());
                    } else {
                        unsupported.put(c.id(), s.reason());
                    }
                }
            }
            Map<String, Object> row = new LinkedHashMap<>();
            row.put("name", r.name());
            row.put("kind", r.kind().name().toLowerCase());
            row.put("vendor", r.vendor());
            row.put("version", r.version());
            row.put("path", r.path().toString());
            row.put("realPath", r.realPath().toString());
            if (!noProbe) {
                row.put("profiles", supported);
                row.put("unsupported", unsupported);
            }
            rows.add(row);
        }
        if (json) {
            System.out.println(new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValueAsString(rows));
            return 0;
        }
        if (rows.isEmpty()) {
            System.out.println("no runtime found (install one: ./jmclbench jvm install 21)");
            return 0;
        }
        System.out.printf("%-16s %-18s %-26s %s%n", "NAME", "VENDOR", "VERSION", "PATH");
        for (Map<String, Object> row : rows) {
            // the HVM is no JVM: its path is the JVM that builds and drives its executable
            Object path = "hvm".equals(row.get("kind")) ? "the mission compiled to C by hvm/ (driven from " + row.get("realPath")
                    + ")" : row.get("realPath");
            System.out.printf("%-16s %-18s %-26s %s%n", row.get("name"), row.get("vendor"), row.get("version"), path);
            if (!noProbe) {
                System.out.println("    profiles: " + String.join(" ", castList(row.get("profiles"))));
                @SuppressWarnings("unchecked")
                Map<String, String> un = (Map<String, String>) row.get("unsupported");
                un.forEach((k, v) -> System.out.println("    not supported: " + k + " (" + v + ")"));
            }
        }
        if (!hvm.buildable()) {
            System.out.println("hvm (the icecap HVM): cannot be built here: " + hvm.detail());
        }
        System.out.println();
        System.out.println("Profiles compose with '+', e.g. g1+pretouch+fifo+pinned or zgc+heap4g (any JVM's heap size: heap<N>m,"
                + " heap<N>g); the native runtime takes only fifo, pinned and noidle,"
                + " the hvm runtime those, int (its interpreter) and hot (hot methods compiled to C); compiled to C otherwise.");
        return 0;
    }

    @SuppressWarnings("unchecked")
    private static List<String> castList(Object o) {
        return (List<String>) o;
    }
}
