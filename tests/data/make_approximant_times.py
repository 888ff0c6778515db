#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The approximants' theta(t) at times of up to the largest double, for the phase reduction.

Each approximant is a truncated Fourier solution theta = sum_k c_{2k+1} cos((2k+1) x) with
the phase x = (w/w0) w0 t. What the program promises is the exact value of that formula with
its own double coefficients and frequency ratio, so the reference takes them as given: here
each method's c_k and w/w0 are computed at 40 digits from the paper's formulas and rounded to
doubles (written to the file, and the test evaluates the program with these very doubles);
then x is formed and reduced modulo 2 pi at 1300 bits (a time of 1.8e308 periods needs
1030 bits for its integer part) and theta evaluated at 40 digits.

Amplitudes as in make_huge_times.py: 1 and 2.5 the doubles, 170deg pi - d with d the double
nearest pi/18. Each time is the double its decimal text rounds to, taken exactly; w0 t is
s 4K(k) for t/T (K of the exact amplitude), 2 pi s for t/T0 and s sqrt(g/L) for t/s with
L = 0.7 and g = 9.80665 as doubles. order:5 is the paper's iteration (as in
make_iteration.py: levels 0 and 1 from Bessel functions, then the projection of sin(theta)
by the midpoint rule until two rules agree to 1e-40).

Writes approximant_times.csv: theta0 text, method, unit, time text, w/w0 and the
coefficients (17 digits, ';'-separated: the doubles), theta (25 digits).
"""

from mpmath import mp

from make_iteration import iterate as iteration_levels
from reference_csv import write_reference

AMPLITUDES = ["1", "2.5", "170deg"]
METHODS = ["harmonic", "lowest", "first", "second", "polynomial", "order:5"]
UNITS = ["t/T", "t/T0", "t/s"]
TIMES = ["1000.3", "999999.3", "1e12", "1e15", "1e300", "1.7976931348623157e308", "-123456789012.345"]
LENGTH, G = "0.7", "9.80665"


def amplitude(text):
    if text.endswith("deg"):
        # The program keeps an expression close to pi as the double nearest its distance from pi.
        return mp.pi - mp.mpf(float(mp.pi - mp.mpf(text[:-3]) * mp.pi / 180))
    return mp.mpf(float(text))


def bessel_over(n, x):
    return mp.besselj(n, x) / x


def iterate(theta0, order):
    """The coefficients and w/w0 of the iteration's level `order` (make_iteration.py's run)."""
    for _, lam, c in iteration_levels(theta0, order):
        pass
    return mp.sqrt(lam), c


def solution(method, theta0):
    """(w/w0, [c1, c3, ...]) at 40 digits."""
    if method == "harmonic":
        return mp.mpf(1), [theta0]
    if method == "lowest":
        return mp.sqrt(2 * bessel_over(1, theta0)), [theta0]
    if method == "first":
        j1 = bessel_over(1, theta0)
        eta = -bessel_over(3, theta0) / (9 * j1)
        c1 = theta0 / (1 + eta)
        return mp.sqrt(2 * j1 * (1 + eta)), [c1, eta * c1]
    if method == "second":
        j1 = bessel_over(1, theta0)
        eta = -bessel_over(3, theta0) / (9 * j1)
        a_ratio = 1 / (1 + eta)
        b_ratio = eta / (1 + eta)
        a = theta0 * a_ratio
        C = []
        for k in range(3):
            inner = 2 * bessel_over(2 * k + 1, a) * a_ratio + b_ratio * (
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
        return iterate(theta0, int(method[6:]))
    raise ValueError(method)


def double_solution(method, theta0):
    """w/w0 and the coefficients as the doubles the program holds: solution() at 40 digits,
    each rounded once."""
    mp.dps = 40
    ratio, coefficients = solution(method, theta0)
    return float(ratio), [float(c) for c in coefficients]


def main():
    rows = []
    for theta0_text in AMPLITUDES:
        mp.dps = 40
        exact = amplitude(theta0_text)
        as_double = mp.mpf(float(exact))  # the double theta0 the approximants are built from
        for method in METHODS:
            ratio, coefficients = double_solution(method, as_double)
            for unit in UNITS:
                for time in TIMES:
                    mp.prec = 1300
                    theta0 = amplitude(theta0_text)
                    s = mp.mpf(float(time))
                    if unit == "t/T":
                        k = mp.sin(theta0 / 2)
                        w0_t = s * 4 * mp.ellipk(k * k)
                    elif unit == "t/T0":
                        w0_t = 2 * mp.pi * s
                    else:
                        w0_t = s * mp.sqrt(mp.mpf(float(G)) / mp.mpf(float(LENGTH)))
                    x = mp.fmod(mp.mpf(ratio) * w0_t, 2 * mp.pi)
                    mp.dps = 40
                    theta = mp.fsum(mp.mpf(c) * mp.cos((2 * j + 1) * x) for j, c in enumerate(coefficients))
                    rows.append([theta0_text, method, unit, time, repr(ratio),
                                 ";".join(repr(c) for c in coefficients), mp.nstr(theta, 25)])
    write_reference("approximant_times.csv", __file__, ["theta0", "method", "unit", "time", "frequency_ratio", "coefficients", "theta"], rows)


if __name__ == "__main__":
    main()
