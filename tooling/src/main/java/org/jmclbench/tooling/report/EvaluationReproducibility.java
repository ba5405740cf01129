package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import static org.jmclbench.tooling.report.EvaluationData.*;

/**
 * Section 2.14: every test the document made, made again on the previous evaluation's data. On a
 * shared 2-core VM a difference the rule separates one day can be gone the next; a reader should
 * know which of the document's findings this machine reproduced and which it did not.
 */
final class EvaluationReproducibility extends EvaluationSections {

    /** What the rule said of one pair in this evaluation and in the previous one. */
    enum Outcome {
        HELD("separated the same way in both"),
        NOW_ONLY("separated in this evaluation only"),
        BEFORE_ONLY("separated in the previous evaluation only"),
        OPPOSITE("separated the opposite way"),
        NEITHER("separated in neither"),
        ABSENT("not in the previous evaluation (a configuration or setting it did not run)");

        final String text;

        Outcome(String text) {
            this.text = text;
        }

        static Outcome of(Separation.Result now, Separation.Result before) {
            if (before == null) {
                return ABSENT;
            }
            if (now.separated() && before.separated()) {
                return now.verdict() == before.verdict() ? HELD : OPPOSITE;
            }
            return now.separated() ? NOW_ONLY : before.separated() ? BEFORE_ONLY : NEITHER;
        }
    }

    /** One of the document's tests with the same test on the previous data (null where that lacks a cell). */
    record Retest(Test test, Separation.Result before, Outcome outcome) {
    }

    private final EvaluationData previous;
    private final String previousSource;
    /** The previous evaluation's cells with a completed run, by {@link #key}. */
    private final Map<String, ReportModel.Cell> previousCells = new HashMap<>();

    /**
     * @param previous the previous evaluation's data, or null when there is none
     * @param previousSource how the document names the file it came from
     */
    EvaluationReproducibility(EvaluationSections document, EvaluationData previous, String previousSource) {
        super(document);
        this.previous = previous;
        this.previousSource = previousSource;
        if (previous != null) {
            previous.model.cells.stream().filter(c -> c.ok > 0).forEach(c -> previousCells.putIfAbsent(key(c), c));
        }
    }

    /**
     * Writes section 2.14.
     *
     * @return for the threats to validity, how many of the tests separated in either evaluation the other did not
     *         separate the same way, e.g. "7 of the 23 tests ..."; null without previous data
     */
    String section() throws java.io.IOException {
        line("### 2.14 Do the findings hold? This evaluation against the previous one (Table 14, Figure 14)");
        line("");
        if (previous == null || previous.dataset == null) {
            line("**No previous evaluation.** " + (previousSource == null
                    ? "None was named (`evaluate --no-run --db FILE` takes one with `--previous`)"
                    : "There is no earlier evaluation's data at `" + previousSource + "` (`./jmclbench evaluate` keeps the data it "
                            + "replaces there)") + ", so no test above is repeated on another day's runs.");
            line("");
            findings.add("Reproducibility: no previous evaluation to repeat the tests on (2.14).");
            return null;
        }
        List<Retest> retests = retests();
        Map<Outcome, Integer> counts = new LinkedHashMap<>();
        for (Outcome o : Outcome.values()) {
            counts.put(o, 0);
        }
        retests.forEach(r -> counts.merge(r.outcome(), 1, Integer::sum));
        line("Each comparison of two configurations above rests on one test (Mann-Whitney U with the bootstrap interval of the "
                + "ratio, docs/REPORT.md). Here each of the document's " + retests.size() + " distinct tests is made again on the "
                + "data of the previous evaluation, `" + previousSource + "` (" + previous.model.runPeriod + "; "
                + previous.model.codeVersions + "): the same two configurations at the same setting, on the same metric. A "
                + "difference separated in both evaluations the same way held; one separated in only one of them is a difference "
                + "this machine did not reproduce from one evaluation to the next, and is best read as not separated.");
        line("");
        line("Table 14: the document's tests by what the rule said in this evaluation and in the previous one.");
        line("");
        table(List.of("outcome", "tests"), counts.entrySet().stream()
                .map(e -> List.of(e.getKey().text, String.valueOf(e.getValue()))).toList());
        ChartSpec ratios = ratios(retests);
        if (ratios != null) {
            figure(ratios.stem(), "Figure 14: each test's ratio of the means B/A in this evaluation against the previous one, "
                    + "coloured by what the rule said of it; on the diagonal a ratio came back unchanged.", () -> charts.write(ratios));
        }
        List<Retest> separated = retests.stream()
                .filter(r -> r.test().result().separated() || r.outcome() == Outcome.BEFORE_ONLY).toList();
        if (!separated.isEmpty()) {
            line("The tests separated in either evaluation, in the document's order; B/A is the ratio of the means, each with "
                    + "what the rule said of it:");
            line("");
            table(List.of("A", "B", "setting", "metric", "this evaluation: B/A", "previous: B/A", "outcome"), separated.stream()
                    .map(r -> List.of(r.test().a().config, r.test().b().config, setting(r.test().a(), r.test().b()), r.test().metric().label,
                            said(r.test().result()), said(r.before()), r.outcome().text))
                    .toList());
        }
        long separatedNow = retests.stream().filter(r -> r.test().result().separated()).count();
        long absent = retests.stream().filter(r -> r.outcome() == Outcome.ABSENT && r.test().result().separated()).count();
        findings.add(String.format(Locale.ROOT, "Reproducibility: of the %d tests separated in this evaluation, the previous one "
                + "separated %d the same way, %d the opposite way and %d not at all, and did not run %d; it separated %d others "
                + "that this one does not (2.14).", separatedNow, counts.get(Outcome.HELD), counts.get(Outcome.OPPOSITE),
                counts.get(Outcome.NOW_ONLY), absent, counts.get(Outcome.BEFORE_ONLY)));
        int either = counts.get(Outcome.HELD) + counts.get(Outcome.NOW_ONLY) + counts.get(Outcome.BEFORE_ONLY) + counts.get(Outcome.OPPOSITE);
        return (either - counts.get(Outcome.HELD)) + " of the " + either + " tests that either evaluation separated";
    }

    /**
     * Figure 14: one mark per test that both evaluations made, x the previous ratio B/A, y this one's (log
     * both, a ratio of 0 or infinity left out), coloured by its outcome; the diagonal is the same ratio
     * twice. Null when no test has a ratio in both.
     */
    static ChartSpec ratios(List<Retest> retests) {
        List<ChartSpec.Series> series = new ArrayList<>();
        double lo = Double.POSITIVE_INFINITY;
        double hi = 0;
        for (Outcome o : Outcome.values()) {
            List<double[]> points = new ArrayList<>();
            List<String> notes = new ArrayList<>();
            for (Retest r : retests) {
                double now = r.test().result().ratio().ratio();
                double before = r.before() == null ? Double.NaN : r.before().ratio().ratio();
                if (r.outcome() != o || !(now > 0 && now < Double.POSITIVE_INFINITY && before > 0 && before < Double.POSITIVE_INFINITY)) {
                    continue;
                }
                points.add(new double[] {before, now});
                notes.add(r.test().b().config + " / " + r.test().a().config + ", " + r.test().metric().label + ": "
                        + num(before, 2) + "x before, " + num(now, 2) + "x now");
                lo = Math.min(lo, Math.min(before, now));
                hi = Math.max(hi, Math.max(before, now));
            }
            if (!points.isEmpty()) {
                series.add(new ChartSpec.Series(o.text, null, null, Palette.OUTCOME_COLORS.get(o.name()),
                        ChartSpec.Style.marks("circle", 4, null), points, null, null, null, notes));
            }
        }
        if (series.isEmpty()) {
            return null;
        }
        series.add(new ChartSpec.Series("the same ratio in both", null, null, "#000000", ChartSpec.Style.line(1).dashed(4f, 4f),
                List.of(new double[] {lo, lo}, new double[] {hi, hi}), null, null, null, null));
        ChartSpec.Axis before = new ChartSpec.Axis("B/A in the previous evaluation (ratio of the means)", ChartSpec.Scale.LOG,
                ChartSpec.Format.NUMBER, null, null);
        ChartSpec.Axis now = new ChartSpec.Axis("B/A in this evaluation (ratio of the means)", ChartSpec.Scale.LOG,
                ChartSpec.Format.NUMBER, null, null);
        return new ChartSpec("reproducibility", "reproducibility", null,
                "The document's tests in two evaluations", ChartSpec.Kind.LINES, false, before, now, null, series, List.of(), null, false);
    }

    /** The document's tests, each pair and metric once (in either order), with the same test on the previous data. */
    List<Retest> retests() {
        Map<String, Retest> byPair = new LinkedHashMap<>();
        for (Test t : tests) {
            String key = key(t.a()) + " ~ " + key(t.b()) + " ~ " + t.metric();
            String reversed = key(t.b()) + " ~ " + key(t.a()) + " ~ " + t.metric();
            if (byPair.containsKey(key) || byPair.containsKey(reversed)) {
                continue;
            }
            ReportModel.Cell a = previousCells.get(key(t.a()));
            ReportModel.Cell b = previousCells.get(key(t.b()));
            Separation.Result before = a == null || b == null ? null : separationOf(a, b, t.metric());
            byPair.put(key, new Retest(t, before, Outcome.of(t.result(), before)));
        }
        return new ArrayList<>(byPair.values());
    }

    /** A cell's configuration and setting, which name the same cell in two evaluations. */
    private static String key(ReportModel.Cell c) {
        return c.config + " | " + c.dataset + " | " + c.policy + " | " + c.particles;
    }

    /** Where A and B were compared, e.g. {@code skip, 6400 particles}; {@code queue vs skip, 6400 particles} for two policies. */
    private String setting(ReportModel.Cell a, ReportModel.Cell b) {
        return (a.dataset.equals(data.dataset) && b.dataset.equals(data.dataset) ? "" : either(a.dataset, b.dataset) + ", ")
                + either(a.policy, b.policy) + ", " + either(String.valueOf(a.particles), String.valueOf(b.particles)) + " particles";
    }

    private static String either(String a, String b) {
        return a.equals(b) ? a : a + " vs " + b;
    }

    /** {@code 0.46x, separated}; {@code 1.02x, not separated}; {@code -} where the previous evaluation has no such pair. */
    private static String said(Separation.Result r) {
        if (r == null) {
            return "-";
        }
        double x = r.ratio().ratio();
        String ratio = Double.isFinite(x) ? num(x, 2) + "x" : Double.isInfinite(x) ? "inf (A's mean 0)" : "0/0";
        return ratio + ", " + switch (r.verdict()) {
            case A_LOWER, B_LOWER -> "separated";
            case NOT_SEPARATED -> "not separated";
            case TOO_FEW -> "too few runs";
        };
    }
}
