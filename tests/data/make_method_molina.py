#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference of the method molina (method_molina.csv): T/T0 = (sin(theta0)/theta0)^(-3/8)
(Molina, Phys. Teach. 35, 489, 1997). Its expansion 1 + theta0^2/16 + ... agrees with the
exact period's to the theta0^2 term: the exponent -3/8 is what makes it so.

Run from this directory:  /usr/bin/python3 make_method_molina.py
"""
import mpmath as mp

from method_reference import write_method


def period(a):
    return (mp.sin(a.theta) / a.theta) ** (mp.mpf(-3) / 8)


if __name__ == "__main__":
    write_method("molina", __file__, period)
