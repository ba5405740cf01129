#!/usr/bin/env python3
"""An independent recomputation of a run folder's numbers from its raw files (no project code).

From odoData.txt and laserData.txt (the job lines), position.txt, positionDeviation.txt and the
dataset's files it recomputes what docs/FORMATS.md (sections 3 and 4) defines: per task and for
all, released / done / late / skipped / terminated, the thesis's missCount, deadline misses and
miss ratio, the nearest-rank statistics of release jitter, task latency, response time, cpu,
abort latency and its noticing and stopping parts, the response time over every released job
(+inf for a job that never completed), the deviations and data.txt; and it checks what the job
lines must satisfy whatever the metrics say (outcomes against deadlines, releases and deadlines
against the dataset, one job at a time on the robot, the estimate changing only when a job
completed). It compares all that with summary.json and data.txt and prints each disagreement.
scripts/audit_store.py does the same for a results store and the report built from it.

usage: python3 scripts/audit_run.py [--home DIR] RUN_DIR...
  --home DIR   where a dataset path recorded relative to the project home is found
               (default: the run's -Djmclbench.home, then this script's project)
exit code: 0 every number agrees, 1 some disagree (listed), 2 a run folder cannot be read
"""
import json
import math
import os
import sys

TWO_PI = 6.283185307179586
# where a relative dataset path is looked up besides the run's own project home (--home DIR)
HOMES = [os.path.dirname(os.path.dirname(os.path.abspath(__file__)))]
PERMILLE = {"p50": 500, "p90": 900, "p99": 990, "p999": 999}


def read_jobs(path):
    """The job lines of odoData.txt / laserData.txt (abort_ns and seen_ns -1 in older folders without them)."""
    jobs = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            c = line.split()
            j = {"index": int(c[0]), "release": int(c[1]), "start": int(c[2]), "end": int(c[3]),
                 "deadline": int(c[4]), "outcome": c[5], "cpu": int(c[6]),
                 "abort": int(c[7]) if len(c) > 7 else -1, "seen": int(c[8]) if len(c) > 8 else -1}
            jobs.append(j)
    return jobs


def nearest_rank(sorted_values, permille):
    """The value at index ceil(q * n) - 1 of the sorted sample (FORMATS.md 4), q = permille / 1000."""
    n = len(sorted_values)
    return sorted_values[(permille * n + 999) // 1000 - 1]


def stats(values):
    """STATS of FORMATS.md 4: count, mean, population stdev, min, nearest-rank p50..p999, max."""
    n = len(values)
    if n == 0:
        return {"count": 0, "mean": None, "stdev": None, "min": None, "p50": None, "p90": None,
                "p99": None, "p999": None, "max": None}
    v = sorted(values)
    mean = math.fsum(v) / n
    var = math.fsum((x - mean) ** 2 for x in v) / n
    out = {"count": n, "mean": mean, "stdev": math.sqrt(var), "min": v[0], "max": v[-1]}
    for k, pm in PERMILLE.items():
        out[k] = nearest_rank(v, pm)
    return out


def released_response(jobs):
    """responseTimeReleasedNs: over every released job, one that never completed counting as +inf."""
    n = len(jobs)
    completed = [j["end"] - j["release"] for j in jobs if j["outcome"] in ("done", "late")]
    out = {"count": n, "completed": len(completed)}
    if n == 0:
        for k in ("min", "p50", "p90", "p99", "p999", "max"):
            out[k] = None
        return out
    v = sorted(completed) + [math.inf] * (n - len(completed))
    out["min"] = v[0]
    out["max"] = v[-1]
    for k, pm in PERMILLE.items():
        out[k] = nearest_rank(v, pm)
    return {k: ("inf" if x == math.inf else x) for k, x in out.items()}


def task_metrics(jobs, policy):
    """A task's entry of summary.json tasks (predict, update or all) from its job lines."""
    cnt = {o: sum(1 for j in jobs if j["outcome"] == o) for o in ("done", "late", "skipped", "terminated")}
    released = len(jobs)
    completed = cnt["done"] + cnt["late"]
    if policy == "queue":
        miss = cnt["late"]
    elif policy == "ideal":
        miss = 0
    else:
        miss = cnt["skipped"] + cnt["terminated"]
    misses = cnt["late"] + cnt["skipped"] + cnt["terminated"]
    done_or_late = [j for j in jobs if j["outcome"] in ("done", "late")]
    aborted = [j for j in jobs if j["abort"] >= 0]
    seen = [j for j in aborted if j["seen"] >= 0]
    m = {"released": released, "completed": completed, **cnt, "missCount": miss,
         "deadlineMisses": misses, "missRatio": (misses / released) if released else None,
         "abortsCompleted": sum(1 for j in aborted if j["outcome"] in ("done", "late")),
         "releaseJitterNs": stats([j["start"] - j["release"] for j in jobs if j["start"] >= 0]),
         "taskLatencyNs": stats([j["end"] - j["start"] for j in done_or_late]),
         "responseTimeNs": stats([j["end"] - j["release"] for j in done_or_late]),
         "cpuNs": stats([j["cpu"] for j in jobs if j["cpu"] >= 0]),
         "abortLatencyNs": stats([j["end"] - j["abort"] for j in aborted]),
         "abortNoticeNs": stats([j["seen"] - j["abort"] for j in seen]),
         "abortStopNs": stats([j["end"] - j["seen"] for j in seen]),
         "responseTimeReleasedNs": released_response(jobs)}
    return m


def read_rows(path, cols):
    rows = []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            c = [float(x) for x in s.split()]
            if len(c) != cols:
                raise ValueError("%s: expected %d columns: %r" % (path, cols, s))
            rows.append(c)
    return rows


def wrap2pi(a):
    r = a - TWO_PI * math.floor(a / TWO_PI)
    return 0.0 if r >= TWO_PI else r


def wrap_pi(a):
    return wrap2pi(a + math.pi) - math.pi


def deviation(run_dir, real_path):
    """ALGORITHM.md 10: estimate minus real pose at each odometry time; the summary's means and maxima."""
    pos = read_rows(os.path.join(run_dir, "position.txt"), 4)
    real = read_rows(real_path, 4)
    dev_file = read_rows(os.path.join(run_dir, "positionDeviation.txt"), 5)
    real_by_time = {r[0]: r for r in real}
    ex, ey, exy, et = [], [], [], []
    problems = []
    for i, (t, x, y, th) in enumerate(pos):
        r = real_by_time.get(t)
        if r is None:
            problems.append("position.txt row %d: time %r not in real.txt" % (i + 1, t))
            continue
        dx, dy = x - r[1], y - r[2]
        dth = wrap_pi(th - r[3])
        ex.append(dx)
        ey.append(dy)
        exy.append(math.sqrt(dx * dx + dy * dy))
        et.append(dth)
    rows = list(zip(ex, ey, exy, et))
    if len(dev_file) != len(rows):
        problems.append("positionDeviation.txt has %d rows, position.txt %d" % (len(dev_file), len(rows)))
    for i, (d, mine) in enumerate(zip(dev_file, rows)):
        for name, a, b in zip(("dx", "dy", "dxy", "dtheta"), d[1:], mine):
            if not close(a, b, 1e-12, 1e-15):
                problems.append("positionDeviation.txt row %d %s: file %r, recomputed %r" % (i + 1, name, a, b))
    if len(rows) != len(real):
        problems.append("position.txt has %d rows, real.txt %d" % (len(rows), len(real)))
    n = len(rows)

    def mm(vals):
        return {"mean": math.fsum(vals) / n, "max": max(vals)}
    dev = {"xy": mm(exy), "x": mm([abs(v) for v in ex]), "y": mm([abs(v) for v in ey]),
           "angle": mm([abs(v) for v in et])}
    return dev, problems


def close(a, b, rel, absol=0.0):
    if a is None or b is None or isinstance(a, str) or isinstance(b, str):
        return a == b
    if a == b:
        return True
    return abs(a - b) <= max(rel * max(abs(a), abs(b)), absol)


class Comparer:
    """Counts the numbers compared, keeps the disagreements and the largest relative difference."""

    def __init__(self, label):
        self.label = label
        self.compared = 0
        self.bad = []
        self.max_rel = 0.0
        self.max_rel_where = None

    def cmp(self, where, reported, mine, rel=1e-12):
        self.compared += 1
        if isinstance(reported, bool) or isinstance(mine, bool):
            ok = reported == mine
        elif reported is None or mine is None or isinstance(reported, str) or isinstance(mine, str):
            ok = reported == mine
        else:
            ok = close(reported, mine, rel)
            d = abs(reported - mine)
            if d:
                r = d / max(abs(reported), abs(mine))
                if r > self.max_rel:
                    self.max_rel, self.max_rel_where = r, where
        if not ok:
            self.bad.append("%s: %s reported %r, recomputed %r" % (self.label, where, reported, mine))

    def cmp_tree(self, where, reported, mine, rel=1e-12):
        if isinstance(mine, dict):
            if not isinstance(reported, dict):
                self.bad.append("%s: %s reported %r, expected an object" % (self.label, where, reported))
                return
            for k in mine:
                if k not in reported:
                    self.bad.append("%s: %s.%s missing from the summary" % (self.label, where, k))
                    continue
                self.cmp_tree(where + "." + k, reported[k], mine[k], rel)
        else:
            self.cmp(where, reported, mine, rel)


def dataset_file(summary, key):
    """A dataset file of the run ({@code odometry}, {@code laser}, {@code real}): as recorded, else
    relative to the project home (a relative --dataset)."""
    path = summary["parameters"]["dataset"][key]
    if os.path.isabs(path) or os.path.exists(path):
        return path
    homes = [a[len("-Djmclbench.home="):] for a in summary["environment"]["runtime"].get("inputArguments") or []
             if a.startswith("-Djmclbench.home=")]
    homes += HOMES
    for h in homes:
        if os.path.exists(os.path.join(h, path)):
            return os.path.join(h, path)
    return path


def invariants(run_dir, summary, predict, update):
    """What the job lines must satisfy by docs/FORMATS.md 3 whatever the metrics say; a list of problems."""
    p = summary["parameters"]
    ideal = bool(p.get("ideal"))
    policy = "ideal" if ideal else p["policy"]
    ts = p.get("timeScale", 1.0)
    out = []
    odo = read_rows(dataset_file(summary, "odometry"), 4)
    laser = read_rows(dataset_file(summary, "laser"), 2)
    for name, jobs, events in (("predict", predict, odo), ("update", update, laser)):
        for i, j in enumerate(jobs):
            where = "%s job %d" % (name, j["index"])
            if j["index"] != i:
                out.append("%s: index %d at line %d" % (where, j["index"], i + 1))
            o = j["outcome"]
            if o not in ("done", "late", "skipped", "terminated"):
                out.append("%s: outcome %s" % (where, o))
            if o in ("done", "late"):
                if not (0 <= j["start"] <= j["end"]):
                    out.append("%s: %s with start %d end %d" % (where, o, j["start"], j["end"]))
                if j["start"] < j["release"]:
                    out.append("%s: started %d ns before its release" % (where, j["release"] - j["start"]))
                if not ideal and (o == "done") != (j["end"] <= j["deadline"]):
                    out.append("%s: %s but end - deadline = %d ns" % (where, o, j["end"] - j["deadline"]))
            if o == "skipped" and (j["start"], j["end"], j["abort"], j["seen"]) != (-1, -1, -1, -1):
                out.append("%s: skipped with times %r" % (where, (j["start"], j["end"], j["abort"], j["seen"])))
            if o == "terminated" and j["start"] < 0 and (j["end"], j["cpu"], j["abort"], j["seen"]) != (-1, -1, -1, -1):
                out.append("%s: terminated before it started, with times %r" % (where, (j["end"], j["cpu"], j["abort"], j["seen"])))
            if o == "terminated" and j["start"] >= 0 and not (j["start"] <= j["end"]):
                out.append("%s: terminated with start %d end %d" % (where, j["start"], j["end"]))
            if j["abort"] >= 0:
                if j["start"] < 0 or j["abort"] < j["start"] or j["abort"] > j["end"]:
                    out.append("%s: abort %d outside [start %d, end %d]" % (where, j["abort"], j["start"], j["end"]))
                if j["seen"] >= 0 and not (j["abort"] <= j["seen"] <= j["end"]):
                    out.append("%s: seen %d outside [abort %d, end %d]" % (where, j["seen"], j["abort"], j["end"]))
            elif j["seen"] >= 0:
                out.append("%s: seen %d without an abort" % (where, j["seen"]))
            if o == "terminated" and j["start"] >= 0 and j["abort"] < 0:
                out.append("%s: terminated after it started without an abort_ns" % where)
            if ideal:
                if j["deadline"] != -1 or j["release"] != j["start"] or o != "done":
                    out.append("%s: ideal job %r" % (where, j))
                continue
            if {"skip": "terminated", "queue": "skipped", "terminate": "skipped"}.get(policy) == o or (
                    policy == "queue" and o == "terminated"):
                out.append("%s: %s under policy %s" % (where, o, policy))
            if policy != "terminate" and j["abort"] >= 0:
                out.append("%s: abort_ns under policy %s" % (where, policy))
        if ideal:
            continue
        # Releases and deadlines from the dataset's event times (javase, rtsj, native; scj/hvm predict: periodic).
        times = [e[0] for e in events]  # the warm-up replays a prefix first, then the whole timeline
        if len(times) != len(jobs):
            out.append("%s: %d jobs for %d events" % (name, len(jobs), len(times)))
            continue
        periodic = name == "predict" and summary.get("engine", {}).get("kind") in ("scj", "hvm")
        for i, (j, t) in enumerate(zip(jobs, times)):
            where = "%s job %d" % (name, j["index"])
            if not periodic and abs(j["release"] - t * ts * 1e9) > 2:
                out.append("%s: release %d ns, event time %r s" % (where, j["release"], t))
            if name == "predict":
                rel_deadline = j["deadline"] - j["release"]
                want = 50e6 * ts if not periodic else (times[-1] - times[0]) / (len(times) - 1) * ts * 1e9
                if abs(rel_deadline - want) > 2:
                    out.append("%s: relative deadline %d ns" % (where, rel_deadline))
            else:
                want = jobs[i + 1]["release"] if i + 1 < len(jobs) else j["release"] + 250e6 * ts
                if abs(j["deadline"] - want) > 2:
                    out.append("%s: deadline %d ns, want %d" % (where, j["deadline"], want))
    # The estimate in force at an odometry time changes only when a job whose event lies in
    # (previous odometry time, this one] completed (ALGORITHM.md 10): else position.txt repeats its row.
    pos_path = os.path.join(run_dir, "position.txt")
    if os.path.exists(pos_path):
        pos = read_rows(pos_path, 4)
        completed = {("predict", j["index"]) for j in predict if j["outcome"] in ("done", "late")}
        completed |= {("update", j["index"]) for j in update if j["outcome"] in ("done", "late")}
        li = 0
        for i in range(len(pos)):
            t = pos[i][0]
            any_done = ("predict", i) in completed
            while li < len(laser) and laser[li][0] <= t:
                any_done = any_done or ("update", li) in completed
                li += 1
            if i > 0 and not any_done and pos[i][1:] != pos[i - 1][1:]:
                out.append("position.txt row %d (t=%r): the estimate changed with no job completed since the last row" % (i + 1, t))
    # The robot runs one job at a time: no two started jobs overlap.
    spans = sorted((j["start"], j["end"], n, j["index"]) for n, js in (("predict", predict), ("update", update))
                   for j in js if j["start"] >= 0)
    for a, b in zip(spans, spans[1:]):
        if b[0] < a[1]:
            out.append("%s job %d [%d, %d] overlaps %s job %d [%d, %d]" % (a[2], a[3], a[0], a[1], b[2], b[3], b[0], b[1]))
    return out


def recompute(run_dir):
    """Everything the oracle derives from the run folder's raw files (of summary.json only its parameters)."""
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    p = summary["parameters"]
    policy = "ideal" if p.get("ideal") else p["policy"]
    predict = read_jobs(os.path.join(run_dir, "odoData.txt"))
    update = read_jobs(os.path.join(run_dir, "laserData.txt"))
    tasks = {"predict": task_metrics(predict, policy), "update": task_metrics(update, policy),
             "all": task_metrics(predict + update, policy)}
    dev, problems = deviation(run_dir, dataset_file(summary, "real"))
    problems += invariants(run_dir, summary, predict, update)
    all_started = [j for j in predict + update if j["start"] >= 0]
    all_completed = [j for j in predict + update if j["outcome"] in ("done", "late")]
    data = {"deviationXY": dev["xy"]["mean"], "deviationX": dev["x"]["mean"],
            "deviationY": dev["y"]["mean"], "deviationAngle": dev["angle"]["mean"],
            "missCount": tasks["all"]["missCount"],
            "averageReleaseJitter": tasks["all"]["releaseJitterNs"]["mean"] / 1e6
            if all_started else None,
            "averageTaskTime": tasks["all"]["taskLatencyNs"]["mean"] / 1e6 if all_completed else None}
    return {"summary": summary, "policy": policy, "tasks": tasks, "deviation": dev,
            "missCount": tasks["all"]["missCount"], "data": data, "problems": problems,
            "jobs": {"predict": predict, "update": update}}


def check(run_dir):
    """Compares one run folder's summary.json and data.txt with the recomputation."""
    rc = recompute(run_dir)
    s = rc["summary"]
    c = Comparer(run_dir)
    for p in rc["problems"]:
        c.bad.append("%s: %s" % (run_dir, p))
    for t in ("predict", "update", "all"):
        c.cmp_tree("tasks." + t, s["tasks"][t], rc["tasks"][t])
    c.cmp("missCount", s["missCount"], rc["missCount"])
    c.cmp_tree("deviation", s["deviation"], rc["deviation"], rel=1e-12)
    data = {}
    with open(os.path.join(run_dir, "data.txt")) as f:
        for line in f:
            k, v = line.split()
            data[k] = float(v)
    for k, v in rc["data"].items():
        c.cmp("data.txt " + k, data.get(k), v, rel=1e-12)
    # durationS: the measured run covers every job's end.
    last_end = max([j["end"] for t in rc["jobs"].values() for j in t] + [0])
    c.compared += 1
    if s["durationS"] * 1e9 + 1 < last_end:
        c.bad.append("%s: durationS %r ends before the last job (%d ns)" % (run_dir, s["durationS"], last_end))
    return c, rc


def main(argv):
    dirs = []
    it = iter(argv)
    for a in it:
        if a == "--home":
            HOMES.insert(0, next(it))
        else:
            dirs.append(a)
    total, worst, worst_where, bad = 0, 0.0, None, []
    for d in dirs:
        try:
            c, _ = check(d)
        except (OSError, ValueError, KeyError, IndexError) as e:
            print("audit_run: %s: cannot read the run folder: %s" % (d, e), file=sys.stderr)
            return 2
        total += c.compared
        bad += c.bad
        if c.max_rel > worst:
            worst, worst_where = c.max_rel, "%s %s" % (d, c.max_rel_where)
        print("%s: %d numbers, %d disagree, largest relative difference %.3g%s" % (
            d, c.compared, len(c.bad), c.max_rel, (" (" + c.max_rel_where + ")") if c.max_rel_where else ""))
    for b in bad:
        print("DISAGREE " + b)
    print("TOTAL: %d run folders, %d numbers compared, %d disagree, largest relative difference %.3g (%s)"
          % (len(dirs), total, len(bad), worst, worst_where))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
