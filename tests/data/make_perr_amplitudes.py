#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# The amplitudes of the period errors' byte test (test_perr_cost.cpp): 400 log-spaced from
# 1e-300 to 3, 400 as pi - d with d log-spaced from 1 to 1e-300 (written as expressions, so
# that d is exact), and 300 evenly spaced from 0.01 to 3.0 (the zero crossings of the
# orders' errors, where MPFR is needed at moderate amplitudes). Writes perr_amplitudes.txt.
import os

lines = ["# written by make_perr_amplitudes.py"]
n = 400
for i in range(n):
    e = -300 + (300 + 0.4771212547) * i / (n - 1)
    lines.append("%.6e" % (10 ** e))
for i in range(n):
    e = -(300 * i / (n - 1))
    lines.append("pi-%.6e" % (10 ** e))
for i in range(300):
    lines.append("%.4f" % (0.01 + i * 0.01))
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "perr_amplitudes.txt"), "w") as f:
    f.write("\n".join(lines) + "\n")
