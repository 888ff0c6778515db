#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference motions of the pendulum in all three regimes (regimes.csv, regime_periods.csv,
energy_periods.csv).

theta'' + sin(theta) = 0 in time w0 t from a start: a state (theta, omega = theta'/w0, the
doubles exactly as written), an energy E (launched from the bottom, omega = sqrt(2 E)), or an
amplitude (released at rest). The energy E = omega^2/2 + 1 - cos(theta) in units of m g L
decides the regime; every value comes from closed forms evaluated with mpmath at 60 digits,
written differently from the C++ code:
  libration (E < 2), m = E/2:  theta = 2 pi n + 2 asin(k sn(u0 + t | m)), theta' = 2 k cn(u0 + t | m),
      u0 = F(atan2(sin(theta_r/2), omega/2) | m);
  separatrix (E = 2):          theta = 2 pi n + 4 atan(exp(t + t1)) - pi, theta' = 2 sech(t + t1),
      t1 = ln tan((theta_r + pi)/4) (time reversed for omega < 0);
  rotation (E > 2), m = 2/E:  theta = 2 pi n + 2 am(u0 + t/k | m), theta' = (2/k) dn(u0 + t/k | m),
      u0 = F(theta_r/2 | m) (time reversed for omega < 0);
with theta_r = theta - 2 pi n in (-pi, pi]. A few rows are checked against mpmath's own ODE
integrator (Taylor series) as well. Periods: libration 4 K(m), rotation 2 k K(m).
energy_periods.csv: T/T0 = T/(2 pi) against the energy of a launch from the bottom, from 0 to
4 across the separatrix (the libration's period below E = 2, one revolution above it), each
also checked against the time mpmath's ODE integrator takes to the first turning point (E < 2)
or to theta = pi (E > 2).

Run from this directory:  python3 make_regimes.py
"""
import math

import mpmath as mp

mp.mp.dps = 60

PI = math.pi
# (start kind, a, b): "state" theta omega, "energy" E -, "amplitude" theta0 -.
STARTS = [
    ("amplitude", 1.0, 0.0),
    ("amplitude", PI - 1e-6, 0.0),
    ("energy", 0.5, 0.0),
    ("energy", 1.5, 0.0),
    ("energy", 2.0, 0.0),
    ("energy", 2.5, 0.0),
    ("energy", 3.0, 0.0),
    ("energy", 50.0, 0.0),
    ("energy", 2.0 - 1e-12, 0.0),
    ("energy", 2.0 + 1e-12, 0.0),
    ("energy", 2.0 - 2.0**-45, 0.0),
    ("energy", 2.0 + 2.0**-45, 0.0),
    ("state", 0.0, 1.9),
    ("state", 0.0, 2.2),
    ("state", 0.0, -2.2),
    ("state", 0.0, 2.0),
    ("state", 0.0, -2.0),
    ("state", 0.0, 2.0 - 1e-12),
    ("state", 0.0, 2.0 + 1e-12),
    ("state", 1.0, 1.5),
    ("state", 1.0, -1.5),
    ("state", -2.5, 0.3),
    ("state", 2.5, -0.3),
    ("state", 3.0, 0.0),
    ("state", -3.0, 0.0),
    ("state", PI, 0.0),
    ("state", 7.0, 0.5),
    ("state", -20.0, 1.0),
    ("state", 10.0, -3.0),
    ("state", 1.0, 1.7551651237807455),  # E - 2 ~ +1.4e-16: just above the separatrix
    ("state", 1.0, 1.755165123780745),   # E - 2 ~ -3.4e-16: just below it
    ("state", 2.0, 1.0806046117362795),  # theta = 2: the gap from the angle's cosine
    ("state", 3.1, 0.04),
    ("state", -3.1, -0.05),
]
TIMES = [0.0, 0.3, 1.0, -1.0, 2.5, 6.0, -7.5, 13.0, 40.0]


def energy_of(kind, a, b):
    if kind == "energy":
        return mp.mpf(a)
    if kind == "amplitude":
        return 1 - mp.cos(mp.mpf(a))
    return mp.mpf(b) ** 2 / 2 + 1 - mp.cos(mp.mpf(a))


def state_of(kind, a, b):
    """The start as exact (theta, omega)."""
    if kind == "energy":
        return mp.mpf(0), mp.sqrt(2 * mp.mpf(a))
    if kind == "amplitude":
        return mp.mpf(a), mp.mpf(0)
    return mp.mpf(a), mp.mpf(b)


def reduce(theta):
    n = mp.nint(theta / (2 * mp.pi))
    r = theta - 2 * n * mp.pi
    if r <= -mp.pi:
        r, n = r + 2 * mp.pi, n - 1
    return n, r


def am(u, m):
    K = mp.ellipk(m)
    n = mp.floor((u + K) / (2 * K))
    r = u - 2 * K * n
    return n * mp.pi + mp.atan2(mp.ellipfun("sn", r, m), mp.ellipfun("cn", r, m))


def motion(kind, a, b, t):
    """(theta, theta') at w0 t, and the regime."""
    E = energy_of(kind, a, b)
    theta, omega = state_of(kind, a, b)
    n, r = reduce(theta)
    t = mp.mpf(t)
    if E < 2:
        m = E / 2
        k = mp.sqrt(m)
        u0 = mp.ellipf(mp.atan2(mp.sin(r / 2), omega / 2), m)
        u = u0 + t
        return 2 * mp.pi * n + 2 * mp.asin(k * mp.ellipfun("sn", u, m)), 2 * k * mp.ellipfun("cn", u, m), "libration"
    sign = 1 if omega >= 0 else -1
    # Time reversal: the motion backwards from (r, omega) is the forward one from (r, -omega) run back.
    if E == 2:
        t1 = mp.log(mp.tan((r + mp.pi) / 4))
        x = t1 + sign * t
        return 2 * mp.pi * n + 4 * mp.atan(mp.exp(x)) - mp.pi, sign * 2 * mp.sech(x), "separatrix"
    m = 2 / E
    k = mp.sqrt(m)
    u = mp.ellipf(r / 2, m) + sign * t / k
    return 2 * mp.pi * n + 2 * am(u, m), sign * 2 / k * mp.ellipfun("dn", u, m), "rotation"


def period(kind, a, b):
    E = energy_of(kind, a, b)
    if E < 2:
        return 4 * mp.ellipk(E / 2)
    if E == 2:
        return None
    m = 2 / E
    return 2 * mp.sqrt(m) * mp.ellipk(m)


def check_against_ode(kind, a, b, t):
    """The closed forms against mpmath's Taylor-series ODE integrator."""
    with mp.workdps(30):
        theta, omega = state_of(kind, a, b)
        f = mp.odefun(lambda _, y: [y[1], -mp.sin(y[0])], 0, [theta, omega])
        y = f(mp.mpf(t))
        want = motion(kind, a, b, t)
        assert abs(y[0] - want[0]) < mp.mpf(10) ** -20 and abs(y[1] - want[1]) < mp.mpf(10) ** -20, (kind, a, b, t)


# Energies of the period-against-energy plot: a grid over [0, 4] and close to the separatrix.
ENERGIES = [0.0, 1e-6, 0.1, 0.5, 1.0, 1.5, 1.6, 1.9, 1.99, 2.0 - 1e-4, 2.0 - 1e-8, 2.0 + 1e-8, 2.0 + 1e-4,
            2.01, 2.1, 2.6, 3.0, 3.5, 4.0]


def period_ratio(E):
    """T/T0 at energy E launched from the bottom: 2 K(E/2)/pi below 2, k K(2/E)/pi above."""
    E = mp.mpf(E)
    if E == 0:
        return mp.mpf(1)
    if E < 2:
        return 4 * mp.ellipk(E / 2) / (2 * mp.pi)
    m = 2 / E
    return 2 * mp.sqrt(m) * mp.ellipk(m) / (2 * mp.pi)


def check_period_by_ode(E):
    """A quarter of the libration (to the turning point) or half a revolution (to theta = pi)
    by mpmath's ODE integrator: the time where theta' = 0 or theta = pi, found by its root."""
    with mp.workdps(30):
        E = mp.mpf(E)
        f = mp.odefun(lambda _, y: [y[1], -mp.sin(y[0])], 0, [mp.mpf(0), mp.sqrt(2 * E)])
        if E < 2:
            want = period_ratio(E) * 2 * mp.pi / 4
            t = mp.findroot(lambda t: f(t)[1], want * mp.mpf("0.999"))
        else:
            want = period_ratio(E) * 2 * mp.pi / 2
            t = mp.findroot(lambda t: f(t)[0] - mp.pi, want * mp.mpf("0.999"))
        assert abs(t - want) < mp.mpf(10) ** -15, (E, t, want)


def text(x):
    return "0" if x == 0 else mp.nstr(x, 25, strip_zeros=False, min_fixed=-1, max_fixed=-1)


if __name__ == "__main__":
    for case in [("state", 0.0, 2.2, 1.88495559215), ("state", -2.5, 0.3, 2.5), ("state", 1.0, -1.5, 6.0),
                 ("energy", 2.0 + 1e-12, 0.0, 6.0), ("state", 7.0, 0.5, 2.5)]:
        check_against_ode(*case)
    with open("regimes.csv", "w") as out:
        out.write("# generated by make_regimes.py; do not edit\n")
        out.write("start,a,b,regime,w0_t,theta,velocity\n")
        for kind, a, b in STARTS:
            for t in TIMES:
                theta, velocity, name = motion(kind, a, b, t)
                out.write(f"{kind},{a!r},{b!r},{name},{t!r},{text(theta)},{text(velocity)}\n")
    for E in [1.6, 2.6]:
        check_period_by_ode(E)
    with open("energy_periods.csv", "w") as out:
        out.write("# generated by make_regimes.py; do not edit\n")
        out.write("energy,period_ratio\n")
        for E in ENERGIES:
            out.write(f"{E!r},{text(period_ratio(E))}\n")
    with open("regime_periods.csv", "w") as out:
        out.write("# generated by make_regimes.py; do not edit\n")
        out.write("start,a,b,regime,energy_minus_2,w0_period\n")
        for kind, a, b in STARTS:
            T = period(kind, a, b)
            E = energy_of(kind, a, b)
            name = "libration" if E < 2 else "separatrix" if E == 2 else "rotation"
            out.write(f"{kind},{a!r},{b!r},{name},{text(E - 2)},{'none' if T is None else text(T)}\n")
