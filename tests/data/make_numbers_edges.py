#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Edge numbers of states and energies: the start's mirror image at every half period, the
quarter periods, and energies a double holds to fewer digits (or not at all).

The exact motion theta'' + sin(theta) = 0 from the state (theta_s, omega_s) (the decimals as
written, not their doubles: next to the separatrix they decide the gap), or launched from the bottom forwards with the energy E as written (E = 2 - 1e-20 is
that number exactly, not its double). A backwards start is the mirror image of the forward
motion from (-theta_s, -omega_s); theta_s = 2 pi n + r with r in (-pi, pi]. A libration
(E < 2, m = k^2 = E/2): theta = 2 pi n + 2 asin(k sn(w0 t + u0 | m)), omega = 2 k cn(..), with
u0 = F(atan2(sin(r/2)/k, omega_s/(2k)) | m), w0 t = s 4 K(m) for t/T. At s = 1/2 + j the
motion is at (2 pi n - r, -omega_s) exactly. 400 bits (times up to 1e15 periods).

Writes numbers_edges.csv: kind, the command's arguments, then theta and omega (30 digits) for
kind 'motion', or E (30 digits) for kind 'energy' (a state at rest or an energy a double does not
hold to every digit), kind 'far' with theta and omega of a rotation far out, or kind 'period' with T/T0 (T_rev/T0) and
the regime of a start only a precision past 2560 bits decides."""

from mpmath import mp

from make_state_long_times import point as long_time_point
from reference_csv import write_reference

mp.prec = 1300

STATES = [
    ("--theta0 1 --omega0 1.7", "1", "1.7"),
    ("--theta0 0.5 --omega0 1.9", "0.5", "1.9"),
    ("--theta0 3 --omega0 0.1", "3", "0.1"),
    ("--theta0 -2 --omega0 -1", "-2", "-1"),
    ("--theta0 7 --omega0 1", "7", "1"),
    ("--theta0 1 --omega0 1", "1", "1"),
    ("--theta0 0.7 --omega0 1.8787454256947578", "0.7", "1.8787454256947578"),
    ("--energy 1.5", None, "1.5"),
    ("--energy 1.99", None, "1.99"),
    ("--energy 2-1e-20", None, mp.mpf(2) - mp.mpf(10) ** -20),
    ("--energy 2-1e-300", None, mp.mpf(2) - mp.mpf(10) ** -300),
    ("--theta0 0 --omega0 -1.5", "0", "-1.5"),
]
TIMES = ["0.25", "0.5", "0.75", "1", "1.5", "2.5", "-0.5", "1000000000000000.5"]

# (arguments, theta as written, omega as written): states whose energy a double holds to fewer
# digits than 17 (below 2.2250738585072014e-308) or not at all.
ENERGIES = [
    ("--theta0 1e-160 --omega0 0", "1e-160", "0"),
    ("--theta0 5e-324 --omega0 0", "5e-324", "0"),
    ("--theta0 1e-300 --omega0 0", "1e-300", "0"),
    ("--theta0 0 --omega0 1e-160", "0", "1e-160"),
]


def start_of(theta_text, second):
    """(theta_s, omega_s, E) of a start, its decimals as written, as the command takes them."""
    if theta_text is None:
        energy = mp.mpf(second)
        return mp.mpf(0), mp.sqrt(2 * energy), energy
    theta_s, omega_s = mp.mpf(theta_text), mp.mpf(second)
    return theta_s, omega_s, omega_s ** 2 / 2 + 2 * mp.sin(theta_s / 2) ** 2


def libration(theta_s, omega_s, energy, s):
    """theta and omega of the forward libration (omega_s >= 0) at s periods T."""
    n = mp.nint(theta_s / (2 * mp.pi))
    r = theta_s - 2 * mp.pi * n
    m = energy / 2
    k = mp.sqrt(m)
    u0 = mp.ellipf(mp.atan2(mp.sin(r / 2) / k, omega_s / (2 * k)), m)
    u = s * 4 * mp.ellipk(m) + u0
    return 2 * mp.pi * n + 2 * mp.asin(k * mp.ellipfun("sn", u, m=m)), 2 * k * mp.ellipfun("cn", u, m=m)


# Rotations next to the separatrix far out (t/T0), the state's numbers as written (the decimal
# 1e-300, not its double: 2.5e-17 apart, which moves omega here by 2.3e-4 of itself); an
# energy as written launched from the bottom; a backwards start (the mirror image). Times on
# both sides of K/2 from the bottom, where omega is k'/dn(K - r) and K - r must be held beyond
# a double, up to the largest double.
FAR_TIMES = ["1e12", "3e12", "1e13", "3e13", "1e14", "1e16", "1e100", "1.7976931348623157e308"]
FAR = [("--theta0 1e-300 --omega0 2", "1e-300", "2", ["441", "1e12", "1e15"] + FAR_TIMES[1:]),
       ("--energy 2+1e-300", None, "2+1e-300", FAR_TIMES),
       ("--theta0 -1e-300 --omega0 -2", "-1e-300", "-2", ["1e12", "3e13"])]


def far_start(theta_text, second):
    """(theta, omega) of a far row's start as written, at the working precision."""
    if theta_text is None:
        energy = mp.mpf(2) + mp.mpf(second[2:])
        return mp.mpf(0), mp.sqrt(2 * energy)
    return mp.mpf(theta_text), mp.mpf(second)


def rotation_far(theta_text, omega_text, s):
    """theta and omega of the rotation at s small-amplitude periods T0 (s the double its text
    rounds to), at 3500 bits, by make_state_long_times.point (the amplitude am(r) by Newton
    on F, not mpmath's ellipfun, which next to the top, dn ~ 1e-271, keeps too few digits);
    a backwards start is the mirror image of the forward motion."""
    with mp.workprec(3500):
        th, w = far_start(theta_text, omega_text)
        mirror = -1 if w < 0 else 1
        theta, omega = long_time_point(mirror * th, mirror * w, mp.mpf(float(s)))
        return mirror * theta, mirror * omega


# Starts only a precision past 2560 bits decides (start_energy.hpp: doubling up to 65536), the
# last two at the smallest distance from the separatrix a double holds (2 k' >= 2.2e-308):
# (arguments, theta or None for an energy, omega or energy, the bits mpmath needs).
PERIODS = [
    ("eval --theta0 2pi/3+1e-500 --omega0 1", "2*pi/3+mpf('1e-500')", "1", 4000),
    ("eval --theta0 pi-1e-300 --omega0 1e-290", "pi-mpf('1e-300')", "1e-290", 4000),
    ("eval --energy 2-1e-600", None, "2-mpf('1e-600')", 4000),
    ("eval --energy 2-2.4755e-616", None, "2-mpf('2.4755e-616')", 4000),
    ("eval --energy 2+2.4755e-616", None, "2+mpf('2.4755e-616')", 4000),
]


def period_ratio(theta_text, second, bits):
    """T/T0 of a libration or T_rev/T0 of a rotation from a start as written, at `bits`."""
    with mp.workprec(bits):
        names = {"pi": mp.pi, "mpf": mp.mpf}
        if theta_text is None:
            energy = eval(second, names)  # the script's own rows only
        else:
            th, w = eval(theta_text, names), mp.mpf(second)
            energy = w ** 2 / 2 + 2 * mp.sin(th / 2) ** 2
        if energy < 2:
            return "libration", 1 / mp.agm(1, mp.sqrt((2 - energy) / 2))
        return "rotation", mp.sqrt(2 / energy) / (2 * mp.agm(1, mp.sqrt((energy - 2) / energy)))


def main():
    rows = []
    for args, theta_text, second, bits in PERIODS:
        kind, ratio = period_ratio(theta_text, second, bits)
        rows.append(["period", args, mp.nstr(ratio, 30), kind])
    for args, theta_text, second in STATES:
        theta_s, omega_s, energy = start_of(theta_text, second)
        assert energy < 2, args
        mirror = -1 if omega_s < 0 else 1
        for time in TIMES:
            theta, omega = libration(mirror * theta_s, mirror * omega_s, energy, mp.mpf(time))
            rows.append(["motion", f"trajectory {args} --at {time}", mp.nstr(mirror * theta, 30),
                         mp.nstr(mirror * omega, 30)])
    for args, theta_text, omega_text in ENERGIES:
        # A state at rest is its amplitude, which holds the double of its angle (5e-324 is
        # 4.94e-324, the amplitude the command prints); a moving state keeps its decimals.
        at_rest = omega_text == "0"
        theta_s = mp.mpf(float(theta_text)) if at_rest else mp.mpf(theta_text)
        energy = mp.mpf(omega_text) ** 2 / 2 + 2 * mp.sin(theta_s / 2) ** 2
        rows.append(["energy", f"eval {args}", mp.nstr(energy, 30), ""])
    for args, theta_text, omega_text, times in FAR:
        for time in times:
            theta, omega = rotation_far(theta_text, omega_text, time)
            rows.append(["far", f"trajectory {args} --time t/T0 --at {time}", mp.nstr(theta, 30), mp.nstr(omega, 30)])
    write_reference("numbers_edges.csv", __file__, ["kind", "arguments", "value", "omega"], rows)


if __name__ == "__main__":
    main()
