# SPDX-License-Identifier: GPL-3.0-or-later
"""The reference table of one period formula, method_NAME.csv, for the table-driven test
MethodReference.EveryMethodFile (tests/test_library_state.cpp): a make_method_NAME.py script
gives the formula T_m/T0 in mpmath, and this module evaluates it with the exact period
1/AGM(1, k') at 900 digits on a fixed list of amplitudes (expressions the program parses),
from the exact amplitude: theta0, k = sin(theta0/2), k' = cos(theta0/2) (from d = pi - theta0
near pi, so that k' keeps its digits). Each row: theta0, T_m/T0 (25 digits), T_m/T - 1 (20
digits, or "below" under 1e-300).
"""
import mpmath as mp

from reference_csv import write_reference

# The amplitudes of the period-error reference (make_period_errors.py), at its 900 digits.
from make_period_errors import AMPLITUDES  # noqa: E402

f = mp.mpf


class Amplitude:
    """theta0 with its moduli k and k', exact."""

    def __init__(self, t):
        self.theta = t
        d = mp.pi - t
        self.k = mp.cos(d / 2) if t > 1 else mp.sin(t / 2)
        self.kp = mp.sin(d / 2) if t > 1 else mp.cos(t / 2)


def write_method(name, script, period):
    """Writes method_NAME.csv for `period`, a function of an Amplitude giving T_m/T0."""
    rows = []
    for text, value in AMPLITUDES:
        a = Amplitude(value())
        p = period(a)
        e = p / (1 / mp.agm(1, a.kp)) - 1
        shown = "below" if abs(e) < f("1e-300") else mp.nstr(e, 20, min_fixed=1, max_fixed=0)
        rows.append([text, mp.nstr(p, 25, min_fixed=1, max_fixed=0), shown])
    write_reference(f"method_{name}.csv", script, ["theta0", "period", "error"], rows)
