#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The claims' largest deviations max |theta_m(t) - theta(t)| over one exact period, at the
exact amplitudes the paper names (pi/3 is pi/3, not its double), with mpmath at 50 digits:
the approximant's w/w0 and coefficients from the paper's formulas (lowest and second order,
as in make_long_time_phase.py), the exact motion theta = 2 asin(k sn(K - w0 t | k^2)); the
maximum is found on a scan of 2000 points and refined by solving d/ds deviation = 0.

Writes claims_deviations.csv: method, amplitude name, p and q (theta0 = p pi / q), the largest
deviation in rad (25 digits). Run from this directory with Debian's python3 (python3-mpmath).
"""
from mpmath import mp

from make_long_time_phase import solution
from reference_csv import write_reference

ROWS = [("lowest", "pi/3", 1, 3), ("lowest", "pi/2", 1, 2), ("lowest", "3pi/4", 3, 4),
        ("lowest", "9pi/10", 9, 10), ("second", "9pi/10", 9, 10), ("second", "95pi/100", 95, 100),
        ("second", "99pi/100", 99, 100)]


def deviation(method, theta0):
    ratio, c = solution(method, theta0)
    k = mp.sin(theta0 / 2)
    m = k * k
    quarter = mp.ellipk(m)

    def g(s):
        w0_t = 4 * quarter * s
        approx = mp.fsum(cj * mp.cos((2 * j + 1) * ratio * w0_t) for j, cj in enumerate(c))
        return approx - 2 * mp.asin(k * mp.ellipfun("sn", quarter - w0_t, m=m))

    return g


def main():
    rows = []
    for method, name, p, q in ROWS:
        mp.dps = 20
        g = deviation(method, mp.pi * p / q)
        n = 2000
        best = max(range(n + 1), key=lambda i: abs(g(mp.mpf(i) / n)))
        mp.dps = 50
        g = deviation(method, mp.pi * p / q)
        s = mp.mpf(best) / n
        for _ in range(30):  # Newton on the derivative
            step = mp.diff(g, s, 1) / mp.diff(g, s, 2)
            s -= step
            if abs(step) < mp.mpf("1e-40"):
                break
        assert abs(s - mp.mpf(best) / n) <= mp.mpf(1) / n, (method, name)
        rows.append([method, name, p, q, mp.nstr(abs(g(s)), 25)])
    write_reference("claims_deviations.csv", __file__, ["method", "at", "p", "q", "deviation"], rows)


if __name__ == "__main__":
    main()
