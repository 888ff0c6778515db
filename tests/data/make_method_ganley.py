#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference of the method ganley (method_ganley.csv): T/T0 = sqrt(F theta0 / sin(F theta0)),
F = sqrt(3)/2 (Ganley, Am. J. Phys. 53, 73, 1985).

Run from this directory:  /usr/bin/python3 make_method_ganley.py
"""
import mpmath as mp

from method_reference import write_method


def period(a):
    x = mp.sqrt(3) / 2 * a.theta
    return mp.sqrt(x / mp.sin(x))


if __name__ == "__main__":
    write_method("ganley", __file__, period)
