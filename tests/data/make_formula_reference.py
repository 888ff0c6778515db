#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference values of user formulas as methods (formula_reference.csv).

For each formula of FORMULAS (the test, tests/test_formulas.cpp, lists the same texts in
the same order) and each amplitude, a double: T_f/T0 and the period error T_f/T - 1,
with mpmath at 120 digits, where T/T0 = 2 K(m)/pi, m = sin(theta0/2)^2 (mpmath's
parameter convention, as the formulas' ellipk and ellipe use). The exact period written
as a formula is checked here to give an error below 1e-100.

Run from this directory:  /usr/bin/python3 make_formula_reference.py
"""
import math

import mpmath as mp

from reference_csv import write_reference

mp.mp.dps = 120

# The same texts as the test's; evaluated here by mpmath's functions of the same names.
FORMULAS = [
    "1/sqrt(cos(theta0/2))",
    "(sin(theta0/2)/(theta0/2))^(-3/4)",
    "sqrt(theta0/(2*besselj(1, theta0))) * (2*ellipe(sin(theta0/2)^2)/pi)^(-0.1) / agm(1, cos(theta0/2))^0.2",
]


def value(text, t):
    env = {"theta0": t, "sqrt": mp.sqrt, "cos": mp.cos, "sin": mp.sin, "besselj": mp.besselj,
           "ellipe": mp.ellipe, "ellipk": mp.ellipk, "agm": mp.agm, "pi": mp.pi}
    return eval(text.replace("^", "**"), {"__builtins__": {}}, env)


def amplitudes():
    near_zero = [1e-6, 3e-6, 1e-5, 1e-4, 1e-3, 0.01, 0.03, 0.1]
    middle = [0.3, 0.5, 0.8, 1.0, 1.3, math.pi / 2, 1.8, 2.0, 2.3, 2.6, 2.9, 3.0, 3.1]
    near_pi = [math.pi - d for d in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6)]
    return near_zero + middle + near_pi


def main():
    rows = []
    for i, text in enumerate(FORMULAS):
        for t in amplitudes():
            x = mp.mpf(t)
            exact = 2 * mp.ellipk(mp.sin(x / 2) ** 2) / mp.pi
            assert abs(exact * mp.agm(1, mp.cos(x / 2)) - 1) < mp.mpf(10) ** -100
            f = value(text, x)
            rows.append([i, repr(t), mp.nstr(f, 25, min_fixed=0, max_fixed=0),
                         mp.nstr(f / exact - 1, 25, min_fixed=0, max_fixed=0)])
    for t in amplitudes():
        x = mp.mpf(t)
        exact = 2 * mp.ellipk(mp.sin(x / 2) ** 2) / mp.pi
        assert abs(value("2*ellipk(sin(theta0/2)^2)/pi", x) / exact - 1) < mp.mpf(10) ** -100
    write_reference("formula_reference.csv", __file__, ["formula", "theta0", "period", "error"], rows)


if __name__ == "__main__":
    main()
