#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Motions from a state or an energy at times of up to 1e300, for trajectory's exact reduction.

The exact motion theta'' + sin(theta) = 0 from the state (theta_s, omega_s), the doubles taken
exactly (or launched from the bottom with energy E, the double, forwards), with
E = omega_s^2/2 + 2 sin^2(theta_s/2). Backwards starts are the mirror image of the forward
motion from (-theta_s, -omega_s). theta_s is first written 2 pi n + r with r in (-pi, pi].
  libration (E < 2), k^2 = E/2: theta = 2 pi n + 2 asin(k sn(w0 t + u0 | k^2)), omega = 2 k cn(..),
    with sn(u0) = sin(r/2)/k, cn(u0) = omega_s/(2k);
  rotation (E > 2), m = 2/E: theta = 2 pi n + 2 am(w0 t sqrt(E/2) + v0 | m),
    omega = sqrt(2E) dn(..), v0 = F(r/2 | m), am(u) = j pi + atan2(sn, cn) of u - 2 j K;
  separatrix: theta = 2 pi n + 2 atan(sinh(w0 t + asinh(tan(r/2)))), omega = 2 / cosh(..).
w0 t is 2 pi s for t/T0, and s times the exact period (4 K(k) of a libration, 2 K(m) sqrt(2/E)
of a rotation's revolution) for t/T. Everything at 1300 bits (a time of 1e300 needs 1000 for
its integer part).

Writes state_times.csv: the trajectory arguments, theta (unwrapped), theta modulo 2 pi in
[0, 2 pi), omega (25 digits).
"""

from mpmath import mp

from reference_csv import write_reference

mp.prec = 1300

# (start arguments, theta_s, omega_s or None with an energy)
STARTS = [
    ("--theta0 0 --omega0 2.2", "0", "2.2"),
    ("--theta0 0.3 --omega0 -3", "0.3", "-3"),
    ("--theta0 7 --omega0 2.5", "7", "2.5"),
    ("--theta0 1 --omega0 0.5", "1", "0.5"),
    ("--theta0 -2 --omega0 -1.2", "-2", "-1.2"),
    ("--theta0 0 --omega0 1.9999999", "0", "1.9999999"),
    # omega the double nearest 2 cos(theta/2): 1.5e-16 and 1.0e-17 from the separatrix.
    ("--theta0 0.7 --omega0 1.8787454256947578", "0.7", "1.8787454256947578"),
    ("--theta0 2.2 --omega0 0.9071922428511546", "2.2", "0.9071922428511546"),
    ("--energy 1.5", None, "1.5"),
    ("--energy 2.5", None, "2.5"),
    ("--energy 2", None, "2"),
]
TIMES = ["1000.3", "999999.3", "1e15", "1e300", "-1e300"]


def am(u, m):
    K = mp.ellipk(m)
    j = mp.floor((u + K) / (2 * K))
    r = u - 2 * K * j
    return j * mp.pi + mp.atan2(mp.ellipfun("sn", r, m=m), mp.ellipfun("cn", r, m=m))


def motion(theta_s, omega_s, energy, unit, s):
    """theta and omega at time s (in `unit`) of the forward motion (omega_s >= 0)."""
    n = mp.nint(theta_s / (2 * mp.pi))
    r = theta_s - 2 * mp.pi * n
    if energy < 2:
        m = energy / 2
        k = mp.sqrt(m)
        u0 = mp.atan2(mp.sin(r / 2) / k, omega_s / (2 * k))
        u0 = mp.ellipf(u0, m)
        w0_t = 2 * mp.pi * s if unit == "t/T0" else s * 4 * mp.ellipk(m)
        u = w0_t + u0
        return 2 * mp.pi * n + 2 * mp.asin(k * mp.ellipfun("sn", u, m=m)), 2 * k * mp.ellipfun("cn", u, m=m)
    if energy == 2:
        tau = 2 * mp.pi * s + mp.asinh(mp.tan(r / 2))
        return 2 * mp.pi * n + 2 * mp.atan(mp.sinh(tau)), 2 / mp.cosh(tau)
    m = 2 / energy
    w0_t = 2 * mp.pi * s if unit == "t/T0" else s * 2 * mp.ellipk(m) * mp.sqrt(m)
    v = w0_t / mp.sqrt(m) + mp.ellipf(r / 2, m)
    return 2 * mp.pi * n + 2 * am(v, m), mp.sqrt(2 * energy) * mp.ellipfun("dn", v, m=m)


def start_state(theta_text, second):
    """(theta_s, omega_s, E, mirror) of a start: the state's doubles taken exactly, or with
    theta_text None the energy's double, launched from the bottom forwards; mirror is -1 for a
    backwards start."""
    if theta_text is None:
        energy = mp.mpf(float(second))
        theta_s, omega_s = mp.mpf(0), mp.sqrt(2 * energy)
    else:
        theta_s, omega_s = mp.mpf(float(theta_text)), mp.mpf(float(second))
        energy = omega_s ** 2 / 2 + 2 * mp.sin(theta_s / 2) ** 2
    return theta_s, omega_s, energy, -1 if omega_s < 0 else 1


def main():
    rows = []
    for args, theta_text, second in STARTS:
        theta_s, omega_s, energy, mirror = start_state(theta_text, second)
        for unit in ["t/T0", "t/T"]:
            if unit == "t/T" and energy == 2:
                continue
            for time in TIMES:
                s = mp.mpf(float(time))
                theta, omega = motion(mirror * theta_s, mirror * omega_s, energy, unit, s)
                theta, omega = mirror * theta, mirror * omega
                rows.append([f"trajectory {args} --time {unit} --at {time}", mp.nstr(theta, 25),
                             mp.nstr(mp.fmod(mp.fmod(theta, 2 * mp.pi) + 2 * mp.pi, 2 * mp.pi), 25),
                             mp.nstr(omega, 25)])
    write_reference("state_times.csv", __file__, ["arguments", "theta", "theta_mod_2pi", "omega"], rows)


if __name__ == "__main__":
    main()
