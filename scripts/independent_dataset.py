#!/usr/bin/env python3
"""An independent dataset in the thesis's text format, written without any of the project's code.

The project's own generator (Java, package org.jmclbench.tooling.generator) and its MCL share
the project's random generator, angle helpers and conventions; a bug common to both would go
unnoticed by tests that only use generated data. This script shares nothing with them: its
own motion (a robot driving a stadium-shaped track at constant speed, pose in closed form),
Python's own random module (Mersenne Twister, random.gauss), its own crossing search (1 ms
scan, then bisection), its own number formatting (Python's correctly rounded %.16e, single
spaces). It writes only odometry.txt, laser.txt and real.txt: no metadata, so a reader must
take the thesis playground and the start pose from the first real.txt line.

Usage: python3 scripts/independent_dataset.py [--seed N] [--duration S] --out DIR
The shipped copy: python3 scripts/independent_dataset.py --seed 2012 --duration 30 \
    --out tooling/src/test/resources/independent
"""
import argparse
import math
import os
import random
import sys

BEACONS = [(0.0, 1.0), (3.0, 0.0), (3.0, 2.0)]  # the thesis's S1, S2, S3
SPEED = 0.3              # m/s along the track
CX, CY = 1.5, 1.0        # centre of the track
HALF = 0.6               # half length of the straight parts, m
RADIUS = 0.45            # radius of the two half circles, m
ODO_PERIOD = 0.05        # s
TURRET_HZ = 3.0          # revolutions per second, counter-clockwise
LASER_SIGMA = 0.01       # rad
MISS = 0.05              # probability that a crossing is not reported
ODO_ALPHA, ODO_FLOOR = 0.03, 0.0002   # odometry noise: sigma = alpha * motion + floor (m, rad)


def track_pose(t):
    """The true pose at time t: anticlockwise around the stadium, starting at the bottom straight's left end.

    Returns (x, y, heading) with the heading unwrapped (it grows by 2 pi per lap).
    """
    straight = 2 * HALF
    arc = math.pi * RADIUS
    lap = 2 * straight + 2 * arc
    s = SPEED * t
    laps, s = divmod(s, lap)
    turn = 2 * math.pi * laps
    if s < straight:                       # bottom, driving +x
        return CX - HALF + s, CY - RADIUS, turn
    s -= straight
    if s < arc:                            # right half circle
        a = -math.pi / 2 + s / RADIUS
        return CX + HALF + RADIUS * math.cos(a), CY + RADIUS * math.sin(a), turn + s / RADIUS
    s -= arc
    if s < straight:                       # top, driving -x
        return CX + HALF - s, CY + RADIUS, turn + math.pi
    s -= straight                          # left half circle
    a = math.pi / 2 + s / RADIUS
    return CX - HALF + RADIUS * math.cos(a), CY + RADIUS * math.sin(a), turn + math.pi + s / RADIUS


def signed(a):
    """Angle folded into [-pi, pi)."""
    return (a + math.pi) % (2 * math.pi) - math.pi


def beam_offset(t, beacon, phase):
    """Turret direction minus the beacon's direction, both relative to the heading, in [-pi, pi)."""
    x, y, h = track_pose(t)
    turret = phase + 2 * math.pi * TURRET_HZ * t
    return signed(turret - (math.atan2(beacon[1] - y, beacon[0] - x) - h))


def crossings(duration, phase):
    """All (time, beacon index) at which the beam points at a beacon, by a 1 ms scan and bisection."""
    found = []
    step = 0.001
    n = int(round(duration / step))
    for b, beacon in enumerate(BEACONS):
        prev_t, prev = 0.0, beam_offset(0.0, beacon, phase)
        for k in range(1, n + 1):
            t = k * step
            cur = beam_offset(t, beacon, phase)
            if prev < 0 <= cur and cur - prev < 1.0:
                lo, hi = prev_t, t
                for _ in range(60):
                    mid = (lo + hi) / 2
                    if beam_offset(mid, beacon, phase) < 0:
                        lo = mid
                    else:
                        hi = mid
                found.append(((lo + hi) / 2, b))
            prev_t, prev = t, cur
    found.sort()
    return found


def line(values):
    return " ".join("%.16e" % v for v in values) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, default=2012)
    parser.add_argument("--duration", type=float, default=30.0)
    parser.add_argument("--out", required=True)
    args = parser.parse_args(argv)
    if not 0 < args.duration <= 600:
        parser.error("--duration: must be in (0, 600] s")

    rnd = random.Random(args.seed)
    phase = rnd.uniform(0, 2 * math.pi)
    count = int(round(args.duration / ODO_PERIOD))

    odometry, real = [], []
    px, py, ph = track_pose(0.0)
    for k in range(1, count + 1):
        t = k * ODO_PERIOD
        x, y, h = track_pose(t)
        # The increment in the frame of the previous pose (forward, left, turn).
        c, s = math.cos(ph), math.sin(ph)
        fwd = c * (x - px) + s * (y - py)
        left = -s * (x - px) + c * (y - py)
        turn = h - ph
        d = math.hypot(fwd, left)
        sxy = ODO_ALPHA * d + ODO_FLOOR
        st = ODO_ALPHA * abs(turn) + ODO_FLOOR
        odometry.append(line([t, fwd + rnd.gauss(0, sxy), left + rnd.gauss(0, sxy), turn + rnd.gauss(0, st)]))
        real.append(line([t, x, y, h % (2 * math.pi)]))
        px, py, ph = x, y, h

    laser = []
    for t, b in crossings(args.duration, phase):
        if rnd.random() < MISS:
            continue
        x, y, h = track_pose(t)
        bearing = math.atan2(BEACONS[b][1] - y, BEACONS[b][0] - x) - h
        angle = (bearing + rnd.gauss(0, LASER_SIGMA)) % (2 * math.pi)
        laser.append(line([t, angle]))

    os.makedirs(args.out, exist_ok=True)
    for name, rows in (("odometry.txt", odometry), ("laser.txt", laser), ("real.txt", real)):
        tmp = os.path.join(args.out, name + ".partial")
        with open(tmp, "w", newline="\n") as f:
            f.writelines(rows)
        os.replace(tmp, os.path.join(args.out, name))
    print("wrote %s: %d odometry, %d laser, %d real lines" % (args.out, len(odometry), len(laser), len(real)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
