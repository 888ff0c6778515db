#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Periods in seconds and angles at times in seconds for extreme lengths and gravities.

T_s = (T/T0) 2 pi sqrt(L/g) with T/T0 = 2 K(k^2)/pi, k = sin(theta0/2); theta(t) of the
exact libration from theta0 at rest: theta = 2 asin(k cd(w0 t | k^2)), w0 = sqrt(g/L).
L, g and t are the doubles their decimal texts round to (as the CLI reads them), taken
exactly, and theta0 the exact angle; 60-digit mpmath.

Writes seconds.csv: kind (period or angle), theta0, L, g, t (angles only), value.
"""

from mpmath import mp

from reference_csv import write_reference

mp.dps = 60

PENDULUMS = [
    ("1", "1e-320"),
    ("5e-324", "9.80665"),
    ("1e-320", "9.80665"),
    ("1e6", "5e-324"),
    ("1e-300", "1e4"),
    ("1e6", "1e4"),
    ("0.5", "9.80665"),
]
THETA0 = ["pi/2", "170deg"]
W0_T = "1.234"  # the times below are 1.234/w0 rounded to 17 digits, at most 1e6


def amplitude(text):
    return mp.pi / 2 if text == "pi/2" else mp.mpf(170) * mp.pi / 180


def double(text):
    return mp.mpf(float(text))


def main():
    rows = []
    for theta0_text in THETA0:
        theta0 = amplitude(theta0_text)  # the exact angle: the CLI keeps an expression's moduli
        k = mp.sin(theta0 / 2)
        ratio = 2 * mp.ellipk(k * k) / mp.pi
        for length, g in PENDULUMS:
            L, G = double(length), double(g)
            rows.append(["period", theta0_text, length, g, "", mp.nstr(ratio * 2 * mp.pi * mp.sqrt(L / G), 25)])
            w0 = mp.sqrt(G / L)
            # The CLI takes times up to 1e6: where 1.234/w0 is beyond, 1e6 (w0 t is then tiny).
            t = min(mp.mpf(float(mp.nstr(mp.mpf(W0_T) / w0, 17))), mp.mpf(10) ** 6)
            u = w0 * t
            theta = 2 * mp.asin(k * mp.ellipfun("cd", u, m=k * k))
            rows.append(["angle", theta0_text, length, g, repr(float(t)), mp.nstr(theta, 25)])
    write_reference("seconds.csv", __file__, ["kind", "theta0", "length", "g", "t", "value"], rows)


if __name__ == "__main__":
    main()
