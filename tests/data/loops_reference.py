#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Reference for tests/test_loops.cpp: the periods of the motions the looping animations draw
# (a 1 m pendulum, g = 9.80665), and the smallest number of frames at 25 per second after
# which every period has run a whole number of times within one frame (n step - k T in
# [0, step] for each T). Writes loops_reference.csv beside itself.
import csv
import math
import os

import mpmath as mp

mp.mp.dps = 40
G = mp.mpf("9.80665")
T0 = 2 * mp.pi * mp.sqrt(1 / G)  # seconds


def exact_period(deg):
    theta = mp.radians(deg)
    return 2 * mp.ellipk(mp.sin(theta / 2) ** 2) / mp.pi * T0


def lowest_period(deg):
    theta = mp.radians(deg)
    return T0 / mp.sqrt(2 * mp.besselj(1, theta) / theta)


def common_frames(periods, step, most=10000):
    for n in range(1, most + 1):
        end = n * step
        ok = True
        for t in periods:
            k = mp.floor(end / t)
            late = end - k * t
            if not (k >= 1 and 0 <= late <= step):
                ok = False
                break
        if ok:
            return n
    return None


cases = {
    "exact 170deg": [exact_period(170)],
    "exact 10deg and 170deg": [exact_period(10), exact_period(170)],
    "swing: exact, harmonic, lowest at 170deg": [exact_period(170), T0, lowest_period(170)],
}
step = mp.mpf(1) / 25
rows = []
for name, periods in cases.items():
    n = common_frames(periods, step)
    rows.append([name, " ".join(mp.nstr(t, 12) for t in periods), "none" if n is None else n])
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "loops_reference.csv")
with open(out, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["motions", "periods_s", "frames_at_25fps"])
    w.writerows(rows)
for r in rows:
    print(*r, sep=", ")
