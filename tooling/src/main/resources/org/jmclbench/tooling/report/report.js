/*
 * jmclbench report page. Data: the JSON block #jmclbench-data (ReportModel). Every string that
 * came from a user or a JVM reaches the DOM through textContent or an attribute, never HTML.
 *
 * Test hook (documented in docs/REPORT.md): window.jmclbenchCharts maps a chart id to its
 * Chart.js instance; each chart canvas carries data-series (datasets drawn) and data-points;
 * document.body carries data-render-count, incremented after every render of the page.
 */
(function () {
  'use strict';
  var DATA = JSON.parse(document.getElementById('jmclbench-data').textContent);
  var charts = {};
  window.jmclbenchCharts = charts;
  var PALETTE = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf',
    '#bcbd22', '#7f7f7f', '#393b79', '#ad494a', '#637939', '#8c6d31', '#843c39', '#7b4173'];
  var colorOf = {};
  DATA.configs.forEach(function (c, i) { colorOf[c.id] = PALETTE[i % PALETTE.length]; });
  var configById = {};
  DATA.configs.forEach(function (c) { configById[c.id] = c; });

  var state = {
    dataset: DATA.defaults.dataset,
    policy: DATA.defaults.policy,
    particles: DATA.defaults.particles,
    configs: new Set(DATA.configs.map(function (c) { return c.id; })),
    engines: new Set(DATA.engines)
  };
  var sortState = { column: null, dir: 1 };

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    if (attrs) { Object.keys(attrs).forEach(function (k) { e.setAttribute(k, attrs[k]); }); }
    if (text !== undefined && text !== null) { e.textContent = String(text); }
    return e;
  }
  function clear(e) { while (e.firstChild) { e.removeChild(e.firstChild); } }
  function fmt(v, digits) {
    if (v === null || v === undefined || !isFinite(v)) { return '\u2013'; }
    if (v === 0) { return '0'; }
    var a = Math.abs(v);
    if (digits === undefined) { digits = a >= 100 ? 1 : a >= 1 ? 2 : a >= 0.01 ? 3 : 4; }
    return v.toFixed(digits);
  }
  function fmtCi(agg, digits) {
    if (!agg || agg.mean === null) { return '\u2013'; }
    return agg.half === null ? fmt(agg.mean, digits) : fmt(agg.mean, digits) + ' \u00b1 ' + fmt(agg.half, digits);
  }
  /** Same reduction as ChartExporter.safe so that the export links find their files. */
  function safe(s) { var t = String(s).replace(/[^A-Za-z0-9._-]/g, '_'); return (t === '' || t.charAt(0) === '.') ? '_' + t : t; }
  function stem(kind, withParticles) {
    var s = safe(state.dataset) + '-' + safe(state.policy);
    if (withParticles) { s += '-' + state.particles; }
    return s + '-' + kind;
  }

  function cellsWhere(pred) { return DATA.cells.filter(pred); }
  /** A cell is shown when both its runtime and its engine are chosen. */
  function chosen(c) { return state.configs.has(c.config) && state.engines.has(c.engine); }
  function settingCells() {
    return cellsWhere(function (c) {
      return c.dataset === state.dataset && c.policy === state.policy && c.particles === state.particles && chosen(c);
    });
  }
  function policyCells() {
    return cellsWhere(function (c) { return c.dataset === state.dataset && c.policy === state.policy && chosen(c); });
  }
  function configOrder(cells) {
    var ids = DATA.configs.map(function (c) { return c.id; });
    return cells.slice().sort(function (a, b) { return ids.indexOf(a.config) - ids.indexOf(b.config); });
  }

  // ---- controls --------------------------------------------------------------------------
  function fillSelect(id, values, current, onChange) {
    var s = document.getElementById(id);
    clear(s);
    values.forEach(function (v) {
      var o = el('option', { value: String(v) }, String(v));
      if (v === current) { o.selected = true; }
      s.appendChild(o);
    });
    s.onchange = function () { onChange(s.value); };
  }
  function buildControls() {
    fillSelect('sel-dataset', DATA.datasets, state.dataset, function (v) { state.dataset = v; render(); });
    fillSelect('sel-policy', DATA.policies, state.policy, function (v) { state.policy = v; render(); });
    fillSelect('sel-particles', DATA.particles, state.particles, function (v) { state.particles = Number(v); render(); });
    var fs = document.getElementById('sel-configs');
    DATA.configs.forEach(function (c) {
      var label = el('label');
      var box = el('input', { type: 'checkbox', value: c.id, 'data-config': c.id });
      box.checked = true;
      box.onchange = function () { if (box.checked) { state.configs.add(c.id); } else { state.configs.delete(c.id); } render(); };
      var sw = el('span', { 'class': 'swatch' });
      sw.style.background = colorOf[c.id];
      label.appendChild(box); label.appendChild(sw); label.appendChild(document.createTextNode(c.id));
      fs.appendChild(label);
    });
    function setAll(on) {
      fs.querySelectorAll('input[type=checkbox]').forEach(function (b) { b.checked = on; });
      state.configs = new Set(on ? DATA.configs.map(function (c) { return c.id; }) : []);
      render();
    }
    document.getElementById('cfg-all').onclick = function () { setAll(true); };
    document.getElementById('cfg-none').onclick = function () { setAll(false); };
    var ef = document.getElementById('sel-engines');
    DATA.engines.forEach(function (e) {
      var label = el('label');
      var box = el('input', { type: 'checkbox', value: e, 'data-engine': e });
      box.checked = true;
      box.onchange = function () { if (box.checked) { state.engines.add(e); } else { state.engines.delete(e); } render(); };
      label.appendChild(box); label.appendChild(document.createTextNode(e));
      ef.appendChild(label);
    });
  }

  // ---- headline --------------------------------------------------------------------------
  function renderHeadline(cells) {
    var h = document.getElementById('headline');
    clear(h);
    var where = state.dataset + ', ' + state.policy + ', ' + state.particles + ' particles';
    var withMiss = cells.filter(function (c) { return c.metrics.MISS_COUNT.mean !== null; });
    if (withMiss.length === 0) {
      h.appendChild(el('p', { 'class': 'big' }, 'No completed run at this setting (' + where + ').'));
      return;
    }
    var best = Math.min.apply(null, withMiss.map(function (c) { return c.metrics.MISS_COUNT.mean; }));
    var winners = withMiss.filter(function (c) { return c.metrics.MISS_COUNT.mean === best; });
    h.appendChild(el('p', { 'class': 'big', id: 'headline-best' }, 'Fewest deadline misses at ' + where + ': ' +
      winners.map(function (c) { return c.config; }).join(', ') + ' (' + fmtCi(winners[0].metrics.MISS_COUNT) +
      ' misses per run, ' + winners[0].metrics.MISS_COUNT.n + (winners[0].metrics.MISS_COUNT.n === 1 ? ' run).' : ' runs).')));
    var javas = withMiss.filter(function (c) { return !isNative(c); });
    var nat = withMiss.filter(isNative)[0];
    var p = el('p', { id: 'headline-ratio' });
    if (!nat) {
      p.textContent = 'No native (C) baseline among the chosen runtimes at this setting, so no Java/C ratio.';
    } else if (javas.length === 0) {
      p.textContent = 'Only the native (C) baseline is chosen: ' + fmt(nat.metrics.LATENCY_MEAN.mean) + ' ms mean task latency.';
    } else {
      javas.sort(function (a, b) {
        return (a.metrics.MISS_COUNT.mean - b.metrics.MISS_COUNT.mean) ||
          ((a.metrics.LATENCY_MEAN.mean || Infinity) - (b.metrics.LATENCY_MEAN.mean || Infinity));
      });
      var j = javas[0];
      nat = nativeFor(j.config, withMiss);
      var lr = ratio(j.metrics.LATENCY_MEAN.mean, nat.metrics.LATENCY_MEAN.mean);
      var mr = ratio(j.metrics.MISS_COUNT.mean, nat.metrics.MISS_COUNT.mean);
      p.textContent = 'Java vs C: the best Java runtime, ' + j.config + ', has a mean task latency ' + lr + ' that of ' +
        nat.config + ' (' + fmt(j.metrics.LATENCY_MEAN.mean) + ' vs ' + fmt(nat.metrics.LATENCY_MEAN.mean) + ' ms) and ' +
        fmt(j.metrics.MISS_COUNT.mean) + ' vs ' + fmt(nat.metrics.MISS_COUNT.mean) + ' misses per run (' + mr + ').';
    }
    h.appendChild(p);
  }
  /** The native baseline to compare a runtime with: on the same machine when the store has several. */
  function isNative(c) { return configById[c.config] && configById[c.config].nativeBaseline; }
  function machineOf(id) { var i = id.lastIndexOf(' @'); return i < 0 ? '' : id.substring(i); }
  function nativeFor(config, cells) {
    var natives = cells.filter(isNative);
    return natives.filter(function (n) { return machineOf(n.config) === machineOf(config); })[0] || natives[0];
  }
  function ratio(a, b) {
    if (a === null || b === null || a === undefined || b === undefined) { return 'n/a'; }
    if (b === 0) { return a === 0 ? '1.00\u00d7 (both zero)' : 'native missed none'; }
    return (a / b).toFixed(2) + '\u00d7';
  }

  // ---- table -----------------------------------------------------------------------------
  var COLUMNS = [
    { key: 'config', label: 'runtime/profile', text: true },
    { key: 'engine', label: 'engine', text: true, title: 'javase: the Java SE release engine (heap, GC); scj: the SCJ mission (immortal, mission, private memory); native: the C baseline' },
    { key: 'memory', label: 'memory', text: true, title: 'memory style: preallocated, allocating (Java SE, C) or scoped (SCJ private memory per release)' },
    { key: 'runs', label: 'ok/runs', text: true },
    { key: 'miss', label: 'misses/run (95% CI)', metric: 'MISS_COUNT', ci: true, best: 'min' },
    { key: 'late', label: 'late/run', metric: 'LATE', best: 'min' },
    { key: 'latMean', label: 'latency mean', metric: 'LATENCY_MEAN', ci: true, best: 'min' },
    { key: 'latP99', label: 'latency p99', metric: 'LATENCY_P99', best: 'min' },
    { key: 'latMax', label: 'latency max', metric: 'LATENCY_MAX', stat: 'max', best: 'min' },
    { key: 'jitMean', label: 'jitter mean', metric: 'JITTER_MEAN', ci: true, best: 'min' },
    { key: 'jitP99', label: 'jitter p99', metric: 'JITTER_P99', best: 'min' },
    { key: 'jitMax', label: 'jitter max', metric: 'JITTER_MAX', stat: 'max', best: 'min' },
    { key: 'warmP99', label: 'latency p99 warm-up', metric: 'WARM_P99', best: 'min', title: 'task latency p99 (ms) of the jobs released in the first seconds of the run (class loading, JIT)' },
    { key: 'steadyP99', label: 'latency p99 steady', metric: 'STEADY_P99', best: 'min', title: 'task latency p99 (ms) of the jobs released after the warm-up' },
    { key: 'warmMiss', label: 'missed warm-up', metric: 'WARM_MISSES', best: 'min', title: 'jobs missed or late per run, released in the warm-up' },
    { key: 'steadyMiss', label: 'missed steady', metric: 'STEADY_MISSES', best: 'min', title: 'jobs missed or late per run, released after the warm-up' },
    { key: 'dev', label: 'deviation', metric: 'DEVIATION', ci: true, best: 'min' },
    { key: 'vsNative', label: 'lat. \u00d7 native', best: 'min' },
    { key: 'failures', label: 'failures', best: 'min' },
    { key: 'unsupported', label: 'not supported', text: true }
  ];
  function tableRows(cells) {
    return configOrder(cells).map(function (c) {
      var nat = nativeFor(c.config, cells);
      var natLat = nat ? nat.metrics.LATENCY_MEAN.mean : null;
      var cfg = configById[c.config] || { versions: [] };
      var row = { cell: c, values: {}, texts: {} };
      row.values.config = c.config; row.texts.config = c.config;
      row.texts.version = cfg.versions.join(', '); row.values.version = row.texts.version;
      row.texts.runs = c.ok + '/' + c.runs; row.values.runs = c.ok;
      row.texts.engine = c.engine; row.values.engine = c.engine;
      row.texts.memory = c.memory; row.values.memory = c.memory;
      COLUMNS.forEach(function (col) {
        if (!col.metric) { return; }
        var agg = c.metrics[col.metric] || { mean: null, max: null, half: null };
        var v = col.stat === 'max' ? agg.max : agg.mean;
        row.values[col.key] = v;
        row.texts[col.key] = col.ci ? fmtCi(agg) : fmt(v);
      });
      var lat = c.metrics.LATENCY_MEAN.mean;
      row.values.vsNative = (natLat && lat !== null) ? lat / natLat : null;
      row.texts.vsNative = row.values.vsNative === null ? '\u2013' : row.values.vsNative.toFixed(2) + '\u00d7';
      row.values.failures = c.failed + c.timeout;
      row.texts.failures = String(row.values.failures) + (c.timeout ? ' (' + c.timeout + ' timeout)' : '');
      row.values.unsupported = c.unsupported;
      row.texts.unsupported = c.unsupported === 0 ? '' : (c.unsupported === c.runs ? 'not supported' : c.unsupported + ' not supported');
      return row;
    });
  }
  function renderTable(cells) {
    var t = document.getElementById('results-table');
    clear(t);
    var rows = tableRows(cells);
    if (sortState.column) {
      var key = sortState.column;
      rows.sort(function (a, b) {
        var x = a.values[key], y = b.values[key];
        var xn = (x === null || x === undefined), yn = (y === null || y === undefined);
        if (xn || yn) { return xn === yn ? 0 : xn ? 1 : -1; }
        return (typeof x === 'string' ? x.localeCompare(y) : x - y) * sortState.dir;
      });
    }
    var best = {};
    COLUMNS.forEach(function (col) {
      if (!col.best) { return; }
      var vals = rows.map(function (r) { return r.values[col.key]; }).filter(function (v) { return v !== null && v !== undefined && isFinite(v); });
      if (vals.length > 1) { best[col.key] = Math.min.apply(null, vals); }
    });
    var thead = el('thead'), tr = el('tr');
    COLUMNS.forEach(function (col) {
      var th = el('th', { scope: 'col', 'data-key': col.key, 'class': col.key === 'config' ? 'name' : '' }, col.label);
      if (col.title) { th.title = col.title; }
      if (sortState.column === col.key) { th.setAttribute('aria-sort', sortState.dir > 0 ? 'ascending' : 'descending'); }
      th.onclick = function () {
        sortState.dir = sortState.column === col.key ? -sortState.dir : 1;
        sortState.column = col.key;
        renderTable(settingCells());
      };
      tr.appendChild(th);
    });
    thead.appendChild(tr); t.appendChild(thead);
    var tbody = el('tbody');
    rows.forEach(function (r) {
      var row = el('tr', { 'data-config': r.cell.config });
      COLUMNS.forEach(function (col) {
        var td = el('td', { 'data-key': col.key }, r.texts[col.key]);
        if (col.key === 'config') {
          td.className = 'name';
          var sw = el('span', { 'class': 'swatch' });
          sw.style.background = colorOf[r.cell.config];
          td.insertBefore(sw, td.firstChild);
        }
        if (best[col.key] !== undefined && r.values[col.key] === best[col.key]) { td.classList.add('best'); td.title = 'best of this column'; }
        if ((col.key === 'failures' && r.values.failures > 0) || (col.key === 'unsupported' && r.values.unsupported > 0)) { td.classList.add('bad'); }
        row.appendChild(td);
      });
      tbody.appendChild(row);
    });
    t.appendChild(tbody);
    if (rows.length === 0) {
      var empty = el('tr'); empty.appendChild(el('td', { colspan: String(COLUMNS.length), 'class': 'name' }, 'No run at this setting for the chosen runtimes.'));
      tbody.appendChild(empty);
    }
  }
  function renderFailures(cells) {
    var box = document.getElementById('failures');
    clear(box);
    var failed = [];
    cells.forEach(function (c) { c.failures.forEach(function (f) { failed.push({ config: c.config, f: f }); }); });
    if (failed.length === 0) { return; }
    box.appendChild(el('h3', null, 'Runs that did not complete (' + failed.length + ')'));
    var details = el('details');
    details.appendChild(el('summary', null, 'Show status, reason and the tail of stderr'));
    failed.forEach(function (x) {
      details.appendChild(el('p', { 'class': 'failure' }, x.config + ' #' + x.f.repetition + ': ' + x.f.status +
        (x.f.exitCode !== null ? ' (exit ' + x.f.exitCode + ')' : '') + (x.f.failure ? ': ' + x.f.failure : '')));
      if (x.f.stderrTail) { details.appendChild(el('pre', { 'class': 'stderr' }, x.f.stderrTail)); }
    });
    box.appendChild(details);
  }

  // ---- environment -----------------------------------------------------------------------
  function renderEnvironment(cells) {
    var box = document.getElementById('environment');
    clear(box);
    var machineIds = new Set();
    var ids = new Set(cells.map(function (c) { return c.config; }));
    DATA.configs.forEach(function (c) { if (ids.has(c.id)) { c.machines.forEach(function (m) { machineIds.add(m); }); } });
    var shown = DATA.machines.filter(function (m) { return machineIds.has(m.id); });
    if (shown.length === 0) { shown = DATA.machines; }
    var machinesBox = el('div', { 'class': 'env-machines' });
    var runtimesBox = el('div', { 'class': 'env-runtimes' });
    shown.forEach(function (m) {
      var box = machinesBox;
      box.appendChild(el('h3', null, 'Machine ' + (m.hostname || m.id)));
      var t = el('table', { 'class': 'machine' });
      [['kernel', m.kernel], ['CPU', m.cpu], ['processors', m.processors], ['virtualisation', m.virtualization || 'not reported']].forEach(function (kv) {
        var tr = el('tr'); tr.appendChild(el('th', null, kv[0])); tr.appendChild(el('td', null, kv[1] === null ? '' : kv[1])); t.appendChild(tr);
      });
      box.appendChild(t);
      if (m.checks.length) {
        var d = el('details');
        d.appendChild(el('summary', null, 'Doctor: ' + m.checks.length + ' checks'));
        var ct = el('table', { 'class': 'doctor' });
        m.checks.forEach(function (c) {
          var tr = el('tr');
          var st = el('td', { 'class': /ok|pass/i.test(c.status) ? 'status-ok' : /fail|error/i.test(c.status) ? 'status-fail' : 'status-warn' }, c.status);
          tr.appendChild(el('td', null, c.check)); tr.appendChild(st); tr.appendChild(el('td', null, c.value)); tr.appendChild(el('td', { 'class': 'advice' }, c.advice || ''));
          tr.title = c.advice || '';
          ct.appendChild(tr);
        });
        d.appendChild(ct);
        box.appendChild(d);
      }
    });
    box.appendChild(machinesBox);
    box.appendChild(runtimesBox);
    runtimesBox.appendChild(el('h3', null, 'Runtimes'));
    DATA.configs.filter(function (c) { return ids.has(c.id); }).forEach(function (c) {
      var box = runtimesBox;
      var p = el('p');
      p.appendChild(el('strong', null, c.id));
      p.appendChild(document.createTextNode(' ' + (c.versions.join(', ') || '') + (c.nativeBaseline ? ' (native C baseline)'
        : ' (engine ' + c.engine + ', memory ' + c.memory + ')')));
      if (c.flags.length) { p.appendChild(el('br')); p.appendChild(el('code', null, c.flags.join(' '))); }
      if (c.facts.length) { p.appendChild(el('br')); p.appendChild(el('span', { 'class': 'facts' }, c.facts.join('; '))); }
      box.appendChild(p);
    });
  }

  // ---- charts ----------------------------------------------------------------------------
  var errorBars = {
    id: 'jmclbenchErrorBars',
    afterDatasetsDraw: function (chart) {
      var ctx = chart.ctx;
      chart.data.datasets.forEach(function (ds, i) {
        if (!ds.errorBars) { return; }
        var meta = chart.getDatasetMeta(i);
        if (meta.hidden) { return; }
        var y = chart.scales[meta.yAxisID || 'y'];
        ctx.save(); ctx.strokeStyle = '#222'; ctx.lineWidth = 1.2;
        meta.data.forEach(function (bar, j) {
          var e = ds.errorBars[j];
          if (!e || e[0] === null || e[1] === null) { return; }
          var x = bar.x, top = y.getPixelForValue(e[1]), bottom = y.getPixelForValue(e[0]), w = Math.min(8, (bar.width || 10) / 3);
          ctx.beginPath(); ctx.moveTo(x, top); ctx.lineTo(x, bottom);
          ctx.moveTo(x - w, top); ctx.lineTo(x + w, top); ctx.moveTo(x - w, bottom); ctx.lineTo(x + w, bottom);
          ctx.stroke();
        });
        ctx.restore();
      });
    }
  };
  var playgroundFrame = {
    id: 'jmclbenchPlayground',
    beforeDatasetsDraw: function (chart) {
      var pg = chart.options.plugins.jmclbenchPlayground;
      if (!pg || !pg.width) { return; }
      var x = chart.scales.x, y = chart.scales.y, ctx = chart.ctx;
      ctx.save(); ctx.strokeStyle = '#888'; ctx.setLineDash([4, 3]);
      ctx.strokeRect(x.getPixelForValue(0), y.getPixelForValue(pg.height), x.getPixelForValue(pg.width) - x.getPixelForValue(0),
        y.getPixelForValue(0) - y.getPixelForValue(pg.height));
      ctx.restore();
    }
  };
  // GC and safepoint pauses of the first repetition as shaded bands on an event-index axis.
  var PAUSE_COLORS = { gc: 'rgba(214, 39, 40, 0.16)', safepoint: 'rgba(148, 103, 189, 0.16)' };
  var pauseBands = {
    id: 'jmclbenchPauses',
    beforeDatasetsDraw: function (chart) {
      var bands = chart.options.plugins.jmclbenchPauses;
      if (!bands || !bands.length) { return; }
      var x = chart.scales.x, area = chart.chartArea, ctx = chart.ctx;
      ctx.save();
      bands.forEach(function (b) {
        var a = Math.max(area.left, x.getPixelForValue(b.from)), e = Math.min(area.right, x.getPixelForValue(b.to));
        if (e < area.left || a > area.right) { return; }
        ctx.fillStyle = PAUSE_COLORS[b.kind] || 'rgba(127, 127, 127, 0.16)';
        ctx.fillRect(a, area.top, Math.max(1, e - a), area.bottom - area.top); // a pause shorter than a pixel still shows
      });
      ctx.restore();
    }
  };
  // An area with nothing allocated (peak 0) has no bar on a log axis: a "0" marks it at the axis.
  var zeroMarks = {
    id: 'jmclbenchZeroMarks',
    afterDatasetsDraw: function (chart) {
      if (!chart.options.plugins.jmclbenchZeroMarks) { return; }
      var ctx = chart.ctx, area = chart.chartArea;
      ctx.save(); ctx.fillStyle = '#333'; ctx.font = '10px sans-serif'; ctx.textAlign = 'center';
      chart.data.datasets.forEach(function (ds, i) {
        var meta = chart.getDatasetMeta(i);
        if (meta.hidden || !ds.areas) { return; }
        ds.areas.forEach(function (a, j) {
          if (a && a.peakBytes === 0 && meta.data[j]) { ctx.fillText('0', meta.data[j].x, area.bottom - 3); }
        });
      });
      ctx.restore();
    }
  };
  Chart.register(errorBars, playgroundFrame, pauseBands, zeroMarks);
  Chart.defaults.animation = false;
  Chart.defaults.font.size = 12;

  /** Cause kinds of docs/FORMATS.md 5, VM causes first, in a stable order and colour across settings. */
  var CAUSE_ORDER = ['gc', 'safepoint', 'jit', 'deopt', 'classload', 'lock', 'os', 'preemption', 'compute', 'queued', 'overlap', 'unknown'];
  var CAUSE_COLORS = { gc: '#d62728', safepoint: '#9467bd', jit: '#ff7f0e', deopt: '#ffbb78', classload: '#e7ba52', lock: '#393b79', os: '#8c564b',
    preemption: '#e377c2', compute: '#1f77b4', queued: '#17becf', overlap: '#bcbd22', unknown: '#7f7f7f' };
  /** Memory areas: the heap, then SCJ's from the longest-lived, then the handlers' private ones (ReportModel.AREA_ORDER). */
  var AREA_ORDER = ['heap', 'immortal', 'mission'];
  var AREA_COLORS = { heap: '#7f7f7f', immortal: '#393b79', mission: '#2ca02c' };
  var PRIVATE_COLORS = ['#ff7f0e', '#e377c2', '#17becf', '#bcbd22', '#8c564b', '#9467bd'];
  /** Bytes in decimal units (kB = 1000 B), as the log axis' powers of ten read best. */
  function bytes(v) {
    if (v === null || v === undefined) { return '\u2013'; }
    var units = ['B', 'kB', 'MB', 'GB'], i = 0;
    while (Math.abs(v) >= 1000 && i < units.length - 1) { v /= 1000; i++; }
    return (i === 0 ? String(Math.round(v)) : String(Number(v.toPrecision(3)))) + ' ' + units[i];
  }
  var FIGURES = [
    { id: 'misses', title: 'Deadline misses vs particles', caption: 'missCount per run (skipped + terminated jobs; late jobs under queue), mean over repetitions with 95% CI error bars, per runtime. The thesis\u2019s histogram with errors.', particles: false },
    { id: 'deviation', title: 'Mean localisation deviation vs particles', caption: 'Mean Euclidean xy deviation of the estimate from the ground truth (m), mean over repetitions with 95% CI error bars.', particles: false },
    { id: 'latency-jitter', title: 'Average task latency and release jitter vs particles', caption: 'Mean over all jobs, then over repetitions (ms). Solid: task latency (end \u2212 start); dashed: release jitter (start \u2212 release).', particles: false },
    { id: 'memory', title: 'Memory areas: peak bytes per engine and memory style', caption: 'The memory-model experiment at a glance: for each runtime, engine and memory style, the peak use of each memory area (bytes, log axis; the largest over the repetitions); the table gives the peaks and the mean bytes one release allocated in the area (heap: per job of the measured run). Java SE: the heap. SCJ: immortal and mission memory, and each handler\u2019s private memory, whose peak is that of one release (0 under the axis: the release allocated nothing, as the preallocated style promises). Hover a bar for the area\u2019s size and the bytes allocated per release. The native baseline reports no areas.', particles: true },
    { id: 'causes', title: 'Why deadlines were missed', caption: 'Jobs missed or late per run (mean over the attributed repetitions), split by each job\u2019s largest cause (the primary cause of ./jmclbench explain): gc, safepoint, jit, os, preemption, compute, queued, overlap, unknown. Runs without attribution evidence are left out.', particles: true },
    { id: 'latency-index', title: 'Task latency vs event index', caption: 'Every job of the first repetition (down-sampled): predict (odometry, every 50 ms) as dots, update (laser) as triangles. The thesis\u2019s XY points graph. Shaded bands: the GC (red) and safepoint (violet) pauses of that repetition, placed on the event index through the jobs\u2019 release times (shown when one runtime is selected or the runtimes\u2019 pauses are those of the first listed).', particles: true },
    { id: 'deviation-time', title: 'Deviation over time, repeated runs', caption: 'Euclidean xy deviation (m) over the run, one line per repetition (up to five) per runtime. The thesis\u2019s XY lines graph.', particles: true },
    { id: 'trajectory', title: 'Estimated vs real trajectory', caption: 'On the playground (dashed frame, metres); black: ground truth; triangles: the beacons; one estimate per runtime (first repetition).', particles: true },
    { id: 'spectrum', title: 'Task latency percentile spectrum', caption: 'HdrHistogram style: every job of every repetition merged; x = 1/(1\u2212p) on a log axis (10 = 90%, 100 = 99%, 1000 = 99.9%), latency (ms) on a log axis.', particles: true },
    { id: 'jitter-cdf', title: 'CDF of release jitter', caption: 'Fraction of jobs released with at most the given jitter (ms, log axis), every job of every repetition merged.', particles: true }
  ];
  function buildFigures() {
    var box = document.getElementById('charts');
    FIGURES.forEach(function (f) {
      var fig = el('figure', { 'class': 'figure', id: 'figure-' + f.id });
      fig.appendChild(el('h3', null, f.title));
      var cb = el('div', { 'class': 'canvas-box' });
      var canvas = el('canvas', { id: 'chart-' + f.id, role: 'img', 'aria-label': f.title, 'data-series': '0', 'data-points': '0' });
      cb.appendChild(canvas);
      fig.appendChild(cb);
      fig.appendChild(el('p', { 'class': 'caption' }, f.caption));
      var ex = el('p', { 'class': 'exports' });
      ex.appendChild(document.createTextNode('Export (all runtimes at this setting): '));
      ex.appendChild(el('a', { 'data-ext': 'svg' }, 'SVG'));
      ex.appendChild(document.createTextNode(' \u00b7 '));
      ex.appendChild(el('a', { 'data-ext': 'png' }, 'PNG'));
      fig.appendChild(ex);
      box.appendChild(fig);
    });
  }
  function axisTitle(text) { return { display: true, text: text }; }
  function xyOptions(title, xTitle, yTitle, extra) {
    var o = {
      responsive: true, maintainAspectRatio: false, parsing: false, normalized: true,
      plugins: { title: { display: true, text: title }, legend: { position: 'bottom', labels: { boxWidth: 12 } } },
      scales: { x: { type: 'linear', title: axisTitle(xTitle) }, y: { type: 'linear', title: axisTitle(yTitle) } }
    };
    if (extra) { extra(o); }
    return o;
  }
  function points(list) { return list.map(function (p) { return { x: p[0], y: p[1] }; }); }
  function draw(id, config) {
    if (charts[id]) { charts[id].destroy(); }
    var canvas = document.getElementById('chart-' + id);
    charts[id] = new Chart(canvas, config);
    var series = config.data.datasets.length;
    var pts = config.data.datasets.reduce(function (n, d) { return n + d.data.filter(function (v) { return v !== null; }).length; }, 0);
    canvas.setAttribute('data-series', String(series));
    canvas.setAttribute('data-points', String(pts));
    var fig = document.getElementById('figure-' + id);
    var f = FIGURES.filter(function (x) { return x.id === id; })[0];
    fig.querySelectorAll('a[data-ext]').forEach(function (a) {
      a.setAttribute('href', 'charts/' + stem(id, f.particles) + '.' + a.getAttribute('data-ext'));
    });
  }
  function where(withParticles) {
    return state.dataset + ', ' + state.policy + (withParticles ? ', ' + state.particles + ' particles' : '');
  }

  function renderCharts(cells, allParticles) {
    var configs = [];
    configOrder(allParticles).forEach(function (c) { if (configs.indexOf(c.config) < 0) { configs.push(c.config); } });
    var particles = [];
    allParticles.forEach(function (c) { if (particles.indexOf(c.particles) < 0) { particles.push(c.particles); } });
    particles.sort(function (a, b) { return a - b; });

    ['misses', 'deviation'].forEach(function (id) {
      var metric = id === 'misses' ? 'MISS_COUNT' : 'DEVIATION';
      var datasets = configs.map(function (cfg) {
        var byP = {};
        allParticles.forEach(function (c) { if (c.config === cfg) { byP[c.particles] = c.metrics[metric]; } });
        return {
          label: cfg, backgroundColor: colorOf[cfg], borderColor: colorOf[cfg],
          data: particles.map(function (p) { return byP[p] && byP[p].mean !== null ? byP[p].mean : null; }),
          errorBars: particles.map(function (p) {
            var a = byP[p];
            return a && a.mean !== null && a.half !== null ? [Math.max(0, a.mean - a.half), a.mean + a.half] : null; // counts and distances are never negative
          })
        };
      });
      datasets = datasets.filter(function (d) { return d.data.some(function (v) { return v !== null; }); });
      draw(id, {
        type: 'bar', data: { labels: particles.map(String), datasets: datasets },
        options: {
          responsive: true, maintainAspectRatio: false,
          plugins: { title: { display: true, text: (id === 'misses' ? 'Deadline misses vs particles' : 'Mean deviation vs particles') + ' (' + where(false) + ')' },
            legend: { position: 'bottom', labels: { boxWidth: 12 } } },
          scales: { x: { title: axisTitle('particles') },
            y: { beginAtZero: true, title: axisTitle(id === 'misses' ? 'missCount per run (mean, 95% CI)' : 'deviation xy (m, mean, 95% CI)') } }
        }
      });
    });

    var lj = [];
    configs.forEach(function (cfg) {
      var mine = allParticles.filter(function (c) { return c.config === cfg; }).sort(function (a, b) { return a.particles - b.particles; });
      [['LATENCY_MEAN', 'task latency', []], ['JITTER_MEAN', 'release jitter', [6, 4]]].forEach(function (m) {
        var data = mine.filter(function (c) { return c.metrics[m[0]].mean !== null; }).map(function (c) { return { x: c.particles, y: c.metrics[m[0]].mean }; });
        if (data.length) {
          lj.push({ label: cfg + ' ' + m[1], data: data, showLine: true, borderColor: colorOf[cfg], backgroundColor: colorOf[cfg], borderDash: m[2] });
        }
      });
    });
    draw('latency-jitter', { type: 'scatter', data: { datasets: lj },
      options: xyOptions('Average task latency and release jitter vs particles (' + where(false) + ')', 'particles', 'time (ms, mean over repetitions)') });

    var li = [];
    cells.forEach(function (c) {
      if (c.latencyPredict.length) { li.push({ label: c.config + ' predict', data: points(c.latencyPredict), pointRadius: 2, pointStyle: 'circle', borderColor: colorOf[c.config], backgroundColor: colorOf[c.config] }); }
      if (c.latencyUpdate.length) { li.push({ label: c.config + ' update', data: points(c.latencyUpdate), pointRadius: 3, pointStyle: 'triangle', borderColor: colorOf[c.config], backgroundColor: 'transparent' }); }
    });
    var withPauses = cells.filter(function (c) { return c.pauses && c.pauses.length; });
    var bands = [];
    withPauses.slice(0, 1).forEach(function (c) {
      c.pauses.forEach(function (p, i) { bands.push({ from: p[0], to: p[1], kind: c.pauseKinds[i] }); });
    });
    draw('latency-index', { type: 'scatter', data: { datasets: li },
      options: xyOptions('Task latency vs event index (' + where(true) + ')' + (bands.length ? ', pauses of ' + withPauses[0].config : ''),
        'event index', 'task latency (ms)', function (o) { o.plugins.jmclbenchPauses = bands; }) });
    document.getElementById('chart-latency-index').setAttribute('data-pauses', String(bands.length));

    var kinds = [];
    var attributed = configOrder(cells).filter(function (c) { return c.causes && Object.keys(c.causes).length; });
    attributed.forEach(function (c) { Object.keys(c.causes).forEach(function (k) { if (kinds.indexOf(k) < 0) { kinds.push(k); } }); });
    kinds.sort(function (a, b) { return CAUSE_ORDER.indexOf(a) - CAUSE_ORDER.indexOf(b) || (a < b ? -1 : a > b ? 1 : 0); });
    draw('causes', {
      type: 'bar',
      data: { labels: attributed.map(function (c) { return c.config; }),
        datasets: kinds.map(function (k, i) {
          return { label: k, backgroundColor: CAUSE_COLORS[k] || PALETTE[i % PALETTE.length],
            data: attributed.map(function (c) { return c.causes[k] === undefined ? 0 : c.causes[k]; }) };
        }) },
      options: {
        responsive: true, maintainAspectRatio: false,
        plugins: { title: { display: true, text: 'Why deadlines were missed (' + where(true) + ')' },
          legend: { position: 'bottom', labels: { boxWidth: 12 } } },
        scales: { x: { stacked: true, title: axisTitle('runtime/profile') },
          y: { stacked: true, beginAtZero: true, title: axisTitle('jobs missed or late per run, by primary cause (mean)') } }
      }
    });

    var dt = [];
    cells.forEach(function (c) {
      c.deviation.forEach(function (s, i) {
        dt.push({ label: c.config + ' #' + c.deviationRepetitions[i], data: points(s), showLine: true, pointRadius: 0, borderWidth: 1.2,
          borderColor: colorOf[c.config], backgroundColor: colorOf[c.config], borderDash: i === 0 ? [] : [2 + i, 2] });
      });
    });
    draw('deviation-time', { type: 'scatter', data: { datasets: dt },
      options: xyOptions('Deviation over time, repeated runs (' + where(true) + ')', 'time (s)', 'deviation xy (m)') });

    var pg = DATA.playgrounds[state.dataset] || { width: 3, height: 2, beacons: [[0, 1], [3, 0], [3, 2]] };
    var tr = [];
    var withReal = cells.filter(function (c) { return c.real.length; })[0];
    if (withReal) { tr.push({ label: 'real', data: points(withReal.real), showLine: true, pointRadius: 0, borderWidth: 2.5, borderColor: '#000', backgroundColor: '#000' }); }
    cells.forEach(function (c) {
      if (c.trajectory.length) { tr.push({ label: c.config + ' estimate', data: points(c.trajectory), showLine: true, pointRadius: 0, borderWidth: 1.2, borderColor: colorOf[c.config], backgroundColor: colorOf[c.config] }); }
    });
    tr.push({ label: 'beacons', data: points(pg.beacons), pointStyle: 'triangle', pointRadius: 9, borderColor: '#000', backgroundColor: '#ffd400' });
    draw('trajectory', { type: 'scatter', data: { datasets: tr },
      options: xyOptions('Estimated vs real trajectory (' + where(true) + ')', 'x (m)', 'y (m)', function (o) {
        o.scales.x.min = -0.15; o.scales.x.max = pg.width + 0.15; o.scales.y.min = -0.15; o.scales.y.max = pg.height + 0.15;
        o.plugins.jmclbenchPlayground = { width: pg.width, height: pg.height };
      }) });

    var sp = cells.filter(function (c) { return c.latencySpectrum.length; }).map(function (c) {
      return { label: c.config, data: c.latencySpectrum.map(function (p) { return { x: p[0], y: Math.max(p[1], 1e-4) }; }), showLine: true, pointRadius: 0, borderColor: colorOf[c.config], backgroundColor: colorOf[c.config] };
    });
    draw('spectrum', { type: 'scatter', data: { datasets: sp },
      options: xyOptions('Task latency by percentile (' + where(true) + ')', 'percentile (log scale of 1/(1\u2212p))', 'task latency (ms, log)', function (o) {
        o.scales.x.type = 'logarithmic'; o.scales.y.type = 'logarithmic'; o.scales.x.min = 1;
        o.scales.x.ticks = { callback: function (v) {
          var exp = Math.log10(v);
          if (Math.abs(exp - Math.round(exp)) > 1e-9) { return null; }
          return v === 1 ? '0%' : (100 - 100 / v).toFixed(Math.max(0, Math.round(exp) - 2)) + '%';
        } };
      }) });

    var cdf = cells.filter(function (c) { return c.jitterCdf.length; }).map(function (c) {
      return { label: c.config, data: points(c.jitterCdf), showLine: true, stepped: true, pointRadius: 0, borderColor: colorOf[c.config], backgroundColor: colorOf[c.config] };
    });
    draw('jitter-cdf', { type: 'scatter', data: { datasets: cdf },
      options: xyOptions('CDF of release jitter (' + where(true) + ')', 'release jitter (ms, log)', 'fraction of jobs', function (o) {
        o.scales.x.type = 'logarithmic'; o.scales.y.min = 0; o.scales.y.max = 1;
        o.scales.x.ticks = { autoSkip: true, maxRotation: 0, callback: function (v) {
          var m = v / Math.pow(10, Math.floor(Math.log10(v) + 1e-9));
          return [1, 2, 5].some(function (k) { return Math.abs(m - k) < 1e-6; }) ? String(Number(v.toPrecision(3))) : null;
        } };
      }) });
  }

  function renderMemory(cells) {
    var withAreas = configOrder(cells).filter(function (c) { return c.memoryAreas && c.memoryAreas.length; });
    var names = [];
    withAreas.forEach(function (c) { c.memoryAreas.forEach(function (a) { if (names.indexOf(a.name) < 0) { names.push(a.name); } }); });
    var rank = function (n) { var i = AREA_ORDER.indexOf(n); return i < 0 ? AREA_ORDER.length : i; };
    names = names.map(function (n, i) { return [n, i]; })
      .sort(function (a, b) { return rank(a[0]) - rank(b[0]) || a[1] - b[1]; }).map(function (x) { return x[0]; });
    var privateIndex = 0;
    var datasets = names.map(function (n) {
      var color = AREA_COLORS[n] || PRIVATE_COLORS[privateIndex++ % PRIVATE_COLORS.length];
      var areas = withAreas.map(function (c) { return c.memoryAreas.filter(function (a) { return a.name === n; })[0] || null; });
      return { label: n, backgroundColor: color, borderColor: color, areas: areas,
        data: areas.map(function (a) { return a && a.peakBytes > 0 ? a.peakBytes : null; }) };
    });
    draw('memory', {
      type: 'bar', data: { labels: withAreas.map(function (c) { return c.config; }), datasets: datasets },
      options: {
        responsive: true, maintainAspectRatio: false,
        plugins: { title: { display: true, text: 'Peak bytes per memory area (' + where(true) + ')' },
          legend: { position: 'bottom', labels: { boxWidth: 12 } }, jmclbenchZeroMarks: true,
          tooltip: { callbacks: { label: function (ctx) {
            var a = ctx.dataset.areas[ctx.dataIndex];
            if (!a) { return ctx.dataset.label; }
            return a.name + ': peak ' + bytes(a.peakBytes) + (a.size !== null ? ' of ' + bytes(a.size) : '') +
              (a.bytesPerRelease !== null ? ', ' + bytes(a.bytesPerRelease) + ' per release' : '');
          } } } },
        scales: { x: { title: axisTitle('runtime / engine memory style') },
          y: { type: 'logarithmic', min: 1, title: axisTitle('peak bytes (log)'),
            ticks: { callback: function (v) {
              var exp = Math.log10(v);
              return Math.abs(exp - Math.round(exp)) < 1e-9 ? bytes(v) : null;
            } } } }
      }
    });
    renderMemoryTable(withAreas, names);
  }
  /** Beside the chart, the numbers: per row and area, the peak and the bytes one release allocated there. */
  function renderMemoryTable(withAreas, names) {
    var fig = document.getElementById('figure-memory');
    var old = fig.querySelector('table.memory-table');
    if (old) { old.parentNode.removeChild(old); }
    if (!withAreas.length) { return; }
    var t = el('table', { 'class': 'memory-table' });
    var head = el('tr');
    head.appendChild(el('th', { 'class': 'name' }, 'peak / per release'));
    names.forEach(function (n) { head.appendChild(el('th', null, n)); });
    t.appendChild(head);
    withAreas.forEach(function (c) {
      var tr = el('tr', { 'data-config': c.config });
      tr.appendChild(el('td', { 'class': 'name' }, c.config));
      names.forEach(function (n) {
        var a = c.memoryAreas.filter(function (x) { return x.name === n; })[0];
        tr.appendChild(el('td', { 'data-area': n }, !a ? '' : bytes(a.peakBytes) +
          (a.bytesPerRelease !== null ? ' / ' + bytes(a.bytesPerRelease) : '')));
      });
      t.appendChild(tr);
    });
    fig.insertBefore(t, fig.querySelector('.caption'));
  }

  var renderCount = 0;
  function render() {
    var cells = settingCells();
    var all = policyCells();
    renderHeadline(cells);
    renderTable(cells);
    renderFailures(cells);
    renderEnvironment(cells);
    renderCharts(cells, all);
    renderMemory(cells);
    renderCount++;
    document.body.setAttribute('data-render-count', String(renderCount));
  }

  buildControls();
  buildFigures();
  if (DATA.cells.length === 0) {
    document.getElementById('headline').appendChild(el('p', { 'class': 'big' }, 'The database holds no runs yet: run ./jmclbench quick first.'));
    document.body.setAttribute('data-render-count', '1');
  } else {
    render();
  }
})();
