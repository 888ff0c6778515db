#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# The reference of the energy bars (tests/test_overlays.cpp): the pendulum released at rest
# from 170 degrees, theta(t) = 2 asin(k sn(K - w0 t, k)), k = sin(theta0/2), by mpmath at 40
# digits; theta' by mpmath's numerical derivative of that theta (not the cn identity), so the
# kinetic energy theta'^2/2 and the potential 1 - cos(theta) are checked independently of the
# program's formulas. Writes overlays_energy_170.csv beside this script.
import os
import mpmath as mp

mp.mp.dps = 40
theta0 = mp.mpf(170) * mp.pi / 180
k = mp.sin(theta0 / 2)
m = k * k
K = mp.ellipk(m)


def theta(t):
    return 2 * mp.asin(k * mp.ellipfun('sn', K - t, m=m))


out = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'overlays_energy_170.csv')
with open(out, 'w') as f:
    f.write('w0_t,theta,E_kin,E_pot,E\n')
    for t in ['0', '0.5', '1', '2', '3.5', str(K), '5', '8']:
        t = mp.mpf(t)
        a = theta(t)
        w = mp.diff(theta, t)
        e_kin = w * w / 2
        e_pot = 1 - mp.cos(a)
        f.write(','.join(mp.nstr(v, 20) for v in (t, a, e_kin, e_pot, 1 - mp.cos(theta0))) + '\n')
