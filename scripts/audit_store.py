#!/usr/bin/env python3
"""Checks a results store, the report built from it and compare's tables against an independent
recomputation from the run folders beside the store (scripts/audit_run.py; no project code).

For every ok run: its run folder (audit_run.py's checks), summary_json against the folder's
summary.json, every row of `metrics` the run's job lines and position files define (the
deadline accounting, the STATS, the deviations, the warm-up split of the attribution), every
HdrHistogram of `histograms` bucket by bucket (its encoding decoded here), and the
taskLatency and deviation series. With --report, the page's cells (each Metric and TaskMetric
aggregate: runs, mean, min, max over the repetitions) and its histogram charts (the latency and
abort latency spectra, the jitter CDF, the completion curves: each point within HdrHistogram's
precision of the pooled jobs' exact value). With --compare, the A and B means compare printed.

usage: python3 scripts/audit_store.py DB [--report DIR/index.html] [--compare OUT]... [--home DIR]
  --compare OUT   a file holding `jmclbench compare --db DB --a SPEC --b SPEC`'s output
exit code: 0 every number agrees, 1 some disagree (listed), 2 the store or a file cannot be read
"""
import base64
import bisect
import json
import math
import os
import sqlite3
import struct
import sys
import zlib

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import audit_run as oracle  # noqa: E402  (the run-folder recomputation beside this file)

COUNTS = ["released", "completed", "done", "late", "skipped", "terminated", "missCount", "deadlineMisses",
          "missRatio", "abortsCompleted"]
TIMINGS = ["releaseJitterNs", "taskLatencyNs", "responseTimeNs", "cpuNs", "responseTimeReleasedNs",
           "abortLatencyNs", "abortNoticeNs", "abortStopNs"]
STATS = ["count", "mean", "stdev", "min", "p50", "p90", "p99", "p999", "max"]
WARMUP_BOUNDARY_NS = 2_000_000_000


def expected_rows(rc):
    """(task, metric, stat) -> value the metrics table must hold for one run, from the recomputation alone."""
    rows = {}
    for task, m in rc["tasks"].items():
        for c in COUNTS:
            if m[c] is not None:
                rows[(task, c, "value")] = m[c]
        for t in TIMINGS:
            for st in STATS:
                v = m[t].get(st)
                if isinstance(v, (int, float)) and v is not None and not (isinstance(v, float) and math.isinf(v)):
                    rows[(task, t, st)] = v
    rows[("run", "missCount", "value")] = rc["missCount"]
    for key, name in (("xy", "deviationXY"), ("x", "deviationX"), ("y", "deviationY"), ("angle", "deviationAngle")):
        for st in ("mean", "max"):
            rows[("run", name, st)] = rc["deviation"][key][st]
    # the attribution's warm-up split (org.jmclbench.tooling.attribution.WarmupSplit, docs/FORMATS.md 5)
    rows[("run", "warmupBoundaryNs", "value")] = WARMUP_BOUNDARY_NS
    jobs = rc["jobs"]
    for task, js in (("predict", jobs["predict"]), ("update", jobs["update"]),
                     ("all", jobs["predict"] + jobs["update"])):
        for part in ("warm", "steady"):
            sel = [j for j in js if (j["release"] < WARMUP_BOUNDARY_NS) == (part == "warm")]
            comp = [j for j in sel if j["outcome"] in ("done", "late")]
            for metric, vals in (("taskLatencyNs", [j["end"] - j["start"] for j in comp]),
                                 ("responseTimeNs", [j["end"] - j["release"] for j in comp])):
                s = oracle.stats(vals)
                for st in STATS:
                    if s[st] is not None:
                        rows[(task, metric + "." + part, st)] = s[st]
            rows[(task, "released." + part, "value")] = len(sel)
            rows[(task, "missedOrLate." + part, "value")] = sum(1 for j in sel if j["outcome"] != "done")
    return rows


# --- HdrHistogram's compressed V2 encoding, decoded independently ---------------------------------

def _zigzag_leb128(buf, pos):
    """One ZigZag LEB128 long of HdrHistogram's V2 payload (at most 9 bytes, the last one 8 bits)."""
    shift, result = 0, 0
    while True:
        b = buf[pos]
        pos += 1
        result |= (b & 0x7F) << shift
        shift += 7
        if not b & 0x80 or shift >= 63:
            if shift >= 63 and b & 0x80:  # ninth byte carries 8 bits
                b = buf[pos]
                pos += 1
                result |= b << 56
            break
    return (result >> 1) ^ -(result & 1), pos


def decode_hdr(b64):
    """(significant digits, lowest trackable value, {counts index: count}) of a stored histogram."""
    raw = base64.b64decode(b64)
    cookie, length = struct.unpack(">ii", raw[:8])
    assert cookie & ~0xF0 == 0x1C849304 & ~0xF0, hex(cookie)
    body = zlib.decompress(raw[8:8 + length])
    cookie2, payload_len, norm_offset, digits, lowest, highest, ratio = struct.unpack(">iiiiqqd", body[:40])
    assert norm_offset == 0
    payload = body[40:40 + payload_len]
    counts, pos, idx = {}, 0, 0
    while pos < len(payload):
        v, pos = _zigzag_leb128(payload, pos)
        if v < 0:
            idx += -v
        else:
            if v:
                counts[idx] = v
            idx += 1
    return digits, lowest, counts


def hdr_layout(digits, lowest):
    """HdrHistogram's sub-bucket half-count magnitude and unit magnitude for these settings."""
    largest_single = 2 * 10 ** digits
    sub_bucket_count_mag = math.ceil(math.log2(largest_single))
    half_mag = max(sub_bucket_count_mag, 1) - 1
    unit_mag = int(math.floor(math.log2(lowest)))
    return half_mag, unit_mag


def index_to_value(i, half_mag, unit_mag):
    half = 1 << half_mag
    bucket = (i >> half_mag) - 1
    sub = (i & (half - 1)) + half
    if bucket < 0:
        sub -= half
        bucket = 0
    return sub << (bucket + unit_mag)


def lowest_equivalent(v, half_mag, unit_mag):
    mask = ((1 << (half_mag + 1)) - 1) << unit_mag
    bucket = (v | mask).bit_length() - unit_mag - (half_mag + 1)
    sub = v >> (bucket + unit_mag)
    return sub << (bucket + unit_mag)


def histogram_values(rc, task, metric):
    """The job values a stored histogram must hold (FORMATS.md 5)."""
    js = rc["jobs"]["predict"] + rc["jobs"]["update"] if task == "all" else rc["jobs"][task]
    if metric == "releaseJitterNs":
        return [j["start"] - j["release"] for j in js if j["start"] >= 0]
    comp = [j for j in js if j["outcome"] in ("done", "late")]
    if metric == "taskLatencyNs":
        return [j["end"] - j["start"] for j in comp]
    if metric == "responseTimeNs":
        return [j["end"] - j["release"] for j in comp]
    if metric == "abortLatencyNs":
        return [j["end"] - j["abort"] for j in js if j["abort"] >= 0]
    raise ValueError(metric)


# --- the report's cells -------------------------------------------------------------------------

METRIC = {  # the report's Metric enum: a run's value, recomputed, in the table's unit
    "MISS_COUNT": lambda rc: rc["missCount"],
    "LATE": lambda rc: rc["tasks"]["all"]["late"],
    "DEADLINE_MISSES": lambda rc: rc["tasks"]["all"]["deadlineMisses"],
    "MISS_RATIO_PREDICT": lambda rc: rc["tasks"]["predict"]["missRatio"],
    "MISS_RATIO_UPDATE": lambda rc: rc["tasks"]["update"]["missRatio"],
    "LATENCY_MEAN": lambda rc: ms(rc["tasks"]["all"]["taskLatencyNs"]["mean"]),
    "LATENCY_P99": lambda rc: ms(rc["tasks"]["all"]["taskLatencyNs"]["p99"]),
    "LATENCY_MAX": lambda rc: ms(rc["tasks"]["all"]["taskLatencyNs"]["max"]),
    "JITTER_MEAN": lambda rc: ms(rc["tasks"]["all"]["releaseJitterNs"]["mean"]),
    "JITTER_P99": lambda rc: ms(rc["tasks"]["all"]["releaseJitterNs"]["p99"]),
    "JITTER_MAX": lambda rc: ms(rc["tasks"]["all"]["releaseJitterNs"]["max"]),
    "DEVIATION": lambda rc: rc["deviation"]["xy"]["mean"],
}
TASK_METRIC = {  # TaskMetric: (field, stat, scale)
    "MISS_RATIO": ("missRatio", None, 1), "DEADLINE_MISSES": ("deadlineMisses", None, 1),
    "LATE": ("late", None, 1), "DROPPED": ("skipped", None, 1), "ABORTED": ("terminated", None, 1),
    "RESPONSE_P50": ("responseTimeReleasedNs", "p50", 1e-6), "RESPONSE_P99": ("responseTimeReleasedNs", "p99", 1e-6),
    "RESPONSE_MAX": ("responseTimeReleasedNs", "max", 1e-6), "LATENCY_P99": ("taskLatencyNs", "p99", 1e-6),
    "LATENCY_MAX": ("taskLatencyNs", "max", 1e-6), "JITTER_P99": ("releaseJitterNs", "p99", 1e-6),
    "ABORT_P50": ("abortLatencyNs", "p50", 1e-6), "ABORT_P99": ("abortLatencyNs", "p99", 1e-6),
    "ABORT_MAX": ("abortLatencyNs", "max", 1e-6), "ABORT_NOTICE_P50": ("abortNoticeNs", "p50", 1e-6),
    "ABORT_NOTICE_P99": ("abortNoticeNs", "p99", 1e-6), "ABORT_NOTICE_MAX": ("abortNoticeNs", "max", 1e-6),
    "ABORT_STOP_MAX": ("abortStopNs", "max", 1e-6),
}


def ms(v):
    """Nanoseconds to milliseconds (None stays None)."""
    return None if v is None else v * 1e-6


def task_value(rc, task, name):
    """A TaskMetric's value of one run, in its unit."""
    field, stat, scale = TASK_METRIC[name]
    v = rc["tasks"][task][field]
    if stat:
        v = v[stat]
    if v == "inf":
        return math.inf
    return None if v is None else v * scale


def warm_values(rc):
    """The report's warm-up aggregates (WARM_P99, ..., WARM_MISS_RATIO) of one run."""
    rows = expected_rows(rc)
    out = {}
    for key, (metric, stat, scale) in {
            "WARM_P99": ("taskLatencyNs.warm", "p99", 1e-6), "STEADY_P99": ("taskLatencyNs.steady", "p99", 1e-6),
            "WARM_MISSES": ("missedOrLate.warm", "value", 1), "STEADY_MISSES": ("missedOrLate.steady", "value", 1),
            "WARM_RELEASED": ("released.warm", "value", 1), "STEADY_RELEASED": ("released.steady", "value", 1),
            "WARM_RESPONSE_P99": ("responseTimeNs.warm", "p99", 1e-6),
            "STEADY_RESPONSE_P99": ("responseTimeNs.steady", "p99", 1e-6)}.items():
        v = rows.get(("all", metric, stat))
        out[key] = None if v is None else v * scale
    for w in ("WARM", "STEADY"):
        rel = out[w + "_RELEASED"]
        out[w + "_MISS_RATIO"] = out[w + "_MISSES"] / rel if rel else None
    return out


def report_data(html_path):
    """The page's inlined model (the jmclbench-data script element)."""
    html = open(html_path, encoding="utf-8").read()
    start = html.index('id="jmclbench-data">') + len('id="jmclbench-data">')
    end = html.index("</script>", start)
    # Jackson writes an infinite double as the string "Infinity" (report.js's num() reads it back)
    def inf(o):
        if isinstance(o, dict):
            return {k: inf(v) for k, v in o.items()}
        if isinstance(o, list):
            return [inf(v) for v in o]
        return {"Infinity": math.inf, "-Infinity": -math.inf}.get(o, o) if isinstance(o, str) else o
    return inf(json.loads(html[start:end]))


def agg_expect(values):
    """What a cell's aggregate over repetitions must say: n, mean (+inf with any +inf), min, max."""
    vs = [v for v in values if v is not None]
    if not vs:
        return {"n": 0, "mean": None, "min": None, "max": None}
    if math.inf in vs:
        return {"n": len(vs), "mean": math.inf, "min": min(vs), "max": math.inf}
    return {"n": len(vs), "mean": math.fsum(vs) / len(vs), "min": min(vs), "max": max(vs)}


# --- the report's histogram charts: within HdrHistogram's precision ------------------------------
HDR_EPS = 2.0 ** -10  # 3 significant digits: a bucket is at most 1/1024 of its values wide
ROUND_EPS = 1e-5      # the page's numbers keep 6 significant digits (SeriesTable.round)


def near_rank_match(y_ns, sorted_vals, ranks):
    """Whether y (a bucket's highest equivalent value, rounded) is the value of one of the ranks (1-based)."""
    for r in ranks:
        v = sorted_vals[min(max(r, 1), len(sorted_vals)) - 1]
        if v * (1 - HDR_EPS - ROUND_EPS) - 1 <= y_ns <= v * (1 + HDR_EPS + ROUND_EPS) + 1:
            return True
    return False


def check_charts(data, cell_runs, note):
    """Spectra, the jitter CDF and completion curves of every cell against the pooled job values."""
    checked = 0
    for chart in data["charts"]:
        if chart["id"] not in ("spectrum", "abort-latency", "jitter-cdf", "completion-predict", "completion-update"):
            continue
        st = chart["setting"]
        for se in chart["series"]:
            key = (st["dataset"], st["policy"], st["particles"], se.get("config"))
            rcs = cell_runs.get(key)
            if rcs is None:
                continue  # a dashed static bound, not a measured series
            where = "chart %s %s %s %sp %s" % (chart["id"], st["dataset"], st["policy"], st["particles"], se["name"])
            pts = se["points"]
            if chart["id"] in ("spectrum", "abort-latency", "jitter-cdf"):
                metric = {"spectrum": "taskLatencyNs", "abort-latency": "abortLatencyNs", "jitter-cdf": "releaseJitterNs"}[chart["id"]]
                vals = sorted(max(v, 0) for rc in rcs for v in histogram_values(rc, "all", metric))
                n = len(vals)
                for x, y in pts:
                    if chart["id"] == "jitter-cdf":
                        lo, hi, yv = y - 1e-5 * max(y, 1e-3), y + 1e-5 * max(y, 1e-3), x
                    else:
                        lo, hi, yv = 1 - 1 / (x * (1 - ROUND_EPS)), 1 - 1 / (x * (1 + ROUND_EPS)), y
                    ranks = range(max(1, math.ceil(lo * n - 1e-9)), math.ceil(min(hi, 1.0) * n + 1e-9) + 1)
                    checked += 1
                    if not near_rank_match(yv * 1e6, vals, ranks) and not (chart["id"] == "jitter-cdf" and yv == 1e-4):
                        note("%s: point (%r, %r): no value of ranks %d..%d of %d within HdrHistogram precision (%r..%r ms)" % (
                            where, x, y, ranks.start, ranks.stop - 1, n, vals[ranks.start - 1] / 1e6, vals[min(ranks.stop - 1, n) - 1] / 1e6))
            else:
                task = chart["id"].split("-")[1]
                resp = sorted(v for rc in rcs for v in histogram_values(rc, task, "responseTimeNs"))
                released = sum(rc["tasks"][task]["released"] for rc in rcs)
                for x, y in pts:
                    t = x * 1e6
                    lo = bisect.bisect_right(resp, t / (1 + HDR_EPS + ROUND_EPS) - 1) / released
                    hi = bisect.bisect_right(resp, t * (1 + HDR_EPS + ROUND_EPS) + 1) / released
                    checked += 1
                    if not (lo - 1e-5 <= y <= hi + 1e-5) and not (x == 1e-4):
                        note("%s: point (%r, %r): completed fraction by then is %r..%r" % (where, x, y, lo, hi))
    return checked


# --- compare's table: A's and B's means as printed -----------------------------------------------
COMPARE_LABELS = [("missCount", "MISS_COUNT"), ("late", "LATE"), ("deadline misses", "DEADLINE_MISSES"),
                  ("predict miss ratio", "MISS_RATIO_PREDICT"), ("update miss ratio", "MISS_RATIO_UPDATE"),
                  ("task latency mean", "LATENCY_MEAN"), ("task latency p99", "LATENCY_P99"),
                  ("task latency max", "LATENCY_MAX"), ("release jitter mean", "JITTER_MEAN"),
                  ("release jitter p99", "JITTER_P99"), ("release jitter max", "JITTER_MAX"),
                  ("deviation xy mean", "DEVIATION")]


def printed_close(text, want):
    """Whether the printed number equals want to the digits printed."""
    if text == "inf":
        return want == math.inf
    decimals = len(text.split(".")[1]) if "." in text else 0
    return abs(float(text) - want) <= 0.5 * 10 ** -decimals * (1 + 1e-9) + 1e-12


def check_compare(path, runs, per_run, note, named=None):
    """compare's output for --db X --a SPEC --b SPEC (SPEC: runtime[/engine], or a row name as the report
    writes it, "native [time scale 0.5]"); its A and B columns. named: (dataset, policy, particles, row name
    without its machine) -> the ok runs of the report's cells of that name, None without --report."""
    import re
    text = open(path).read().splitlines()
    spec = {}
    for line in text[:2]:
        k, v = line.split(":", 1)
        spec[k.strip()] = v.strip()

    def select(sp, dataset, policy, particles):
        if named is not None and (dataset, policy, particles, sp) in named:
            return named[(dataset, policy, particles, sp)]
        if " [" in sp and named is None:
            raise ValueError("%s: compare named a row (%s): give --report too, to select its runs by the report's cell" % (path, sp))
        parts = sp.split("/")
        sel = [r for r in runs if r[3] == parts[0] and (r[9], r[7], r[8]) == (dataset, policy, particles)]
        eng = next((p for p in parts[1:] if p in ("javase", "scj", "rtsj", "rtsj-atomic", "native", "hvm")), None)
        if eng:
            sel = [r for r in sel if r[5] == eng]
        elif any(r[5] == "javase" for r in sel):
            sel = [r for r in sel if r[5] == "javase"]
        if any(r[6] == "preallocated" for r in sel):
            sel = [r for r in sel if r[6] == "preallocated"]
        return [per_run[r[0]] for r in sel]

    checked, section = 0, None
    for line in text:
        m = re.match(r"== (\S+)\s+(\S+)\s+(\d+) particles ==", line)
        if m:
            section = (m.group(1), m.group(2), int(m.group(3)))
            a_runs = select(spec["A"], *section)
            b_runs = select(spec["B"], *section)
            continue
        if section is None:
            continue
        for label, name in COMPARE_LABELS:
            if line.startswith(label + " (") or line.startswith(label + "  "):
                cols = re.findall(r"(inf|-?[0-9.]+)( \[[^]]*\])? n=(\d+)", line)
                for (mean_text, _, n_text), rcs in zip(cols, (a_runs, b_runs)):
                    e = agg_expect([METRIC[name](rc) for rc in rcs])
                    checked += 1
                    if int(n_text) != e["n"] or not printed_close(mean_text, e["mean"]):
                        note("compare %s %s: printed %s n=%s, recomputed %r n=%d" % (section, label, mean_text, n_text, e["mean"], e["n"]))
                break
    return checked


def check_series(con, key, folder, rc, note):
    """The stored series of one run against its job lines and position files (runs of at most 2000 rows)."""
    series = {n: json.loads(j) for n, j in con.execute("select name, json from series where run_key = ?", (key,))}
    checked = 0
    for task in ("predict", "update"):
        s = series.get("taskLatency." + task)
        jobs = rc["jobs"][task]
        if s is None:
            note("%s: series taskLatency.%s missing" % (key, task))
            continue
        if len(jobs) > 2000:
            continue
        want = [[j["index"], j["release"] / 1e9,
                 j["end"] - j["start"] if j["outcome"] in ("done", "late") else None,
                 j["end"] - j["release"] if j["outcome"] in ("done", "late") else None, j["outcome"]] for j in jobs]
        checked += 1
        if len(s["rows"]) != len(want) or any(
                a[0] != b[0] or abs(a[1] - b[1]) > 1e-12 or a[2:] != b[2:] for a, b in zip(s["rows"], want)):
            bad = next((a, b) for a, b in zip(s["rows"], want) if a != b) if len(s["rows"]) == len(want) else len(s["rows"])
            note("%s: series taskLatency.%s differs from the job lines (%r)" % (key, task, bad))
    dev = oracle.read_rows(os.path.join(folder, "positionDeviation.txt"), 5)
    s = series.get("deviation")
    if s is not None and len(dev) <= 2000:
        checked += 1
        if s["rows"] != dev:
            note("%s: series deviation differs from positionDeviation.txt" % key)
    return checked


def cell_key(cell):
    """A report cell's configuration as the runs table spells it (the profile empty when none), with
    the machine label the report appends to its name (" @label") when the store holds several machines,
    and the run-key settings the columns lack (time scale, workload arguments, dataset digest, runtime
    version, the alloc load's rates: runs that differ in them are never pooled, docs/REPORT.md)."""
    name, at, label = cell["config"].rpartition(" @")
    return (cell["dataset"], cell["policy"], cell["particles"], cell["runtime"], cell["profile"] or "",
            cell["engine"], cell["memory"], cell["load"], label if at else None,
            cell.get("timeScale"), cell.get("workloadArgs"), cell.get("datasetDigest"), cell.get("runtimeVersion"),
            cell.get("allocMbPerS"), cell.get("allocLiveMb"))


def run_settings(con):
    """run_key -> (time scale, workload arguments, dataset digest, runtime version, alloc MB/s, alloc MB
    live), read here from the spec_json of the matrix that ran it (the time scale and the alloc rates,
    failing that, from its summary; the rates only under a load that allocates): None where the store
    does not tell. Two datasets of one label in one matrix are told apart by the path the summary names."""
    specs = {}
    for mid, spec in con.execute("select matrix_id, spec_json from matrices"):
        try:
            specs[mid] = json.loads(spec) if spec else {}
        except ValueError:
            specs[mid] = {}
    out = {}
    for key, mid, dataset, summary_json, version, load in con.execute(
            "select run_key, matrix_id, dataset, summary_json, runtime_version, load from runs"):
        spec = specs.get(mid) or {}
        try:
            params = (json.loads(summary_json) or {}).get("parameters", {}) if summary_json else {}
        except ValueError:
            params = {}
        number = lambda v: float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None
        scale = number(spec.get("timeScale"))
        if scale is None:
            scale = number(params.get("timeScale"))
        args = spec.get("workloadArgs")
        args = " ".join(str(a) for a in args) if isinstance(args, list) else None
        ds = [d for d in spec.get("datasets") or [] if d.get("label") == dataset and isinstance(d.get("digest"), str)]
        if len(ds) > 1:
            ds = [d for d in ds if d.get("path") == (params.get("dataset") or {}).get("path")]
        rates = (None, None)
        if load in ("alloc", "mixed"):
            given = str(spec.get("loadAlloc", "")).split(",")
            if len(given) == 2 and all(g.strip().isdigit() for g in given):
                rates = (int(given[0]), int(given[1]))
            else:
                lp = params.get("load") or {}
                if isinstance(lp.get("allocMbPerS"), int) and isinstance(lp.get("allocLiveMb"), int):
                    rates = (lp["allocMbPerS"], lp["allocLiveMb"])
        out[key] = (scale, args, ds[0]["digest"] if len(ds) == 1 else None, version) + rates
    return out


def machine_labels(con, machine_ids):
    """machine_id -> the label the report must give its runs: none for one machine; else the host
    name, with the machine id where two machines share that host name (runs of two machines are
    never pooled, docs/REPORT.md)."""
    if len(machine_ids) < 2:
        return {}
    host = {m: h for m, h in con.execute("select machine_id, hostname from machines")}
    hosts = [host.get(m) for m in machine_ids]
    label = {}
    for m in machine_ids:
        h = host.get(m)
        label[m] = str(m) if h is None else "%s (%s)" % (h, m) if hosts.count(h) > 1 else h
    return label


def main(argv):
    try:
        return audit(argv)
    except (OSError, ValueError, KeyError, sqlite3.Error, StopIteration) as e:
        print("audit_store: %s" % (str(e) or "usage: audit_store.py DB [--report INDEX_HTML] [--compare OUT]... [--home DIR]"),
              file=sys.stderr)
        return 2


def audit(argv):
    """Checks the store and the files argv names; the exit code."""
    db, report, compares, it = None, None, [], iter(argv)
    for a in it:
        if a == "--compare":
            compares.append(next(it))
        elif a == "--report":
            report = next(it)
        elif a == "--home":
            oracle.HOMES.insert(0, next(it))
        else:
            db = a
    if db is None or not os.path.isfile(db):
        raise ValueError("%s: no such results store" % db if db else "")
    base = os.path.dirname(os.path.abspath(db))
    con = sqlite3.connect("file:%s?mode=ro" % db, uri=True)
    runs = con.execute("select run_key, run_dir, summary_json, runtime, profile, engine, memory, policy, particles, "
                       "dataset, load from runs where status = 'ok'").fetchall()
    machine_of = dict(con.execute("select run_key, machine_id from runs where status = 'ok'").fetchall())
    label_of = machine_labels(con, set(machine_of.values()))
    compared, bad, worst, worst_at = 0, [], 0.0, None
    hdr_compared = 0
    per_run = {}

    def cmp(where, got, want, rel=1e-12):
        nonlocal compared, worst, worst_at
        compared += 1
        if got is None or want is None or isinstance(got, str) or isinstance(want, str):
            if got != want:
                bad.append("%s: stored %r, recomputed %r" % (where, got, want))
            return
        if math.isinf(got) or math.isinf(want):
            if got != want:
                bad.append("%s: stored %r, recomputed %r" % (where, got, want))
            return
        d = abs(got - want)
        r = d / max(abs(got), abs(want)) if d else 0.0
        if r > worst:
            worst, worst_at = r, where
        if r > rel:
            bad.append("%s: stored %r, recomputed %r" % (where, got, want))

    for key, run_dir, summary_json, *_ in runs:
        folder = os.path.join(base, run_dir)
        c, rc = oracle.check(folder)
        compared += c.compared
        bad += c.bad
        if c.max_rel > worst:
            worst, worst_at = c.max_rel, folder + " " + str(c.max_rel_where)
        per_run[key] = rc
        with open(os.path.join(folder, "summary.json")) as f:
            if json.loads(summary_json) != json.load(f):
                bad.append("%s: summary_json differs from %s/summary.json" % (key, run_dir))
        stored = {(t, m, s): v for t, m, s, v in con.execute(
            "select task, metric, stat, value from metrics where run_key = ?", (key,))}
        want = expected_rows(rc)
        for k, v in want.items():
            if k not in stored:
                bad.append("%s: metrics row %s missing (recomputed %r)" % (key, "/".join(k), v))
                continue
            cmp("%s metrics %s" % (key, "/".join(k)), stored[k], v)
        # rows not expected for the metrics recomputed here: a null or infinite statistic stored anyway
        owned = set(COUNTS) | set(TIMINGS) | {m for (_, m, _) in want if "." in m}
        for k in stored:
            if k[1] in owned and k[0] in ("predict", "update", "all") and k not in want:
                bad.append("%s: unexpected metrics row %s = %r" % (key, "/".join(k), stored[k]))
        compared += check_series(con, key, folder, rc, bad.append)
        hdrs = {(t, m): h for t, m, h in con.execute(
            "select task, metric, hdr from histograms where run_key = ?", (key,))}
        for task in ("predict", "update", "all"):
            for metric in ("releaseJitterNs", "taskLatencyNs", "responseTimeNs", "abortLatencyNs"):
                vals = histogram_values(rc, task, metric)
                h = hdrs.get((task, metric))
                if h is None:
                    if vals or metric != "abortLatencyNs":
                        bad.append("%s: histogram %s/%s missing" % (key, task, metric))
                    continue
                digits, lowest, counts = decode_hdr(h)
                half_mag, unit_mag = hdr_layout(digits, lowest)
                got = {}
                for i, n in counts.items():
                    v = index_to_value(i, half_mag, unit_mag)
                    got[v] = got.get(v, 0) + n
                exp = {}
                for v in vals:
                    lv = lowest_equivalent(max(v, 0), half_mag, unit_mag)
                    exp[lv] = exp.get(lv, 0) + 1
                hdr_compared += 1
                compared += 1
                if got != exp or digits != 3:
                    bad.append("%s: histogram %s/%s: %d values in %d buckets, recomputed %d in %d (digits %d)" % (
                        key, task, metric, sum(got.values()), len(got), len(vals), len(exp), digits))
                if any(v < 0 for v in vals):
                    bad.append("%s: histogram %s/%s: %d negative values clamped to 0" % (
                        key, task, metric, sum(1 for v in vals if v < 0)))

    if report:
        data = report_data(report)
        by_cell = {}
        settings = run_settings(con)
        for key, run_dir, _, runtime, profile, engine, memory, policy, particles, dataset, load in runs:
            by_cell.setdefault((dataset, policy, particles, runtime, profile or "", engine, memory, load or "none",
                                label_of.get(machine_of[key])) + settings[key], []).append(per_run[key])
        seen = 0
        for cell in data["cells"]:
            rcs = by_cell.get(cell_key(cell))
            if rcs is None:
                if cell["ok"]:
                    bad.append("report cell %s/%s/%s/%s: no ok runs found" % (
                        cell["config"], cell["dataset"], cell["policy"], cell["particles"]))
                continue
            seen += 1
            where = "report %s %s %sp" % (cell["config"], cell["policy"], cell["particles"])
            cmp(where + " ok", cell["ok"], len(rcs))
            expect = {}
            for name, f in METRIC.items():
                expect[name] = agg_expect([f(rc) for rc in rcs])
            for task in ("predict", "update", "all"):
                for name in TASK_METRIC:
                    expect[task + "." + name] = agg_expect([task_value(rc, task, name) for rc in rcs])
            wv = [warm_values(rc) for rc in rcs]
            for name in wv[0]:
                expect[name] = agg_expect([w[name] for w in wv])
            for name, e in expect.items():
                a = cell["metrics"].get(name)
                if a is None:
                    bad.append("%s: metric %s missing" % (where, name))
                    continue
                for st in ("n", "mean", "min", "max"):
                    cmp("%s %s.%s" % (where, name, st), a.get(st), e[st], rel=1e-9)
                if e["n"] >= 1 and e["mean"] is not None and a.get("low") is not None and not math.isinf(e["mean"]):
                    compared += 1
                    if not (a["low"] - 1e-12 <= e["mean"] <= a["high"] + 1e-12):
                        bad.append("%s: %s interval [%r, %r] misses the mean %r" % (where, name, a["low"], a["high"], e["mean"]))
            extra = set(cell["metrics"]) - set(expect)
            if extra:
                print("report metrics not recomputed here: %s" % sorted(extra))
        print("report: %d cells checked of %d" % (seen, len(data["cells"])))
        cell_runs = {}
        for cell in data["cells"]:
            rcs = by_cell.get(cell_key(cell))
            if rcs:
                cell_runs[(cell["dataset"], cell["policy"], cell["particles"], cell["config"])] = rcs
        pts = check_charts(data, cell_runs, bad.append)
        compared += pts
        print("report: %d chart points checked against the jobs within HdrHistogram precision" % pts)

    named = None
    if report:
        named = {}
        for (dataset, policy, particles, config), rcs in cell_runs.items():
            named.setdefault((dataset, policy, particles, config.rpartition(" @")[0] if " @" in config else config), []).extend(rcs)
    for path in compares:
        k = check_compare(path, runs, per_run, bad.append, named)
        compared += k
        print("compare %s: %d means checked" % (path, k))
    for b in bad:
        print("DISAGREE " + b)
    print("TOTAL: %d ok runs, %d numbers compared (%d histograms bucket by bucket), %d disagree, "
          "largest relative difference %.3g (%s)" % (len(runs), compared, hdr_compared, len(bad), worst, worst_at))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
