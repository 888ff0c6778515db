#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The exact theta(t) next to its zero crossings, at w0 t = K - u and 3K + u for u = 1e-12 to
1e-2: there the Jacobi functions are evaluated at a small argument and the library switches
between their Maclaurin series and the Landen recursion.

For each amplitude (the double theta0 taken exactly, or pi - d with d the double given) and
each u, w0 t is the double nearest K - u (and 3K + u), taken exactly, and s = t/T the
double nearest 1/4 - u/(4K) (and 3/4 + u/(4K)); the exact libration
from theta0 at rest is theta = 2 asin(k sn(K - w0 t | k^2)), k = sin(theta0/2), at 60 digits.

The test holds theta to 1e-14 theta0 and, within 1e-6 of a crossing, to a few ulps of
itself.

Writes crossing_times.csv: theta0 text, which time ("w0_t" or "s"), its value (shortest
round-trip decimal), theta (25 digits).
Run from this directory with Debian's python3 (python3-mpmath).
"""
from mpmath import mp

from reference_csv import write_reference

mp.dps = 60

AMPLITUDES = ["0.3", "1", "2.5", "3.1", "pi-1e-6"]
DISTANCES = ["1e-12", "1e-11", "1e-10", "5e-10", "1e-9", "2e-9", "3e-9", "6e-9", "9.9e-9", "1e-8",
             "1.01e-8", "3e-8", "6e-8", "9.9e-8", "1e-7", "3e-7", "1e-6", "1e-5", "1e-4", "1e-3", "1e-2"]


def amplitude(text):
    if text.startswith("pi-"):
        return mp.pi - mp.mpf(float(text[3:]))
    return mp.mpf(float(text))


def main():
    rows = []
    for text in AMPLITUDES:
        theta0 = amplitude(text)
        k = mp.sin(theta0 / 2)
        m = k * k
        quarter = mp.ellipk(m)
        for u in DISTANCES:
            for w0_t in (float(quarter - mp.mpf(u)), float(3 * quarter + mp.mpf(u))):
                theta = 2 * mp.asin(k * mp.ellipfun("sn", quarter - mp.mpf(w0_t), m=m))
                rows.append([text, "w0_t", repr(w0_t), mp.nstr(theta, 25)])
            # The same distance in exact periods: s the double nearest 1/4 - u/(4K) (and 3/4 +
            # u/(4K)), taken exactly; theta is then right to a few ulps of itself.
            for s in (float(mp.mpf(1) / 4 - mp.mpf(u) / (4 * quarter)), float(mp.mpf(3) / 4 + mp.mpf(u) / (4 * quarter))):
                theta = 2 * mp.asin(k * mp.ellipfun("sn", quarter - 4 * quarter * mp.mpf(s), m=m))
                rows.append([text, "s", repr(s), mp.nstr(theta, 25)])
    write_reference("crossing_times.csv", __file__, ["theta0", "time", "value", "theta"], rows)


if __name__ == "__main__":
    main()
