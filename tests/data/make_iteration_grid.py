#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The paper's iteration on both sides of the distance from pi where the library hands the
levels from extended precision to MPFR (iteration_mp_below = 0.02), and at 0.99pi: every
level's T_N/T0 to order 174 (pi - 0.0201), 120 (0.99pi) and 60 (pi - 0.0199), with
40-digit arithmetic. The projection of sin(theta) is the trapezoid rule on a quarter
period, its intervals halved (every node kept) until two rules agree to 1e-36:
make_iteration.py's midpoint rule recomputes every node and takes hours to these orders.
(iteration_switch.csv has the coefficients of every level to order 37 and 40.)

Amplitudes pi - d with d the double given (0.0201 and 0.0199: the two sides of the
switch) and 0.99pi (the double nearest, taken exactly).

Writes iteration_grid.csv: theta0 text, N, T_N/T0 (25 digits, empty where the level has no
period), then c1, c3, ... (';'-separated, 25 digits) for N in COEFFICIENT_ORDERS (none
here), else empty. Each level is also printed to standard error as it is made. Run from this
directory with Debian's python3 (python3-mpmath): about 45 minutes, two amplitudes at a time
(order 174 near pi is the slow part).
"""
import math
import multiprocessing
import sys

from mpmath import mp

from reference_csv import write_reference

mp.dps = 40

# (amplitude, highest order)
AMPLITUDES = [("pi-0.0201", 174), ("0.99pi", 120), ("pi-0.0199", 60)]
COEFFICIENT_ORDERS = set()


def cos_table(L):
    """cos(m pi / (4L)) for m = 0 .. 8L - 1."""
    return [mp.cos(m * mp.pi / (4 * L)) for m in range(8 * L)]


def node_sums(u, count, theta0, L, parity, table):
    """For k < count: the sum over the nodes m pi/(4L), m < 2L of the given parity, of
    sin(theta0 theta(x))/theta0 cos((2k+1)x), theta(x)/theta0 = sum_j u_j cos((2j+1)x); the
    node 0 has weight 1/2."""
    period = 8 * L
    f = []
    rows = []
    for m in range(parity, 2 * L, 2):
        cosines = [table[((2 * j + 1) * m) % period] for j in range(len(u))]
        value = mp.sin(theta0 * mp.fdot(u, cosines)) / theta0
        f.append(value / 2 if m == 0 else value)
        rows.append(m)
    return [mp.fdot(f, [table[((2 * k + 1) * m) % period] for m in rows]) for k in range(count)]


def projection(u, count, theta0, state):
    """C_k/theta0 for k < count; state holds L (kept from level to level) and the tables."""
    L = max(state["L"], count // 2 + 16)
    tables = state["tables"]
    sums = node_sums(u, count, theta0, L, 0, tables.setdefault(L, cos_table(L)))
    coarse = [2 * v / L for v in sums]
    while True:
        mid = node_sums(u, count, theta0, L, 1, tables.setdefault(L, cos_table(L)))
        sums = [a + b for a, b in zip(sums, mid)]
        fine = [v / L for v in sums]
        if max(abs(a - b) for a, b in zip(coarse, fine)) < mp.mpf("1e-36"):
            state["L"] = L
            return fine
        L *= 2
        coarse = fine


def iterate(theta0, order):
    """Yields (N, lambda, [c1, c3, ...]) for N = 0..order."""
    state = {"L": 0, "tables": {}}
    u = [mp.one]
    for level in range(order + 1):
        count = level + 1
        if level <= 1:
            C = [2 * (-1) ** k * mp.besselj(2 * k + 1, theta0) / theta0 for k in range(count)]
        else:
            C = projection(u, count, theta0, state)
        lam = mp.fsum(C[k] / (2 * k + 1) ** 2 for k in range(count))
        u = [C[k] / ((2 * k + 1) ** 2 * lam) for k in range(count)]
        yield level, lam, [theta0 * v for v in u]


def amplitude(text):
    if text.startswith("pi-"):
        return mp.pi - mp.mpf(float(text[3:]))
    return mp.mpf(0.99 * math.pi)


def rows_of(text, order):
    theta0 = amplitude(text)
    rows = []
    for n, lam, c in iterate(theta0, order):
        period = mp.nstr(1 / mp.sqrt(lam), 25) if lam > 0 else ""
        coefficients = ";".join(mp.nstr(v, 25) for v in c) if n in COEFFICIENT_ORDERS else ""
        print(text, n, period, file=sys.stderr, flush=True)
        rows.append([text, n, period, coefficients])
    return rows


def main():
    # One process per amplitude (two at a time).
    with multiprocessing.Pool(2) as pool:
        rows = [row for part in pool.starmap(rows_of, AMPLITUDES) for row in part]
    write_reference("iteration_grid.csv", __file__, ["theta0", "order", "period_ratio", "coefficients"], rows)


if __name__ == "__main__":
    main()
