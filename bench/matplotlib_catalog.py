#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The same work as `pendulum-figures render --all -f png,pdf --dpi 300`, done the usual
way with numpy, scipy and matplotlib: the yardstick for `make bench`.

Usage: matplotlib_catalog.py OUTDIR [--paper]
  --paper: only the paper's seven figures (Fig. 1 to 7)
Needs: python3-matplotlib, python3-scipy (Debian).
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy import integrate, special  # noqa: E402

PI = np.pi
CM = 1 / 2.54


def exact_theta(theta0, s):
    """theta at t = s T (exact), by Jacobi elliptic functions."""
    k = np.sin(theta0 / 2)
    K = special.ellipk(k * k)
    sn, cn, dn, _ = special.ellipj(K - 4 * K * s, k * k)
    return 2 * np.arcsin(k * sn)


def period_ratio(theta0):
    return 2 / PI * special.ellipk(np.sin(theta0 / 2) ** 2)


def c_quad(theta0, n):
    K = special.ellipk(np.sin(theta0 / 2) ** 2)
    f = lambda x: exact_theta(theta0, x / (2 * PI)) * np.cos((2 * n + 1) * x)
    return 4 / PI * integrate.quad(f, 0, PI / 2, epsabs=1e-13)[0]


def first(t):
    eta = -special.jv(3, t) / (9 * special.jv(1, t))
    c1 = t / (1 + eta)
    return np.sqrt(2 * special.jv(1, t) / t * (1 + eta)), [c1, eta * c1]


def second(t):
    _, (a, b) = first(t)
    J = special.jv
    C = [(-1) ** k * (2 * J(2 * k + 1, a) + b * (J(2 * k + 4, a) - J(abs(2 * k - 2), a))) for k in range(3)]
    lam = (C[0] + C[1] / 9 + C[2] / 25) / t
    return np.sqrt(lam), [C[k] / ((2 * k + 1) ** 2 * lam) for k in range(3)]


def lowest(t):
    return np.sqrt(2 * special.jv(1, t) / t), [t]


def poly(t):
    return 1 / (1 + t**2 / 16 + 11 * t**4 / 3072), [
        t + t**3 / 192 + 17 * t**5 / 61440, -(t**3 / 192 + t**5 / 3072), t**5 / 20480]


def iterate(theta0, order, points=4096):
    x = (np.arange(points) + 0.5) * PI / (2 * points)
    c = np.array([theta0])
    out = []
    for level in range(order + 1):
        h = 2 * np.arange(len(c)) + 1
        f = np.sin(np.cos(np.outer(x, h)) @ c)
        hk = 2 * np.arange(level + 1) + 1
        C = 2 / points * (np.cos(np.outer(hk, x)) @ f)
        lam = np.sum(C / hk**2) / theta0
        c = C / (hk**2 * lam)
        out.append(np.sqrt(lam))
    return out


def coeff_axes(ax, n, approx, name, ylabel):
    t = np.linspace(1e-3, PI - 1e-3, 401)
    circles = np.arange(1, 24) * PI / 24
    ax.plot(circles, [c_quad(x, n) for x in circles], "ko", mfc="none", label="exact")
    ax.plot(t, [approx(x)[1][n] for x in t], "k-", label=name)
    ax.plot(t, [poly(x)[1][n] for x in t], "k:", label="polynomial")
    ax.set_xlim(0, PI)
    ax.set_xticks([0, PI / 4, PI / 2, 3 * PI / 4, PI], ["0", "π/4", "π/2", "3π/4", "π"])
    ax.set_xlabel(r"$\vartheta_0$")
    ax.set_ylabel(ylabel)
    ax.legend(frameon=False)


def traj_axes(ax, theta0, methods):
    s = np.linspace(0, 1, 301)
    T = 4 * special.ellipk(np.sin(theta0 / 2) ** 2)
    ax.plot(np.linspace(0, 1, 25), exact_theta(theta0, np.linspace(0, 1, 25)), "ko", mfc="none", label="exact")
    for name, f, style in methods:
        w, c = f(theta0)
        y = sum(ck * np.cos((2 * k + 1) * w * s * T) for k, ck in enumerate(c))
        ax.plot(s, y, style, label=name)
    ax.set_xlabel("$t/T$")
    ax.set_ylabel(r"$\vartheta$")


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(out / f"{name}.png", dpi=300)
    fig.savefig(out / f"{name}.pdf")
    plt.close(fig)


def main(out, paper_only=False):
    out.mkdir(parents=True, exist_ok=True)
    harmonic = lambda t: (1.0, [t])

    fig, ax = plt.subplots(figsize=(6 * CM, 4.5 * CM))
    coeff_axes(ax, 0, lowest, "lowest order", "$c_1$")
    save(fig, out, "c1-lowest")

    for name, f, label in [("trajectory-lowest", lowest, "lowest order"), ("trajectory-first", first, "first order")]:
        fig, axes = plt.subplots(2, 2, figsize=(12 * CM, 9 * CM))
        for ax, t in zip(axes.flat, [PI / 3, PI / 2, 3 * PI / 4, 9 * PI / 10]):
            traj_axes(ax, t, [(label, f, "k-"), ("harmonic", harmonic, "k:")])
        axes.flat[0].legend(frameon=False)
        save(fig, out, name)

    fig, axes = plt.subplots(1, 2, figsize=(12 * CM, 4.5 * CM))
    for n, ax in enumerate(axes):
        coeff_axes(ax, n, first, "first order", f"$c'_{2 * n + 1}$")
    save(fig, out, "coefficients-first")

    fig, axes = plt.subplots(1, 3, figsize=(12.9 * CM, 3.7 * CM))
    for n, ax in enumerate(axes):
        coeff_axes(ax, n, second, "second order", f"$c''_{2 * n + 1}$")
    save(fig, out, "coefficients-second")

    fig, axes = plt.subplots(1, 3, figsize=(12.6 * CM, 3.6 * CM))
    for ax, t in zip(axes, [9 * PI / 10, 95 * PI / 100, 99 * PI / 100]):
        traj_axes(ax, t, [("second order", second, "k-")])
    save(fig, out, "trajectory-second")

    fig, (a, b) = plt.subplots(1, 2, figsize=(12 * CM, 4.5 * CM))
    t = np.linspace(1e-3, PI - 1e-3, 401)
    circles = np.arange(1, 24) * PI / 24
    a.plot(circles, period_ratio(circles), "ko", mfc="none", label="exact")
    for name, f, style in [("lowest order", lowest, "k--"), ("first order", first, "k:"), ("second order", second, "k-")]:
        p = np.array([1 / f(x)[0] for x in t])
        a.plot(t, p, style, label=name)
        b.plot(t, 100 * (p / period_ratio(t) - 1), style, label=name)
    a.set_ylim(1, 3)
    b.set_ylim(-20, 2)
    a.legend(frameon=False)
    save(fig, out, "period")
    if paper_only:
        return

    fig, ax = plt.subplots(figsize=(8 * CM, 5.6 * CM))
    for t in [PI / 2, 3 * PI / 4, 9 * PI / 10, 0.95 * PI, 0.99 * PI]:
        w = np.array(iterate(t, 40))
        ax.semilogy(np.arange(41), np.abs(1 / w / period_ratio(t) - 1))
    ax.set_ylim(1e-16, 1)
    save(fig, out, "convergence")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--paper"]
    main(Path(args[0] if args else "matplotlib-figures"), "--paper" in sys.argv[1:])
