#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Approximants of librations started from a state or an energy, every method, at times up to
the largest double either way, with their phase formed from the exact frequency ratio.

The neighbour of make_state_approximant_times.py (which takes the double w/w0 as exact and
stops at 1e300): here the truth a program must reach. The start's doubles are taken exactly
(an energy as written); E = omega_s^2/2 + 2 sin^2(theta_s/2), the amplitude
theta0 = 2 asin(sqrt(E/2)) exactly, and each method's w/w0 and coefficients are its formulas
(make_long_time_phase.solution) at that exact amplitude. The clock starts at the turning point
+theta0: clock0 = u0 - K with sn(u0) = sin(r/2)/k, cn(u0) = omega_s/(2k) (theta_s = 2 pi n + r),
or u0' + K for a backwards start (the mirror image of the forward motion from
(-theta_s, -omega_s): the clock still counts from the actual motion's turning point +theta0).
theta = 2 pi n + sum c_j cos((2j+1) (w/w0) (w0 t + clock0)), with
w0 t = 2 pi s for t/T0 and 4 K s for t/T; the phase reduced modulo 2 pi at 1400 bits (1.8e308
periods need 1030 for the integer part).

Writes state_approximant_long.csv: the trajectory arguments, theta0 (25 digits), theta (25
digits). Run from this directory with Debian's python3: about half a minute.
"""
import os
import sys

from mpmath import mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_long_time_phase import solution  # noqa: E402
from reference_csv import write_reference  # noqa: E402

STARTS = [  # (arguments, theta_s, omega_s or None with an energy)
    ("--theta0 1 --omega0 0.5", "1", "0.5"),
    ("--theta0 -2 --omega0 -0.8", "-2", "-0.8"),
    ("--theta0 7 --omega0 0.4", "7", "0.4"),
    ("--theta0 2.5 --omega0 0", "2.5", "0"),
    ("--energy 1.5", None, "1.5"),
]
METHODS = ["harmonic", "lowest", "first", "second", "polynomial"]
UNITS = ["t/T0", "t/T"]
MAX = "1.7976931348623157e308"
TIMES = ["1000.3", "1e15", "-7.5e15", "1e100", "1e300", MAX, "-" + MAX]


def start(theta_text, second):
    """(theta_s, omega_s, E): the doubles as written are exact; an energy launches from the
    bottom forwards."""
    if theta_text is None:
        energy = mp.mpf(second)
        return mp.mpf(0), mp.sqrt(2 * energy), energy
    theta_s, omega_s = mp.mpf(theta_text), mp.mpf(second)
    return theta_s, omega_s, omega_s ** 2 / 2 + 2 * mp.sin(theta_s / 2) ** 2


def clock(theta_s, omega_s, energy):
    """(center, clock0): 2 pi n of the swing (signed as the start) and the time since the
    motion was at its turning point +theta0, in units of 1/w0."""
    mirror = -1 if omega_s < 0 else 1
    m = energy / 2
    k = mp.sqrt(m)
    n = mp.nint(mirror * theta_s / (2 * mp.pi))
    r = mirror * theta_s - 2 * mp.pi * n
    u0 = mp.ellipf(mp.atan2(mp.sin(r / 2) / k, mirror * omega_s / (2 * k)), m)
    clock0 = u0 - mp.ellipk(m) if mirror > 0 else u0 + mp.ellipk(m)
    return mirror * 2 * mp.pi * n, clock0


def main():
    rows = []
    for args, theta_text, second in STARTS:
        mp.prec = 1400
        theta_s, omega_s, energy = start(theta_text, second)
        theta0 = 2 * mp.asin(mp.sqrt(energy / 2))
        center, clock0 = clock(theta_s, omega_s, energy)
        quarter = mp.ellipk(energy / 2)
        for method in METHODS:
            mp.prec = 1400
            ratio, coefficients = solution(method, theta0)
            for unit in UNITS:
                for time in TIMES:
                    s = mp.mpf(float(time))
                    w0_t = 2 * mp.pi * s if unit == "t/T0" else 4 * quarter * s
                    x = mp.fmod(ratio * (w0_t + clock0), 2 * mp.pi)
                    theta = center + mp.fsum(c * mp.cos((2 * j + 1) * x) for j, c in enumerate(coefficients))
                    rows.append([f"trajectory {args} --method {method} --time {unit} --at {time}",
                                 mp.nstr(theta0, 25), mp.nstr(theta, 25)])
    write_reference("state_approximant_long.csv", __file__, ["arguments", "theta0", "theta"], rows)


if __name__ == "__main__":
    main()
