package org.jmclbench.tooling.report;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * One chart as data, built once from the store ({@link ChartSpecs}) and drawn by two renderers:
 * the page's script with Chart.js and {@link ChartExporter} with JFreeChart. Everything a reader
 * sees (what is plotted, titles, axis labels and scales, colours, the file name) is decided here;
 * a renderer only maps it onto its library. Serialised into the page as JSON.
 *
 * @param id         the figure it fills ({@code misses}, {@code spectrum}, ...; {@link ChartSpecs#FIGURES})
 * @param stem       the exported file's name without extension
 * @param setting    where in the store the chart is (particles null: a chart over the particle sweep; null: a
 *                   chart of no one setting, the evaluation's tests across settings, say)
 * @param kind       bars, stacked bars or x/y lines and marks
 * @param horizontal bars drawn across (categories on the vertical axis)
 * @param x          the category axis of bar charts, the x axis of lines
 * @param y          the value axis
 * @param categories the bars' categories (bar kinds only), in drawing order
 * @param series     what is drawn, in legend order
 * @param bands      shaded intervals of x behind the data (pauses), or empty
 * @param frame      a rectangle from (0, 0) drawn behind the data (the playground), or null
 * @param valueLabels each bar's value written at its end
 * @param legendPerRuntime the legend names each runtime once, by its runtime's name, in the colour of its
 *                   first series, and shows or hides all its series: the +infinity marks of a runtime are
 *                   explained by their band's label, not by an entry of their own
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record ChartSpec(String id, String stem, Setting setting, String title, Kind kind, boolean horizontal, Axis x, Axis y,
                        List<Category> categories, List<Series> series, List<Band> bands, Frame frame, boolean valueLabels,
                        boolean legendPerRuntime) {

    /** A chart whose legend names every series. */
    public ChartSpec(String id, String stem, Setting setting, String title, Kind kind, boolean horizontal, Axis x, Axis y,
                     List<Category> categories, List<Series> series, List<Band> bands, Frame frame, boolean valueLabels) {
        this(id, stem, setting, title, kind, horizontal, x, y, categories, series, bands, frame, valueLabels, false);
    }

    /**
     * Whether a chart of a setting draws nothing that belongs to a runtime: no series and no bar
     * category names one (the playground's beacons alone, say), so the chart says nothing of any run.
     */
    boolean aboutNoRuntime() {
        return setting != null && series.stream().noneMatch(s -> s.config() != null)
                && (categories == null || categories.stream().noneMatch(c -> c.config() != null));
    }

    /** How the series are drawn. */
    public enum Kind {
        /** Grouped bars, one value per category and series, optional error bars. */
        BARS,
        /** Bars stacked per category: a series is one segment; a missing value is a zero-height segment. */
        STACKED_BARS,
        /** Points on x/y axes, joined by a line and/or drawn as marks. */
        LINES
    }

    /** An axis' scale. */
    public enum Scale { LINEAR, LOG }

    /** How an axis' tick values are written. */
    public enum Format {
        /** Plain numbers. */
        NUMBER,
        /** x = 1/(1-p) written as the percentile p: 10 is 90%, 1000 is 99.9%. */
        PERCENTILE,
        /** Bytes in decimal units: 1 B, 10 kB, 2 MB. */
        BYTES
    }

    /** The dataset, policy and (for a chart at one load) particle count a chart shows. */
    public record Setting(String dataset, String policy, Integer particles) {
    }

    /**
     * An axis: its label (with the unit), scale, tick format and fixed bounds (null: from the data);
     * {@code beyond}, a band at its top for +infinity, or null.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Axis(String label, Scale scale, Format format, Double min, Double max, Beyond beyond) {
        /** An axis without a band for +infinity. */
        public Axis(String label, Scale scale, Format format, Double min, Double max) {
            this(label, scale, format, min, max, null);
        }

        static Axis linear(String label) {
            return new Axis(label, Scale.LINEAR, Format.NUMBER, null, null);
        }

        Axis range(Double lo, Double hi) {
            return new Axis(label, scale, format, lo, hi, beyond);
        }

        /** The same axis with a band for +infinity on top: its max is the band's top. */
        Axis beyond(Beyond band, double top) {
            return new Axis(label, scale, format, min, top, band);
        }
    }

    /**
     * A band above a linear axis' numbers for values that are no number: a response time of a job
     * that never completed (+infinity). The axis' ticks end at {@code from}, a break is drawn
     * there, the band reaches the axis' max and is named {@code label}; the marks of +infinity sit
     * at {@code at} inside it, where the only tick reads {@code tick}. A mark drawn at a number
     * read as that number (2.25 ms for +infinity in the evaluation's Figure 4f).
     */
    public record Beyond(double from, double at, String tick, String label) {
        /** What +infinity's tick and band read. */
        static final String TICK = "\u221e";
        static final String NEVER_COMPLETED = "\u221e: never completed (a dropped or aborted job)";
    }

    /** A bar category; {@code config} and {@code engine} name the runtime it belongs to (null: none). */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Category(String label, String config, String engine) {
    }

    /**
     * A series. {@code config} and {@code engine} name the runtime it belongs to, so that the page
     * can hide it with its runtime (null: a series of no runtime, the ground truth say).
     *
     * @param points  x/y pairs (LINES)
     * @param values  one per category, null where none (bar kinds)
     * @param errors  per value (bars) or per point (LINES), the interval [low, high] of y drawn as an
     *                error bar (null: none there), or null
     * @param colors  per value, its own colour (one series of bars in the runtimes' colours), or null
     * @param notes   per value or point, what a pointer over it reads, or null
     * @param xErrors per point (LINES), the interval [low, high] of x drawn as a horizontal error bar, or null
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Series(String name, String config, String engine, String color, Style style, List<double[]> points,
                         List<Double> values, List<double[]> errors, List<String> colors, List<String> notes,
                         List<double[]> xErrors) {
        /** A series without horizontal error bars. */
        public Series(String name, String config, String engine, String color, Style style, List<double[]> points,
                      List<Double> values, List<double[]> errors, List<String> colors, List<String> notes) {
            this(name, config, engine, color, style, points, values, errors, colors, notes, null);
        }
    }

    /**
     * How a series is drawn: a line of {@code width} (dashed: {@code dash} on/off lengths,
     * {@code stepped}), marks ({@code marker} circle, triangle or square, radius {@code size}; none
     * when null), marks filled with {@code fill} (null: the series colour; "none": hollow).
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Style(boolean line, double width, float[] dash, boolean stepped, String marker, double size, String fill) {
        static final Style BAR = new Style(false, 0, null, false, null, 0, null);

        static Style line(double width) {
            return new Style(true, width, null, false, null, 0, null);
        }

        static Style marks(String marker, double size, String fill) {
            return new Style(false, 0, null, false, marker, size, fill);
        }

        Style dashed(float... pattern) {
            return new Style(line, width, pattern, stepped, marker, size, fill);
        }

        Style steps() {
            return new Style(line, width, dash, true, marker, size, fill);
        }
    }

    /** A shaded interval [from, to] of x, of a kind (gc, safepoint), belonging to one runtime's run. */
    public record Band(double from, double to, String kind, String color, String config) {
    }

    /** A rectangle (0, 0) to (width, height) in data units. */
    public record Frame(double width, double height) {
    }

    /** The same chart with bands and a frame behind its data. */
    ChartSpec behind(List<Band> newBands, Frame newFrame) {
        return new ChartSpec(id, stem, setting, title, kind, horizontal, x, y, categories, series, newBands, newFrame,
                valueLabels, legendPerRuntime);
    }

    /** The same chart with other series (a reference line added, say). */
    ChartSpec withSeries(List<Series> newSeries) {
        return new ChartSpec(id, stem, setting, title, kind, horizontal, x, y, categories, newSeries, bands, frame,
                valueLabels, legendPerRuntime);
    }

    /** The same chart under another title (what it lacks, said). */
    ChartSpec withTitle(String newTitle) {
        return new ChartSpec(id, stem, setting, newTitle, kind, horizontal, x, y, categories, series, bands, frame,
                valueLabels, legendPerRuntime);
    }

    /** The same chart with a legend naming each runtime once ({@code legendPerRuntime}). */
    ChartSpec withLegendPerRuntime() {
        return new ChartSpec(id, stem, setting, title, kind, horizontal, x, y, categories, series, bands, frame, valueLabels, true);
    }

    /** The same chart under another file name (the evaluation's figures). */
    public ChartSpec withStem(String newStem) {
        return new ChartSpec(id, newStem, setting, title, kind, horizontal, x, y, categories, series, bands, frame,
                valueLabels, legendPerRuntime);
    }
}
