#!/usr/bin/env python3
"""An independent recomputation of `explain`'s miss attribution from a run folder (no project code).

From the job lines (odoData.txt, laserData.txt), summary.json's engine.clock and the runtime's
events (the JFR recording, read with the JDK's `jfr print --json`, or a unified-logging GC log)
it recomputes, by the definitions of docs/FORMATS.md section 5 ("Attribution"), each missed or
late job's window, blocker and causes with their times, and the cause.* metrics; it checks what
must hold whatever the tool says (every time non-negative, the stand-still causes - queued, os,
gc, safepoint, preemption, lock - and compute never more than the window together, compute only
where the CPU time exceeds the relative deadline, overlap and unknown only alone). It compares
all that with `explain --json` output and with a results store's attributions and metrics rows.

Thresholds (Attribution.Settings' defaults, quoted by FORMATS): a start delay, queued time or
unexplained delay counts from 1 ms; a runtime event's overlap from 100 us; preemption above 1 ms
and 1.5 x the CPU time; the job's own code is org.jmclbench.core.* (core-immortal's MCL).

usage: python3 scripts/audit_explain.py [--db FILE] [--explain FILE]... [RUN_DIR...]
  --db FILE       every ok run of the store (run_dir beside it): its attributions and cause.* metrics
  --explain FILE  `explain --json` output; its runDir names the run folder (audited too)
exit code: 0 every number agrees, 1 some disagree (listed), 2 a file cannot be read
"""
import json
import os
import re
import shutil
import sqlite3
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from audit_run import Comparer, read_jobs  # noqa: E402  (the job-line reader and comparer of the run oracle)

OS_NS = 1_000_000          # a start delay, queued or unexplained time below this is not a cause
MIN_OVERLAP_NS = 100_000   # a runtime event overlapping the window less than this is not a cause
PREEMPT_RATIO = 1.5
PREEMPT_MIN_NS = 1_000_000
JOB_CODE = "org.jmclbench.core."
STAND_STILL = ("queued", "os", "gc", "safepoint", "preemption", "lock")
RUN_TREE_DEPTH = 5
JFR_TYPES = ("jdk.GarbageCollection", "jdk.GCPhasePause", "jdk.SafepointBegin", "jdk.SafepointEnd",
             "jdk.Compilation", "jdk.Deoptimization", "jdk.ClassLoad", "jdk.ThreadPark", "jdk.JavaMonitorEnter")


# ---- runtime events: (kind, start, end, thread, detail) on the run's timeline (ns from the run start)

def iso_epoch_ns(s):
    """'2026-11-29T11:39:01.725181618Z' (UTC, as jfr prints) -> ns since the epoch, exactly."""
    m = re.fullmatch(r"(\d+)-(\d+)-(\d+)T(\d+):(\d+):(\d+)(?:\.(\d+))?Z", s)
    if not m:
        raise ValueError("JFR time %r" % s)
    import calendar
    y, mo, d, h, mi, se = (int(m.group(i)) for i in range(1, 7))
    frac = (m.group(7) or "0")[:9].ljust(9, "0")
    return calendar.timegm((y, mo, d, h, mi, se)) * 1_000_000_000 + int(frac)


def iso_duration_ns(s):
    """'PT0.009813072S', 'PT1M2.5S', 'PT1H', 'PT-0.1S' -> ns."""
    m = re.fullmatch(r"PT(?:(-?\d+)H)?(?:(-?\d+)M)?(?:(-?)(\d+)(?:\.(\d+))?S)?", s)
    if not m:
        raise ValueError("JFR duration %r" % s)
    ns = int(m.group(1) or 0) * 3600 * 10**9 + int(m.group(2) or 0) * 60 * 10**9
    if m.group(4) is not None:
        sec = int(m.group(4)) * 10**9 + int((m.group(5) or "0")[:9].ljust(9, "0"))
        ns += -sec if m.group(3) else sec
    return ns


def jfr_tool():
    for c in (os.environ.get("JFR"), os.path.join(os.environ.get("JAVA_HOME", ""), "bin", "jfr"), shutil.which("jfr")):
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    raise OSError("no jfr tool (JDK bin/jfr: set JFR or JAVA_HOME)")


def read_jfr(path, start_epoch):
    key = (os.path.abspath(path), start_epoch)
    if key not in JFR_READ:  # a run's store rows and its explain output are checked from one reading
        JFR_READ[key] = read_jfr_uncached(path, start_epoch)
    return JFR_READ[key]


JFR_READ = {}


def read_jfr_uncached(path, start_epoch):
    out = subprocess.run([jfr_tool(), "print", "--json", "--events", ",".join(JFR_TYPES), path],
                         capture_output=True, text=True, check=False)
    if out.returncode != 0:
        raise OSError("%s: jfr print failed: %s" % (path, out.stderr.strip()[:300]))
    raw = json.loads(out.stdout)["recording"]["events"]
    ev, pause_ids, collections, sp_begin, sp_end = [], set(), {}, {}, {}

    def span(v):
        s = iso_epoch_ns(v["startTime"]) - start_epoch
        return s, s + (iso_duration_ns(v["duration"]) if "duration" in v else 0)

    def thread(v):
        t = v.get("eventThread") or {}
        return t.get("javaName") or t.get("osName")

    def method(v):
        m = v.get("method") or {}
        return (m.get("type") or {}).get("name", "?").replace("/", ".") + "." + m.get("name", "?")
    for e in raw:
        t, v = e["type"], e["values"]
        if t == "jdk.GCPhasePause":
            pause_ids.add(v["gcId"])
            ev.append(("gc",) + span(v) + (None, "%s #%s" % (v.get("name"), v["gcId"])))
        elif t == "jdk.GarbageCollection":
            collections[v["gcId"]] = v
        elif t == "jdk.SafepointBegin":
            sp_begin[v["safepointId"]] = span(v)[0]
        elif t == "jdk.SafepointEnd":
            sp_end[v["safepointId"]] = span(v)[1]
        elif t == "jdk.Compilation":
            ev.append(("jit",) + span(v) + (thread(v), method(v)))
        elif t == "jdk.Deoptimization":
            ev.append(("deopt",) + span(v) + (thread(v), method(v)))
        elif t == "jdk.ClassLoad":
            ev.append(("classload",) + span(v) + (thread(v), "class"))
        elif t in ("jdk.ThreadPark", "jdk.JavaMonitorEnter"):
            ev.append(("lock",) + span(v) + (thread(v), t))
    # a collection recorded without pause phases that paused for all its duration is one pause
    for gid, v in collections.items():
        if gid not in pause_ids and v.get("sumOfPauses") == v.get("duration"):
            ev.append(("gc",) + span(v) + (None, "collection #%s" % gid))
    for sid, b in sp_begin.items():  # a safepoint: from its begin (time to reach it) to its end
        if sid in sp_end:
            ev.append(("safepoint", b, max(b, sp_end[sid]), None, "safepoint #%s" % sid))
    return ev


GC_LINE = re.compile(r"\[(\d+)ns\].*\[gc\s*\]\s+GC\((\d+)\) Pause .* (\d+(?:\.\d+)?)ms\s*$")
SP_LINE = re.compile(r"\[(\d+)ns\].*\[safepoint\s*\].*Reaching safepoint: (\d+) ns.*Total: (\d+) ns")


def read_gc_log(path, start_nano):
    """Unified logging with the timenanos decoration (JDK 9+): a pause line is logged at its end,
    with its length in ms; a safepoint line at its end with its total (reaching it included)."""
    ev = []
    with open(path, errors="replace") as f:
        for line in f:
            m = GC_LINE.search(line)
            if m:
                end = int(m.group(1)) - start_nano
                ev.append(("gc", end - round(float(m.group(3)) * 1e6), end, None, "GC(%s)" % m.group(2)))
                continue
            m = SP_LINE.search(line)
            if m:
                end = int(m.group(1)) - start_nano
                ev.append(("safepoint", end - int(m.group(3)), end, None, "safepoint"))
    return ev


def find_up(run_dir, name):
    p = os.path.abspath(run_dir)
    for _ in range(RUN_TREE_DEPTH + 1):
        if os.path.isfile(os.path.join(p, name)):
            return os.path.join(p, name)
        p = os.path.dirname(p)
    return None


def run_events(run_dir, summary, events_file=None):
    """The runtime's events: from events_file (*.jfr: a recording, else a GC log) when given, else
    recording.jfr, then gc.log, in the run folder or its parents (FORMATS: up to five levels)."""
    clock = (summary.get("engine") or {}).get("clock")
    if events_file:
        jfr, gc = (events_file, None) if events_file.endswith(".jfr") else (None, events_file)
    else:
        jfr, gc = find_up(run_dir, "recording.jfr"), find_up(run_dir, "gc.log")
    if clock is None or (jfr is None and gc is None):
        return [], "none"
    if jfr:
        return read_jfr(jfr, clock["runStartEpochNs"]), "jfr"
    return read_gc_log(gc, clock["runStartNanoTime"]), "gc.log"


# ---- interval arithmetic

def union(spans):
    out = []
    for s, e in sorted(tuple(x) for x in spans):
        if out and s <= out[-1][1]:
            out[-1][1] = max(out[-1][1], e)
        else:
            out.append([s, e])
    return out


def covered(disjoint, a, b):
    return sum(max(0, min(e, b) - max(s, a)) for s, e in disjoint)


# ---- the attribution by FORMATS.md

class Oracle:
    def __init__(self, jobs, events):
        self.jobs = jobs
        self.events = events
        self.gc = union([(e[1], e[2]) for e in events if e[0] == "gc"])
        self.stw = union([(e[1], e[2]) for e in events if e[0] in ("gc", "safepoint")])
        self.started = [j for j in jobs if j["start"] >= 0]

    def holder(self, j):
        """The job holding the robot at j's release: released at or before it, started, not yet ended
        (the release engine takes the robot for a job at its release); the latest released such."""
        c = [b for b in self.started if b is not j and b["release"] <= j["release"] and b["end"] > j["release"]]
        return max(c, key=lambda b: b["release"]) if c else None

    def own(self, kind, job):
        return [(e[1], e[2]) for e in self.events if e[0] == kind and e[3] and job["task"] in e[3].lower()]

    def delay_causes(self, j, c):
        delay = j["start"] - j["release"]
        if delay <= OS_NS:
            return
        # other jobs' work between this release and this start, less the pauses during it (gc/safepoint)
        busy = sum(max(0, min(b["end"], j["start"]) - max(b["start"], j["release"]))
                   - covered(self.stw, max(b["start"], j["release"]), min(b["end"], j["start"]))
                   for b in self.started if b is not j and b["start"] < j["start"]
                   and min(b["end"], j["start"]) > max(b["start"], j["release"]))
        if busy >= OS_NS:
            c["queued"] = busy
        rest = delay - busy - covered(self.stw, j["release"], j["start"])
        if rest > OS_NS:
            c["os"] = rest

    def vm_causes(self, job, ws, we, c):
        gc = covered(self.gc, ws, we)
        if gc >= MIN_OVERLAP_NS:
            c["gc"] = gc
        sp = covered(self.stw, ws, we) - gc
        if sp >= MIN_OVERLAP_NS:
            c["safepoint"] = sp
        for k in ("jit", "deopt"):
            mine = [(e[1], e[2]) for e in self.events if e[0] == k and e[4].startswith(JOB_CODE)
                    and e[1] <= we and e[2] >= ws]
            if mine:
                c[k] = covered(union(mine), ws, we) if k == "jit" else 0
        if job is not None:
            for k in ("classload", "lock"):
                # a pause during the load or wait is gc or safepoint, counted once
                ns = (covered(union(self.own(k, job) + self.stw), job["start"], job["end"])
                      - covered(self.stw, job["start"], job["end"]))
                if ns >= MIN_OVERLAP_NS:
                    c[k] = ns

    def run_causes(self, job, ws, we, c):
        self.vm_causes(job, ws, we, c)
        if job["cpu"] >= 0:
            wall = job["end"] - job["start"]
            off = wall - job["cpu"] - covered(union(self.stw + self.own("lock", job)), job["start"], job["end"])
            if off > PREEMPT_MIN_NS and wall > PREEMPT_RATIO * job["cpu"]:
                c["preemption"] = off

    def superseding(self, j):
        """A terminated job's next release (any task) by its deadline, or None."""
        nxt = [s for s in self.jobs if s["release"] > j["release"]]
        s = min(nxt, key=lambda x: x["release"]) if j["outcome"] == "terminated" and nxt else None
        return None if s is not None and s["release"] > j["deadline"] else s

    def explain(self, j):
        c = {}
        blocked = None
        ran = None  # the job whose run the window covers: j, or the job that held the robot
        if j["start"] >= 0:
            ran = j
            ws, we = j["release"], j["end"]
            self.delay_causes(j, c)
            self.run_causes(j, ws, we, c)
            if j["cpu"] >= 0 and j["cpu"] > j["deadline"] - j["release"]:
                c["compute"] = j["cpu"]
            if not c and self.superseding(j) is not None:
                c["overlap"] = we - ws  # aborted by the next release while it ran normally
        else:
            b = self.holder(j)
            if b is not None:
                blocked = "%s#%d" % (b["task"], b["index"])
                ran = b
                ws, we = b["release"], b["end"]
                self.delay_causes(b, c)
                self.run_causes(b, ws, we, c)
                if b["cpu"] >= 0 and b["release"] + b["cpu"] > j["release"]:
                    c["compute"] = b["cpu"]
                if not c:
                    c["overlap"] = we - j["release"]
            else:
                # the robot was free: superseded by the next release (any task) before its handler started it
                s = self.superseding(j)
                ws = j["release"]
                we = s["release"] if s else j["deadline"]
                self.vm_causes(None, ws, we, c)
                if s is not None and not c:
                    c["overlap"] = we - ws
        if not c:
            c["unknown"] = we - ws
        return {"window": (ws, we), "blockedBy": blocked, "causes": c, "ran": ran}


def primaries(causes):
    """The kinds that may come first: the largest ns, jit and deopt only when nothing else."""
    main = {k: v for k, v in causes.items() if k not in ("jit", "deopt")} or causes
    top = max(main.values())
    return {k for k, v in main.items() if v == top}


def invariants(j, a):
    """What a job's attribution must satisfy whatever the tool computes. compute is the CPU time of the
    job that ran (the job, or its blocker), which FORMATS 3 says includes its time stamps and the robot's
    hand-over: it may exceed that job's end - start, by as much as it does in its job line."""
    out = []
    ran = a.get("ran")
    handover = max(0, ran["cpu"] - (ran["end"] - ran["start"])) if ran and ran["cpu"] >= 0 else 0
    ws, we = a["window"]
    c = a["causes"]
    where = "%s job %d (%s)" % (j["task"], j["index"], j["outcome"])
    if we < ws:
        out.append("%s: window ends %d before it starts %d" % (where, we, ws))
    for k, v in c.items():
        if v < 0:
            out.append("%s: %s %d ns < 0" % (where, k, v))
    still = sum(c.get(k, 0) for k in STAND_STILL)
    if still > we - ws:
        out.append("%s: %s = %d ns > window %d ns" % (where, "+".join(STAND_STILL), still, we - ws))
    if still + c.get("compute", 0) > we - ws + handover:
        out.append("%s: %s + compute = %d ns > window %d ns + CPU beyond the job's end - start %d ns"
                   % (where, "+".join(STAND_STILL), still + c.get("compute", 0), we - ws, handover))
    for k in ("overlap", "unknown"):
        if k in c and len(c) > 1:
            out.append("%s: %s beside %s" % (where, k, sorted(c)))
    return out


def oracle_run(run_dir, events_file=None):
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    jobs = []
    for name, task in (("odoData.txt", "predict"), ("laserData.txt", "update")):
        for j in read_jobs(os.path.join(run_dir, name)):
            j["task"] = task
            jobs.append(j)
    events, source = run_events(run_dir, summary, events_file)
    o = Oracle(jobs, events)
    missed = sorted((j for j in jobs if j["outcome"] != "done"), key=lambda j: (j["task"], j["index"]))
    att = {(j["task"], j["index"]): (j, o.explain(j)) for j in missed}
    return att, len(events), source


def metrics_of(att):
    m = {"cause.jobs": {"count": len(att)}}
    for _, a in att.values():
        for k in a["causes"]:
            m.setdefault("cause." + k, {}).setdefault("count", 0)
            m["cause." + k]["count"] += 1
    return m


def compare_jobs(c, label, att, tool_jobs):
    """tool_jobs: {(task, index): {"outcome", "windowStartNs", "windowEndNs", "blockedBy", "causes": [...]}}."""
    for key in sorted(set(att) | set(tool_jobs)):
        where = "%s %s#%d" % (label, key[0], key[1])
        if key not in tool_jobs:
            c.bad.append("%s: %s missing from the tool's attributions" % (c.label, where))
            continue
        if key not in att:
            c.bad.append("%s: %s attributed by the tool, not missed or late" % (c.label, where))
            continue
        j, a = att[key]
        t = tool_jobs[key]
        c.cmp(where + " outcome", t["outcome"], j["outcome"])
        c.cmp(where + " windowStartNs", t["windowStartNs"], a["window"][0], 0)
        c.cmp(where + " windowEndNs", t["windowEndNs"], a["window"][1], 0)
        c.cmp(where + " blockedBy", t["blockedBy"], a["blockedBy"])
        kinds = [x["kind"] for x in t["causes"]]
        tc = {x["kind"]: x["ns"] for x in t["causes"]}
        if len(set(kinds)) != len(kinds):
            c.bad.append("%s: %s lists a kind twice: %s" % (c.label, where, kinds))
        c.cmp(where + " kinds", ",".join(sorted(tc)), ",".join(sorted(a["causes"])))
        for k in sorted(set(tc) & set(a["causes"])):
            c.cmp(where + " " + k, tc[k], a["causes"][k], 0)
        c.compared += 1
        if kinds and kinds[0] not in primaries(tc):
            c.bad.append("%s: %s primary %s is not its largest cause %s" % (c.label, where, kinds[0], tc))
        for p in invariants(j, {"window": (t["windowStartNs"], t["windowEndNs"]), "causes": tc, "ran": a["ran"]}):
            c.bad.append("%s: tool: %s" % (c.label, p))


def tool_primaries(jobs):
    out = {}
    for t in jobs.values():
        k = "cause." + t["causes"][0]["kind"]
        out[k] = out.get(k, 0) + 1
    return out


def audit_explain(c, path):
    with open(path) as f:
        d = json.load(f)
    run_dir = d["runDir"]
    # the capture explain read (it may have been named with --events): "JFR PATH (N events)", "GC log PATH (...)"
    m = re.match(r"(JFR|GC log) (.+?) \(\d+ events\)$", d["events"])
    att, n_events, source = oracle_run(run_dir, m.group(2) if m else None)
    tool = {(x["task"], x["index"]): x for x in d["jobs"]}
    compare_jobs(c, "explain", att, tool)
    mine = metrics_of(att)
    for k in sorted(set(mine) - {"cause.jobs"} | {"cause." + x for x in d["causeCounts"]}):
        c.cmp("explain causeCounts " + k, d["causeCounts"].get(k[6:]), mine.get(k, {}).get("count"))
    prim = tool_primaries(tool)
    for k in sorted(set(prim) | {"cause." + x for x in d["primaryCauseCounts"]}):
        c.cmp("explain primaryCauseCounts " + k, d["primaryCauseCounts"].get(k[6:]), prim.get(k))
    # the events read: explain says how many in its source line
    m = re.search(r"\((\d+) events\)", d["events"])
    c.cmp("explain events", int(m.group(1)) if m else 0, n_events)
    return run_dir, att, source, n_events


def audit_db(c, db, checked):
    con = sqlite3.connect("file:%s?mode=ro" % db, uri=True)
    runs = con.execute("SELECT run_key, run_dir FROM runs WHERE status = 'ok' AND run_dir IS NOT NULL").fetchall()
    for key, rel in runs:
        run_dir = rel if os.path.isabs(rel) else os.path.join(os.path.dirname(os.path.abspath(db)), rel)
        att, n_events, source = oracle_run(run_dir)
        checked.append((run_dir, att, source, n_events))
        tool = {}
        for task, idx, outcome, cj in con.execute(
                "SELECT task, job_index, outcome, causes_json FROM attributions WHERE run_key = ?", (key,)):
            x = json.loads(cj)
            x["outcome"] = outcome
            tool[(task, idx)] = x
        compare_jobs(c, "store " + key, att, tool)
        stored = {}
        for metric, stat, value in con.execute(
                "SELECT metric, stat, value FROM metrics WHERE run_key = ? AND task = 'run' AND metric LIKE 'cause.%'", (key,)):
            stored.setdefault(metric, {})[stat] = value
        mine = metrics_of(att)
        mine.setdefault("cause.events", {})["count"] = n_events
        prim = tool_primaries(tool)
        for k in sorted(set(mine) | set(stored)):
            c.cmp("store %s %s count" % (key, k), stored.get(k, {}).get("count"), mine.get(k, {}).get("count"))
            if k not in ("cause.jobs", "cause.events"):
                # a kind some job has but none as its primary is stored with primary 0
                c.cmp("store %s %s primary" % (key, k), stored.get(k, {}).get("primary"), prim.get(k, 0))
    con.close()
    return len(runs)


def main(argv):
    db, explains, dirs = None, [], []
    it = iter(argv)
    for a in it:
        if a == "--db":
            db = next(it)
        elif a == "--explain":
            explains.append(next(it))
        else:
            dirs.append(a)
    c = Comparer("audit_explain")
    checked = []
    try:
        if db:
            audit_db(c, db, checked)
        for e in explains:
            checked.append(audit_explain(c, e))
        for d in dirs:
            checked.append((d,) + oracle_run(d))
    except (OSError, ValueError, KeyError, IndexError, sqlite3.Error, StopIteration) as e:
        print("audit_explain: cannot read: %s" % e, file=sys.stderr)
        return 2
    jobs = 0
    for d, att, source, n_events in checked:
        jobs += len(att)
        for j, a in att.values():
            for p in invariants(j, a):
                c.bad.append("%s: oracle: %s" % (d, p))
        kinds = {}
        for _, a in att.values():
            for k in a["causes"]:
                kinds[k] = kinds.get(k, 0) + 1
        print("%s: %d jobs attributed (events: %s, %d) %s" % (d, len(att), source, n_events, json.dumps(kinds, sort_keys=True)))
    for b in c.bad:
        print("DISAGREE " + b)
    print("TOTAL: %d run folders, %d jobs, %d numbers compared, %d disagree, largest relative difference %.3g (%s)"
          % (len(checked), jobs, c.compared, len(c.bad), c.max_rel, c.max_rel_where))
    return 1 if c.bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
