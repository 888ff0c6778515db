#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""`pendulum-figures eval --theta0 @FILE --columns theta0,period_exact` done the usual way:
numpy reads the amplitudes, scipy's complete elliptic integral gives T/T0 = 2K(k)/pi with
k = sin(theta0/2), and numpy.savetxt writes the CSV. The yardstick of `make bench`.

Usage: numpy_eval.py AMPLITUDES OUT.csv
Needs: python3-numpy, python3-scipy (Debian).
"""
import sys

import numpy as np
from scipy import special

theta0 = np.loadtxt(sys.argv[1])
k = np.sin(theta0 / 2)
period = 2 * special.ellipk(k * k) / np.pi
np.savetxt(sys.argv[2], np.column_stack([theta0, period]), fmt="%.17g", delimiter=",",
           header="theta0,period_exact", comments="")
