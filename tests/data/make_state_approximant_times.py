#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Approximants of librations from a state or an energy, at times of up to 1e300 periods.

An approximant of a libration that does not start at rest runs on the libration's own clock:
theta = 2 pi n + sum_k c_k cos((2k+1) (w/w0) (w0 t + clock0)), clock0 the exact time since
the motion was at its turning point +theta0 (for a backwards start, the mirror image of the
forward motion from (-theta_s, -omega_s): -f(tau) = f(tau + 2K)). With
theta = 2 asin(k sn(u | k^2)), k^2 = E/2, the turning point is u = K and the start u0 has
sn(u0) = sin(r/2)/k, cn(u0) = omega_s/(2k) (theta_s = 2 pi n + r): clock0 = u0 - K, or
u0' + K backwards.

The coefficients and w/w0 are the method's formulas at the double amplitude
2 atan2(k, k') with k = sqrt(E/2), k' = sqrt((2 - E)/2) rounded as the program rounds them
(E and 2 - E rounded once from their exact values), at 40 digits, rounded to doubles and
written to the file; the phase is reduced at 1300 bits. Times are in t/T0 (w0 t = 2 pi s).

Writes state_approximant_times.csv: the trajectory arguments, w/w0 and the coefficients
(17 digits, ';'-separated), theta (25 digits).
"""
import math
import os
import sys

from mpmath import mp

from reference_csv import write_reference

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_approximant_times import double_solution  # noqa: E402
from make_state_times import start_state  # noqa: E402

STARTS = [
    ("--theta0 1 --omega0 0.5", "1", "0.5"),
    ("--theta0 -2 --omega0 -0.8", "-2", "-0.8"),
    ("--theta0 7 --omega0 0.4", "7", "0.4"),
    ("--energy 1.5", None, "1.5"),
]
METHODS = ["harmonic", "lowest", "first", "polynomial"]
TIMES = ["1000.3", "999999.3", "1e15", "1e300", "-1e300"]


def main():
    rows = []
    for args, theta_text, second in STARTS:
        mp.prec = 1300
        theta_s, omega_s, energy, mirror = start_state(theta_text, second)
        m = energy / 2
        k = mp.sqrt(m)
        n = mp.nint(mirror * theta_s / (2 * mp.pi))
        r = mirror * theta_s - 2 * mp.pi * n
        u0 = mp.ellipf(mp.atan2(mp.sin(r / 2) / k, mirror * omega_s / (2 * k)), m)
        clock0 = u0 - mp.ellipk(m) if mirror > 0 else u0 + mp.ellipk(m)
        center = mirror * 2 * mp.pi * n
        # The amplitude as the program holds it: from k and k' rounded once.
        k_double = math.sqrt(0.5 * float(energy))
        kp_double = math.sqrt(0.5 * float(2 - energy))
        theta0 = mp.mpf(2 * math.atan2(k_double, kp_double))
        for method in METHODS:
            ratio, coefficients = double_solution(method, theta0)
            for time in TIMES:
                mp.prec = 1300
                x = mp.fmod(mp.mpf(ratio) * (2 * mp.pi * mp.mpf(float(time)) + clock0), 2 * mp.pi)
                theta = center + mp.fsum(mp.mpf(c) * mp.cos((2 * j + 1) * x) for j, c in enumerate(coefficients))
                rows.append([f"trajectory {args} --method {method} --time t/T0 --at {time}", repr(ratio),
                             ";".join(repr(c) for c in coefficients), mp.nstr(theta, 25)])
    write_reference("state_approximant_times.csv", __file__, ["arguments", "frequency_ratio", "coefficients", "theta"], rows)


if __name__ == "__main__":
    main()
