"""The reference Monte-Carlo Localization of docs/ALGORITHM.md sections 1-7, in plain Python.

Standard library only: Python floats are IEEE 754 binary64 and never fused, so + - * / sqrt and
floor give the same bits as Java and C; atan2, exp, sin and cos come from the C library Python is
linked to, which is why the vectors that depend on them carry a tolerance. make_vectors.py writes
what this computes into the conformance vectors.
"""

import math

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
