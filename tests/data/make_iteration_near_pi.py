#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The paper's order-N iteration at pi - 1e-12, independently of make_iteration.py.

Level n keeps n + 1 harmonics c_0..c_n: sin(theta(x)), theta(x) = sum_j c_j cos((2j+1)x) of
the previous level (theta0 cos x before level 0), is projected on cos((2k+1)x), k = 0..n:
C_k = (2/pi) int_0^pi sin(theta(x)) cos((2k+1)x) dx; then lambda = sum_k C_k/(2k+1)^2 / theta0
(so that sum c = theta0) and c_k = C_k / ((2k+1)^2 lambda). T_n/T0 = 1/sqrt(lambda) where
lambda > 0 (no period otherwise).

Unlike make_iteration.py (midpoint rule on [0, pi/2], Bessel functions at levels 0 and 1,
45 digits), every level here is projected by the trapezoidal rule on [0, pi] with its end
points, M doubled until two rules agree to 2^-(P - 40), in fixed point with P fractional
bits (exact integer sums, mpmath for the cosines and the sines). The whole run is done at
P = 256 and at P = 512 bits, and the two must agree to 1e-40 at every level: the values are
the iteration's own, not rounding.

Writes iteration_near_pi.csv: theta0 expression, order N, lambda, T_N/T0 (empty where
lambda <= 0).

Run with /usr/bin/python3 (python3-mpmath): a few minutes.
"""
import sys

from mpmath import mp

from reference_csv import write_reference

EXPRESSION = "pi-1e-12"
HIGHEST = 100


def run(bits, highest=HIGHEST, keep=()):
    """[(N, lambda)] for N = 0..highest at `bits` fractional bits; for the levels in `keep`
    (N, lambda, [c_0, .., c_N]) with the coefficients in radians."""
    mp.prec = bits + 64
    one = 1 << bits
    # pi - 1e-12 as the CLI holds it: pi - d with d the double nearest 1e-12 (the iteration
    # there is so sensitive that decimal 1e-12 gives T_92 larger by 9e-15).
    theta0 = mp.pi - mp.mpf(1e-12)
    theta0_fixed = int(mp.nint(theta0 * one))

    tables = {}

    def table(M):
        # cos(m pi / M), m = 0 .. 2M - 1, in fixed point.
        if M not in tables:
            tables[M] = [int(mp.nint(mp.cos(m * mp.pi / M) * one)) for m in range(2 * M)]
        return tables[M]

    def project(c, count, M):
        t = table(M)
        period = 2 * M
        width = max(len(c), count)
        sums = [0] * count
        for i in range(M + 1):
            cosines = [t[((2 * j + 1) * i) % period] for j in range(width)]
            theta = sum(cj * cosines[j] for j, cj in enumerate(c)) >> bits
            f = int(mp.nint(mp.sin(mp.ldexp(theta, -bits)) * one))
            if i == 0 or i == M:
                f //= 2  # the trapezoidal rule's end weights
            for k in range(count):
                sums[k] += f * cosines[k]
        return [(2 * s // M) >> bits for s in sums]

    c = [theta0_fixed]
    M = 64
    out = []
    tolerance = 1 << 40
    for level in range(highest + 1):
        count = level + 1
        M = max(M, 4 * count)
        coarse = project(c, count, M)
        while True:
            fine = project(c, count, 2 * M)
            M *= 2
            if max(abs(a - b) for a, b in zip(coarse, fine)) < tolerance:
                break
            coarse = fine
        C = [mp.ldexp(v, -bits) for v in fine]
        lam = mp.fsum(C[k] / (2 * k + 1) ** 2 for k in range(count)) / theta0
        c = [int(mp.nint(C[k] / ((2 * k + 1) ** 2 * lam) * one)) for k in range(count)]
        if level in keep:
            out.append((level, lam, [C[k] / ((2 * k + 1) ** 2 * lam) for k in range(count)]))
        else:
            out.append((level, lam))
        # Harmonics that fell below the precision only cost time.
        print(bits, level, M, mp.nstr(lam, 20), file=sys.stderr, flush=True)
        M //= 2
    return out


def main():
    low = run(256)
    high = run(512)
    mp.prec = 600
    rows = []
    for (n, a), (_, b) in zip(low, high):
        assert abs(a - b) < mp.mpf("1e-40"), (n, a, b)
        ratio = 1 / mp.sqrt(b) if b > 0 else None
        rows.append([EXPRESSION, n, mp.nstr(b, 30), mp.nstr(ratio, 30) if ratio is not None else ""])
    write_reference("iteration_near_pi.csv", __file__, ["theta0", "order", "lambda", "period_ratio"], rows)


if __name__ == "__main__":
    main()
