#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""theta(t) and theta'/w0 of rotations from a state, far out in time, independently of the
program: the reduced time must be carried beyond one double (a double w0 t reduced modulo
the revolution is off by half an ulp of up to 700 rad, which theta' turns into 300 ulps).

A rotation from (theta0, omega0), E = 1 - cos(theta0) + omega0^2/2 > 2, goes as
w0 t = k (F(theta/2 | m) - F(theta0/2 | m)), m = k^2 = 2/E (F the incomplete elliptic
integral of the first kind, F(phi + n pi) = F(phi) + 2 n K). For a time s in T0
(w0 t = 2 pi s, s the double its text rounds to), u = w0 t / k + F(theta0/2) is split as
u = 2 n K + r with |r| <= K, phi in [-pi/2, pi/2] solves F(phi | m) = r (Newton, F' =
1/sqrt(1 - m sin^2 phi)), theta = 2 (phi + n pi) and theta'/w0 = (2/k) sqrt(1 - m sin^2 phi).
Everything at 2400 bits: 1 - m is 2.5e-601 for (1e-300, 2).

Writes state_long_times.csv: the trajectory arguments, theta and omega (25 digits).
Run with /usr/bin/python3 (python3-mpmath): about a minute.
"""
from mpmath import mp

from reference_csv import write_reference

STATES = [("1e-300", "2"), ("3", "0.5")]
TIMES = ["0.3", "441", "1000.25", "123456.789", "1e15", "1.7976931348623157e308"]


def point(theta0, omega0, s):
    energy = 1 - mp.cos(theta0) + omega0 ** 2 / 2
    m = 2 / energy
    k = mp.sqrt(m)
    quarter = mp.ellipk(m)
    u = 2 * mp.pi * s / k + mp.ellipf(theta0 / 2, m)
    n = mp.nint(u / (2 * quarter))
    r = u - 2 * n * quarter
    # Near m = 1 the amplitude is close to gd(r) = asin(tanh(r)): Newton from there.
    phi = mp.asin(mp.tanh(r))
    for _ in range(200):
        step = (mp.ellipf(phi, m) - r) * mp.sqrt(1 - m * mp.sin(phi) ** 2)
        phi -= step
        if abs(step) < mp.mpf(2) ** (-mp.prec + 40):
            break
    theta = 2 * (phi + n * mp.pi)
    omega = 2 / k * mp.sqrt(1 - m * mp.sin(phi) ** 2)
    return theta, omega


def main():
    rows = []
    for theta0_text, omega0_text in STATES:
        for time in TIMES:
            mp.prec = 2400 + 1100  # 1.8e308 T0 needs 1030 bits for its integer part
            theta, omega = point(mp.mpf(float(theta0_text)), mp.mpf(float(omega0_text)), mp.mpf(float(time)))
            args = f"trajectory --theta0 {theta0_text} --omega0 {omega0_text} --time t/T0 --at {time}"
            rows.append([args, mp.nstr(theta, 25), mp.nstr(omega, 25)])
    write_reference("state_long_times.csv", __file__, ["arguments", "theta", "omega"], rows)


if __name__ == "__main__":
    main()
