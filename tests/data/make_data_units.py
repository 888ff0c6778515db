#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes data_units.csv: where measured data land on a panel's axes, for the unit
conversions of [[panel.data]] (tests/test_data_series.cpp), with mpmath at 40 digits.
T0 = 2 pi sqrt(L/g); T/T0 = 2 K(k^2)/pi with k = sin(theta0/2)."""
import mpmath as mp

mp.mp.dps = 40


def t0(L, g):
    return 2 * mp.pi * mp.sqrt(mp.mpf(L) / mp.mpf(g))


def ratio(theta):
    return 2 * mp.ellipk(mp.sin(theta / 2) ** 2) / mp.pi


deg = mp.pi / 180
T0a = t0(1, "9.80665")
T0b = t0("0.5", "9.81")
rows = [
    # name, value
    ("deg_to_rad_x", 30 * deg),
    ("rad_to_deg_axis_x", mp.mpf("0.5") / deg),
    ("ratio_to_seconds_y", mp.mpf("1.1") * T0b),
    ("t0_L0.5_g9.81", T0b),
    ("residual_exact_y", mp.mpf("2.163") / T0a - ratio(60 * deg)),
    ("residual_exact_err", mp.mpf("0.009") / T0a),
    ("residual_harmonic_y", mp.mpf("2.163") / T0a - 1),
    ("time_s_to_t_over_T", mp.mpf("1.5") / (T0a * ratio(90 * deg))),
    ("time_t0_to_t_over_T", mp.mpf("0.8") / ratio(90 * deg)),
    ("time_T_to_t_over_T0", mp.mpf("0.5") * ratio(90 * deg)),
    ("time_t0_to_seconds", mp.mpf("0.25") * T0a),
    ("measured_residual_first", mp.mpf("2.014") / T0a - ratio(10 * deg)),
]
with open("data_units.csv", "w") as out:
    out.write("# Written by make_data_units.py (mpmath, 40 digits); 17 significant digits.\n")
    out.write("name,value\n")
    for name, v in rows:
        out.write(f"{name},{mp.nstr(v, 17)}\n")
