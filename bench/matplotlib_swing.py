#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The `swing` animation done the usual way, with matplotlib's FuncAnimation and its
Pillow GIF writer: the yardstick for `make bench`.

The exact pendulum, the harmonic one and the paper's lowest order, released together
at 170 degrees (a 1 m pendulum, g = 9.80665 m/s^2): rods and bobs beside theta(t) drawn as
they swing, 1280 x 720 pixels, 30 frames per second, three exact periods.

Usage: matplotlib_swing.py OUT.gif
Needs: python3-matplotlib, python3-scipy, python3-pil (Debian).
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from scipy import special  # noqa: E402

THETA0 = np.radians(170.0)
FPS = 30
PERIODS = 3
G = 9.80665
LENGTH = 1.0
W0 = np.sqrt(G / LENGTH)
COLORS = ["#000000", "#0072b2", "#d55e00"]
LABELS = ["exact", "harmonic", "lowest order"]


def exact_theta(t):
    k = np.sin(THETA0 / 2)
    m = k * k
    K = special.ellipk(m)
    sn, cn, dn, _ = special.ellipj(K - W0 * t, m)
    return 2 * np.arcsin(k * sn)


def harmonic_theta(t):
    return THETA0 * np.cos(W0 * t)


def lowest_theta(t):
    w = np.sqrt(2 * special.j1(THETA0) / THETA0)
    return THETA0 * np.cos(w * W0 * t)


MOTIONS = [exact_theta, harmonic_theta, lowest_theta]
PERIOD = 4 * special.ellipk(np.sin(THETA0 / 2) ** 2) / W0
FRAMES = int(round(PERIODS * PERIOD * FPS)) + 1


def main(out):
    fig, (ax_p, ax_t) = plt.subplots(1, 2, figsize=(12.8, 7.2), dpi=100, gridspec_kw={"width_ratios": [1, 1.4]})
    ax_p.set_aspect("equal")
    ax_p.set_xlim(-1.2, 1.2)
    ax_p.set_ylim(-1.2, 1.2)
    ax_p.axis("off")
    ax_p.add_patch(plt.Circle((0, 0), 1.0, fill=False, color="0.85", lw=1))
    ax_p.plot([0, np.sin(THETA0)], [0, -np.cos(THETA0)], ls=":", color="0.6")
    rods, bobs, trails = [], [], []
    for c in COLORS:
        rods.append(ax_p.plot([], [], color=c, lw=2.5)[0])
        bobs.append(ax_p.plot([], [], "o", color=c, ms=18)[0])
        trails.append(ax_p.plot([], [], color=c, lw=1.5, alpha=0.4)[0])
    ax_p.plot([0], [0], "ko", ms=6)
    clock = ax_p.text(-1.15, 1.1, "", fontsize=16)

    s = np.linspace(0, PERIODS, 600)
    t = s * PERIOD
    for f, c, lab in zip(MOTIONS, COLORS, LABELS):
        ax_t.plot(s, f(t), color=c, lw=2, label=lab)
    ax_t.set_xlim(0, PERIODS)
    ax_t.set_ylim(-1.1 * np.pi, 1.1 * np.pi)
    ax_t.set_yticks([-np.pi, -np.pi / 2, 0, np.pi / 2, np.pi], ["−π", "−π/2", "0", "π/2", "π"])
    ax_t.set_xlabel("t/T", fontsize=16)
    ax_t.set_ylabel("ϑ", fontsize=16)
    ax_t.tick_params(labelsize=14)
    ax_t.legend(fontsize=13, loc="upper right")
    cursor = ax_t.axvline(0, color="0.5", lw=1)
    dots = [ax_t.plot([], [], "o", color=c, ms=9)[0] for c in COLORS]

    def draw(i):
        time = i / FPS
        for f, rod, bob, trail, dot in zip(MOTIONS, rods, bobs, trails, dots):
            th = f(time)
            x, y = np.sin(th), -np.cos(th)
            rod.set_data([0, x], [0, y])
            bob.set_data([x], [y])
            past = np.linspace(max(0.0, time - 0.3 * PERIOD), time, 30)
            tp = f(past)
            trail.set_data(np.sin(tp), -np.cos(tp))
            dot.set_data([time / PERIOD], [th])
        cursor.set_xdata([time / PERIOD, time / PERIOD])
        clock.set_text(f"t = {time / PERIOD:.2f} T")
        return rods + bobs + trails + dots + [cursor, clock]

    anim = FuncAnimation(fig, draw, frames=FRAMES, blit=False)
    anim.save(out, writer=PillowWriter(fps=FPS))


if __name__ == "__main__":
    main(sys.argv[1])
