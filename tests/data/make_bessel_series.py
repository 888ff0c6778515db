#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""J_n(x) and J_n(x)/x for the power series the library sums in extended precision
(|x| <= 4), from mpmath's besselj at 60 digits. Each x is the double its text rounds to,
taken exactly.

Writes bessel_series.csv: n, x (shortest round-trip decimal), J_n(x) and J_n(x)/x (25 digits).
"""

from mpmath import mp

from reference_csv import write_reference

mp.dps = 60

ORDERS = [0, 1, 2, 3, 5, 8, 13, 21, 40]
ARGUMENTS = [1e-3, 0.25, 0.7, 1.3, 2.0, 2.9, 3.5, 3.99, 4.0, -3.3]


def main():
    rows = []
    for n in ORDERS:
        for x in ARGUMENTS:
            j = mp.besselj(n, mp.mpf(x))
            rows.append([n, repr(x), mp.nstr(j, 25), mp.nstr(j / mp.mpf(x), 25)])
    write_reference("bessel_series.csv", __file__, ["n", "x", "J_n(x)", "J_n(x)/x"], rows)


if __name__ == "__main__":
    main()
