#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""theta(t) just before the zero crossing at t = T/4, where the Jacobi functions are
evaluated at a small argument u = K (1 - 4 s) (s = t/T) and switch from the Landen
recursion to their Maclaurin series at |u| = 1e-8.

For each amplitude (the double theta0, taken exactly) and each target u: s is the double
nearest 1/4 - u/(4K), taken exactly, so 1 - 4 s is exact in doubles as in the library; the
exact libration from theta0 at rest is theta = 2 asin(k sn(K (1 - 4 s) | k^2)), k = sin(theta0/2),
at 60 digits.

Writes zero_crossing.csv: theta0 and s (shortest round-trip decimal) and theta (25 digits).
"""

from mpmath import mp

from reference_csv import write_reference

mp.dps = 60

AMPLITUDES = [0.3, 1.0, 2.5, 3.1]
# Either side of the Maclaurin threshold 1e-8, between, and either side of 1e-4.
TARGETS = ["3e-9", "9.9e-9", "1.01e-8", "3e-8", "1e-6", "3e-5", "9.9e-5", "1e-4", "1.01e-4", "3e-4"]


def main():
    rows = []
    for theta0 in AMPLITUDES:
        k = mp.sin(mp.mpf(theta0) / 2)
        quarter = mp.ellipk(k * k)
        for target in TARGETS:
            s = float(mp.mpf(1) / 4 - mp.mpf(target) / (4 * quarter))
            x = mp.mpf(1) - 4 * mp.mpf(s)
            theta = 2 * mp.asin(k * mp.ellipfun("sn", quarter * x, m=k * k))
            rows.append([repr(theta0), repr(s), mp.nstr(theta, 25)])
    write_reference("zero_crossing.csv", __file__, ["theta0", "s", "theta"], rows)


if __name__ == "__main__":
    main()
