#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Each approximant's theta(t) at times up to the largest double, with its phase formed from
its exact frequency ratio: the truth a program must reach when it carries w/w0 to the
precision the time needs (not w/w0 rounded to a double, which after 1e15 periods moves
theta by its whole amplitude).

For each amplitude (the double theta0 taken exactly, or pi - d with d the double given),
each method's w/w0 and coefficients c_{2k+1} are computed from the paper's formulas at the
exact amplitude; the time s (in exact periods t/T, the double its text rounds to) gives
w0 t = 4 K(k) s, the phase x = (w/w0) w0 t is reduced modulo 2 pi at 1300 bits (1.8e308
periods need 1030 bits for the integer part), and theta = sum c_k cos((2k+1) x) at 50 digits.
order:3 is the paper's iteration (make_iteration.py: levels 0 and 1 from Bessel functions,
then the projection of sin(theta) until two rules agree to 1e-40): its w/w0 is known to
about 1e-40, so its rows stop at 1e15 periods.

Writes long_time_phase.csv: theta0 text, method, s, theta (25 digits).
Run from this directory with Debian's python3 (python3-mpmath): about a minute.
"""
from mpmath import mp

from make_iteration import iterate as iteration_levels
from reference_csv import write_reference

AMPLITUDES = ["1", "2.5", "pi-1e-12", "pi-0.01"]
METHODS = ["harmonic", "lowest", "first", "second", "polynomial", "order:3"]
TIMES = ["0.9", "0.37", "1000.3", "1000000.3", "1e15", "-7.5e15", "1e100", "1.7976931348623157e308"]


def amplitude(text):
    if text.startswith("pi-"):
        return mp.pi - mp.mpf(float(text[3:]))
    return mp.mpf(float(text))


def over(n, x):
    return mp.besselj(n, x) / x


def solution(method, theta0):
    """(w/w0, [c1, c3, ...]) at the working precision."""
    if method == "harmonic":
        return mp.mpf(1), [theta0]
    if method == "lowest":
        return mp.sqrt(2 * over(1, theta0)), [theta0]
    j1 = over(1, theta0)
    eta = -over(3, theta0) / (9 * j1)
    if method == "first":
        c1 = theta0 / (1 + eta)
        return mp.sqrt(2 * j1 * (1 + eta)), [c1, eta * c1]
    if method == "second":
        a_ratio = 1 / (1 + eta)
        b_ratio = eta / (1 + eta)
        a = theta0 * a_ratio
        C = []
        for k in range(3):
            inner = 2 * over(2 * k + 1, a) * a_ratio + b_ratio * (
                mp.besselj(2 * k + 4, a) - mp.besselj(abs(2 * k - 2), a))
            C.append(inner if k % 2 == 0 else -inner)
        lam = mp.fsum(C[k] / (2 * k + 1) ** 2 for k in range(3))
        return mp.sqrt(lam), [theta0 * C[k] / ((2 * k + 1) ** 2 * lam) for k in range(3)]
    if method == "polynomial":
        t2 = theta0 ** 2
        period = 1 + t2 / 16 + 11 * t2 * t2 / 3072
        return 1 / period, [theta0 + theta0 ** 3 / 192 + 17 * theta0 ** 5 / 61440,
                            -(theta0 ** 3 / 192 + theta0 ** 5 / 3072), theta0 ** 5 / 20480]
    if method.startswith("order:"):
        for _, lam, c in iteration_levels(theta0, int(method[6:])):
            pass
        return mp.sqrt(lam), c
    raise ValueError(method)


def main():
    rows = []
    for text in AMPLITUDES:
        for method in METHODS:
            if method.startswith("order:") and text.startswith("pi-"):
                continue  # the iteration's reference close to pi is make_iteration_near_pi.py's
            mp.prec = 1400
            theta0 = amplitude(text)
            ratio, coefficients = solution(method, theta0)
            k = mp.sin(theta0 / 2)
            quarter = mp.ellipk(k * k)
            for time in TIMES:
                if method.startswith("order:") and abs(float(time)) > 1e16:
                    continue
                mp.prec = 1400
                x = mp.fmod(ratio * 4 * quarter * mp.mpf(float(time)), 2 * mp.pi)
                theta = mp.fsum(c * mp.cos((2 * j + 1) * x) for j, c in enumerate(coefficients))
                mp.dps = 50
                rows.append([text, method, time, mp.nstr(+theta, 25)])
    write_reference("long_time_phase.csv", __file__, ["theta0", "method", "s", "theta"], rows)


if __name__ == "__main__":
    main()
