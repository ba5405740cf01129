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
precision of the pooled jobs' exact value), each aggregate's bootstrap interval and each cell's
missSeparation. With --evaluation, every Wilson interval of the evaluation document's miss-ratio columns. With --compare, the A and B means compare printed, their bootstrap intervals, the
ratios B/A and their intervals, the Mann-Whitney p-values and the separation verdicts.

The statistics (docs/REPORT.md "Statistics") are recomputed from their definitions: the Mann-Whitney
p exactly (the rank-sum distribution counted in integers, or the normal approximation), the rule from
it; a bootstrap bound, which the tool draws from its own seeded generator, within a band of this
script's own resamples (BOOT_K below says why the band is that wide).

usage: python3 scripts/audit_store.py DB [--report DIR/index.html [--evaluation EVALUATION.md]] [--compare OUT]... [--home DIR]
  --compare OUT   a file holding `jmclbench compare --db DB --a SPEC --b SPEC`'s output
  --evaluation F  `jmclbench evaluate --no-run --db DB`'s document: each Wilson interval of its miss ratios
exit code: 0 every number agrees, 1 some disagree (listed), 2 the store or a file cannot be read
"""
import base64
import bisect
import json
import math
import os
import random
import re
import sqlite3
import statistics
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


# --- the statistics (docs/REPORT.md "Statistics"), recomputed from their textbook definitions ----
Z95 = statistics.NormalDist().inv_cdf(0.975)  # Wilson's z for a 95% interval
BOOT_RESAMPLES = 10_000  # the tool's resample count (compare's footer names it; checked there)
# A bootstrap bound is the q-quantile of B = 10,000 resampled statistics (the tool's, seeded, and this
# script's, from another generator): two independent estimates of one quantile of the ideal bootstrap
# distribution F. The fraction of this script's resamples below the tool's bound is q with a standard
# deviation of sqrt(2 q (1 - q) / B) (both sides' sampling error; 0.0022 at q = 0.025), whatever F is
# (atoms included): the bound must lie between this script's resampled values of ranks B (q -+ K sd).
# K = 6 leaves ~1e-9 a bound to chance, so a test run of some hundred intervals does not flake, and
# still tells a 95% from a 90% or a 99% interval (q = 0.05 or 0.005 lies 11 sd away).
BOOT_K = 6.0
MIN_REPETITIONS = 10  # Separation.MIN_REPETITIONS, as docs/REPORT.md states the rule
ALPHA = 0.05


def wilson(k, n):
    """The 95% Wilson score interval of k successes in n trials (no continuity correction)."""
    p, z2 = k / n, Z95 * Z95
    centre = (p + z2 / (2 * n)) / (1 + z2 / n)
    half = Z95 / (1 + z2 / n) * math.sqrt(p * (1 - p) / n + z2 / (4 * n * n))
    return p, max(0.0, centre - half), min(1.0, centre + half)


def mann_whitney_p(a, b):
    """Two-sided Mann-Whitney U p-value as docs/REPORT.md defines it: none below 3 values a side, 1 for
    identical samples, exact (the distribution of the rank sum) below 50 values in all without ties,
    else the normal approximation without tie or continuity correction."""
    m, n = len(a), len(b)
    if m < 3 or n < 3:
        return None
    pooled = sorted(a + b)
    if pooled[0] == pooled[-1]:
        return 1.0
    # midranks of the pooled sample; U of a = rank sum of a - m (m + 1) / 2
    rank, i = {}, 0
    while i < len(pooled):
        j = i
        while j < len(pooled) and pooled[j] == pooled[i]:
            j += 1
        rank[pooled[i]] = (i + 1 + j) / 2
        i = j
    u = sum(rank[x] for x in a) - m * (m + 1) / 2
    umin = min(u, m * n - u)
    if m + n < 50 and len(rank) == m + n:
        # ways[s]: m-subsets of the ranks 1..m+n whose sum is s (integers: exact)
        ways = [[0] * (m * (m + n) + 1) for _ in range(m + 1)]
        ways[0][0] = 1
        for r in range(1, m + n + 1):
            for size in range(min(r, m), 0, -1):
                row, prev = ways[size], ways[size - 1]
                for s in range(len(row) - 1, r - 1, -1):
                    if prev[s - r]:
                        row[s] += prev[s - r]
        base = m * (m + 1) // 2
        tail = sum(ways[m][base + k] for k in range(int(umin) + 1))
        return min(1.0, 2 * tail / math.comb(m + n, m))
    z = (umin - m * n / 2) / math.sqrt(m * n * (m + n + 1) / 12)
    return min(1.0, 2 * statistics.NormalDist().cdf(z))


def _resampled_means(xs, rng):
    """BOOT_RESAMPLES means of len(xs) values drawn from xs with replacement."""
    n = len(xs)
    drawn = rng.choices(xs, k=n * BOOT_RESAMPLES)
    return [sum(drawn[i:i + n]) / n for i in range(0, n * BOOT_RESAMPLES, n)]


def _boot_band(sorted_stats, q):
    """The values between which a bootstrap q-quantile of BOOT_RESAMPLES resamples must lie (BOOT_K)."""
    d = BOOT_K * math.sqrt(2 * q * (1 - q) / BOOT_RESAMPLES)
    b = len(sorted_stats)
    return (sorted_stats[max(0, math.floor((q - d) * (b - 1)))], sorted_stats[min(b - 1, math.ceil((q + d) * (b - 1)))])


def _slack(v, printed):
    """printed: half a unit of the last digit printed; plus the rounding of a sum of doubles (the tool
    adds a resample's values in another order: 2.8 + 2.0 + 1.6 + 0.6 differs in the last bit)."""
    return printed + 1e-12 * max(1.0, abs(v)) if not math.isinf(v) else 0.0


def _within(v, lo, hi, slack):
    return (lo == v or lo - _slack(lo, slack) <= v) and (hi == v or v <= hi + _slack(hi, slack))


def check_boot_mean(values, low, high, where, note, slack=0.0, rng=None):
    """A 95% percentile-bootstrap interval [low, high] of the mean of values (low None: none given):
    none for one value; the value itself for equal values; else inside [min, max] around the mean, each
    bound within BOOT_K of this script's own bootstrap. slack: the printed precision. The checks made."""
    mean = math.fsum(values) / len(values)
    if len(values) < 2 or math.inf in values:
        if low is not None:
            note("%s: an interval [%r, %r] of %d value(s)%s" % (where, low, high, len(values), " with +inf" if math.inf in values else ""))
        return 1
    if low is None:
        note("%s: no interval of %d values" % (where, len(values)))
        return 1
    lo_v, hi_v = min(values), max(values)
    if not (_within(low, lo_v, mean, slack) and _within(high, mean, hi_v, slack)):
        note("%s: bootstrap interval [%r, %r] not within min %r <= low <= mean %r <= high <= max %r" % (
            where, low, high, lo_v, mean, hi_v))
        return 1
    if lo_v == hi_v:
        return 1
    means = sorted(_resampled_means(values, rng or random.Random(BOOT_SEED)))
    for q, got in ((0.025, low), (0.975, high)):
        band = _boot_band(means, q)
        if not _within(got, band[0], band[1], slack):
            note("%s: bootstrap %g-quantile %r outside this script's %d-resample band [%r, %r]" % (
                where, q, got, BOOT_RESAMPLES, band[0], band[1]))
    return 3


def ratio_resamples(a, b, rng):
    """BOOT_RESAMPLES ratios of resampled means B/A: 1 where both are 0, +inf where only A's is."""
    out = []
    for mb, ma in zip(_resampled_means(b, rng), _resampled_means(a, rng)):
        out.append(1.0 if ma == 0 and mb == 0 else math.inf if ma == 0 else mb / ma)
    out.sort()
    return out


BOOT_SEED = 20260601  # this script's generator is Python's Mersenne Twister, not the tool's: only the seed is fixed, for a reproducible audit


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

    checked, section, counts = 0, None, {"p": 0, "verdict": 0, "bootstrap": 0}
    footer = next((line for line in text if "B/A CI: percentile bootstrap" in line), "")
    fm = re.search(r"B/A CI: percentile bootstrap, (\d+) resamples", footer)
    if not fm or int(fm.group(1)) != BOOT_RESAMPLES:
        note("compare %s: the footer names %s bootstrap resamples, docs/REPORT.md %d" % (
            path, fm.group(1) if fm else "no", BOOT_RESAMPLES))
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
                where = "compare %s %s" % (section, label)
                xs = [[v for v in (METRIC[name](rc) for rc in rcs) if v is not None] for rcs in (a_runs, b_runs)]
                for k, v in check_compare_stats(line, label, xs[0], xs[1], where, note).items():
                    counts[k] += v
                break
    return checked, counts


NUM = r"(?:inf|-?[0-9]+(?:\.[0-9]+)?)"
CELL = r"(-|(%s)(?: \[(%s), (%s)\])? n=(\d+))" % (NUM, NUM, NUM)
COMPARE_ROW = re.compile(r" \([^)]*\) +%s +%s +(1 \(0/0\)|-|%s)  (-|\[(%s), (%s)\]) +(.*?)\s*$" % (CELL, CELL, NUM, NUM, NUM))
VERDICT = re.compile(r"(A lower than B|B lower than A|not separated|not separated: n too small to separate) \("
                     r"(?:p (=|<) ([0-9.]+), )?n = (\d+) vs (\d+)(; the ratio's 95% interval includes 1|"
                     r"; the test and the ratio of means point opposite ways|; 10 a side needed)?\)$")


def half_unit(text):
    """Half a unit of the last digit of a printed number."""
    return 0.5 * 10 ** -(len(text.split(".")[1]) if "." in text else 0)


def number(text):
    return math.inf if text == "inf" else float(text)


def check_compare_stats(line, label, a, b, where, note):
    """One row of compare's table against the statistics recomputed here: each side's bootstrap interval,
    the ratio of means and its bootstrap interval, the Mann-Whitney p and the separation verdict, by
    docs/REPORT.md's rule. The counts of what was checked."""
    counts = {"p": 0, "verdict": 0, "bootstrap": 0}
    m = COMPARE_ROW.match(line[len(label):])
    if not m:
        note("%s: row not understood: %r" % (where, line))
        return counts
    (a_cell, _, a_lo, a_hi, _, b_cell, _, b_lo, b_hi, _, ratio_text, ci_text, r_lo, r_hi, verdict_text) = m.groups()
    for xs, cell, lo, hi in ((a, a_cell, a_lo, a_hi), (b, b_cell, b_lo, b_hi)):
        if cell != "-" and xs:
            slack = max(half_unit(lo), half_unit(hi)) if lo else 0.0
            counts["bootstrap"] += check_boot_mean(xs, number(lo) if lo else None, number(hi) if hi else None,
                                                   where + " bootstrap interval", note, slack)
    if not a or not b:
        if verdict_text != "no data":
            note("%s: %d vs %d values, printed %r, not 'no data'" % (where, len(a), len(b), verdict_text))
        return counts
    ma, mb = math.fsum(a) / len(a), math.fsum(b) / len(b)
    want_ratio = "1 (0/0)" if ma == 0 and mb == 0 else "inf" if ma == 0 else None
    if (ratio_text if want_ratio else None) != want_ratio or (not want_ratio and not printed_close(ratio_text, mb / ma)):
        note("%s: ratio B/A printed %s, recomputed %r" % (where, ratio_text, want_ratio or mb / ma))
    excludes = None  # whether the tool's ratio interval lies wholly on one side of 1: "A" (above 1), "B", "no"; None unsure
    if len(a) < 2 or len(b) < 2:
        if ci_text != "-":
            note("%s: a ratio interval %s of %d vs %d values" % (where, ci_text, len(a), len(b)))
    elif ci_text == "-":
        note("%s: no ratio interval of %d vs %d values" % (where, len(a), len(b)))
    else:
        lo, hi = number(r_lo), number(r_hi)
        ratios = ratio_resamples(a, b, random.Random(BOOT_SEED))
        for q, got, text in ((0.025, lo, r_lo), (0.975, hi, r_hi)):
            band = _boot_band(ratios, q)
            counts["bootstrap"] += 1
            if not _within(got, band[0], band[1], half_unit(text)):
                note("%s: ratio interval's %g-quantile printed %s, outside this script's %d-resample band [%r, %r]" % (
                    where, q, text, BOOT_RESAMPLES, band[0], band[1]))
        # the printed bounds, rounded to 3 decimals: sure of the side of 1 only half a unit away from it
        excludes = ("A" if lo - half_unit(r_lo) > 1 else "B" if hi + half_unit(r_hi) < 1
                    else "no" if lo + half_unit(r_lo) <= 1 <= hi - half_unit(r_hi) else None)
    p = mann_whitney_p(a, b)
    v = VERDICT.match(verdict_text)
    if not v:
        note("%s: verdict not understood: %r" % (where, verdict_text))
        return counts
    kind, rel, p_text, n1, n2, suffix = v.groups()
    ns = (int(n2), int(n1)) if kind == "B lower than A" else (int(n1), int(n2))
    if ns != (len(a), len(b)):
        note("%s: printed n = %s vs %s, recomputed %d vs %d" % (where, n1, n2, len(a), len(b)))
    counts["p"] += 1
    if p is None:
        if p_text is not None:
            note("%s: printed p %s %s of %d vs %d values (none below 3 a side)" % (where, rel, p_text, len(a), len(b)))
    elif p_text is None:
        note("%s: no p printed, recomputed %r" % (where, p))
    elif not ((rel == "<" and p_text == "0.001" and p < 0.001)
              or (rel == "=" and p >= 0.001 - 1e-12 and abs(float(p_text) - p) <= half_unit(p_text) * (1 + 1e-9))):
        note("%s: printed p %s %s, recomputed %r" % (where, rel, p_text, p))
    # the verdict, by docs/REPORT.md's rule; where the printed ratio interval touches 1, either verdict
    counts["verdict"] += 1
    want = {VERDICT_TEXT[w] for w in separation_verdicts(a, b, {"A", "B", "no"} if excludes is None else {excludes})}
    if kind not in want:
        note("%s: printed %r, recomputed %s (p %r, ratio interval %s)" % (where, verdict_text, " or ".join(sorted(want)), p, ci_text))
    elif kind == "not separated" and p is not None and p < ALPHA and len(a) >= MIN_REPETITIONS and len(b) >= MIN_REPETITIONS:
        # the reason a significant test did not separate: the printed interval around 1, or on the side
        # of 1 the test does not point to
        want_suffix = {"no": "; the ratio's 95% interval includes 1", "A": "; the test and the ratio of means point opposite ways",
                       "B": "; the test and the ratio of means point opposite ways"}.get(excludes)
        if suffix is None or (want_suffix is not None and suffix != want_suffix):
            note("%s: printed %r, its reason recomputed %r (ratio interval %s)" % (where, verdict_text, want_suffix, ci_text))
    return counts


def separation_sides(a, b):
    """Which sides of 1 the tool's 95% bootstrap interval of the ratio B/A may lie on, by this script's
    own resamples: "A" wholly above 1 (A lower), "B" wholly below, "no" around 1; more than one where
    the bound's band reaches across 1."""
    if len(a) < 2 or len(b) < 2:
        return {"no"}
    ratios = ratio_resamples(a, b, random.Random(BOOT_SEED))
    low, high = _boot_band(ratios, 0.025), _boot_band(ratios, 0.975)
    sides = set()
    if low[1] > 1:
        sides.add("A")
    if high[0] < 1:
        sides.add("B")
    if low[0] <= 1 <= high[1]:
        sides.add("no")
    return sides


VERDICT_TEXT = {"TOO_FEW": "not separated: n too small to separate", "NOT_SEPARATED": "not separated",
                "A_LOWER": "A lower than B", "B_LOWER": "B lower than A"}


def separation_verdicts(a, b, sides=None):
    """The verdicts (Separation.Verdict names) docs/REPORT.md's rule allows for A and B; sides: where the
    ratio's interval lies (separation_sides), recomputed here when not given."""
    if len(a) < MIN_REPETITIONS or len(b) < MIN_REPETITIONS:
        return {"TOO_FEW"}
    p = mann_whitney_p(a, b)
    if p is None or not p < ALPHA:
        return {"NOT_SEPARATED"}
    a_above = sum(1.0 if x > y else 0.5 if x == y else 0.0 for x in a for y in b)
    by_test = "A" if a_above < len(a) * len(b) / 2 else "B"
    sides = sides or separation_sides(a, b)
    out = {"A_LOWER" if by_test == "A" else "B_LOWER"} if by_test in sides else set()
    if sides - {by_test}:
        out.add("NOT_SEPARATED")
    return out


def check_miss_separation(data, by_cell, note):
    """Each cell's missSeparation (misses per run against every other cell of its setting) against the
    rule recomputed here. The pairs checked, and of them those with enough runs to be separated."""
    checked, full = 0, 0
    by_setting = {}
    for cell in data["cells"]:
        rcs = by_cell.get(cell_key(cell))
        if rcs:
            by_setting.setdefault((cell["dataset"], cell["policy"], cell["particles"]), []).append((cell, rcs))
    for cells in by_setting.values():
        for cell, rcs in cells:
            a = [v for v in (METRIC["MISS_COUNT"](rc) for rc in rcs) if v is not None]
            for other, ors in cells:
                if other is cell:
                    continue
                b = [v for v in (METRIC["MISS_COUNT"](rc) for rc in ors) if v is not None]
                got = (cell.get("missSeparation") or {}).get(other["config"])
                want = separation_verdicts(a, b)
                checked += 1
                full += len(a) >= MIN_REPETITIONS and len(b) >= MIN_REPETITIONS
                if got not in want:
                    note("report %s %s %sp: missSeparation against %s is %r, recomputed %s (misses %r vs %r)" % (
                        cell["config"], cell["policy"], cell["particles"], other["config"], got, " or ".join(sorted(want)), a, b))
    return checked, full


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


# --- the evaluation document's Wilson intervals (docs/EVALUATION.md, `jmclbench evaluate`) --------
WILSON_CELL = re.compile(r"^(%s) \[(%s), (%s)\] %%" % (NUM, NUM, NUM))


def table_cells(line):
    """The cells of a markdown table row as EvaluationSections.table escapes them (a pipe as \\|)."""
    cells = re.split(r"(?<!\\)\|", line.strip())[1:-1]
    return [c.strip().replace("\\|", "|").replace("&lt;", "<").replace("&gt;", ">").replace("\\\\", "\\") for c in cells]


def miss_counts(rcs, column):
    """(k, n) behind a miss-ratio column over a cell's runs, from the job lines: a task's deadline misses over
    its released jobs ("predict/update miss ratio", else both tasks), or a window's missed or late jobs over
    the jobs released in it ("warm-up", "steady")."""
    if column.startswith("warm-up") or column.startswith("steady"):
        w = "WARM" if column.startswith("warm-up") else "STEADY"
        vs = [warm_values(rc) for rc in rcs]
        return sum(v[w + "_MISSES"] or 0 for v in vs), sum(v[w + "_RELEASED"] or 0 for v in vs)
    task = column.split()[0] if column.split()[0] in ("predict", "update") else "all"
    return (sum(rc["tasks"][task]["deadlineMisses"] for rc in rcs), sum(rc["tasks"][task]["released"] for rc in rcs))


def check_evaluation(path, cell_runs, note):
    """Every Wilson interval of the evaluation document's tables (a "miss ratio" column: "p [low, high] %") against
    the 95% Wilson score interval of the misses and released jobs recomputed from the cell's runs (the row's
    configuration, policy and particles, the caption's "at N particles" without that column, the document's
    dataset without a dataset column, any policy without that column). The intervals checked."""
    lines = open(path, encoding="utf-8").read().splitlines()
    main = re.search(r"dataset `([^`]+)`", "\n".join(lines))
    checked, caption, header = 0, "", None
    for i, line in enumerate(lines):
        if re.match(r"Table \d+:", line):
            caption, header = line, None
            continue
        if not line.startswith("|"):
            header = None
            continue
        if header is None:
            header = table_cells(line)
            continue
        if line.startswith("| ---"):
            continue
        row = dict(zip(header, table_cells(line)))
        for column in (h for h in header if "miss ratio" in h):
            text = row[column]
            at = re.search(r"at (\d+) particles", caption)
            where = "evaluation %s line %d: %s %s" % (os.path.basename(path), i + 1, row.get("configuration"), column)
            try:
                key = (row.get("dataset") or (main.group(1) if main else None), row.get("policy"),
                       int(row["particles"]) if "particles" in row else int(at.group(1)), row.get("configuration"))
            except (AttributeError, ValueError):
                note("%s: the row names no particle count" % where)
                continue
            # a table without a policy column (Table 9) names a cell by the rest, which must then be one
            found = [k for k in cell_runs if all(want is None or want == got for want, got in zip(key, k))]
            if len(found) != 1:
                note("%s: %s report cell %r" % (where, "no" if not found else "more than one", key))
                continue
            rcs = cell_runs[found[0]]
            k, n = miss_counts(rcs, column)
            checked += 1
            m = WILSON_CELL.match(text)
            if n == 0 or not m:
                if not (n == 0 and text == "n/a"):
                    note("%s: printed %r, recomputed %d of %d" % (where, text, k, n))
                continue
            want = [100 * v for v in wilson(k, n)]
            if not all(printed_close(t, w) for t, w in zip(m.groups(), want)):
                note("%s: printed %r, recomputed the Wilson interval of %d of %d: %.4f [%.4f, %.4f] %%" % (where, text, k, n, *want))
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
    does not tell, a value of its own (the report's "[version unknown]" rows: never pooled with runs that tell it). Two datasets of one label in one matrix are told apart by the path the summary names."""
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
        print("audit_store: %s" % (str(e) or "usage: audit_store.py DB [--report INDEX_HTML [--evaluation EVALUATION_MD]] [--compare OUT]... [--home DIR]"),
              file=sys.stderr)
        return 2


def audit(argv):
    """Checks the store and the files argv names; the exit code."""
    db, report, evaluation, compares, it = None, None, None, [], iter(argv)
    for a in it:
        if a == "--compare":
            compares.append(next(it))
        elif a == "--report":
            report = next(it)
        elif a == "--evaluation":
            evaluation = next(it)
        elif a == "--home":
            oracle.HOMES.insert(0, next(it))
        else:
            db = a
    if db is None or not os.path.isfile(db):
        raise ValueError("%s: no such results store" % db if db else "")
    if evaluation and not report:
        raise ValueError("--evaluation %s: give --report too (the document's rows are the report's cells)" % evaluation)
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
        seen, boot_checked = 0, 0
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
            values = {}
            for name, f in METRIC.items():
                values[name] = [f(rc) for rc in rcs]
            for task in ("predict", "update", "all"):
                for name in TASK_METRIC:
                    values[task + "." + name] = [task_value(rc, task, name) for rc in rcs]
            wv = [warm_values(rc) for rc in rcs]
            for name in wv[0]:
                values[name] = [w[name] for w in wv]
            expect = {name: agg_expect(vs) for name, vs in values.items()}
            for name, e in expect.items():
                a = cell["metrics"].get(name)
                if a is None:
                    bad.append("%s: metric %s missing" % (where, name))
                    continue
                for st in ("n", "mean", "min", "max"):
                    cmp("%s %s.%s" % (where, name, st), a.get(st), e[st], rel=1e-9)
                if e["n"] >= 1:
                    k = check_boot_mean([v for v in values[name] if v is not None], a.get("low"), a.get("high"),
                                        "%s %s" % (where, name), bad.append)
                    compared += k
                    boot_checked += k
            extra = set(cell["metrics"]) - set(expect)
            if extra:
                print("report metrics not recomputed here: %s" % sorted(extra))
        print("report: %d cells checked of %d" % (seen, len(data["cells"])))
        print("report: %d bootstrap interval checks" % boot_checked)
        k, v = check_miss_separation(data, by_cell, bad.append)
        compared += k
        print("report: %d miss separations checked (%d with 10 runs a side)" % (k, v))
        cell_runs = {}
        for cell in data["cells"]:
            rcs = by_cell.get(cell_key(cell))
            if rcs:
                cell_runs[(cell["dataset"], cell["policy"], cell["particles"], cell["config"])] = rcs
        pts = check_charts(data, cell_runs, bad.append)
        compared += pts
        print("report: %d chart points checked against the jobs within HdrHistogram precision" % pts)
        if evaluation:
            k = check_evaluation(evaluation, cell_runs, bad.append)
            compared += k
            print("evaluation: %d Wilson intervals checked" % k)

    named = None
    if report:
        named = {}
        for (dataset, policy, particles, config), rcs in cell_runs.items():
            named.setdefault((dataset, policy, particles, config.rpartition(" @")[0] if " @" in config else config), []).extend(rcs)
    for path in compares:
        k, st = check_compare(path, runs, per_run, bad.append, named)
        compared += k + sum(st.values())
        print("compare %s: %d means checked" % (path, k))
        print("compare %s: %d p-values, %d verdicts, %d bootstrap bounds checked" % (path, st["p"], st["verdict"], st["bootstrap"]))
    for b in bad:
        print("DISAGREE " + b)
    print("TOTAL: %d ok runs, %d numbers compared (%d histograms bucket by bucket), %d disagree, "
          "largest relative difference %.3g (%s)" % (len(runs), compared, hdr_compared, len(bad), worst, worst_at))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
