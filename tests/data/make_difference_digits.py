#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The digits a difference a - b of two doubles deserves, for the residual columns of `data`.

Rule: a - b computed in doubles carries the rounding of its terms, 2^-52 max(|a|, |b|) (one
ulp of the larger, at most), so it deserves floor(log10(|a - b| / (2^-52 max(|a|, |b|))))
significant digits (13 units of that rounding know one digit, not two), clamped to 1 .. 17; 17 where nothing cancels (|a - b| >= max(|a|, |b|):
terms of opposite signs, or one of them 0). Evaluated with mpmath at 60 digits from the
doubles a and b taken exactly, the difference a - b rounded to a double first (as the program
has it). Rows at the boundaries: |a - b| exactly 10^n units of 2^-52 of the terms (n digits) and
half a unit less (n - 1).

Writes difference_digits.csv: a, b (17 digits, each a double), digits; and residual_digits.csv:
measured periods y (T/T0, at theta0 = 1 rad) of a residual panel, the digits the rule gives
their residual y - T/T0 (the double T/T0 as the program has it), and the true residual
y - T(1)/T0 (T/T0 = 2 K(sin^2(1/2)) / pi) rounded to those digits.
"""
import math

from mpmath import mp

from reference_csv import write_reference

mp.dps = 60


def digits(a, b):
    d = mp.mpf(a - b)  # the double difference, as the program holds it
    size = max(abs(mp.mpf(a)), abs(mp.mpf(b)))
    if size == 0 or abs(d) >= size:
        return 17
    units = abs(d) / (size * mp.mpf(2) ** -52)
    n = int(mp.floor(mp.log10(units))) if units > 0 else 1
    return min(17, max(1, n))


def main():
    pairs = [
        (1.0, 1.0 + 2 ** -52),        # one ulp apart: 1 digit
        (1.0000001, 1.0),             # 1e-7 of the terms: 9 digits
        (1.0663342455799631, 1.0659423091234541),  # T_exact - T_lowest at 1 rad
        (1.0663342455799661, 1.0663342455799631),  # a measurement 13 units from T(1)/T0: 1 digit
        (1.1, 0.2),                   # no near cancellation: 16 digits
        (2.5, -0.5),                  # opposite signs: 17
        (3.0, 0.0),                   # one term 0: 17
        (0.0, 0.0),                   # an exact zero
        (1e-300, 1.0000000001e-300),  # tiny terms, the same rule
    ]
    # The boundaries: b - a = 10^n units of 2^-52 with b = 1, the larger term (n digits), and
    # half a unit less, the double a above (n - 1 digits, 1 at least); a, b, a - b exact.
    for n in range(1, 16):
        d = 10 ** n * 2.0 ** -52
        assert 1.0 - (1.0 - d) == d
        pairs.append((1.0 - d, 1.0))
        pairs.append((math.nextafter(1.0 - d, 2.0), 1.0))
    rows = []
    for a, b in pairs:
        rows.append([repr(a), repr(b), digits(a, b)])
    write_reference("difference_digits.csv", __file__, ["a", "b", "digits"], rows)
    exact = 2 * mp.ellipk(mp.sin(mp.mpf(1) / 2) ** 2) / mp.pi
    rows = []
    for y in [1.0663342455799661, 1.0664, 2.0, 0.5]:
        n = digits(y, float(exact))
        rows.append([repr(y), n, mp.nstr(mp.mpf(y) - exact, n)])
    write_reference("residual_digits.csv", __file__, ["y", "digits", "residual"], rows)


if __name__ == "__main__":
    main()
