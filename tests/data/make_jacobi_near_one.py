#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""sn, cn, dn(u | m) next to m = 1, m = 1 - k'^2: k' = 1e-10 .. 5e-10 (the Jacobi branch below
k' = 1e-9 and its first-order term) at arguments where k'^2 cosh^2 u is near its limit k' (the
first-order term is then ~1e-12 of cn and dn), and k' = 2e-9 (above it: the Landen recursion)
at an argument where cn is not small.
mpmath's ellipfun at 400 bits, k' and u the doubles as written (exact binary values).

Writes jacobi_near_one.csv: kp, u, sn, cn, dn (25 significant digits)."""

from mpmath import mp, mpf, ellipfun, nstr

mp.prec = 400

ROWS = [("1e-10", "11"), ("1e-10", "11.5"), ("3e-10", "10.5"), ("5e-10", "10"), ("1e-10", "-11"),
        ("2e-9", "3")]

def as_double(text):
    return mpf(float(text))  # the double the test passes, exactly

with open("jacobi_near_one.csv", "w") as out:
    out.write("kp,u,sn,cn,dn\n")
    for kp_text, u_text in ROWS:
        kp, u = as_double(kp_text), as_double(u_text)
        m = 1 - kp * kp
        values = [ellipfun(name, u, m=m) for name in ("sn", "cn", "dn")]
        out.write(",".join([kp_text, u_text] + [nstr(v, 25) for v in values]) + "\n")
