#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference values of the paper's order-N iteration done in 45-digit arithmetic.

Level n keeps n + 1 harmonics: sin(theta_{n-1}) is projected on cos((2k+1)x), k = 0..n,
giving C_k; lambda = sum_k C_k/(2k+1)^2 / theta0 and c_k = C_k / ((2k+1)^2 lambda). Levels 0
and 1 project sin(theta0 cos x) exactly through Bessel functions. The projection is the
midpoint rule on [0, pi/2] with L points, which is the trapezoidal rule on 4L points over
the period: exact up to the aliased harmonics of sin(theta), which fall off geometrically.
L is doubled until two rules agree to 1e-40, so every value below is the iteration's own
(exact-arithmetic) value, with no rounding of the stored coefficients.

Writes iteration.csv: theta0 (as an expression and its value), order N, lambda, T_N/T0 and
T_N/T - 1 against the exact period (empty where lambda <= 0: no period exists there).

Run with /usr/bin/python3 (python3-mpmath, and python3-gmpy2 for speed): about 10 minutes.
"""
import sys

from mpmath import mp

from reference_csv import write_reference

mp.dps = 45

# (expression, value, highest order)
AMPLITUDES = [
    ("pi/2", lambda: mp.pi / 2, 200),
    ("3pi/4", lambda: 3 * mp.pi / 4, 200),
    ("9pi/10", lambda: 9 * mp.pi / 10, 200),
    ("0.95pi", lambda: mp.mpf("0.95") * mp.pi, 40),
    ("0.99pi", lambda: mp.mpf("0.99") * mp.pi, 40),
    ("pi-1e-6", lambda: mp.pi - mp.mpf("1e-6"), 20),
    ("pi-1e-9", lambda: mp.pi - mp.mpf("1e-9"), 50),
]


def projection(c, count, L, table):
    """C_k, k < count, by the midpoint rule with L points; table[m] = cos(m pi / (4L))."""
    period = 8 * L
    C = [mp.zero] * count
    width = max(len(c), count)
    for i in range(L):
        step = 2 * (2 * i + 1)
        index = 2 * i + 1
        cosines = []
        for _ in range(width):
            cosines.append(table[index])
            index = (index + step) % period
        f = mp.sin(mp.fsum(cj * cosines[j] for j, cj in enumerate(c)))
        for k in range(count):
            C[k] += f * cosines[k]
    return [2 * v / L for v in C]


def cos_table(L):
    return [mp.cos(m * mp.pi / (4 * L)) for m in range(8 * L)]


def iterate(theta0, order):
    """Yields (N, lambda, [c1, c3, ...]) for N = 0..order: lambda = (w/w0)^2 of level N and
    its Fourier coefficients."""
    c = [theta0]
    L = 16
    tables = {}
    for level in range(order + 1):
        count = level + 1
        if level <= 1:
            C = [2 * (-1) ** k * mp.besselj(2 * k + 1, theta0) for k in range(count)]
        else:
            L = max(L, count)
            coarse = projection(c, count, L, tables.setdefault(L, cos_table(L)))
            while True:
                fine = projection(c, count, 2 * L, tables.setdefault(2 * L, cos_table(2 * L)))
                if max(abs(a - b) for a, b in zip(coarse, fine)) < mp.mpf("1e-40"):
                    C = fine
                    break
                L *= 2
                coarse = fine
        lam = mp.fsum(C[k] / (2 * k + 1) ** 2 for k in range(count)) / theta0
        c = [C[k] / ((2 * k + 1) ** 2 * lam) for k in range(count)]
        yield level, lam, c


def exact_period_ratio(theta0):
    k = mp.sin(theta0 / 2)
    return 2 * mp.ellipk(k * k) / mp.pi


def main():
    rows = []
    for name, value, order in AMPLITUDES:
        theta0 = value()
        exact = exact_period_ratio(theta0)
        for n, lam, _ in iterate(theta0, order):
            if lam > 0:
                ratio = 1 / mp.sqrt(lam)
                rows.append([name, mp.nstr(theta0, 20), n, mp.nstr(lam, 30), mp.nstr(ratio, 30),
                             mp.nstr(ratio / exact - 1, 20)])
            else:
                rows.append([name, mp.nstr(theta0, 20), n, mp.nstr(lam, 30), "", ""])
            print(name, n, file=sys.stderr, flush=True)
    write_reference("iteration.csv", __file__, ["theta0", "value", "order", "lambda", "period_ratio", "error"], rows)


if __name__ == "__main__":
    main()
