#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Plain numbers from 3 to pi as eval reads them: the double theta0 of the text, and d = pi - x,
k = sin(x/2) and k' = cos(x/2) of the exact decimal x the text is, each rounded once to a double.

The texts: the largest double below pi in 16 to 19 digits, decimals closer to pi than any double
(18 and 19 digits), pi - 10^-n for n = 1..18 in 19 digits, doubles from 3 written exactly, forms
with an exponent, 20 and 21 digits (read by MPFR), and 3000 random decimals of 1 to 19 digits
from 3 to pi (a fixed seed). mpmath at 400 bits, then float() rounds once to the nearest double.

Writes eval_plain_moduli.csv: text, theta0, d, k, kp (each double as repr, the shortest text
that reads back to it).
"""

import csv
import os
import random

from mpmath import mp, mpf, sin, cos

mp.prec = 400

FIXED = [
    "3", "3.0", "3.125", "3.140625", "3.0000000000000004", "3.1", "3.14", "3.14159",
    "3.141592653589793", "3.1415926535897931", "3.14159265358979311", "3.141592653589793116",
    "3.1415926535897932", "3.14159265358979323", "3.141592653589793238",
    "3.14159265358979312", "3.1415926535897926", "3.141592653589793115",
    "31415926535897931e-16", "0.31415926535897931e1", "314.159e-2", "3.0e0", "3.1E+0",
    "3.14159265358979311599", "3.141592653589793238462", "2.9999999999999999999e0",
]


def texts():
    out = list(FIXED)
    for n in range(1, 19):
        out.append(mp.nstr(mp.pi - mpf(10) ** -n, 19, strip_zeros=False, min_fixed=-1, max_fixed=2))
    rng = random.Random(37)
    while len(out) < len(FIXED) + 18 + 3000:
        digits = rng.randint(1, 19)
        x = mpf(3) + (mp.pi - 3) * mpf(rng.random())
        t = mp.nstr(x, digits, strip_zeros=False, min_fixed=-1, max_fixed=2)
        if mpf(t) < mp.pi and mpf(t) >= 3:
            out.append(t)
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "eval_plain_moduli.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["text", "theta0", "d", "k", "kp"])
        for t in texts():
            x = mpf(t)
            assert 2.9 < x < mp.pi, t
            w.writerow([t, repr(float(x)), repr(float(mp.pi - x)), repr(float(sin(x / 2))), repr(float(cos(x / 2)))])


if __name__ == "__main__":
    main()
