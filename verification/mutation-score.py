#!/usr/bin/env python3
"""The mutation score of the SCJ mission's checks: how many realistic bugs they catch.

    verification/mutation-score.py [--only ID,...] [--work DIR] [--retries N] [--unit-timeout S] [--list] [--check]

Copies the tree (the files git knows, as they are now) to a work folder, never touching the
tree itself, and for each mutant of the catalogue below: writes the bug into the copy, runs the
unit tests of the modules the mission is made of (core-immortal, rtsj-compat, scj-mission) and,
when they pass (or are killed after their timeout), `./jmclbench verify` on the checks of the real mission (the toy program's checks
never run shipped code), stopping at the first failing check; then puts the file back (first of
all the copy without a mutant, which must pass both, or every mutant would look caught). A mutant
is caught when a unit test fails or a check fails by what it checks (verify's results file says
why each check failed: a property violated, a vacuous search, a search limit, a JPF crash), missed
when everything passes, and inconclusive when the run was cut short: the unit tests or verify
killed after their timeout, or the failing check over its wall-clock budget (on a loaded VM that
is load, not a bug found). Inconclusive mutants are not scored; `--retries N` runs each again up
to N times, and any left make the exit status 1. Prints a row per mutant and the score, and
writes them to verification/target/mutation-score.md in the copy's source tree. Needs what
verify needs (JPF_CORE_SRC, Maven's cache warm: it runs Maven offline). About an hour on a
2-core VM: a benchmark script, not CI.

Each mutant is a bug a developer could write in the shipped code: one exact text (it must
occur exactly once in its file, else the catalogue is stale and the script stops with exit 2;
`--check` checks only that, and MutationScoreScriptTest runs it) and its replacement.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

SCJ = "scj-mission/src/main/java/org/jmclbench/scj/"
MCL = "core-immortal/src/main/java/org/jmclbench/core/mcl/"
RT = "rtsj-compat/src/main/java/org/jmclbench/rtsjcompat/"
# the policies' rule, which the mission's JobGate asks
POLICY = "core-immortal/src/main/java/org/jmclbench/core/policy/OverrunPolicy.java"

# id, file, text, replacement, the bug in words
MUTANTS = [
    ("gate-skip-no-reservation", POLICY,
     "            s.reserved = k;\n", "",
     "skip: an admitted event does not reserve the robot, so a second one is admitted too"),
    ("gate-terminate-latest-unset", POLICY,
     "            s.latest = k; // the job in progress sees this at its next poll and aborts\n", "",
     "terminate: a release does not announce itself, so the job in progress is never asked to abort"),
    ("gate-abort-any-policy", POLICY,
     "    public boolean abortRequested(State s, int k) {\n        return false;",
     "    public boolean abortRequested(State s, int k) {\n        return s.latest != k;",
     "the abort request is not limited to terminate"),
    ("gate-never-freed", POLICY,
     "            if (s.reserved == k) {\n                s.reserved = State.FREE;\n            }\n", "",
     "skip: the robot is never freed after a job, so every later event is dropped"),
    ("gate-ended-early", SCJ + "JobGate.java",
     "boolean last = ended == events;", "boolean last = ended == events - 1;",
     "the mission ends one event early"),
    ("gate-ended-unsynchronised", SCJ + "JobGate.java",
     "public synchronized boolean ended()", "public boolean ended()",
     "the count of ended events is updated by two handlers without the lock"),
    ("gate-overrun-inverted", SCJ + "JobGate.java",
     "periodicEndNs > releaseNs", "periodicEndNs < releaseNs",
     "skip: the periodic task's overrun test is inverted"),
    ("runner-robot-not-released", SCJ + "JobRunner.java",
     "        gate.release(k);\n", "",
     "a job ends without handing the robot back to the gate"),
    ("runner-deadline-from-start", SCJ + "JobRunner.java",
     "end <= r.deadlineNs[k]", "start <= r.deadlineNs[k]",
     "a job is judged on time when it started before its deadline"),
    ("runner-event-not-ended", SCJ + "JobRunner.java",
     "        if (!completed) {\n            r.outcome[k] = JobRecords.TERMINATED;\n",
     "        if (!completed) {\n            r.outcome[k] = JobRecords.TERMINATED;\n            return end;\n",
     "a terminated job's event is never counted as ended"),
    ("runner-periodic-stop-inverted", SCJ + "JobRunner.java",
     "        if (!requested && now < abortAtNs) {\n",
     "        if (!requested) {\n",
     "terminate: the periodic job's stop at its next release is never seen"),
    ("queue-take-stuck", SCJ + "ReleaseQueue.java",
     "        head++;\n", "",
     "the release queue hands out the same event again"),
    ("queue-offer-unsynchronised", SCJ + "ReleaseQueue.java",
     "synchronized void offer(int k)", "void offer(int k)",
     "the sensor offers to the release queue without its lock"),
    ("robot-predict-unsynchronised", SCJ + "Robot.java",
     "public synchronized boolean predict(int k, AbortSignal abort)", "public boolean predict(int k, AbortSignal abort)",
     "predict does not take the robot's monitor"),
    ("robot-covariance-short", SCJ + "Robot.java",
     "for (int c = 0; c < 6; c++)", "for (int c = 0; c < 5; c++)",
     "the record of an update's covariance misses its last term"),
    ("sensor-not-rearmed", SCJ + "LaserSensor.java",
     "            scheduleNextReleaseTime(nextRelease);\n", "",
     "the laser sensor is not rearmed for its next event"),
    ("sensor-release-before-offer", SCJ + "LaserSensor.java",
     "            queue.offer(k);\n            update.release();\n",
     "            update.release();\n            queue.offer(k);\n",
     "the update handler is released before its event is in the queue"),
    ("predict-stop-at-own-release", SCJ + "PredictHandler.java",
     "entry.releaseNs[entry.odoEvent[i + 1]]", "entry.releaseNs[entry.odoEvent[i]]",
     "terminate: a periodic job is stopped at its own release instead of the next"),
    ("prealloc-generator-not-committed", MCL + "PreallocatedLocalizer.java",
     "        Rng r = rng;\n        rng = work;\n        work = r;\n",
     "",
     "preallocated: a completed job does not commit the generator it drew from"),
    ("prealloc-update-draws-committed", MCL + "PreallocatedLocalizer.java",
     "        Rng r = work;\n        r.copyFrom(rng);\n        if (!FilterSteps.resample",
     "        Rng r = rng;\n        if (!FilterSteps.resample",
     "preallocated: an update draws from the committed generator, which an abort then leaves advanced"),
    ("scoped-generator-not-copied", MCL + "ScopedLocalizer.java",
     "        rng.copyFrom(r);\n", "",
     "scoped: a completed job does not copy its generator back"),
    ("scoped-keeps-private-array", MCL + "ScopedLocalizer.java",
     "        System.arraycopy(qx, 0, x, 0, n);\n", "        x = qx;\n",
     "scoped: the committed x keeps the job's private-memory array instead of a copy"),
    ("scoped-commit-before-poll", MCL + "ScopedLocalizer.java",
     "        if (!FilterSteps.predict(x, y, theta, qx, qy, qt, n, dx, dy, dtheta, r, abort, pollMask)) {\n            return false;\n        }\n        commit(qx, qy, qt, r);\n",
     "        boolean completed = FilterSteps.predict(x, y, theta, qx, qy, qt, n, dx, dy, dtheta, r, abort, pollMask);\n        commit(qx, qy, qt, r);\n        if (!completed) {\n            return false;\n        }\n",
     "scoped: predict commits its particles before it looks at whether it was aborted"),
    ("predict-polls-every-fourth", MCL + "FilterSteps.java",
     "            if ((i & pollMask) == 0 && abort.abortRequested()) {\n                return false;\n            }\n            double ndx",
     "            if ((i & ((pollMask << 2) | 3)) == 0 && abort.abortRequested()) {\n                return false;\n            }\n            double ndx",
     "predict polls every fourth interval"),
    ("covariance-no-poll", MCL + "FilterSteps.java",
     "            if ((i & pollMask) == 0 && abort.abortRequested()) {\n                return false;\n            }\n            double ux",
     "            double ux",
     "the covariance loop does not poll"),
    ("resample-copy-no-poll", MCL + "FilterSteps.java",
     "            if ((m & pollMask) == 0 && abort.abortRequested()) {\n                return false;\n            }\n            int k = index[m];",
     "            int k = index[m];",
     "the resampled particles' copy does not poll"),
    ("weights-not-normalised", MCL + "Likelihood.java",
     "w[i] = w[i] / total;", "w[i] = w[i] * total;",
     "the weights are multiplied by their total instead of divided"),
    ("periodic-late-dropped", RT + "PeriodicRuntime.java",
     "                    countLateRelease();\n", "                    countLateRelease();\n                    k++;\n                    continue;\n",
     "rtsj-compat: a periodic release that starts late is dropped instead of run"),
    ("private-memory-not-emptied", RT + "Area.java",
     "        used = 0;\n        cycles++;", "        cycles++;",
     "rtsj-compat: a private memory is not emptied after a release"),
    ("aperiodic-releases-coalesced", RT + "AperiodicRuntime.java",
     "            pending++;\n", "            pending = 1;\n",
     "rtsj-compat: releases that arrive while the handler runs are merged into one"),
]

# The checks of the real mission (the toy program's never run shipped code).
VERIFY_ONLY = "P2-static,P6-static,P4-static,mission-"
UNIT_MODULES = "core-immortal,rtsj-compat,scj-mission"


# A run killed after this long is inconclusive: a mutant that hangs, or a machine too loaded to tell.
UNIT_TIMEOUT_S = 180
VERIFY_TIMEOUT_S = 900
HUNG = -9


def run(cmd, cwd, log, timeout):
    """The command's exit status, or HUNG when it ran past timeout (its whole process group killed)."""
    with open(log, "w") as f:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            return p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, 9)
            p.wait()
            return HUNG


def copy_tree(src, dst):
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=src, check=True,
                           capture_output=True).stdout.decode().split("\0")
    for f in files:
        if not f or not os.path.isfile(os.path.join(src, f)):
            continue
        target = os.path.join(dst, f)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        if not os.path.exists(target) or open(os.path.join(src, f), "rb").read() != open(target, "rb").read():
            shutil.copy(os.path.join(src, f), target)  # a new mtime: Maven recompiles what changed


def judge(mid, tree, logs, unit_timeout):
    """(verdict, by) of the mutant now written in tree: caught, MISSED, INCONCLUSIVE, INVALID or ERROR."""
    unit_log = os.path.join(logs, mid + "-unit.log")
    rc = run(["mvn", "-o", "-q", "-B", "-pl", UNIT_MODULES, "test"], tree, unit_log, unit_timeout)
    unit_hung = rc == HUNG
    if rc != 0 and not unit_hung and "COMPILATION ERROR" in open(unit_log).read():
        return "INVALID", "does not compile"
    if rc != 0 and not unit_hung:
        failed = sorted(set(re.findall(r"\[ERROR\]\s+(?:\x1b\[[0-9;]*m)*(\w+Test)\.", open(unit_log).read())))
        return "caught", "unit tests: " + (", ".join(failed[:3]) or "failed")
    verify_log = os.path.join(logs, mid + "-verify.log")
    results = os.path.join(logs, mid + "-verify.json")
    if os.path.exists(results):
        os.remove(results)  # a file left by an earlier run must not be read as this one's
    rc = run(["./jmclbench", "verify", "--only", VERIFY_ONLY, "--fail-fast", "--out", results,
              "--logs", os.path.join(logs, mid + "-jpf")], tree, verify_log, VERIFY_TIMEOUT_S)
    # Unit tests killed after their timeout say nothing (a mutant that hangs them, or load); a check
    # that fails by what it checks still catches the mutant.
    hung = f"unit tests killed after {unit_timeout} s" if unit_hung else None
    if rc == HUNG:
        verdict, by = "INCONCLUSIVE", f"verify: killed after {VERIFY_TIMEOUT_S} s"
    elif rc == 0:
        verdict, by = "MISSED", "-"
    else:
        verdict, by = verify_verdict(results, rc, verify_log)
    if hung and verdict == "MISSED":
        return "INCONCLUSIVE", hung + ", verify passes"
    if hung:
        return verdict, f"{by}; {hung}"
    return verdict, by


def verify_verdict(results, rc, verify_log):
    """(verdict, by) of a verify that failed, from its results file: each failing check's failure field."""
    try:
        checks = json.load(open(results))["checks"]
    except (OSError, ValueError, KeyError, TypeError):
        return "ERROR", f"verify exit {rc}, no results file (log {verify_log})"
    failing = [c for c in checks if not c.get("passed")]
    if not failing:
        return "ERROR", f"verify exit {rc}, every check passed (log {verify_log})"
    first = failing[0]  # --fail-fast: the only one
    why = first.get("failure")
    if why == "over-budget":
        return "INCONCLUSIVE", f"verify: {first['id']} over its budget"
    if why is None:
        return "ERROR", f"verify: {first['id']} failed with no failure reason (log {verify_log})"
    return "caught", f"verify: {first['id']} ({why})"


class OneLineParser(argparse.ArgumentParser):
    """argparse, with bad usage as one line (argparse prints the usage before it) and exit 2."""

    def error(self, message):
        print(f"mutation-score: {message}", file=sys.stderr)
        sys.exit(2)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(here)
    p = OneLineParser(description=__doc__.split("\n")[0])
    p.add_argument("--only", help="comma-separated mutant ids")
    p.add_argument("--work", default=os.path.join(os.environ.get("TMPDIR", "/tmp"), "jmclbench-mutants"),
                   help="the folder of the tree's copy (kept, so later runs build incrementally)")
    p.add_argument("--retries", type=int, default=0, metavar="N",
                   help="run an inconclusive mutant (killed after its timeout, a check over its budget) up to N more times")
    p.add_argument("--unit-timeout", type=int, default=UNIT_TIMEOUT_S, metavar="S",
                   help=f"kill the unit tests after S seconds (default {UNIT_TIMEOUT_S}; they take about 25 s)")
    p.add_argument("--list", action="store_true", help="list the catalogue and exit")
    p.add_argument("--check", action="store_true",
                   help="check that every mutant's text occurs once in the sources (the catalogue is not stale) and exit")
    a = p.parse_args()
    if a.retries < 0:
        p.error(f"--retries: {a.retries} is below 0")
    if a.unit_timeout < 1:
        p.error(f"--unit-timeout: {a.unit_timeout} is below 1")
    ids = [m[0] for m in MUTANTS]
    if a.list:
        for m in MUTANTS:
            print(f"{m[0]:34} {m[1].split('/')[0]:14} {m[4]}")
        return 0
    chosen = MUTANTS
    if a.only is not None:  # an empty --only chose every mutant: an hour's run for none asked
        wanted = a.only.split(",")
        if "" in wanted:
            print("mutation-score: --only: an empty mutant id (give ids, see --list)", file=sys.stderr)
            return 2
        unknown = [w for w in wanted if w not in ids]
        if unknown:
            print(f"mutation-score: --only: no mutant {', '.join(unknown)} (see --list)", file=sys.stderr)
            return 2
        chosen = [m for m in MUTANTS if m[0] in wanted]
    work = os.path.abspath(a.work)
    above = work
    while not os.path.exists(above):
        above = os.path.dirname(above)
    if not os.path.isdir(above):  # os.makedirs below would end in a traceback
        print(f"mutation-score: --work: {a.work}: {above} is not a folder", file=sys.stderr)
        return 2
    for mid, path, text, _, _ in chosen:
        n = open(os.path.join(repo, path)).read().count(text)
        if n != 1:
            print(f"mutation-score: mutant {mid}: its text occurs {n} times in {path} (catalogue stale)",
                  file=sys.stderr)
            return 2
    if a.check:
        print(f"mutation-score: {len(chosen)} mutants, each text found once in its source")
        return 0

    tree = os.path.join(work, "tree")
    logs = os.path.join(work, "logs")
    os.makedirs(tree, exist_ok=True)
    os.makedirs(logs, exist_ok=True)
    copy_tree(repo, tree)
    print(f"mutation-score: {len(chosen)} mutants on a copy in {tree}", flush=True)
    # The unmutated copy must pass, or every mutant would look caught.
    verdict, by = judge("baseline", tree, logs, a.unit_timeout)
    if verdict != "MISSED":
        print(f"mutation-score: the copy without a mutant does not pass: {verdict.lower()}, {by} (logs {logs}/baseline-*)",
              file=sys.stderr)
        return 1
    rows = []
    for mid, path, text, replacement, why in chosen:
        t0 = time.time()
        f = os.path.join(tree, path)
        original = open(f).read()
        open(f, "w").write(original.replace(text, replacement, 1))
        try:
            for attempt in range(1 + a.retries):
                verdict, by = judge(mid, tree, logs, a.unit_timeout)
                if verdict != "INCONCLUSIVE":
                    break
                if attempt < a.retries:
                    print(f"{mid:34} inconclusive ({by}), again", flush=True)
        finally:
            open(f, "w").write(original)
        secs = time.time() - t0
        rows.append((mid, verdict, by, secs, why))
        print(f"{mid:34} {verdict:12} {by:48} {secs:6.0f} s", flush=True)

    scored = [r for r in rows if r[1] in ("caught", "MISSED")]
    caught = sum(1 for r in scored if r[1] == "caught")
    inconclusive = [r[0] for r in rows if r[1] == "INCONCLUSIVE"]
    score = f"{caught} of {len(scored)} caught ({100.0 * caught / max(1, len(scored)):.0f}%)"
    score += f", {len(inconclusive)} inconclusive (not scored)"
    print("mutation score: " + score)
    if inconclusive:
        print(f"inconclusive: {len(inconclusive)}, run them again: --only {','.join(inconclusive)}")
    out = os.path.join(tree, "verification", "target", "mutation-score.md")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as md:
        md.write("| mutant | bug | verdict | caught by | s |\n| --- | --- | --- | --- | ---: |\n")
        for mid, verdict, by, secs, why in rows:
            md.write(f"| {mid} | {why} | {verdict} | {by} | {secs:.0f} |\n")
        md.write(f"\nScore: {score}.\n")
    print(f"table: {out}")
    return 0 if all(r[1] in ("caught", "MISSED") for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
