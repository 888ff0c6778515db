#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes measured.csv: ten periods of a 1 m pendulum (g = 9.80665 m/s^2) as a lab course
measures them: the exact period (mpmath, 30 digits) with a fixed, made-up reading error of a
few milliseconds, rounded to the stopwatch's 1 ms, and the uncertainty of each reading."""
import mpmath as mp

mp.mp.dps = 30
L, g = mp.mpf(1), mp.mpf("9.80665")
T0 = 2 * mp.pi * mp.sqrt(L / g)
# Reading errors (s) and uncertainties (s): larger swings are timed over fewer periods.
offsets = [0.004, -0.006, 0.003, 0.008, -0.004, 0.010, -0.009, 0.012, 0.006, -0.015]
uncertainty = [0.006, 0.006, 0.007, 0.007, 0.008, 0.009, 0.010, 0.012, 0.014, 0.016]
with open("measured.csv", "w") as out:
    out.write("# A 1 m pendulum timed at ten amplitudes (g = 9.80665 m/s^2).\n")
    out.write("# theta0 in degrees, T and its uncertainty dT in seconds.\n")
    out.write("theta0,T,dT\n")
    for i in range(10):
        deg = 10 * (i + 1)
        k = mp.sin(mp.radians(deg) / 2)
        T = T0 * 2 * mp.ellipk(k**2) / mp.pi
        out.write(f"{deg},{float(T) + offsets[i]:.3f},{uncertainty[i]:.3f}\n")
