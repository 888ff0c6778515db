#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference values for states and energies as written (tests/test_states_exact.cpp).

Every number from mpmath at 800 digits (the states next to pi and the energies within
1e-300 of the separatrix need them), printed to 25 significant digits, from the inputs as
written (decimals and expressions in pi, never their doubles). Imports nothing from the tool.
Run: /usr/bin/python3 tests/data/make_state_reference.py > tests/data/state_reference.csv
"""
import re
import sys

from mpmath import mp, mpf, agm, sqrt, sin, cos, asin, atan2, ellipfun, floor, pi, nstr

mp.dps = 800


def value(text):
    """An input as written: a decimal, or an expression in pi (evaluated here, exactly as written)."""
    # Every decimal exactly (mpf of its text), and "2pi" as 2*pi.
    text = re.sub(r"(\d+\.?\d*(?:e[+-]?\d+)?)", r'mpf("\1")', text)
    text = text.replace(")pi", ")*pi_").replace("pi", "pi_").replace("pi__", "pi_")
    return eval(text, {"pi_": +pi, "mpf": mpf, "__builtins__": {}})  # the test inputs only


def num(text):
    """A decimal as written, exactly (through mpf of the string, at 800 digits)."""
    return mpf(text)


def state(theta, omega):
    """Energy, gap 2 - E, regime and period ratio (T/T0 or T_rev/T0) of a state."""
    energy = omega ** 2 / 2 + 2 * sin(theta / 2) ** 2
    gap = 2 * cos(theta / 2) ** 2 - omega ** 2 / 2
    return energy, gap


def ratio(energy, gap):
    if gap > 0:
        return "libration", 1 / agm(1, sqrt(gap / 2))
    k = sqrt(2 / energy)
    return "rotation", k / (2 * agm(1, sqrt(-gap / energy)))


def amplitude(energy, gap):
    k = sqrt(energy / 2)
    return 2 * atan2(k, sqrt(gap / 2))


def row(*fields):
    print(",".join(str(f) for f in fields))


def out(x):
    return nstr(x, 25, min_fixed=0, max_fixed=0) if not isinstance(x, str) else x


def energy_rows(text):
    e = value(text)
    kind, r = ratio(e, 2 - e)
    row("energy", text, "", kind, out(r), out(sqrt(2 * e)), out(amplitude(e, 2 - e)) if kind == "libration" else "")


def state_rows(theta_text, omega_text):
    th, w = value(theta_text), value(omega_text)
    e, gap = state(th, w)
    kind, r = ratio(e, gap)
    row("state", theta_text, omega_text, kind, out(r), out(e), out(amplitude(e, gap)) if kind == "libration" else "")


def rotation_theta(theta_text, omega_text, t_over_T0):
    """theta(t) of a rotation started at (theta0, omega0 > 0): 2 am((t + tau0)/k | k^2), unwrapped."""
    th, w = value(theta_text), value(omega_text)
    e, gap = state(th, w)
    k = sqrt(2 / e)
    m = k ** 2
    K = pi / (2 * agm(1, sqrt(-gap / e)))
    # tau0 = k F(theta0/2 | m): for these starts theta0/2 is tiny, F = theta0/2 (1 + O(theta0^2)).
    tau0 = k * (th / 2)
    u = (t_over_T0 * 2 * pi + tau0) / k
    n = floor((u + K) / (2 * K))
    r = u - n * 2 * K
    sn, cn = ellipfun("sn", r, m=m), ellipfun("cn", r, m=m)
    return 2 * pi * n + 2 * atan2(sn, cn)


def libration_theta(theta0_text, t_over_T0):
    """theta(t) released at rest from theta0: sin(theta/2) = k sn(K - t | k^2)."""
    th = value(theta0_text)
    k = sin(th / 2)
    m = k ** 2
    K = pi / (2 * agm(1, cos(th / 2)))
    t = t_over_T0 * 2 * pi
    t = t - floor(t / (4 * K)) * 4 * K
    return 2 * asin(k * ellipfun("sn", K - t, m=m))


def main():
    print("# mpmath, 800 digits, from the inputs as written (tests/data/make_state_reference.py)")
    print("# energy rows: omega0 = sqrt(2 E) in column 6; state rows: E; theta_at rows: the time in column 5, theta in 6")
    print("kind,first,second,regime,period_ratio,value,amplitude")
    # Amplitudes at rest as states (item 1) and the separatrix scan by energy.
    for d in ("1e-9", "1e-20", "1e-300"):
        th = pi - num(d)
        row("rest", "pi-" + d, "0", "libration", out(1 / agm(1, sin(num(d) / 2))), "", out(th))
    for k in range(1, 301):
        energy_rows("2-1e-%d" % k)
        energy_rows("2+1e-%d" % k)
    for text in ("1e-308", "1e-310", "1e-320", "5e-324", "1e308", "1", "+1", "2/2", "0.5", "1.5", "2.5"):
        energy_rows(text)
    # States from 1e-300 to pi - 1e-300, omega0 from 0 to 1e150 (rest at 0 is an amplitude).
    thetas = ("1e-300", "1e-160", "1e-20", "0.5", "1", "2", "3", "pi-1e-9", "pi-1e-20", "pi-1e-300")
    omegas = ("1e-300", "1e-160", "1e-8", "0.5", "1.9", "2", "2.1", "1e3", "1e150")
    for th in thetas:
        for w in omegas:
            # pi - 1e-300 with 1e-300 has 2 - E = -d^4/24 = -4e-1202 under terms of 5e-601: no
            # precision here (nor the tool's 2560 bits) decides it; the tool refuses it (exit 2).
            if (th, w) != ("pi-1e-300", "1e-300"):
                state_rows(th, w)
    for th, w in (("0", "1e-160"), ("1e-300", "2"), ("1e-20", "2"), ("2pi/3", "1.000001"), ("2pi/3", "0.999999")):
        state_rows(th, w)
    row("theta_at", "1e-300", "2", "rotation", "441", out(rotation_theta("1e-300", "2", 441)), "")
    row("theta_at", "3", "", "libration", "1e15", out(libration_theta("3", mpf(10) ** 15)), "")
    row("theta_at", "1", "", "libration", "1e15", out(libration_theta("1", mpf(10) ** 15)), "")


if __name__ == "__main__":
    sys.exit(main())
