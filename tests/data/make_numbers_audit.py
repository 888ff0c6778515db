#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The reproductions of the audit of every printed number (issue_numbers_audit.md), by mpmath.

Each row is one printed field of one command, the inputs taken as written (pi-1e-9 is that
number, not its double; 2-1e-20 is below 2): the exact period of a libration
T/T0 = 2 K(k^2) / pi, k^2 = E/2; of a rotation's revolution T_rev/T0 = K(m) sqrt(m) / pi,
m = 2/E; E = omega^2/2 + 2 sin^2(theta/2); the motion at a time as make_state_times.py writes
it. A regime is the word the command prints; 'exit2:WORD' is a refusal whose message holds
WORD. Everything at 2400 bits (an energy 5e-601 from 2 needs 2000).

Writes numbers_audit.csv: the command, the field, the value (25 digits, or a word).
"""
import os
import re
import sys

from mpmath import mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_state_times import motion  # noqa: E402
from reference_csv import write_reference  # noqa: E402

mp.prec = 2400


def written(text):
    """The exact value of a written number: a decimal, pi-d, 2pi/3, 2-1e-20, 2+1e-20."""
    text = re.sub(r"(\d+(?:\.\d*)?(?:e[-+]?\d+)?)", r"mpf('\1')", text)
    text = re.sub(r"(\))pi", r"\1*pi", text)
    return mp.mpf(eval(text, {"pi": +mp.pi, "mpf": mp.mpf}))  # noqa: S307 (the fixed table below)


def state_energy(theta, omega):
    return omega ** 2 / 2 + 2 * mp.sin(theta / 2) ** 2


def period(energy):
    """(regime, T/T0 or T_rev/T0) of a motion of energy E."""
    if abs(energy - 2) < mp.mpf(2) ** (20 - mp.prec):  # 2 to the reference's own rounding
        return "separatrix", None
    if energy < 2:
        return "libration", 2 * mp.ellipk(energy / 2) / mp.pi
    m = 2 / energy
    return "rotation", mp.ellipk(m) * mp.sqrt(m) / mp.pi


def fmt(x):
    return mp.nstr(x, 25) if x != 0 else "0"


def eval_rows(args, energy):
    regime, p = period(energy)
    rows = [[args, "regime", regime]]
    if p is not None:
        rows.append([args, "period_exact" if regime == "libration" else "revolution_period", fmt(p)])
    if regime == "libration":
        rows.append([args, "amplitude", fmt(2 * mp.asin(mp.sqrt(energy / 2)))])
    return rows


STATES = [  # (theta, omega) as written
    ("pi-1e-9", "0"), ("pi-1e-20", "0"), ("pi-1e-300", "0"),  # 1
    ("1e-300", "2"),  # 2
    ("2pi/3", "1"), ("-2pi/3", "-1"), ("4pi/3", "1"),  # 3
    ("1e-160", "0"), ("0", "1e-160"), ("1e-300", "1e-300"),  # 5
]
ENERGIES = ["2-1e-20", "2+1e-20", "1e-308", "1e-320", "5e-324", "1e308", "2"]
# (arguments, theta as written, omega as written, unit, time): trajectories of the exact motion
TRAJECTORIES = [
    ("--theta0 1e-300 --omega0 2", "1e-300", "2", "t/T0", "441"),  # 2
    ("--theta0 3 --omega0 0", "3", "0", "t/T0", "1e15"),  # 9
    ("--energy 1.99", None, "1.99", "t/T", "0.5"),  # 8
    ("--energy 1.5", None, "1.5", "t/T", "0.75"),
    ("--theta0 3.14 --omega0 0", "3.14", "0", "t/T", "0.75"),
]


def trajectory_rows():
    rows = []
    for args, theta_text, second, unit, time in TRAJECTORIES:
        if theta_text is None:
            energy = written(second)
            theta_s, omega_s = mp.mpf(0), mp.sqrt(2 * energy)
        else:
            theta_s, omega_s = written(theta_text), written(second)
            energy = state_energy(theta_s, omega_s)
        theta, omega = motion(theta_s, omega_s, energy, unit, mp.mpf(time))
        # Quarter periods land on a zero exactly (the reference's own rounding is far below).
        theta, omega = [0 if abs(v) < mp.mpf(10) ** -300 else v for v in (theta, omega)]
        command = f"trajectory {args} --time {unit} --at {time}"
        rows += [[command, "theta", fmt(theta)], [command, "omega", fmt(omega)]]
    return rows


def main():
    rows = []
    for theta_text, omega_text in STATES:
        theta, omega = written(theta_text), written(omega_text)
        rows += eval_rows(f"eval --theta0 {theta_text} --omega0 {omega_text}", state_energy(theta, omega))
    for text in ENERGIES:
        energy = written(text)
        args = f"eval --energy {text}"
        rows += eval_rows(args, energy)
        rows.append([args, "omega0", fmt(mp.sqrt(2 * energy))])
    for theta_text in ["1", "+1", "2/2"]:  # 11: one value for every spelling
        rows.append([f"eval --theta0 {theta_text}", "period_exact", fmt(2 * mp.ellipk(mp.sin(written(theta_text) / 2) ** 2) / mp.pi)])
    rows.append(["eval --theta0 pi --omega0 0", "exit", "exit2:pi"])
    rows.append(["eval --theta0 1e-330", "exit", "exit2:smallest double"])
    rows += trajectory_rows()
    write_reference("numbers_audit.csv", __file__, ["arguments", "field", "value"], rows)


if __name__ == "__main__":
    main()
