#!/usr/bin/env python3
"""Writes the conformance vectors of docs/ALGORITHM.md sections 1-7 into this folder.

The values come from an independent reference of the algorithm in plain Python (standard
library only): reference_mcl.py (the filter) and reference_deadlines.py (the deadline
accounting of docs/FORMATS.md). The files are the contract between the Java workload and the
C baseline; conformance/README.md describes their format.

Usage:  python3 conformance/make_vectors.py [--out DIR]
The output is deterministic: running it again must reproduce the committed files byte for
byte (a JUnit test checks this).
"""

import argparse
import math
import os
import sys

from reference_deadlines import abort_latency, account
from reference_mcl import (MASK, PI, SIGMA_LASER, THESIS, TWO_PI, Filter, Rng, bearing, likelihood, likelihood_rtol,
                           resample_multinomial, resample_systematic, splitmix64, wrap2pi, wrap_pi)

HEADER = "# jmclbench conformance vectors, written by conformance/make_vectors.py; do not edit.\n" \
         "# Format: conformance/README.md. Contract: docs/ALGORITHM.md.\n"

# ---------------------------------------------------------------- writing

def hexd(v):
    """A double's IEEE 754 bit pattern as 16 lower-case hex digits."""
    import struct
    return "%016x" % struct.unpack("<Q", struct.pack("<d", v))[0]


def hexu(v):
    return "%016x" % (v & MASK)


def g17(v):
    return "%.17g" % v


SEEDS = [0, 1, 42, -1, -(1 << 63), 1234567890123456789]


def write_rng(out):
    out.write(HEADER)
    out.write("# Section 1: xoshiro256** seeded with splitmix64. Bit-exact.\n"
              "# Columns: seed (uint64, hex) call (0-based count of next() calls before this one) next (uint64, hex)\n"
              "# Seeds are the run's 64-bit seed as unsigned: ffffffffffffffff is Java's -1L.\n")
    for seed in SEEDS:
        r = Rng(seed)
        for k in range(1000):
            v = r.next()
            if k < 8 or k == 999:
                out.write("%s %d %s\n" % (hexu(seed), k, hexu(v)))


def write_doubles(out, what, draw, calls, doc):
    out.write(HEADER)
    out.write(doc)
    out.write("# Columns: seed (uint64, hex) call (0-based count of %s() calls before this one) value (double bits, hex)"
              " value (%%.17g, for humans; readers ignore it)\n" % what)
    for seed in SEEDS[:4]:
        r = Rng(seed)
        for k in range(calls):
            v = draw(r)
            out.write("%s %d %s %s\n" % (hexu(seed), k, hexd(v), g17(v)))


def write_wrap(out):
    out.write(HEADER)
    out.write("# Section 3: wrap2pi and wrapPi use only /, *, - and floor, so they are bit-exact.\n"
              "# Columns: function (wrap2pi|wrappi) a (double bits, hex) result (double bits, hex) a result (%.17g, for humans)\n")
    values = [0.0, -0.0, 1.0, -1.0, PI, -PI, TWO_PI, -TWO_PI, 3 * PI, -3 * PI, 7.0, -7.0, 100.0, -100.0,
              1e6 + 0.5, -1e6 - 0.5, 1e-300, -1e-300, -1e-17, TWO_PI - 1e-15, math.nextafter(TWO_PI, 0.0),
              math.nextafter(-TWO_PI, 0.0), math.nextafter(PI, 0.0), math.nextafter(-PI, 0.0), 4.0, -2.5]
    r = Rng(2024)
    for _ in range(8):
        values.append((r.uniform() - 0.5) * 40.0)
    for name, f in (("wrap2pi", wrap2pi), ("wrappi", wrap_pi)):
        for a in values:
            v = f(a)
            out.write("%s %s %s %s %s\n" % (name, hexd(a), hexd(v), g17(a), g17(v)))


def write_bearing(out):
    out.write(HEADER)
    out.write("# Section 3: bearing(px, py, ptheta, bx, by) = wrap2pi(atan2(by - py, bx - px) - ptheta).\n"
              "# atan2 comes from each language's math library: compare on the circle,\n"
              "# |wrapPi(actual - expected)| <= 1e-12. Cases keep 1e-9 away from the wrap point.\n"
              "# Columns: px py ptheta bx by expected (all %.17g)\n")
    cases = [(0.0, 0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 3.0, 0.0), (0.0, 0.0, 0.0, 3.0, 2.0),
             (0.5, 0.5, 0.0, 0.0, 1.0), (1.5, 1.0, PI, 3.0, 2.0), (1.5, 1.0, 3 * PI / 2, 3.0, 0.0),
             (2.9, 0.1, 1.0, 3.0, 0.0), (1.0, 1.0, 6.0, 0.0, 1.0), (3.0, 1.0, 0.5, 3.0, 2.0)]
    r = Rng(7)
    while len(cases) < 40:
        cases.append((3.0 * r.uniform(), 2.0 * r.uniform(), TWO_PI * r.uniform(),
                      [0.0, 3.0, 3.0][len(cases) % 3], [1.0, 0.0, 2.0][len(cases) % 3]))
    for c in cases:
        v = bearing(*c)
        if v < 1e-9 or v > TWO_PI - 1e-9:
            continue
        out.write(" ".join(g17(x) for x in c) + " " + g17(v) + "\n")


def write_likelihood(out):
    out.write(HEADER)
    out.write("# Section 7.1: likelihood(x, y, theta, angle) on the playground of the latest 'playground' line.\n"
              "# Lines:\n"
              "#   playground W H B bx_1 by_1 ... bx_B by_B     (B beacons, in summation order)\n"
              "#   case x y theta angle expected rtol           (%.17g; pass when\n"
              "#        |actual - expected| <= rtol * expected; rtol >= 1e-12 grows with the\n"
              "#        sensitivity of exp() to a last-bit atan2 difference, see make_vectors.py)\n")
    playgrounds = [THESIS, (4.0, 4.0, [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)])]
    r = Rng(11)
    for pg in playgrounds:
        out.write("playground %s %s %d %s\n" % (g17(pg[0]), g17(pg[1]), len(pg[2]),
                                                " ".join("%s %s" % (g17(bx), g17(by)) for bx, by in pg[2])))
        cases = []
        # Near a true measurement (large likelihood), and random poses/angles (small ones).
        for k in range(10):
            x, y, t = pg[0] * r.uniform(), pg[1] * r.uniform(), TWO_PI * r.uniform()
            bx, by = pg[2][k % len(pg[2])]
            a = wrap2pi(bearing(x, y, t, bx, by) + 0.03 * r.gaussian())
            cases.append((x, y, t, a))
        for _ in range(10):
            cases.append((pg[0] * r.uniform(), pg[1] * r.uniform(), TWO_PI * r.uniform(), TWO_PI * r.uniform()))
        for c in cases:
            v = likelihood(c[0], c[1], c[2], c[3], pg)
            if v < 1e-200:  # keep far from underflow, where relative comparisons mean nothing
                continue
            out.write("case %s %s %s\n" % (" ".join(g17(x) for x in c), g17(v),
                                           "%.3g" % likelihood_rtol(c[0], c[1], c[2], c[3], pg)))


def write_resample(out):
    out.write(HEADER)
    out.write("# Section 7.5 for given weights: bit-exact (only additions, divisions and comparisons).\n"
              "# Lines (doubles as IEEE 754 bits in hex, indices as decimal integers):\n"
              "#   systematic N u w_0 .. w_{N-1} i_0 .. i_{N-1}\n"
              "#     u is the offset uniform()/N, passed in; i_m is the old particle new particle m copies.\n"
              "#   multinomial N seed w_0 .. w_{N-1} i_0 .. i_{N-1} next\n"
              "#     the N draws come from a generator seeded with seed (uint64, hex); next is that\n"
              "#     generator's next() after the resampling (it checks that exactly N uniforms were drawn).\n")
    cases = []
    cases.append(([0.25] * 4, 0.0))          # t == c exactly: 't > c' must not advance
    cases.append(([0.25] * 4, 0.25 / 4 * 3))
    cases.append(([1.0, 0.0, 0.0, 0.0], 0.1))  # one particle takes all
    cases.append(([0.0, 0.0, 0.0, 1.0], 0.0))  # leading zeros
    cases.append(([0.0, 0.5, 0.0, 0.5, 0.0], 0.19))
    cases.append(([1.0], 0.5))
    cases.append(([0.1, 0.2, 0.3, 0.4], 0.2499))
    r = Rng(99)
    for n in (8, 13, 64, 100):
        raw = [r.uniform() ** 3 for _ in range(n)]
        total = 0.0
        for v in raw:
            total = total + v
        cases.append(([v / total for v in raw], r.uniform() / n))
    for w, u in cases:
        n = len(w)
        idx, _ = resample_systematic(w, n, u)
        out.write("systematic %d %s %s %s\n" % (n, hexd(u), " ".join(hexd(v) for v in w), " ".join(map(str, idx))))
    for k, (w, _) in enumerate(cases):
        n = len(w)
        seed = 1000 + k
        rng = Rng(seed)
        idx, _ = resample_multinomial(w, n, rng)
        out.write("multinomial %d %s %s %s %s\n" % (n, hexu(seed), " ".join(hexd(v) for v in w),
                                                    " ".join(map(str, idx)), hexu(rng.next())))


# The small filter scenarios: (name, particles, seed, estimate, resample, init, covariance, start, steps).
# A step is ("predict", dx, dy, dtheta) or ("update", angle); angles are what a robot at the
# true pose would measure, so the weights are informative.
def scenario_steps(start, moves, beacon_order):
    x, y, t = start
    steps = []
    for k, (dx, dy, dt) in enumerate(moves):
        steps.append(("predict", dx, dy, dt))
        c, s = math.cos(t), math.sin(t)
        x, y, t = x + dx * c - dy * s, y + dx * s + dy * c, wrap2pi(t + dt)
        bx, by = THESIS[2][beacon_order[k % len(beacon_order)]]
        steps.append(("update", wrap2pi(bearing(x, y, t, bx, by) + 0.01)))
    return steps


SCENARIOS = [
    ("default", 8, 1, "mean", "systematic", "known", True, (0.5, 0.5, 0.0),
     [(0.02, 0.0, 0.01), (0.02, 0.001, 0.03), (0.0, 0.0, 0.0)], [0, 1, 2]),
    ("thesis", 8, 5, "best", "multinomial", "known", True, (1.5, 1.0, 1.0),
     [(0.015, -0.002, -0.02), (0.02, 0.0, 0.05)], [2, 0]),
    ("global", 8, -3, "mean", "systematic", "uniform", False, (1.0, 1.0, 0.0),
     [(0.01, 0.0, 0.0), (0.01, 0.0, 0.1)], [1, 2]),
    ("blocks", 70, 1234567890123456789, "mean", "multinomial", "known", True, (2.0, 0.7, 4.0),
     [(0.03, 0.0, -0.04), (0.0, 0.0, 0.2)], [0, 2]),
    # A start heading outside [0, 2pi): the initial estimate is reported wrapped, like every heading.
    ("wrapstart", 8, 11, "mean", "systematic", "known", False, (1.0, 1.5, -1.0),
     [(0.01, 0.0, 0.02)], [1]),
]
# Steps given directly: a measured angle no particle can explain (every term of every
# likelihood underflows to 0), so the weights fall back to 1/N and 'best' is an exact tie.
SCENARIOS_LOST = [
    ("lost", 8, 21, "best", "systematic", "known", True, (0.1, 1.8, 0.0),
     [("predict", 0.0, 0.0, 0.0), ("update", 2.35), ("predict", 0.01, 0.0, 0.0), ("update", 2.35)]),
]


def write_mcl(out):
    out.write(HEADER)
    out.write("# Sections 4-7: small filters run through init, predict and update. Doubles %.17g.\n"
              "# Tolerance: 1e-9 absolute on every x, y and covariance term, and on every angle compared\n"
              "# on the circle (|wrapPi(actual - expected)|); the sin/cos/atan2/exp of two libraries differ\n"
              "# in the last bit (1e-16), which a few steps amplify by far less than 1e6. Every discrete decision\n"
              "# (resampling comparison, best particle) is at least 'margin' (relative for best) from\n"
              "# flipping, far more than such differences, so indices agree exactly.\n"
              "# Lines:\n"
              "#   scenario NAME N SEED ESTIMATE RESAMPLE INIT COV X0 Y0 THETA0   (SEED uint64 hex; COV 0|1;\n"
              "#            playground: the thesis's; ESTIMATE mean|best, RESAMPLE systematic|multinomial,\n"
              "#            INIT known|uniform, the start pose for known)\n"
              "#   init | predict DX DY DTHETA | update ANGLE    a step; the lines after it are the state after it:\n"
              "#   particle I X Y THETA                           one line per particle, I = 0..N-1\n"
              "#   estimate X Y THETA\n"
              "#   covariance CXX CXY CXT CYY CYT CTT              after an update, when COV is 1\n"
              "#   margin M                                       after the last step of a scenario (informative)\n"
              "#   end\n")
    scenarios = [(name, n, seed, est, res, init, cov, start, scenario_steps(start, moves, order))
                 for name, n, seed, est, res, init, cov, start, moves, order in SCENARIOS]
    scenarios += SCENARIOS_LOST
    for name, n, seed, est, res, init, cov, start, steps in scenarios:
        f = Filter(n, seed, est, res, init, cov, THESIS, start)
        out.write("scenario %s %d %s %s %s %s %d %s %s %s\n" % (name, n, hexu(seed), est, res, init, int(cov),
                                                                 g17(start[0]), g17(start[1]), g17(start[2])))

        def state():
            for i in range(n):
                out.write("particle %d %s %s %s\n" % (i, g17(f.x[i]), g17(f.y[i]), g17(f.t[i])))
            out.write("estimate %s %s %s\n" % tuple(g17(v) for v in f.est))

        out.write("init\n")
        state()
        for step in steps:
            if step[0] == "predict":
                f.predict(step[1], step[2], step[3])
                out.write("predict %s %s %s\n" % (g17(step[1]), g17(step[2]), g17(step[3])))
                state()
            else:
                f.update(step[1])
                out.write("update %s\n" % g17(step[1]))
                state()
                if cov:
                    out.write("covariance %s\n" % " ".join(g17(v) for v in f.cov))
        if name == "lost" and f.fallbacks != 2:
            raise SystemExit("scenario lost: the likelihoods did not underflow as intended")
        if f.margin < 1e-6:
            raise SystemExit("scenario %s: a discrete decision is only %g from flipping; choose another seed"
                             % (name, f.margin))
        out.write("margin %.3g\nend\n" % f.margin)


def deadline_cases():
    """Hand-made edge cases, then seeded random runs: (name, [(task, outcome, release, start, end, abort)])."""
    cases = [
        ("empty", []),
        ("one-predict-done", [("predict", "done", 0, 100, 2100, -1)]),
        ("all-dropped", [("update", "skipped", 1000 * k, -1, -1, -1) for k in range(3)]),
        # aborts: requested at the end (nothing asked), mid-way, of a job never started, before the start
        # (it counts from the start; the job completed all the same)
        ("aborted-with-and-without-times", [
            ("predict", "done", 0, 10, 510, 510), ("update", "terminated", 100, 520, 900, 600),
            ("update", "terminated", 200, -1, -1, 300), ("predict", "late", 300, 900, 60000300, 400),
            ("update", "done", 400, 60000310, 60000400, -1)]),
        ("ties-and-pending", [
            ("predict", "done", 0, 0, 500, -1), ("predict", "done", 1000, 1000, 1500, -1),
            ("predict", "late", 2000, 2000, 2500, -1), ("update", "done", 3000, 3000, 3500, -1),
            ("update", "pending", -1, -1, -1, -1), ("predict", "pending", -1, -1, -1, -1)]),
    ]
    # cumulative probabilities of done, late, skipped, terminated (with times); the rest terminated before starting
    for seed, n, cut in ((21, 97, (0.70, 0.82, 0.92, 0.97)), (2026, 1001, (0.90, 0.975, 0.99, 0.995))):
        r = Rng(seed)
        ra = Rng(seed + 1)  # the abort requests: a stream of their own, so the jobs stay those of before
        jobs = []
        t = 0
        for _ in range(n):
            t += 1 + (r.next() >> 44)
            task = "predict" if r.uniform() < 0.6 else "update"
            u = r.uniform()
            start = t + (r.next() >> 50)
            end = start + 1 + (r.next() >> 40)
            # an abort request anywhere from before the start to after the end, or none
            a = ra.uniform()
            abort = -1 if a < 0.5 else start - (ra.next() >> 52) + int((a - 0.5) * 2.4 * (end - start))
            if u < cut[0]:
                jobs.append((task, "done", t, start, end, abort))
            elif u < cut[1]:
                jobs.append((task, "late", t, start, end + 50000000, abort))
            elif u < cut[2]:
                jobs.append((task, "skipped", t, -1, -1, -1))
            elif u < cut[3]:
                jobs.append((task, "terminated", t, start, end, max(abort, start)))
            else:
                jobs.append((task, "terminated", t, -1, -1, abort))
        cases.append(("random-%d" % seed, jobs))
    return cases


def write_deadlines(out):
    out.write(HEADER)
    out.write("# docs/FORMATS.md section 4: deadline accounting and response time over every release, per task.\n"
              "# case NAME JOBS, then JOBS lines: job TASK OUTCOME RELEASE_NS START_NS END_NS (-1: no such time)\n"
              "# then for predict, update and all:\n"
              "#   count TASK released done late skipped terminated deadlineMisses missRatio (double bits, hex, or null)"
              " missRatio (%.17g, for humans)\n"
              "#   response TASK count completed min p50 p90 p99 p999 max (ns; inf: not completed; null: nothing released)\n"
              "#   abort TASK count completed min p50 p90 p99 p999 max: abort latency, end - abort_ns, over the jobs an\n"
              "#     abort took hold of (abort_ns: the request, or the start when before it; none at or after the end)\n"
              "# end. Pending jobs were never released and count nowhere. Integers exact, missRatio bit-exact.\n")
    for name, jobs in deadline_cases():
        out.write("case %s %d\n" % (name, len(jobs)))
        for task, outcome, release, start, end, abort in jobs:
            out.write("job %s %s %d %d %d %d\n" % (task, outcome, release, start, end, abort))
        for task in ("predict", "update", "all"):
            n, by, misses, ratio, completed, quantiles = account(jobs, task)
            out.write("count %s %d %d %d %d %d %d %s %s\n" % (
                task, n, by["done"], by["late"], by["skipped"], by["terminated"], misses,
                "null" if ratio is None else hexd(ratio), "null" if ratio is None else g17(ratio)))
            out.write("response %s %d %d %s\n" % (task, n, completed, " ".join(
                "null" if q is None else "inf" if q == math.inf else "%d" % q for q in quantiles)))
        for task in ("predict", "update", "all"):
            n, completed, quantiles = abort_latency(jobs, task)
            out.write("abort %s %d %d %s\n" % (task, n, completed, " ".join(
                "null" if q is None else "%d" % q for q in quantiles)))
        out.write("end\n")


FILES = [
    ("rng.txt", write_rng),
    ("uniform.txt", lambda o: write_doubles(o, "uniform", Rng.uniform, 12,
                                            "# Section 1: uniform() = (next() >> 11) * 2^-53. Bit-exact.\n")),
    ("gaussian.txt", lambda o: write_doubles(o, "gaussian", Rng.gaussian, 12,
                                             "# Section 2: gaussian() = twelve uniforms summed, minus 6. Bit-exact.\n")),
    ("wrap.txt", write_wrap),
    ("bearing.txt", write_bearing),
    ("likelihood.txt", write_likelihood),
    ("resample.txt", write_resample),
    ("mcl.txt", write_mcl),
    ("deadlines.txt", write_deadlines),
]


def self_check():
    """Published values, so that this reference does not merely agree with itself."""
    # splitmix64 seeded with 0 (Vigna's reference splitmix64.c): first output.
    assert splitmix64(0)[1] == 0xE220A8397B1DCDAF, hex(splitmix64(0)[1])
    assert math.copysign(1.0, wrap2pi(-0.0)) == 1.0  # -0.0 - (2pi * -0.0) is +0.0 in IEEE arithmetic
    assert 2.0 * SIGMA_LASER * SIGMA_LASER == 2.0 * (SIGMA_LASER * SIGMA_LASER)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)),
                    help="folder to write the vector files into (default: this script's folder)")
    args = ap.parse_args()
    self_check()
    os.makedirs(args.out, exist_ok=True)
    for name, write in FILES:
        path = os.path.join(args.out, name)
        with open(path + ".tmp", "w", newline="\n") as out:
            write(out)
        os.replace(path + ".tmp", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
