package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;

import org.jmclbench.tooling.attribution.JfrFlags;
import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * What the report says of the configurations and machines behind its numbers, beside the numbers
 * themselves ({@link ReportModel}): which code made the runs, each configuration's versions, flags
 * and trust facts, each machine's doctor checks, and the machine labels that keep merged stores apart.
 */
final class ConfigurationFacts {
    private ConfigurationFacts() {
    }

    /**
     * Runs of two machines (merged stores) are never pooled: each runtime is shown per machine,
     * labelled by its host name, and by host name and machine id where two machines share a host
     * name (cloned VMs, containers), so that the label alone keeps them apart.
     */
    static void labelMachines(List<StoredRun> runs, Map<String, StoredRuns.Machine> machineRows) {
        Map<String, String> hostOf = new HashMap<>();
        for (StoredRun r : runs) {
            StoredRuns.Machine mc = machineRows.get(r.machineId);
            hostOf.put(String.valueOf(r.machineId), mc != null && mc.hostname() != null ? mc.hostname() : null);
        }
        if (hostOf.size() < 2) {
            return;
        }
        Map<String, Long> machinesPerHost = hostOf.values().stream().filter(Objects::nonNull)
                .collect(Collectors.groupingBy(h -> h, Collectors.counting()));
        for (StoredRun r : runs) {
            String id = String.valueOf(r.machineId);
            String host = hostOf.get(id);
            r.machineLabel = host == null ? id : machinesPerHost.get(host) > 1 ? host + " (" + id + ")" : host;
        }
    }

    /**
     * Which jmclbench code made the runs, oldest first: a store resumed after a change holds runs of
     * more than one commit, and a reader must see that before comparing them.
     */
    static String codeVersions(List<StoredRun> runs) {
        if (runs.isEmpty()) {
            return "none yet"; // no version at all is not "more than one"
        }
        Map<String, List<StoredRun>> byVersion = runs.stream().collect(Collectors.groupingBy(
                r -> r.codeVersion == null ? "" : r.codeVersion, LinkedHashMap::new, Collectors.toList()));
        Comparator<List<StoredRun>> byFirstStart = Comparator.comparing(
                rs -> rs.stream().map(r -> r.startedAt).filter(Objects::nonNull).min(Comparator.naturalOrder()).orElse(""));
        if (byVersion.size() == 1) {
            String only = byVersion.keySet().iterator().next();
            return only.isEmpty() ? "which jmclbench version made them is not recorded: the store predates that"
                    : "every run by jmclbench commit " + only;
        }
        List<String> parts = byVersion.entrySet().stream().sorted(Map.Entry.comparingByValue(byFirstStart))
                .map(e -> e.getValue().size() + (e.getValue().size() == 1 ? " run" : " runs")
                        + (e.getKey().isEmpty() ? " by a version not recorded" : " by commit " + e.getKey()))
                .toList();
        return "made by more than one version of jmclbench, oldest first: " + String.join(", ", parts);
    }

    /** The kind of a stored run, from its runtime, engine and summary. */
    static RuntimeKind kindOf(StoredRun run) {
        return RuntimeKind.of(run.runtime, run.engine, run.summary());
    }

    static List<ReportModel.ConfigInfo> configs(List<StoredRun> runs) {
        Map<String, List<StoredRun>> byConfig = new LinkedHashMap<>();
        runs.stream().sorted(Comparator.comparing(StoredRun::configOnMachine))
                .forEach(r -> byConfig.computeIfAbsent(r.configOnMachine(), k -> new ArrayList<>()).add(r));
        Map<String, RuntimeKind> kinds = new LinkedHashMap<>();
        byConfig.forEach((id, rs) -> kinds.put(id, kindOf(rs.stream().filter(StoredRun::ok).findFirst().orElse(rs.get(0)))));
        Map<String, String> colors = Palette.runtimes(kinds);
        List<ReportModel.ConfigInfo> out = new ArrayList<>();
        for (Map.Entry<String, List<StoredRun>> e : byConfig.entrySet()) {
            StoredRun first = e.getValue().get(0);
            Set<String> versions = new LinkedHashSet<>();
            List<String> flags = new ArrayList<>(); // a list: an argument may repeat ("-n 1 ... --seed 1")
            Set<String> machines = new LinkedHashSet<>();
            List<String> facts = new ArrayList<>();
            Execution execution = null;
            for (StoredRun r : e.getValue()) {
                if (r.ok() && execution == null) {
                    execution = Execution.of(kinds.get(e.getKey()), r.engine, r.memory, r.summary());
                }
                if (r.runtimeVersion != null) {
                    versions.add(r.runtimeVersion);
                }
                if (r.machineId != null) {
                    machines.add(r.machineId);
                }
                if (r.ok() && facts.isEmpty()) {
                    facts.addAll(facts(r.summary()));
                }
                if (r.ok() && flags.isEmpty()) {
                    JsonNode rt = r.summary().at("/environment/runtime");
                    rt.path("inputArguments").forEach(a -> shownFlag(a.asText()).ifPresent(flags::add));
                    if (versions.isEmpty() && rt.hasNonNull("version")) {
                        versions.add(rt.path("version").asText());
                    }
                }
            }
            out.add(new ReportModel.ConfigInfo(e.getKey(), first.runtime, first.profile, first.engine, first.memory, kinds.get(e.getKey()),
                    colors.get(e.getKey()), List.copyOf(versions), List.copyOf(flags), List.copyOf(machines), List.copyOf(facts), execution));
        }
        return out;
    }

    /**
     * A JVM argument as the page shows it. What the harness adds to every run says nothing about the
     * configuration: its JFR recording's or GC log's per-run file names (three lines of paths a
     * runtime) are cut to the option's name, and the workload's home folder is left out.
     */
    static Optional<String> shownFlag(String arg) {
        if (arg.startsWith("-Djmclbench.home=")) {
            return Optional.empty();
        }
        return Optional.of(JfrFlags.withoutRunPaths(arg));
    }

    /** What says how far a run's numbers can be trusted: scheduling, priorities, allocation (FORMATS.md 4). */
    static List<String> facts(JsonNode summary) {
        List<String> out = new ArrayList<>();
        JsonNode params = summary.path("parameters");
        if (params.hasNonNull("timeScale") && params.get("timeScale").asDouble() != 1.0) {
            out.add("replayed at time scale " + params.get("timeScale").asText() + " (deadlines scaled too)");
        }
        JsonNode kind = summary.at("/engine/kind");
        if (kind.isTextual()) {
            // the HVM's mode (compiled to C or interpreted) is what its row measures, so the report says it
            String mode = summary.at("/engine/mode").isTextual() ? ", " + summary.at("/engine/mode").asText() : "";
            out.add("engine " + kind.asText() + (summary.at("/engine/level").isInt()
                    ? " (SCJ level " + summary.at("/engine/level").asInt() + mode + ")" : mode.isEmpty() ? "" : " (" + mode.substring(2) + ")"));
        }
        if (params.hasNonNull("memory")) {
            out.add("memory " + params.get("memory").asText());
        }
        JsonNode sched = summary.at("/environment/scheduling");
        if (sched.hasNonNull("policy")) {
            out.add("scheduling " + sched.get("policy").asText()
                    + (sched.hasNonNull("priority") ? " priority " + sched.get("priority").asText() : ""));
        }
        JsonNode engine = summary.path("engine");
        if (engine.hasNonNull("prioritiesApplied")) {
            out.add(engine.get("prioritiesApplied").asBoolean() ? "thread priorities applied" : "thread priorities not applied by the OS");
        }
        if (engine.hasNonNull("allocatedBytes")) {
            out.add(engine.get("allocatedBytes").asText() + " bytes allocated while measuring");
        }
        if (summary.at("/environment").hasNonNull("clocksource")) {
            out.add("clocksource " + summary.at("/environment/clocksource").asText());
        }
        return out;
    }

    static List<ReportModel.MachineInfo> machines(StoredRuns store) {
        ObjectMapper json = new ObjectMapper();
        List<ReportModel.MachineInfo> out = new ArrayList<>();
        for (StoredRuns.Machine mc : store.machines().values()) {
            List<Map<String, String>> checks = new ArrayList<>();
            String virtualization = null;
            try {
                JsonNode doctor = mc.doctorJson() == null ? null : json.readTree(mc.doctorJson());
                if (doctor != null && doctor.isArray()) {
                    for (JsonNode check : doctor) {
                        Map<String, String> row = new LinkedHashMap<>();
                        for (String k : List.of("check", "status", "value", "advice")) {
                            row.put(k, check.hasNonNull(k) ? check.get(k).asText() : "");
                        }
                        checks.add(row);
                        String name = row.get("check").toLowerCase(java.util.Locale.ROOT);
                        if (virtualization == null && (name.contains("virt") || name.contains("hypervisor"))) {
                            virtualization = row.get("value");
                        }
                    }
                }
            } catch (Exception e) {
                checks.add(Map.of("check", "doctor_json", "status", "unreadable", "value", "", "advice", ""));
            }
            out.add(new ReportModel.MachineInfo(mc.machineId(), mc.hostname(), mc.kernel(), mc.cpuModel(), mc.processors(),
                    virtualization, checks));
        }
        return out;
    }
}
