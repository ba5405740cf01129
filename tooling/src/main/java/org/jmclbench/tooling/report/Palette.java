package org.jmclbench.tooling.report;

import org.jmclbench.tooling.runtime.RuntimeKind;

import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The report's colours, one place for the page, the exported charts and the evaluation's figures:
 * one colour per runtime row (runtime, profile, engine, memory style, machine), fixed colours for
 * the causes of a miss and for the memory areas.
 */
final class Palette {

    /**
     * Forty colours, any two far apart and none pale on white: Tableau 10, then the next entries
     * of colorcet's glasbey_category10 (HoloViz, CC-BY 4.0), a palette that adds each colour as
     * far as it can from all before it, leaving out the few with less than 2:1 contrast on white.
     * A store's rows are many (the evaluation has over thirty) and a chart shows any few of them,
     * so every pair must stay apart, not only neighbours. Past forty, hues at the golden angle.
     */
    static final List<String> RUNTIME_COLORS = List.of("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
            "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#3a0183", "#004301", "#5e0040", "#b80080", "#004e53", "#6b6500",
            "#7d0200", "#6126ff", "#574964", "#8cb894", "#028268", "#8300a0", "#ad8944", "#5b3400", "#ff6f76", "#798cff",
            "#dd00ff", "#515646", "#00458a", "#ff018d", "#af98b5", "#b75700", "#027000", "#cd88ff", "#7a98b5", "#a56089",
            "#6f8957", "#bd7d76", "#8b2945", "#00adff");

    /** Cause kinds of docs/FORMATS.md 5, VM causes first, in a stable order and colour across settings. */
    static final Map<String, String> CAUSE_COLORS = orderedMap("gc", "#d62728", "safepoint", "#9467bd", "jit", "#ff7f0e",
            "deopt", "#ffbb78", "classload", "#e7ba52", "lock", "#393b79", "os", "#8c564b", "preemption", "#e377c2",
            "compute", "#1f77b4", "queued", "#17becf", "overlap", "#bcbd22", "unknown", "#7f7f7f");

    /** Memory areas: the heap, then SCJ's from the longest-lived; the handlers' private memories take {@link #PRIVATE_COLORS}. */
    static final Map<String, String> AREA_COLORS = orderedMap("heap", "#7f7f7f", "immortal", "#393b79", "mission", "#2ca02c");
    static final List<String> PRIVATE_COLORS = List.of("#ff7f0e", "#e377c2", "#17becf", "#bcbd22", "#8c564b", "#9467bd");

    /**
     * What the rule said of a test in two evaluations (section 2.14): held green, not reproduced
     * orange and purple, reversed red, never separated grey.
     */
    static final Map<String, String> OUTCOME_COLORS = orderedMap("HELD", "#2ca02c", "NOW_ONLY", "#ff7f0e",
            "BEFORE_ONLY", "#9467bd", "OPPOSITE", "#d62728", "NEITHER", "#7f7f7f");

    /** A pause band: its kind's cause colour, see-through. */
    static String bandColor(String kind) {
        String c = CAUSE_COLORS.getOrDefault(kind, "#7f7f7f");
        return String.format(Locale.ROOT, "rgba(%d, %d, %d, 0.16)", Integer.parseInt(c.substring(1, 3), 16),
                Integer.parseInt(c.substring(3, 5), 16), Integer.parseInt(c.substring(5, 7), 16));
    }

    private Palette() {
    }

    /**
     * A colour per configuration, in a fixed order (the C baseline, the JVMs, the HVM; then by name),
     * so that a row keeps its colour in every chart of a store, on the page and in the files.
     */
    static Map<String, String> runtimes(Map<String, RuntimeKind> configs) {
        Map<String, String> out = new LinkedHashMap<>();
        List<String> ordered = configs.keySet().stream().sorted(Comparator.comparing((String id) -> rank(configs.get(id)))
                .thenComparing(Comparator.naturalOrder())).toList();
        for (int i = 0; i < ordered.size(); i++) {
            out.put(ordered.get(i), color(i));
        }
        return out;
    }

    private static int rank(RuntimeKind kind) {
        return switch (kind) {
            case NATIVE -> 0;
            case JVM -> 1;
            case HVM -> 2;
        };
    }

    /** The i-th colour of a store's rows. */
    static String color(int i) {
        if (i < RUNTIME_COLORS.size()) {
            return RUNTIME_COLORS.get(i);
        }
        float hue = (float) (((i - RUNTIME_COLORS.size()) * 0.381966) % 1.0); // golden angle: each new hue far from the last
        return String.format(Locale.ROOT, "#%06x", java.awt.Color.HSBtoRGB(hue, 0.75f, 0.7f) & 0xffffff);
    }

    /** The colour of the i-th private memory area of a chart. */
    static String area(String name, int privateIndex) {
        String c = AREA_COLORS.get(name);
        return c != null ? c : PRIVATE_COLORS.get(privateIndex % PRIVATE_COLORS.size());
    }

    private static Map<String, String> orderedMap(String... kv) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            m.put(kv[i], kv[i + 1]);
        }
        return java.util.Collections.unmodifiableMap(m);
    }
}
