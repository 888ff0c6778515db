#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""theta(t) of the iteration's order-92 level at pi - 1e-12, independently of the program.

The level's coefficients c_0..c_92 and lambda = (w/w0)^2 come from make_iteration_near_pi.py's
fixed-point run (at 256 and at 512 fractional bits, which must agree to 1e-40); the level is
then evaluated at 60 digits: theta = sum_k c_k cos((2k+1) x), x = sqrt(lambda) w0 t, with
w0 t = s 4 K(k) (s = t/T in periods of the exact motion of pi - d, d the double nearest
1e-12, as the program holds it).

Writes order92_near_pi.csv: the trajectory arguments and theta (25 digits); the last two
times, 1e6 periods out, are the ends of the longest range a figure's panel takes.

Run with /usr/bin/python3 (python3-mpmath): a few minutes.
"""
import os
import sys

from mpmath import mp

from reference_csv import write_reference

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_iteration_near_pi as iteration  # noqa: E402

ORDER = 92
TIMES = ["0.1", "0.25", "0.5", "1", "2.7", "999999.75", "1000000"]


def main():
    low = iteration.run(256, ORDER, keep={ORDER})[ORDER]
    high = iteration.run(512, ORDER, keep={ORDER})[ORDER]
    mp.prec = 600
    assert abs(low[1] - high[1]) < mp.mpf("1e-40")
    assert max(abs(a - b) for a, b in zip(low[2], high[2])) < mp.mpf("1e-40")
    lam, c = high[1], high[2]
    d = mp.mpf(1e-12)
    kp = mp.sin(d / 2)
    four_k = 2 * mp.pi / mp.agm(1, kp)
    rows = []
    for time in TIMES:
        x = mp.sqrt(lam) * mp.mpf(float(time)) * four_k
        theta = mp.fsum(ck * mp.cos((2 * k + 1) * x) for k, ck in enumerate(c))
        rows.append([f"trajectory --theta0 pi-1e-12 --method order:{ORDER} --at {time}", mp.nstr(theta, 25)])
    write_reference("order92_near_pi.csv", __file__, ["arguments", "theta"], rows)


if __name__ == "__main__":
    main()
