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
  var chartText = window.jmclbenchText, bytes = chartText.bytes; // report-plugins.js: how the charts write numbers, titles, legends
  var fmt = chartText.number, fmtCi = chartText.interval; // and how the tables and the headline write them

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    if (attrs) { Object.keys(attrs).forEach(function (k) { e.setAttribute(k, attrs[k]); }); }
    if (text !== undefined && text !== null) { e.textContent = String(text); }
    return e;
  }
  function clear(e) { while (e.firstChild) { e.removeChild(e.firstChild); } }
  function cellsWhere(pred) { return DATA.cells.filter(pred); }
  /** A cell is shown when both its runtime and its engine are chosen. */
  function chosen(c) { return state.configs.has(c.config) && state.engines.has(c.engine); }
  function settingCells() {
    return cellsWhere(function (c) {
      return c.dataset === state.dataset && c.policy === state.policy && c.particles === state.particles && chosen(c);
    });
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
      sw.style.background = c.color;
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
    var lowest = Math.min.apply(null, withMiss.map(function (c) { return c.metrics.MISS_COUNT.mean; }));
    var winners = withMiss.filter(function (c) { return c.metrics.MISS_COUNT.mean === lowest; });
    var jobs = missCountJobs();
    var sep = winners[0].missSeparation || {};
    var unseparated = withMiss.filter(function (c) { return winners.indexOf(c) < 0 && sep[c.config] !== 'A_LOWER'; });
    // a mean over repetitions, not a count: the lowest mean is named as such, and a mean of zero as none in any run
    var runs = winners[0].metrics.MISS_COUNT.n + (winners[0].metrics.MISS_COUNT.n === 1 ? ' run' : ' runs');
    h.appendChild(el('p', { 'class': 'big', id: 'headline-best' }, 'Lowest mean ' + jobs + ' at ' + where + ': ' +
      winners.map(function (c) { return c.config; }).join(', ') +
      (lowest === 0 ? ' had none (' + runs + (winners.length === 1 ? ')' : ' each)')
        : ' (' + fmtCi(winners[0].metrics.MISS_COUNT) + ' per run, ' + runs + ')') +
      separationNote(winners, withMiss, unseparated)));
    if (unseparated.length > HEADLINE_NAMES) {
      var which = el('details', { id: 'headline-unseparated' });
      which.appendChild(el('summary', null, 'which ' + unseparated.length));
      which.appendChild(el('p', null, unseparated.map(function (c) { return c.config; }).join(', ')));
      h.appendChild(which);
    }
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
      // a tie at the lowest is said as one: the latency only chose among the tied, it ranks nothing
      var tied = javas.filter(function (c) { return c !== j && c.metrics.MISS_COUNT.mean === j.metrics.MISS_COUNT.mean; }).length;
      var who = tied === 0 ? ', the chosen Java runtime with the lowest mean ' + jobs + ', '
        : ', of the ' + (tied + 1) + ' chosen Java runtimes tied at the lowest mean ' + jobs + ' the one with the lowest mean task latency, ';
      nat = nativeFor(j, withMiss);
      var lr = ratio(j.metrics.LATENCY_MEAN.mean, nat.metrics.LATENCY_MEAN.mean);
      var mr = ratio(j.metrics.MISS_COUNT.mean, nat.metrics.MISS_COUNT.mean);
      // fewer dropped jobs can come from later releases (a dispatcher that waits for the job), so the jitter stands beside them
      p.textContent = 'Java vs C: ' + j.config + who + 'has a mean task latency ' + lr + ' that of ' +
        nat.config + ' (' + fmt(j.metrics.LATENCY_MEAN.mean) + ' vs ' + fmt(nat.metrics.LATENCY_MEAN.mean) + ' ms), a release jitter p99 of ' +
        fmt(j.metrics.JITTER_P99.mean) + ' vs ' + fmt(nat.metrics.JITTER_P99.mean) + ' ms, and ' +
        fmt(j.metrics.MISS_COUNT.mean) + ' vs ' + fmt(nat.metrics.MISS_COUNT.mean) + ' ' + jobs + ' per run (' + mr + ').';
    }
    h.appendChild(p);
  }
  /**
   * Which of the others the lowest is not separated from ({@code not}; docs/REPORT.md: at least 10
   * runs a side, Mann-Whitney U and the bootstrap interval of the ratio): a lowest mean is not a ranking.
   */
  function separationNote(winners, cells, not) {
    var others = cells.filter(function (c) { return winners.indexOf(c) < 0; });
    if (others.length === 0) { return '.'; }
    var sep = winners[0].missSeparation || {};
    if (not.length === 0) { return '; lower than every other chosen runtime (separated: docs/REPORT.md).'; }
    var few = not.some(function (c) { return sep[c.config] === 'TOO_FEW'; });
    // a headline of twenty names is not read at a glance: past a few, their count, and the names below
    var names = not.length <= HEADLINE_NAMES ? not.map(function (c) { return c.config; }).join(', ')
      : not.length + ' of the ' + others.length + ' other chosen runtimes';
    return '; not separated from ' + names + (few ? ' (fewer than 10 runs a side: no ranking)' : '') + ' (docs/REPORT.md).';
  }
  var HEADLINE_NAMES = 4;
  /** The marked cell's tooltip: the lowest value, which ranks nothing by itself (docs/REPORT.md). */
  var LOWEST_TITLE = 'lowest value of this column (not a ranking: compare says whether two runtimes are separated)';
  /** What missCount counts under the chosen policy: dropped, dropped or aborted, or late jobs (Metric.missCountJobs). */
  function missCountJobs() { return (DATA.missCountJobs || {})[state.policy] || 'missed jobs'; }
  function isNative(c) { return configById[c.config] && configById[c.config].kind === 'NATIVE'; }
  function machineOf(id) { var i = id.lastIndexOf(' @'); return i < 0 ? '' : id.substring(i); }
  /**
   * The native baseline to compare a Java cell with, like with like: on its machine, under its load
   * and with its profile (scheduling) where the store has that, else the first native on its machine;
   * first of all at its time scale, workload arguments and dataset content where the store has a native run so.
   */
  function nativeFor(cell, cells) {
    function sameSettings(n) {
      return n.timeScale === cell.timeScale && n.workloadArgs === cell.workloadArgs && n.datasetDigest === cell.datasetDigest;
    }
    var natives = cells.filter(function (n) { return isNative(n) && machineOf(n.config) === machineOf(cell.config); });
    var like = natives.filter(sameSettings);
    natives = like.length ? like : natives;
    function same(n) { return (n.load || '') === (cell.load || '') && n.profile === cell.profile; }
    function sameLoad(n) { return (n.load || '') === (cell.load || ''); }
    return natives.filter(same)[0] || natives.filter(sameLoad)[0] || natives[0] || cells.filter(isNative)[0];
  }
  function ratio(a, b) {
    if (a === null || b === null || a === undefined || b === undefined) { return 'n/a'; }
    if (b === 0) { return a === 0 ? '1.00\u00d7 (both zero)' : 'the native baseline had none'; }
    return (a / b).toFixed(2) + '\u00d7';
  }

  // ---- table -----------------------------------------------------------------------------
  /** What a response-time p99 cell is: each run's 99th percentile over its released jobs, then their mean. */
  function responseP99Title(task) {
    return task + ': the 99th percentile of the response time (end \u2212 release, ms) over every released job of a run, a '
      + 'dropped or aborted job counting as never completed (+\u221e); mean over repetitions. \u221e: in at least one run the '
      + 'p99 fell among the jobs that never completed (about 1% or more of them were dropped or aborted)';
  }
  var COLUMNS = [
    { key: 'config', label: 'runtime/profile', text: true },
    { key: 'engine', label: 'engine', text: true, title: 'javase: the Java SE release engine (heap, GC); scj: the SCJ mission (immortal, mission, private memory); native: the C baseline' },
    { key: 'memory', label: 'memory', text: true, title: 'memory style: preallocated, allocating (Java SE, C) or scoped (SCJ private memory per release)' },
    { key: 'runs', label: 'ok/runs', text: true },
    { key: 'miss', label: function () { return missCountJobs() + '/run (95% CI)'; }, metric: 'MISS_COUNT', ci: true, best: 'min',
      title: "the thesis's missCount: dropped jobs under skip, dropped or aborted under terminate, late under queue" },
    { key: 'late', label: 'late/run', metric: 'LATE', best: 'min' },
    { key: 'missRatioP', label: 'miss ratio predict', metric: 'predict.MISS_RATIO', ci: true, best: 'min', title: 'predict jobs not completed by their deadline (late, dropped, aborted) over those released, per run' },
    { key: 'missRatioU', label: 'miss ratio update', metric: 'update.MISS_RATIO', ci: true, best: 'min', title: 'update jobs not completed by their deadline (late, dropped, aborted) over those released, per run' },
    { key: 'respP99P', label: 'response p99 predict', metric: 'predict.RESPONSE_P99', best: 'min', title: responseP99Title('predict') },
    { key: 'respP99U', label: 'response p99 update', metric: 'update.RESPONSE_P99', best: 'min', title: responseP99Title('update') },
    { key: 'latMean', label: 'latency mean', metric: 'LATENCY_MEAN', ci: true, best: 'min' },
    { key: 'latP99', label: 'latency p99', metric: 'LATENCY_P99', best: 'min' },
    { key: 'latMax', label: 'latency max', metric: 'LATENCY_MAX', stat: 'max', best: 'min' },
    { key: 'jitMean', label: 'jitter mean', metric: 'JITTER_MEAN', ci: true, best: 'min' },
    { key: 'jitP99', label: 'jitter p99', metric: 'JITTER_P99', best: 'min' },
    { key: 'jitMax', label: 'jitter max', metric: 'JITTER_MAX', stat: 'max', best: 'min' },
    { key: 'warmP99', label: 'latency p99 warm-up', metric: 'WARM_P99', best: 'min', title: 'task latency p99 (ms) of the jobs released in the first seconds of the run (class loading, JIT)' },
    { key: 'steadyP99', label: 'latency p99 steady', metric: 'STEADY_P99', best: 'min', title: 'task latency p99 (ms) of the jobs released after the warm-up' },
    { key: 'warmMiss', label: 'miss ratio warm-up', metric: 'WARM_MISS_RATIO', ci: true, best: 'min', title: 'jobs released in the warm-up and missed or late, over those released then, per run' },
    { key: 'steadyMiss', label: 'miss ratio steady', metric: 'STEADY_MISS_RATIO', ci: true, best: 'min', title: 'jobs released after the warm-up and missed or late, over those released then, per run (the windows differ in length: compare ratios, not counts)' },
    { key: 'dev', label: 'deviation', metric: 'DEVIATION', ci: true, best: 'min' },
    { key: 'vsNative', label: 'lat. \u00d7 native', best: 'min' },
    { key: 'failures', label: 'failures', best: 'min' },
    { key: 'unsupported', label: 'not supported', text: true }
  ];
  function tableRows(cells) {
    return configOrder(cells).map(function (c) {
      var nat = nativeFor(c, cells);
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
        var agg = c.metrics[col.metric] || { mean: null, max: null, low: null, high: null };
        var v = col.stat === 'max' ? agg.max : agg.mean;
        if (v === 'Infinity') { v = Infinity; } // JSON has no infinity: the model writes it as a string
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
      var th = el('th', { scope: 'col', 'data-key': col.key, 'class': col.key === 'config' ? 'name' : '' },
        typeof col.label === 'function' ? col.label() : col.label);
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
          sw.style.background = configById[r.cell.config].color;
          td.insertBefore(sw, td.firstChild);
        }
        if (best[col.key] !== undefined && r.values[col.key] === best[col.key]) { td.classList.add('best'); td.title = LOWEST_TITLE; }
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
  // Each chart is a specification built once in Java (ChartSpecs, DATA.charts) and drawn here as it
  // is: this script only leaves out what belongs to runtimes or engines not chosen.
  // the Chart.js plugins (error bars, the playground's frame, pause bands, zero marks) are in report-plugins.js

  function buildFigures() {
    var box = document.getElementById('charts');
    DATA.figures.forEach(function (f) {
      var fig = el('figure', { 'class': 'figure', id: 'figure-' + f.id });
      fig.appendChild(el('h3', null, f.heading));
      var cb = el('div', { 'class': 'canvas-box' });
      cb.appendChild(el('canvas', { id: 'chart-' + f.id, role: 'img', 'aria-label': f.heading, 'data-series': '0', 'data-points': '0' }));
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

  var SPECS = {};
  function specKey(dataset, policy, particles, id) { return [dataset, policy, particles === null || particles === undefined ? '' : particles, id].join('\u0000'); }
  DATA.charts.forEach(function (s) { SPECS[specKey(s.setting.dataset, s.setting.policy, s.setting.particles, s.id)] = s; });
  function chosenConfig(config, engine) { return state.configs.has(config) && state.engines.has(engine); }
  /** What of a specification the chosen runtimes and engines keep: a filter, nothing computed. */
  function shown(spec) {
    var keep = (spec.categories || []).map(function (c) { return !c.config || chosenConfig(c.config, c.engine); });
    // per-category lists of bars lose the categories left out; a series of points keeps its own
    function pick(list) { return list && spec.kind !== 'LINES' ? list.filter(function (v, i) { return keep[i]; }) : list; }
    var series = spec.series.filter(function (s) { return !s.config || chosenConfig(s.config, s.engine); }).map(function (s) {
      return Object.assign({}, s, { values: pick(s.values), errors: pick(s.errors), colors: pick(s.colors), notes: pick(s.notes) });
    }).filter(function (s) {
      return s.points ? s.points.length > 0 : s.values.some(function (v) { return v !== null && v !== undefined; });
    });
    var owners = series.map(function (s) { return s.config; });
    var first = (spec.bands || []).filter(function (b) { return owners.indexOf(b.config) >= 0; })[0];
    return { categories: (spec.categories || []).filter(function (c, i) { return keep[i]; }), series: series,
      bands: first ? spec.bands.filter(function (b) { return b.config === first.config; }) : [] };
  }
  // report-chart-config.js: a specification as a Chart.js configuration, and the room its names need
  var chartConfigs = window.jmclbenchChartConfig, chartConfig = chartConfigs.chartConfig, aboutARuntime = chartConfigs.aboutARuntime,
    oneSeriesInRuntimeColours = chartConfigs.oneSeriesInRuntimeColours, legendItems = chartConfigs.legendItems,
    uprightNamesBox = chartConfigs.uprightNamesBox, widestName = chartConfigs.widestName,
    ROWS_IN_A_BOX = chartConfigs.ROWS_IN_A_BOX, NAMES_BESIDE = chartConfigs.NAMES_BESIDE;
  function draw(f, spec, view, settingHasRuns) {
    if (charts[f.id]) { charts[f.id].destroy(); }
    var canvas = document.getElementById('chart-' + f.id);
    var rows = spec && spec.kind !== 'LINES' ? view.categories.length : 0;
    var items = spec && !oneSeriesInRuntimeColours(view) ? legendItems(spec, view) : 0;
    // many rows: a horizontal chart grows a line per row, a vertical one makes room for its turned
    // labels; a long legend (three entries a line across the page) may take half the box and no more,
    // so the box grows until it needs no more than that (Chart.js cuts a legend that needs more)
    var height = rows <= ROWS_IN_A_BOX ? 0 : spec.horizontal ? 8 + 1.3 * rows : Math.max(36, uprightNamesBox(view.categories));
    if (items > ROWS_IN_A_BOX) { height = Math.max(height, 22, 6 + 3 * Math.ceil(items / 3)); }
    canvas.parentNode.style.height = height ? height + 'rem' : '';
    // names beside horizontal bars get at most half the box's width: past NAMES_BESIDE the figure takes
    // the page's width, where they ran under the axis title (the evaluation's breakdown chart)
    var wideNames = !!spec && spec.horizontal && widestName(view.categories) > NAMES_BESIDE;
    document.getElementById('figure-' + f.id).classList.toggle('crowded', rows > ROWS_IN_A_BOX || items > ROWS_IN_A_BOX || wideNames);
    var config = spec ? chartConfig(spec, view) : { type: 'scatter', data: { datasets: [] },
      // a figure of another policy (abort latency, breakdown load) has no chart where the table has runs
      options: { responsive: true, maintainAspectRatio: false, plugins: { title: { display: true,
        text: chartText.titleLines(f.heading + (settingHasRuns ? ': nothing to draw at this setting (the caption says where it is drawn)'
          : ': no run at this setting')) } } } };
    if (spec && !aboutARuntime(view)) {
      // bare axes read as a chart of zeros, and the beacons on an empty playground as a chart: say why nothing is on them
      config.options.plugins.subtitle = { display: true, color: '#a00',
        text: 'nothing to draw: no completed run of the chosen runtimes has these values' };
    }
    charts[f.id] = new Chart(canvas, config);
    var pts = config.data.datasets.reduce(function (n, d) { return n + d.data.filter(function (v) { return v !== null; }).length; }, 0);
    canvas.setAttribute('data-series', String(config.data.datasets.length));
    canvas.setAttribute('data-points', String(pts));
    canvas.setAttribute('data-pauses', String(view.bands.length));
    document.getElementById('figure-' + f.id).querySelectorAll('a[data-ext]').forEach(function (a) {
      if (spec) { a.setAttribute('href', 'charts/' + spec.stem + '.' + a.getAttribute('data-ext')); } else { a.removeAttribute('href'); }
    });
  }
  function renderCharts(cells) {
    DATA.figures.forEach(function (f) {
      var spec = SPECS[specKey(state.dataset, state.policy, f.perSetting ? state.particles : null, f.id)];
      var view = spec ? shown(spec) : { categories: [], series: [], bands: [] };
      draw(f, spec, view, cells.length > 0);
      if (f.id === 'memory') {
        renderMemoryTable(configOrder(cells).filter(function (c) { return c.memoryAreas && c.memoryAreas.length; }),
          view.series.map(function (s) { return s.name; }));
      }
    });
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
    renderHeadline(cells);
    renderTable(cells);
    renderFailures(cells);
    renderEnvironment(cells);
    renderCharts(cells);
    renderCount++;
    document.body.setAttribute('data-render-count', String(renderCount));
  }

  buildControls();
  if (DATA.cells.length === 0) {
    // no figures: empty boxes with captions would say nothing the headline does not
    document.getElementById('headline').appendChild(el('p', { 'class': 'big' }, 'The database holds no runs yet: run ./jmclbench quick first.'));
    document.body.setAttribute('data-render-count', '1');
  } else {
    buildFigures();
    render();
  }
})();
