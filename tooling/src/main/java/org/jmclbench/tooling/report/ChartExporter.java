package org.jmclbench.tooling.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Rectangle;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Rectangle2D;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

import org.jfree.chart.ChartUtils;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.CategoryAxis;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.category.StatisticalBarRenderer;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.title.TextTitle;
import org.jfree.data.statistics.DefaultStatisticalCategoryDataset;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;
import org.jfree.svg.SVGGraphics2D;
import org.jfree.svg.SVGUtils;

/**
 * Renders the report's charts on the server side with JFreeChart and writes each as SVG
 * (JFreeSVG) and PNG beside the page, for papers and slides; the page links to them.
 */
final class ChartExporter {

    static final int WIDTH = 900;
    /** The page's palette, so that a runtime has the same colour in the page and the files. */
    static final Color[] PALETTE = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c), new Color(0xff7f0e),
        new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf), new Color(0xbcbd22),
        new Color(0x7f7f7f), new Color(0x393b79), new Color(0xad494a), new Color(0x637939), new Color(0x8c6d31),
        new Color(0x843c39), new Color(0x7b4173)};
    static final int HEIGHT = 520;

    private final ReportModel model;
    private final Path dir;

    ChartExporter(ReportModel model, Path dir) {
        this.model = model;
        this.dir = dir;
    }

    /** A chart file's stem: names from the store are reduced to safe file-name characters. */
    static String stem(String kind, String dataset, String policy, Integer particles) {
        StringBuilder sb = new StringBuilder(safe(dataset)).append('-').append(safe(policy));
        if (particles != null) {
            sb.append('-').append(particles);
        }
        return sb.append('-').append(kind).toString();
    }

    static String safe(String s) {
        String t = s.replaceAll("[^A-Za-z0-9._-]", "_");
        return t.isEmpty() || t.startsWith(".") ? "_" + t : t;
    }

    /** Writes every chart of every setting; returns the number of files written. */
    int exportAll(Consumer<String> progress) throws IOException {
        Files.createDirectories(dir);
        List<Runnable> jobs = new ArrayList<>();
        List<Exception> errors = new ArrayList<>();
        for (String dataset : model.datasets) {
            for (String policy : model.policies) {
                List<ReportModel.Cell> cells = model.cells.stream()
                        .filter(c -> c.dataset.equals(dataset) && c.policy.equals(policy)).toList();
                if (cells.isEmpty()) {
                    continue;
                }
                String where = dataset + ", " + policy;
                jobs.add(() -> write(stem("misses", dataset, policy, null),
                        vsParticles("Deadline misses vs particles (" + where + ")", "missCount per run (mean, 95% CI)", cells, Metric.MISS_COUNT)));
                jobs.add(() -> write(stem("deviation", dataset, policy, null),
                        vsParticles("Mean deviation vs particles (" + where + ")", "deviation xy (m, mean, 95% CI)", cells, Metric.DEVIATION)));
                jobs.add(() -> write(stem("latency-jitter", dataset, policy, null), latencyJitter(where, cells)));
                for (Integer particles : model.particles) {
                    List<ReportModel.Cell> setting = cells.stream().filter(c -> c.particles == particles).toList();
                    if (setting.isEmpty()) {
                        continue;
                    }
                    String at = where + ", " + particles + " particles";
                    jobs.add(() -> write(stem("causes", dataset, policy, particles), causes(at, setting)));
                    jobs.add(() -> write(stem("latency-index", dataset, policy, particles), latencyIndex(at, setting)));
                    jobs.add(() -> write(stem("deviation-time", dataset, policy, particles), deviationTime(at, setting)));
                    jobs.add(() -> write(stem("trajectory", dataset, policy, particles), trajectory(at, dataset, setting)));
                    jobs.add(() -> write(stem("spectrum", dataset, policy, particles), spectrum(at, setting)));
                    jobs.add(() -> write(stem("jitter-cdf", dataset, policy, particles), jitterCdf(at, setting)));
                    jobs.add(() -> write(stem("memory", dataset, policy, particles), memory(at, setting)));
                }
            }
        }
        int[] done = {0};
        long start = System.nanoTime();
        long[] last = {start};
        jobs.parallelStream().forEach(job -> {
            try {
                job.run();
            } catch (RuntimeException e) {
                synchronized (errors) {
                    errors.add(e);
                }
            }
            synchronized (done) {
                done[0]++;
                if (System.nanoTime() - last[0] > 1_000_000_000L || done[0] == jobs.size()) {
                    progress.accept("charts " + ReportCommand.eta(done[0], jobs.size(), start));
                    last[0] = System.nanoTime();
                }
            }
        });
        if (!errors.isEmpty()) {
            throw new IOException("chart export failed: " + errors.get(0).getMessage(), errors.get(0));
        }
        return jobs.size() * 2;
    }

    /**
     * The evaluation's figures (EvaluationDocument), drawn by the report's own chart code: misses vs
     * particles with 95% CI error bars, a latency percentile spectrum, memory per area, causes.
     */
    void evaluationMisses(String stem, String title, List<ReportModel.Cell> cells) throws IOException {
        Files.createDirectories(dir);
        write(stem, vsParticles(title, "deadline misses per run (mean, 95% CI)", cells, Metric.MISS_COUNT));
    }

    void evaluationSpectrum(String stem, String at, List<ReportModel.Cell> cells) throws IOException {
        Files.createDirectories(dir);
        write(stem, spectrum(at, cells));
    }

    void evaluationMemory(String stem, String at, List<ReportModel.Cell> cells) throws IOException {
        Files.createDirectories(dir);
        write(stem, memory(at, cells));
    }

    void evaluationCauses(String stem, String at, List<ReportModel.Cell> cells) throws IOException {
        Files.createDirectories(dir);
        write(stem, causes(at, cells));
    }

    /**
     * Horizontal bars: per configuration, the largest particle count it sustained with no miss
     * (0 where even the smallest count missed), in the configurations' colours.
     */
    void evaluationSustainable(String stem, String title, Map<String, Integer> sustained) throws IOException {
        Files.createDirectories(dir);
        org.jfree.data.category.DefaultCategoryDataset data = new org.jfree.data.category.DefaultCategoryDataset();
        sustained.forEach((config, n) -> data.addValue(n, "particles", config));
        org.jfree.chart.renderer.category.BarRenderer renderer = new org.jfree.chart.renderer.category.BarRenderer() {
            private static final long serialVersionUID = 1L;

            @Override
            public java.awt.Paint getItemPaint(int row, int column) {
                Color c = colorOf(String.valueOf(data.getColumnKey(column)));
                return c != null ? c : PALETTE[column % PALETTE.length];
            }
        };
        renderer.setShadowVisible(false);
        renderer.setBarPainter(new org.jfree.chart.renderer.category.StandardBarPainter());
        renderer.setDefaultItemLabelGenerator(new org.jfree.chart.labels.StandardCategoryItemLabelGenerator());
        renderer.setDefaultItemLabelsVisible(true);
        // the count at the end of its bar, so that a 0 (missed even at the smallest count) is read too
        renderer.setDefaultPositiveItemLabelPosition(new org.jfree.chart.labels.ItemLabelPosition(
                org.jfree.chart.labels.ItemLabelAnchor.OUTSIDE3, org.jfree.chart.ui.TextAnchor.CENTER_LEFT));
        renderer.setMaximumBarWidth(0.08);
        CategoryAxis x = new CategoryAxis("runtime / engine memory style");
        x.setMaximumCategoryLabelLines(2);
        NumberAxis y = new NumberAxis("largest particle count with no miss");
        y.setUpperMargin(0.12);
        CategoryPlot plot = new CategoryPlot(data, x, y, renderer);
        plot.setOrientation(org.jfree.chart.plot.PlotOrientation.HORIZONTAL);
        plot.setRangeAxisLocation(org.jfree.chart.axis.AxisLocation.BOTTOM_OR_RIGHT);
        write(stem, finish(new JFreeChart(title, JFreeChart.DEFAULT_TITLE_FONT, plot, false)));
    }

    private void write(String stem, JFreeChart chart) {
        try {
            ChartUtils.saveChartAsPNG(dir.resolve(stem + ".png").toFile(), chart, WIDTH, HEIGHT);
            SVGGraphics2D g2 = new SVGGraphics2D(WIDTH, HEIGHT);
            g2.setGeomDoubleConverter(ChartExporter::twoDecimals); // a hundredth of a pixel is plenty
            chart.draw(g2, new Rectangle(0, 0, WIDTH, HEIGHT));
            SVGUtils.writeToSVG(dir.resolve(stem + ".svg").toFile(), g2.getSVGElement());
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** The colour of the runtime a series belongs to (longest matching name), or null. */
    private Color colorOf(String series) {
        int best = -1;
        int bestLength = -1;
        for (int i = 0; i < model.configs.size(); i++) {
            String id = model.configs.get(i).id();
            if ((series.equals(id) || series.startsWith(id + " ")) && id.length() > bestLength) {
                best = i;
                bestLength = id.length();
            }
        }
        return best < 0 ? null : PALETTE[best % PALETTE.length];
    }

    private void colour(org.jfree.chart.renderer.AbstractRenderer r, List<String> names) {
        for (int i = 0; i < names.size(); i++) {
            Color c = colorOf(names.get(i));
            if (c != null) {
                r.setSeriesPaint(i, c);
            }
        }
    }

    /** Log axis ticks at powers of ten, printed as plain numbers. */
    static LogAxis logAxis(String label, java.text.NumberFormat format) {
        LogAxis a = new LogAxis(label);
        a.setStandardTickUnits(NumberAxis.createIntegerTickUnits());
        a.setNumberFormatOverride(format);
        return a;
    }

    /** 1/(1-p) printed as the percentile p: 10 -> 90%, 1000 -> 99.9%. */
    static final class PercentileFormat extends java.text.NumberFormat {
        private static final long serialVersionUID = 1L;

        @Override
        public StringBuffer format(double v, StringBuffer to, java.text.FieldPosition pos) {
            double p = 100 - 100 / v;
            int decimals = Math.max(0, (int) Math.round(Math.log10(v)) - 2);
            return to.append(String.format(java.util.Locale.ROOT, "%." + decimals + "f%%", Math.max(0, p)));
        }

        @Override
        public StringBuffer format(long v, StringBuffer to, java.text.FieldPosition pos) {
            return format((double) v, to, pos);
        }

        @Override
        public Number parse(String source, java.text.ParsePosition pos) {
            throw new UnsupportedOperationException();
        }
    }

    private JFreeChart vsParticles(String title, String yLabel, List<ReportModel.Cell> cells, Metric metric) {
        DefaultStatisticalCategoryDataset data = new DefaultStatisticalCategoryDataset();
        for (ReportModel.Cell c : sortByParticles(cells)) {
            ReportModel.Agg a = c.metrics.get(metric.name());
            if (a.mean() != null) {
                data.add(a.mean().doubleValue(), a.half() == null ? 0.0 : a.half().doubleValue(), c.config, Integer.valueOf(c.particles));
            }
        }
        StatisticalBarRenderer renderer = new StatisticalBarRenderer();
        renderer.setErrorIndicatorPaint(Color.BLACK);
        renderer.setShadowVisible(false);
        renderer.setBarPainter(new org.jfree.chart.renderer.category.StandardBarPainter());
        List<String> names = new ArrayList<>();
        for (int i = 0; i < data.getRowCount(); i++) {
            names.add(String.valueOf(data.getRowKey(i)));
        }
        colour(renderer, names);
        NumberAxis y = new NumberAxis(yLabel);
        CategoryPlot plot = new CategoryPlot(data, new CategoryAxis("particles"), y, renderer);
        if (y.getLowerBound() < 0) {
            y.setLowerBound(0); // a count or a distance is never negative: the interval is cut at zero
        }
        return finish(new JFreeChart(title, JFreeChart.DEFAULT_TITLE_FONT, plot, true));
    }

    private JFreeChart latencyJitter(String where, List<ReportModel.Cell> cells) {
        Map<String, XYSeries> series = new LinkedHashMap<>();
        for (ReportModel.Cell c : sortByParticles(cells)) {
            add(series, c.config + " task latency", c.particles, c.metrics.get(Metric.LATENCY_MEAN.name()).mean());
            add(series, c.config + " release jitter", c.particles, c.metrics.get(Metric.JITTER_MEAN.name()).mean());
        }
        JFreeChart chart = xy("Average task latency and release jitter vs particles (" + where + ")", "particles",
                new NumberAxis("time (ms, mean over repetitions; dashed: release jitter)"), series, true, true);
        List<String> names = new ArrayList<>(series.keySet());
        for (int i = 0; i < names.size(); i++) {
            if (names.get(i).endsWith(" release jitter")) {
                chart.getXYPlot().getRenderer().setSeriesStroke(i, new BasicStroke(1.5f, BasicStroke.CAP_BUTT,
                        BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f));
            }
        }
        return chart;
    }

    /** Cause kinds in the page's order and colours (report.js CAUSE_ORDER, CAUSE_COLORS). */
    static final Map<String, Color> CAUSE_COLORS = causeColors();

    private static Map<String, Color> causeColors() {
        Map<String, Color> m = new LinkedHashMap<>();
        String[][] kinds = {{"gc", "d62728"}, {"safepoint", "9467bd"}, {"jit", "ff7f0e"}, {"deopt", "ffbb78"},
                {"classload", "e7ba52"}, {"lock", "393b79"}, {"os", "8c564b"}, {"preemption", "e377c2"},
                {"compute", "1f77b4"}, {"queued", "17becf"}, {"overlap", "bcbd22"}, {"unknown", "7f7f7f"}};
        for (String[] k : kinds) {
            m.put(k[0], new Color(Integer.parseInt(k[1], 16)));
        }
        return m;
    }

    /** Stacked bars: per runtime, the jobs missed or late per run by primary cause. */
    private JFreeChart causes(String at, List<ReportModel.Cell> cells) {
        List<String> kinds = new ArrayList<>(CAUSE_COLORS.keySet());
        for (ReportModel.Cell c : cells) {
            c.causes.keySet().stream().filter(k -> !kinds.contains(k)).forEach(kinds::add);
        }
        org.jfree.data.category.DefaultCategoryDataset data = new org.jfree.data.category.DefaultCategoryDataset();
        List<String> used = new ArrayList<>();
        for (String kind : kinds) {
            if (cells.stream().noneMatch(c -> c.causes.containsKey(kind))) {
                continue;
            }
            used.add(kind);
            for (ReportModel.Cell c : cells) {
                if (!c.causes.isEmpty()) {
                    data.addValue(c.causes.getOrDefault(kind, 0.0), kind, c.config);
                }
            }
        }
        org.jfree.chart.renderer.category.StackedBarRenderer renderer = new org.jfree.chart.renderer.category.StackedBarRenderer();
        renderer.setShadowVisible(false);
        renderer.setBarPainter(new org.jfree.chart.renderer.category.StandardBarPainter());
        for (int i = 0; i < used.size(); i++) {
            Color c = CAUSE_COLORS.get(used.get(i));
            if (c != null) {
                renderer.setSeriesPaint(i, c);
            }
        }
        CategoryPlot plot = new CategoryPlot(data, new CategoryAxis("runtime/profile"),
                new NumberAxis("jobs missed or late per run, by primary cause (mean)"), renderer);
        // Bars across, so that each configuration's full name fits beside its bar.
        plot.setOrientation(org.jfree.chart.plot.PlotOrientation.HORIZONTAL);
        return finish(new JFreeChart("Why deadlines were missed (" + at + ")", JFreeChart.DEFAULT_TITLE_FONT, plot, true));
    }

    /** Area colours as on the page (report.js AREA_COLORS, PRIVATE_COLORS). */
    static final Map<String, Color> AREA_COLORS = Map.of("heap", new Color(0x7f7f7f), "immortal", new Color(0x393b79),
            "mission", new Color(0x2ca02c));
    static final Color[] PRIVATE_COLORS = {new Color(0xff7f0e), new Color(0xe377c2), new Color(0x17becf), new Color(0xbcbd22),
        new Color(0x8c564b), new Color(0x9467bd)};

    /**
     * Grouped bars on a log axis: per configuration (runtime, engine, memory style), the peak bytes of
     * each memory area; an area with a peak of 0 has no bar (as on the page).
     */
    private JFreeChart memory(String at, List<ReportModel.Cell> cells) {
        List<ReportModel.Cell> withAreas = cells.stream().filter(c -> !c.memoryAreas.isEmpty())
                .sorted(java.util.Comparator.comparingInt(c -> configIndex(c.config))).toList();
        List<String> names = new ArrayList<>();
        for (ReportModel.Cell c : withAreas) {
            c.memoryAreas.stream().map(ReportModel.MemoryArea::name).filter(n -> !names.contains(n)).forEach(names::add);
        }
        names.sort(java.util.Comparator.comparingInt(n -> {
            int i = ReportModel.AREA_ORDER.indexOf(n);
            return i < 0 ? ReportModel.AREA_ORDER.size() : i;
        }));
        org.jfree.data.category.DefaultCategoryDataset data = new org.jfree.data.category.DefaultCategoryDataset();
        for (String n : names) {
            for (ReportModel.Cell c : withAreas) {
                Long peak = c.memoryAreas.stream().filter(a -> a.name().equals(n)).map(ReportModel.MemoryArea::peakBytes)
                        .filter(v -> v != null).findFirst().orElse(null);
                data.addValue(peak == null || peak <= 0 ? null : peak.doubleValue(), n, c.config);
            }
        }
        org.jfree.chart.renderer.category.BarRenderer renderer = new org.jfree.chart.renderer.category.BarRenderer();
        renderer.setShadowVisible(false);
        renderer.setBarPainter(new org.jfree.chart.renderer.category.StandardBarPainter());
        int privateIndex = 0;
        for (int i = 0; i < names.size(); i++) {
            Color c = AREA_COLORS.get(names.get(i));
            renderer.setSeriesPaint(i, c != null ? c : PRIVATE_COLORS[privateIndex++ % PRIVATE_COLORS.length]);
        }
        ValueAxis y;
        if (data.getRowCount() > 0) {
            LogAxis log = logAxis("peak bytes (log)", new ByteFormat());
            log.setSmallestValue(1);
            y = log;
        } else {
            y = new NumberAxis("peak bytes (no memory areas reported)");
        }
        CategoryAxis x = new CategoryAxis("runtime / engine memory style");
        x.setMaximumCategoryLabelLines(3); // long names wrap: temurin-25/default / scj scoped
        CategoryPlot plot = new CategoryPlot(data, x, y, renderer);
        return finish(new JFreeChart("Peak bytes per memory area (" + at + ")", JFreeChart.DEFAULT_TITLE_FONT, plot, true));
    }

    /** Bytes in decimal units, as on the page: 1 B, 10 kB, 2 MB. */
    static final class ByteFormat extends java.text.NumberFormat {
        private static final long serialVersionUID = 1L;
        private static final String[] UNITS = {"B", "kB", "MB", "GB"};

        @Override
        public StringBuffer format(double v, StringBuffer to, java.text.FieldPosition pos) {
            int i = 0;
            while (Math.abs(v) >= 1000 && i < UNITS.length - 1) {
                v /= 1000;
                i++;
            }
            return to.append(new java.math.BigDecimal(v).round(new java.math.MathContext(3)).stripTrailingZeros().toPlainString())
                    .append(' ').append(UNITS[i]);
        }

        @Override
        public StringBuffer format(long v, StringBuffer to, java.text.FieldPosition pos) {
            return format((double) v, to, pos);
        }

        @Override
        public Number parse(String source, java.text.ParsePosition pos) {
            throw new UnsupportedOperationException();
        }
    }

    private int configIndex(String config) {
        for (int i = 0; i < model.configs.size(); i++) {
            if (model.configs.get(i).id().equals(config)) {
                return i;
            }
        }
        return Integer.MAX_VALUE;
    }

    private JFreeChart latencyIndex(String at, List<ReportModel.Cell> cells) {
        Map<String, XYSeries> series = new LinkedHashMap<>();
        for (ReportModel.Cell c : cells) {
            thin(c.latencyPredict, EXPORT_POINTS, true).forEach(p -> add(series, c.config + " predict", p[0], p[1]));
            thin(c.latencyUpdate, EXPORT_POINTS, true).forEach(p -> add(series, c.config + " update", p[0], p[1]));
        }
        JFreeChart chart = xy("Task latency vs event index (" + at + ")", "event index",
                new NumberAxis("task latency (ms); dots: predict, triangles: update"), series, false, true);
        List<String> names = new ArrayList<>(series.keySet());
        java.awt.geom.Path2D.Double triangle = new java.awt.geom.Path2D.Double();
        triangle.moveTo(0, -3.5);
        triangle.lineTo(3, 2.5);
        triangle.lineTo(-3, 2.5);
        triangle.closePath();
        for (int i = 0; i < names.size(); i++) {
            if (names.get(i).endsWith(" update")) {
                ((XYLineAndShapeRenderer) chart.getXYPlot().getRenderer()).setSeriesShape(i, triangle);
            }
        }
        // The pauses of the first runtime that has some, as on the page.
        cells.stream().filter(c -> !c.pauses.isEmpty()).findFirst().ifPresent(c -> {
            for (int i = 0; i < c.pauses.size(); i++) {
                Color k = CAUSE_COLORS.getOrDefault(c.pauseKinds.get(i), Color.GRAY);
                chart.getXYPlot().addDomainMarker(new org.jfree.chart.plot.IntervalMarker(c.pauses.get(i)[0], c.pauses.get(i)[1],
                        new Color(k.getRed(), k.getGreen(), k.getBlue(), 48)), org.jfree.chart.ui.Layer.BACKGROUND);
            }
        });
        return chart;
    }

    private JFreeChart deviationTime(String at, List<ReportModel.Cell> cells) {
        Map<String, XYSeries> series = new LinkedHashMap<>();
        for (ReportModel.Cell c : cells) {
            for (int i = 0; i < c.deviation.size(); i++) {
                String name = c.config + " #" + c.deviationRepetitions.get(i);
                thin(c.deviation.get(i), EXPORT_POINTS, false).forEach(p -> add(series, name, p[0], p[1]));
            }
        }
        return xy("Deviation over time, repeated runs (" + at + ")", "time (s)", new NumberAxis("deviation xy (m)"), series, true, false);
    }

    private JFreeChart trajectory(String at, String dataset, List<ReportModel.Cell> cells) {
        Map<String, XYSeries> series = new LinkedHashMap<>();
        for (ReportModel.Cell c : cells) {
            if (!c.real.isEmpty() && !series.containsKey("real")) {
                XYSeries real = new XYSeries("real", false, true);
                c.real.forEach(p -> real.add(p[0], p[1]));
                series.put("real", real);
            }
        }
        for (ReportModel.Cell c : cells) {
            c.trajectory.forEach(p -> add(series, c.config + " estimate", p[0], p[1]));
        }
        ReportModel.Playground pg = model.playgrounds.getOrDefault(dataset, ReportModel.Playground.thesis());
        XYSeries beacons = new XYSeries("beacons", false, true);
        pg.beacons().forEach(b -> beacons.add(b[0], b[1]));
        series.put("beacons", beacons);
        NumberAxis y = new NumberAxis("y (m)");
        y.setRange(-0.1, pg.height() + 0.1);
        JFreeChart chart = xy("Estimated vs real trajectory (" + at + ")", "x (m)", y, series, true, false);
        XYPlot plot = chart.getXYPlot();
        plot.getDomainAxis().setRange(-0.1, pg.width() + 0.1);
        XYLineAndShapeRenderer r = (XYLineAndShapeRenderer) plot.getRenderer();
        int b = series.size() - 1;
        r.setSeriesLinesVisible(b, false);
        r.setSeriesShapesVisible(b, true);
        r.setSeriesShape(b, new Rectangle2D.Double(-6, -6, 12, 12));
        r.setSeriesPaint(b, Color.BLACK);
        if (series.containsKey("real")) {
            r.setSeriesPaint(0, Color.DARK_GRAY);
            r.setSeriesStroke(0, new BasicStroke(2.5f));
        }
        plot.addAnnotation(new org.jfree.chart.annotations.XYShapeAnnotation(
                new Rectangle2D.Double(0, 0, pg.width(), pg.height()), new BasicStroke(1f), Color.GRAY));
        return chart;
    }

    private JFreeChart spectrum(String at, List<ReportModel.Cell> cells) {
        Map<String, XYSeries> series = new LinkedHashMap<>();
        for (ReportModel.Cell c : cells) {
            c.latencySpectrum.forEach(p -> add(series, c.config, p[0], Math.max(p[1], 1e-4)));
        }
        LogAxis x = logAxis("percentile (log scale of 1/(1-p))", new PercentileFormat());
        x.setSmallestValue(1);
        LogAxis y = logAxis("task latency (ms, log)", new java.text.DecimalFormat("0.####"));
        y.setSmallestValue(1e-4);
        JFreeChart chart = xy("Task latency by percentile, all jobs of all repetitions (" + at + ")", null, y, series, true, false);
        chart.getXYPlot().setDomainAxis(x);
        return chart;
    }

    private JFreeChart jitterCdf(String at, List<ReportModel.Cell> cells) {
        Map<String, XYSeries> series = new LinkedHashMap<>();
        for (ReportModel.Cell c : cells) {
            c.jitterCdf.forEach(p -> add(series, c.config, p[0], p[1]));
        }
        LogAxis x = logAxis("release jitter (ms, log)", new java.text.DecimalFormat("0.####"));
        x.setSmallestValue(1e-4);
        NumberAxis y = new NumberAxis("fraction of jobs");
        y.setRange(0, 1.02);
        JFreeChart chart = xy("CDF of release jitter (" + at + ")", null, y, series, true, false);
        chart.getXYPlot().setDomainAxis(x);
        return chart;
    }

    static String twoDecimals(double v) {
        double r = Math.round(v * 100) / 100.0;
        return r == Math.rint(r) ? Long.toString((long) r) : Double.toString(r);
    }

    /** Points per series in the exported files: enough for print, and the export stays fast. */
    static final int EXPORT_POINTS = 300;

    /** At most {@code max} points: every k-th, or with {@code keepPeaks} the largest y of each bucket. */
    static List<double[]> thin(List<double[]> points, int max, boolean keepPeaks) {
        if (points.size() <= max) {
            return points;
        }
        int bucket = (points.size() + max - 1) / max;
        List<double[]> out = new ArrayList<>();
        for (int i = 0; i < points.size(); i += bucket) {
            double[] best = points.get(i);
            for (int k = i + 1; keepPeaks && k < Math.min(points.size(), i + bucket); k++) {
                if (points.get(k)[1] > best[1]) {
                    best = points.get(k);
                }
            }
            out.add(best);
        }
        return out;
    }

    private static void add(Map<String, XYSeries> series, String name, double x, Double y) {
        if (y != null && Double.isFinite(y) && Double.isFinite(x)) {
            series.computeIfAbsent(name, n -> new XYSeries(n, false, true)).add(x, y);
        }
    }

    private static List<ReportModel.Cell> sortByParticles(List<ReportModel.Cell> cells) {
        return cells.stream().sorted(java.util.Comparator.comparingInt((ReportModel.Cell c) -> c.particles)).toList();
    }

    private JFreeChart xy(String title, String xLabel, ValueAxis yAxis, Map<String, XYSeries> series,
                                 boolean lines, boolean shapes) {
        XYSeriesCollection data = new XYSeriesCollection();
        series.values().forEach(data::addSeries);
        XYLineAndShapeRenderer renderer = new XYLineAndShapeRenderer(lines, shapes);
        renderer.setDrawOutlines(false);
        renderer.setDrawSeriesLineAsPath(true); // one SVG path a series, not one a segment
        for (int i = 0; i < series.size(); i++) {
            renderer.setSeriesShape(i, new Ellipse2D.Double(-2, -2, 4, 4));
        }
        colour(renderer, new ArrayList<>(series.keySet()));
        XYPlot plot = new XYPlot(data, new NumberAxis(xLabel == null ? "" : xLabel), yAxis, renderer);
        ((NumberAxis) plot.getDomainAxis()).setAutoRangeIncludesZero(false);
        return finish(new JFreeChart(title, JFreeChart.DEFAULT_TITLE_FONT, plot, true));
    }

    private static JFreeChart finish(JFreeChart chart) {
        chart.setBackgroundPaint(Color.WHITE);
        chart.getPlot().setBackgroundPaint(Color.WHITE);
        if (chart.getPlot() instanceof XYPlot p) {
            p.setDomainGridlinePaint(Color.LIGHT_GRAY);
            p.setRangeGridlinePaint(Color.LIGHT_GRAY);
        } else if (chart.getPlot() instanceof CategoryPlot p) {
            p.setRangeGridlinePaint(Color.LIGHT_GRAY);
        }
        TextTitle t = chart.getTitle();
        t.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        return chart;
    }
}
