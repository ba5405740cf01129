#!/usr/bin/env python3
"""Writes the conformance vectors of docs/ALGORITHM.md sections 1-7 into this folder.

An independent reference of the algorithm in plain Python (standard library only): Python
floats are IEEE 754 binary64 and never fused, so + - * / sqrt and floor give the same bits
as Java and C; atan2, exp, sin and cos come from the C library Python is linked to, which is
why the vectors that depend on them carry a tolerance. The files are the contract between
the Java workload and the C baseline; conformance/README.md describes their format.

Usage:  python3 conformance/make_vectors.py [--out DIR]
The output is deterministic: running it again must reproduce the committed files byte for
byte (a JUnit test checks this).
"""

import argparse
import math
import os
import sys

MASK = (1 << 64) - 1
TWO_PI = 6.283185307179586
PI = math.pi

# Section 6 and 7 constants.
INIT_SIGMA = 0.05
ALPHA_XY = 0.10
FLOOR_XY = 0.002
ALPHA_THETA = 0.10
ALPHA_THETA_XY = 0.05
FLOOR_THETA = 0.004
SIGMA_LASER = 0.05
TWO_SIGMA_SQ = 2.0 * SIGMA_LASER * SIGMA_LASER  # same bits as 2 * (SIGMA_LASER^2)

THESIS = (3.0, 2.0, [(0.0, 1.0), (3.0, 0.0), (3.0, 2.0)])

HEADER = "# jmclbench conformance vectors, written by conformance/make_vectors.py; do not edit.\n" \
         "# Format: conformance/README.md. Contract: docs/ALGORITHM.md.\n"


# ---------------------------------------------------------------- section 1: random numbers

def splitmix64(state):
    """One splitmix64 step: returns (new_state, output)."""
    state = (state + 0x9E3779B97F4A7C15) & MASK
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return state, z ^ (z >> 31)


def rotl(x, k):
    return ((x << k) | (x >> (64 - k))) & MASK


class Rng:
    """xoshiro256** seeded with splitmix64, uniform and Irwin-Hall Gaussian (sections 1-2)."""

    def __init__(self, seed):
        sm = seed & MASK
        s = []
        for _ in range(4):
            sm, z = splitmix64(sm)
            s.append(z)
        self.s = s

    def next(self):
        s0, s1, s2, s3 = self.s
        result = (rotl((s1 * 5) & MASK, 7) * 9) & MASK
        t = (s1 << 17) & MASK
        s2 ^= s0
        s3 ^= s1
        s1 ^= s2
        s0 ^= s3
        s2 ^= t
        s3 = rotl(s3, 45)
        self.s = [s0, s1, s2, s3]
        return result

    def uniform(self):
        return float(self.next() >> 11) * (2.0 ** -53)

    def gaussian(self):
        s = 0.0
        for _ in range(12):
            s = s + self.uniform()
        return s - 6.0


# ---------------------------------------------------------------- section 3: angles

def ieee_floor(v):
    """floor() as C and Java define it: math.floor returns an int, which loses the sign of -0.0."""
    f = float(math.floor(v))
    return math.copysign(0.0, v) if f == 0.0 else f


def wrap2pi(a):
    r = a - TWO_PI * ieee_floor(a / TWO_PI)
    return 0.0 if r >= TWO_PI else r


def wrap_pi(a):
    return wrap2pi(a + PI) - PI


def bearing(px, py, pt, bx, by):
    return wrap2pi(math.atan2(by - py, bx - px) - pt)


# ---------------------------------------------------------------- section 7.1: likelihood

def likelihood(x, y, theta, angle, playground):
    w = 0.0
    for bx, by in playground[2]:
        d = wrap_pi(bearing(x, y, theta, bx, by) - angle)
        w = w + math.exp(-(d * d) / TWO_SIGMA_SQ)
    return w


def likelihood_rtol(x, y, theta, angle, playground):
    """A relative tolerance for likelihood(): a last-bit difference of atan2 (about 1e-15 rad
    after wrapping) moves exp(-d^2/2s^2) by the relative amount d/s^2 * 1e-15; the sum is
    dominated by its largest term. At least 1e-12, with a factor 4 of headroom."""
    terms = []
    for bx, by in playground[2]:
        d = wrap_pi(bearing(x, y, theta, bx, by) - angle)
        terms.append((math.exp(-(d * d) / TWO_SIGMA_SQ), abs(d)))
    total = sum(t for t, _ in terms)
    sensitivity = sum(t * d for t, d in terms) / total / (SIGMA_LASER * SIGMA_LASER)
    return max(1e-12, 4.0 * sensitivity * 2e-15)


# ---------------------------------------------------------------- section 7.5: resampling

def resample_systematic(w, n, u):
    """Indices and the smallest |t - c| of any comparison (how far from flipping it was)."""
    out = []
    c = w[0]
    i = 0
    margin = math.inf
    for m in range(n):
        t = u + float(m) / float(n)
        while True:
            if i < n - 1:
                margin = min(margin, abs(t - c))
            if t > c and i < n - 1:
                i += 1
                c = c + w[i]
            else:
                break
        out.append(i)
    return out, margin


def resample_multinomial(w, n, rng):
    cumulative = []
    c = 0.0
    for k in range(n):
        c = c + w[k]
        cumulative.append(c)
    out = []
    margin = math.inf
    for _ in range(n):
        t = rng.uniform()
        k = 0
        while k < n and not (t < cumulative[k]):
            k += 1
        out.append(min(k, n - 1))
        margin = min(margin, min(abs(t - ck) for ck in cumulative[:n - 1]) if n > 1 else math.inf)
    return out, margin


# ---------------------------------------------------------------- sections 4-7: the filter

class Filter:
    """The localizer of sections 4-7, in the order of draws written there."""

    def __init__(self, n, seed, estimate, resample, init, covariance, playground, start):
        self.n = n
        self.rng = Rng(seed)
        self.estimate_mode = estimate
        self.resample_mode = resample
        self.covariance_on = covariance
        self.playground = playground
        self.margin = math.inf  # smallest distance of any discrete decision from flipping
        self.fallbacks = 0  # updates whose likelihoods summed to zero
        x0, y0, t0 = start
        self.x, self.y, self.t = [], [], []
        if init == "known":
            for _ in range(n):
                self.x.append(x0 + INIT_SIGMA * self.rng.gaussian())
                self.y.append(y0 + INIT_SIGMA * self.rng.gaussian())
                self.t.append(wrap2pi(t0 + INIT_SIGMA * self.rng.gaussian()))
            self.est = (x0, y0, wrap2pi(t0))
        else:
            width, height = playground[0], playground[1]
            for _ in range(n):
                self.x.append(width * self.rng.uniform())
                self.y.append(height * self.rng.uniform())
                self.t.append(TWO_PI * self.rng.uniform())
            self.est = (width / 2, height / 2, 0.0)
        self.cov = [0.0] * 6

    def predict(self, dx, dy, dtheta):
        d = math.sqrt(dx * dx + dy * dy)
        sigma_xy = ALPHA_XY * d + FLOOR_XY
        sigma_theta = ALPHA_THETA * abs(dtheta) + ALPHA_THETA_XY * d + FLOOR_THETA
        for i in range(self.n):
            ndx = dx + sigma_xy * self.rng.gaussian()
            ndy = dy + sigma_xy * self.rng.gaussian()
            ndt = dtheta + sigma_theta * self.rng.gaussian()
            c = math.cos(self.t[i])
            s = math.sin(self.t[i])
            self.x[i] = self.x[i] + (ndx * c - ndy * s)
            self.y[i] = self.y[i] + (ndx * s + ndy * c)
            self.t[i] = wrap2pi(self.t[i] + ndt)
        ex, ey, et = self.est
        c = math.cos(et)
        s = math.sin(et)
        self.est = (ex + (dx * c - dy * s), ey + (dx * s + dy * c), wrap2pi(et + dtheta))

    def update(self, angle):
        n = self.n
        w = [likelihood(self.x[i], self.y[i], self.t[i], angle, self.playground) for i in range(n)]
        total = 0.0
        for v in w:
            total = total + v
        if total == 0.0 or math.isnan(total) or math.isinf(total):
            self.fallbacks += 1
            w = [1.0 / n] * n
        else:
            w = [v / total for v in w]
        if self.estimate_mode == "mean":
            sx = sy = ss = sc = 0.0
            for i in range(n):
                sx = sx + w[i] * self.x[i]
                sy = sy + w[i] * self.y[i]
                ss = ss + w[i] * math.sin(self.t[i])
                sc = sc + w[i] * math.cos(self.t[i])
            est = (sx, sy, wrap2pi(math.atan2(ss, sc)))
        else:
            best = 0
            for i in range(1, n):
                if w[i] > w[best]:
                    best = i
            ranked = sorted(w, reverse=True)
            if n > 1 and ranked[0] != ranked[-1]:  # all equal (the 1/N fallback): an exact tie, index 0
                self.margin = min(self.margin, (ranked[0] - ranked[1]) / ranked[0])
            est = (self.x[best], self.y[best], self.t[best])
        if self.covariance_on:
            ex, ey, et = est
            cov = [0.0] * 6
            for i in range(n):
                ux = self.x[i] - ex
                uy = self.y[i] - ey
                ut = wrap_pi(self.t[i] - et)
                cov[0] = cov[0] + w[i] * ux * ux
                cov[1] = cov[1] + w[i] * ux * uy
                cov[2] = cov[2] + w[i] * ux * ut
                cov[3] = cov[3] + w[i] * uy * uy
                cov[4] = cov[4] + w[i] * uy * ut
                cov[5] = cov[5] + w[i] * ut * ut
            self.cov = cov
        else:
            self.cov = [0.0] * 6
        if self.resample_mode == "systematic":
            idx, margin = resample_systematic(w, n, self.rng.uniform() / n)
        else:
            idx, margin = resample_multinomial(w, n, self.rng)
        self.margin = min(self.margin, margin)
        self.x = [self.x[k] for k in idx]
        self.y = [self.y[k] for k in idx]
        self.t = [self.t[k] for k in idx]
        self.est = est


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


# ---------------------------------------------------------------- deadline accounting (FORMATS.md section 4)

QUANTILES = [("min", 0), ("p50", 500), ("p90", 900), ("p99", 990), ("p999", 999), ("max", 1000)]


def account(jobs, task):
    """The deadline accounting and the response time over every release of one task ('all': both)."""
    mine = [j for j in jobs if (task == "all" or j[0] == task) and j[1] != "pending"]
    n = len(mine)
    by = {o: sum(1 for j in mine if j[1] == o) for o in ("done", "late", "skipped", "terminated")}
    misses = by["late"] + by["skipped"] + by["terminated"]
    finite = sorted(j[4] - j[2] for j in mine
                    if j[1] in ("done", "late") and j[2] >= 0 and j[3] >= 0 and j[4] >= 0)
    values = finite + [math.inf] * (n - len(finite))
    quantiles = []
    for _, pm in QUANTILES:
        if n == 0:
            quantiles.append(None)
            continue
        i = min(n - 1, max(0, (pm * n + 999) // 1000 - 1))
        quantiles.append(values[i])
    return n, by, misses, (misses / n if n else None), len(finite), quantiles


def abort_from(job):
    """When an abort took hold of a job (FORMATS.md section 3, abort_ns): the request, or the start when
    requested before it; None when the job never started or nothing was requested before its end."""
    _, _, _, start, end, abort = job
    if abort < 0 or start < 0 or end < 0:
        return None
    at = max(abort, start)
    return at if at < end else None


def abort_latency(jobs, task):
    """Abort latency (end - abort_ns) over the released jobs an abort took hold of, and how many completed."""
    mine = [j for j in jobs if (task == "all" or j[0] == task) and j[1] != "pending" and abort_from(j) is not None]
    values = sorted(j[4] - abort_from(j) for j in mine)
    n = len(values)
    quantiles = [None if n == 0 else values[min(n - 1, max(0, (pm * n + 999) // 1000 - 1))] for _, pm in QUANTILES]
    return n, sum(1 for j in mine if j[1] in ("done", "late")), quantiles


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
