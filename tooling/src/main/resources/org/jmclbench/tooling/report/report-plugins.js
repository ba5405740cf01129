/*
 * jmclbench report page: the Chart.js plugins the charts of report.js use, registered once before
 * report.js runs: intervals as error bars, the playground's frame, GC and safepoint pause bands,
 * the band for +infinity, and a "0" where a log axis cannot draw a bar; and how the charts write their text
 * (window.jmclbenchText): bytes, log-axis tick labels, long titles, a legend per runtime.
 */
(function () {
  'use strict';
  /** A value's pixel on a scale; on a log scale a value at or below zero is the scale's low end. */
  function pixel(scale, v) { return scale.type === 'logarithmic' && v <= 0 ? scale.getPixelForValue(scale.min) : scale.getPixelForValue(v); }
  // Intervals [low, high] per bar or point: errorBars of y (vertical), xErrorBars of x (horizontal, points only).
  var errorBars = {
    id: 'jmclbenchErrorBars',
    afterDatasetsDraw: function (chart) {
      if (chart.options.indexAxis === 'y') { return; }
      var ctx = chart.ctx;
      chart.data.datasets.forEach(function (ds, i) {
        if (!ds.errorBars && !ds.xErrorBars) { return; }
        var meta = chart.getDatasetMeta(i);
        if (meta.hidden) { return; }
        var y = chart.scales[meta.yAxisID || 'y'], x = chart.scales[meta.xAxisID || 'x'];
        ctx.save(); ctx.strokeStyle = ds.errorBarColor || '#222'; ctx.lineWidth = 1.2;
        meta.data.forEach(function (item, j) {
          var e = ds.errorBars ? ds.errorBars[j] : null, w = Math.min(8, (item.width || 10) / 3);
          if (e && e[0] !== null && e[1] !== null) {
            var top = pixel(y, e[1]), bottom = pixel(y, e[0]);
            ctx.beginPath(); ctx.moveTo(item.x, top); ctx.lineTo(item.x, bottom);
            ctx.moveTo(item.x - w, top); ctx.lineTo(item.x + w, top); ctx.moveTo(item.x - w, bottom); ctx.lineTo(item.x + w, bottom);
            ctx.stroke();
          }
          var h = ds.xErrorBars ? ds.xErrorBars[j] : null;
          if (h && h[0] !== null && h[1] !== null) {
            var left = pixel(x, h[0]), right = pixel(x, h[1]);
            ctx.beginPath(); ctx.moveTo(left, item.y); ctx.lineTo(right, item.y);
            ctx.moveTo(left, item.y - w); ctx.lineTo(left, item.y + w); ctx.moveTo(right, item.y - w); ctx.lineTo(right, item.y + w);
            ctx.stroke();
          }
        });
        ctx.restore();
      });
    }
  };
  var frame = {
    id: 'jmclbenchFrame',
    beforeDatasetsDraw: function (chart) {
      var f = chart.options.plugins.jmclbenchFrame;
      if (!f || !f.width) { return; }
      var x = chart.scales.x, y = chart.scales.y, ctx = chart.ctx;
      ctx.save(); ctx.strokeStyle = '#888'; ctx.setLineDash([4, 3]);
      ctx.strokeRect(x.getPixelForValue(0), y.getPixelForValue(f.height), x.getPixelForValue(f.width) - x.getPixelForValue(0),
        y.getPixelForValue(0) - y.getPixelForValue(f.height));
      ctx.restore();
    }
  };
  var bands = {
    id: 'jmclbenchPauses',
    beforeDatasetsDraw: function (chart) {
      var list = chart.options.plugins.jmclbenchPauses;
      if (!list || !list.length) { return; }
      var x = chart.scales.x, area = chart.chartArea, ctx = chart.ctx;
      ctx.save();
      list.forEach(function (b) {
        var a = Math.max(area.left, x.getPixelForValue(b.from)), e = Math.min(area.right, x.getPixelForValue(b.to));
        if (e < area.left || a > area.right) { return; }
        ctx.fillStyle = b.color;
        ctx.fillRect(a, area.top, Math.max(1, e - a), area.bottom - area.top); // a pause shorter than a pixel still shows
      });
      ctx.restore();
    }
  };
  // A band for +infinity above the numbers (ChartSpec.Beyond): shaded, named, with a dashed break where the numbers end.
  var beyond = {
    id: 'jmclbenchBeyond',
    beforeDatasetsDraw: function (chart) {
      var b = chart.options.plugins.jmclbenchBeyond;
      if (!b || b.from === undefined) { return; } // Chart.js hands a plugin {} for its null options
      var y = chart.scales.y, area = chart.chartArea, ctx = chart.ctx, from = y.getPixelForValue(b.from);
      ctx.save(); ctx.fillStyle = '#eeeeee'; ctx.fillRect(area.left, area.top, area.right - area.left, from - area.top);
      ctx.strokeStyle = '#888'; ctx.lineWidth = 1.2; ctx.setLineDash([6, 4]);
      ctx.beginPath(); ctx.moveTo(area.left, from); ctx.lineTo(area.right, from); ctx.stroke();
      ctx.fillStyle = '#444'; ctx.font = '11px sans-serif'; ctx.textAlign = 'left'; ctx.textBaseline = 'top';
      ctx.fillText(b.label, area.left + 4, area.top + 2);
      ctx.restore();
    }
  };
  // A value of 0 has no bar on a log axis, and none to see on a linear one: a "0" marks it at the axis.
  var zeroMarks = {
    id: 'jmclbenchZeroMarks',
    afterDatasetsDraw: function (chart) {
      var ctx = chart.ctx, area = chart.chartArea;
      ctx.save(); ctx.fillStyle = '#333'; ctx.font = '10px sans-serif'; ctx.textAlign = 'center';
      chart.data.datasets.forEach(function (ds, i) {
        var meta = chart.getDatasetMeta(i);
        if (meta.hidden || !ds.zeros) { return; }
        ds.zeros.forEach(function (zero, j) { if (zero && meta.data[j]) { ctx.fillText('0', meta.data[j].x, area.bottom - 3); } });
      });
      ctx.restore();
    }
  };
  /** Bytes in decimal units (kB = 1000 B), as the log axis' powers of ten read best (ChartFormats.bytes). */
  function bytes(v) {
    if (v === null || v === undefined) { return '\u2013'; }
    var units = ['B', 'kB', 'MB', 'GB'], i = 0;
    while (Math.abs(v) >= 1000 && i < units.length - 1) { v /= 1000; i++; }
    return String(Number(v.toPrecision(3))) + ' ' + units[i];
  }
  /** A number for the tables: three significant digits or so (1.89, 0.403, 0.0083), or the given decimals. */
  function number(v, digits) {
    if (v === Infinity || v === 'Infinity') { return '\u221e'; } // a response time among jobs that never completed
    if (v === null || v === undefined || !isFinite(v)) { return '\u2013'; }
    if (v === 0) { return '0'; }
    return v.toFixed(digits === undefined ? decimals(v) : digits);
  }
  function decimals(v) { var a = Math.abs(v); return a >= 100 ? 1 : a >= 1 ? 2 : a >= 0.01 ? 3 : 4; }
  /**
   * "mean [low, high]", the three with the mean's decimals: each with its own, a mean of 0.0100 and
   * a low of 0.00998 read "0.010 [0.0100, 0.011]", the low as if it were above the mean.
   */
  function interval(agg, digits) {
    if (!agg || agg.mean === null || agg.mean === undefined) { return '\u2013'; }
    var d = digits !== undefined ? digits : agg.mean === 0 || !isFinite(agg.mean) ? undefined : decimals(agg.mean);
    return agg.low === null || agg.low === undefined ? number(agg.mean, d)
      : number(agg.mean, d) + ' [' + number(agg.low, d) + ', ' + number(agg.high, d) + ']';
  }
  var ONE_TWO_FIVE = [1, 2, 5];
  // A log axis labels 1, 2 and 5 times each power of ten; percentiles and bytes their powers alone
  // unless that labels fewer than three ticks (an axis of a decade or two), as the export does.
  function tickLabel(axis) {
    function whole(v) { var e = Math.log10(v); return Math.abs(e - Math.round(e)) < 1e-9; }
    return function (v, i, ticks) {
      var exp = Math.log10(v), m = v / Math.pow(10, Math.floor(exp + 1e-9));
      var oneTwoFive = ONE_TWO_FIVE.some(function (k) { return Math.abs(m - k) < 1e-6; });
      var few = ticks.filter(function (t) { return whole(t.value); }).length < 3;
      if (!(axis.format === 'NUMBER' || few ? oneTwoFive : whole(v))) { return null; }
      if (axis.format === 'PERCENTILE') { return v === 1 ? '0%' : (100 - 100 / v).toFixed(Math.max(0, Math.ceil(exp - 1e-9) - 2)) + '%'; }
      return axis.format === 'BYTES' ? bytes(v) : String(Number(v.toPrecision(3)));
    };
  }
  // A log axis fitted to data that hold fewer than three of those values (1 to 2.6 B) is carried
  // up to its third, as the export's: the largest value for it from (min, max).
  function threeLabelMax(min, max) {
    if (!(min > 0) || !(max > min)) { return max; }
    function count(hi) {
      var n = 0;
      for (var k = Math.floor(Math.log10(min)); k <= Math.ceil(Math.log10(hi)); k++) {
        ONE_TWO_FIVE.forEach(function (m) { var v = m * Math.pow(10, k); if (v >= min * (1 - 1e-9) && v <= hi * (1 + 1e-9)) { n++; } });
      }
      return n;
    }
    function next(v) {
      for (var e = Math.floor(Math.log10(v)); ; e++) {
        for (var i = 0; i < 3; i++) { var c = ONE_TWO_FIVE[i] * Math.pow(10, e); if (c > v * (1 + 1e-9)) { return c; } }
      }
    }
    var hi = max;
    for (var i = 0; i < 6 && count(hi) < 3; i++) { hi = next(hi); }
    return hi;
  }
  // A title that names the configurations left out runs to hundreds of characters, and Chart.js
  // squeezes one line into the chart's width until it cannot be read: cut it into lines of words
  // (of at most `width` characters, 80 unless said; a vertical axis's title has a chart's height).
  var TITLE_LINE = 80;
  function titleLines(text, width) {
    var most = width || TITLE_LINE, lines = [], line = '';
    text.split(' ').forEach(function (w) {
      if (line && (line + ' ' + w).length > most) { lines.push(line); line = w; } else { line = line ? line + ' ' + w : w; }
    });
    if (line) { lines.push(line); }
    return lines.length > 1 ? lines : text;
  }
  /**
   * A legend that names each runtime once, by its first series, and shows or hides all its series:
   * for a chart that says so (ChartSpec.legendPerRuntime: its caption tells a runtime's several series
   * apart, or its +infinity marks are explained by their band).
   */
  function legendPerRuntime(legend) {
    function key(d) { return d.config || d.label; }
    legend.labels.generateLabels = function (chart) {
      var seen = {};
      return Chart.defaults.plugins.legend.labels.generateLabels(chart).filter(function (item) {
        var k = key(chart.data.datasets[item.datasetIndex]);
        if (seen[k]) { return false; }
        seen[k] = true;
        item.text = k;
        return true;
      });
    };
    legend.onClick = function (e, item, l) {
      var chart = l.chart, k = key(chart.data.datasets[item.datasetIndex]), show = !chart.isDatasetVisible(item.datasetIndex);
      chart.data.datasets.forEach(function (d, i) { if (key(d) === k) { chart.setDatasetVisibility(i, show); } });
      chart.update();
    };
  }
  window.jmclbenchText = { bytes: bytes, number: number, interval: interval, tickLabel: tickLabel, threeLabelMax: threeLabelMax,
    titleLines: titleLines, legendPerRuntime: legendPerRuntime };

  Chart.register(errorBars, frame, bands, beyond, zeroMarks);
  Chart.defaults.animation = false;
  Chart.defaults.font.size = 12;
})();
