#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The paper's iteration on both sides of the distance from pi where the library hands it
from extended precision to MPFR (d = 0.02): every level's T_N/T0 and coefficients, with
45-digit arithmetic (make_iteration.py's iterate: levels 0 and 1 from Bessel functions,
then the projection of sin(theta) until two rules agree to 1e-40).

Amplitudes pi - d with d the double given (pi - 0.0201 on the extended side, pi - 0.0199 on
the MPFR side) and 0.99pi (the double nearest, taken exactly).

Writes iteration_switch.csv: theta0 text, N, T_N/T0, then c1, c3, ... (';'-separated, 25 digits).
Run from this directory with Debian's python3 (python3-mpmath): a few minutes.
"""
import math

from mpmath import mp

from make_iteration import iterate
from reference_csv import write_reference

mp.dps = 45

AMPLITUDES = [("pi-0.0201", 37), ("pi-0.0199", 37), ("0.99pi", 40)]


def amplitude(text):
    if text.startswith("pi-"):
        return mp.pi - mp.mpf(float(text[3:]))
    return mp.mpf(0.99 * math.pi)


def main():
    rows = []
    for text, order in AMPLITUDES:
        theta0 = amplitude(text)
        for n, lam, c in iterate(theta0, order):
            period = mp.nstr(1 / mp.sqrt(lam), 25) if lam > 0 else ""
            rows.append([text, n, period, ";".join(mp.nstr(v, 25) for v in c)])
    write_reference("iteration_switch.csv", __file__, ["theta0", "order", "period_ratio", "coefficients"], rows)


if __name__ == "__main__":
    main()
