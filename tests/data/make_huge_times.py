#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""theta(t) at times of up to a million periods (the CLI's limit), for trajectory's phase reduction.

Amplitudes only: a state's period comes from its energy, rounded to a double. The exact
libration from theta0 at rest: theta = 2 asin(k cd(u | k^2)), u = w0 t reduced
modulo 4 K(k) at 80 digits; the harmonic motion theta0 cos(w0 t). 170deg is pi - d with d
the double nearest pi/18 (as the CLI keeps it), 1 and 2.5 the doubles. Each time is the double its
decimal text rounds to (as the CLI reads it), taken exactly; w0 t is s 4K for t/T, 2 pi s for
t/T0 and s sqrt(g/L) for t/s.

Writes huge_times.csv: the trajectory arguments and theta (25 digits).
"""

from mpmath import mp

from reference_csv import write_reference

mp.dps = 80

# (theta0 text, theta0 value, extra arguments, unit, time text, method)
CASES = []
for theta0_text, theta0 in [("1", lambda: mp.mpf(1)), ("2.5", lambda: mp.mpf("2.5")), ("170deg", None)]:
    for unit in ["t/T0", "t/s"]:
        for time in ["999999.3", "999999.87", "123456.789", "-765432.1"]:
            CASES.append((theta0_text, unit, time, "exact", ""))
    CASES.append((theta0_text, "t/T", "999999.3", "harmonic", ""))
    CASES.append((theta0_text, "t/T0", "999999.3", "harmonic", ""))
    CASES.append((theta0_text, "t/s", "-999999.7", "harmonic", ""))
LENGTH, G = "0.7", "9.80665"


def amplitude(text):
    if text.endswith("deg"):
        # The CLI keeps an expression close to pi as the double nearest its distance from pi.
        return mp.pi - mp.mpf(float(mp.pi - mp.mpf(text[:-3]) * mp.pi / 180))
    return mp.mpf(float(text))


def main():
    rows = []
    for theta0_text, unit, time, method, extra in CASES:
        theta0 = amplitude(theta0_text)
        k = mp.sin(theta0 / 2)
        four_k = 4 * mp.ellipk(k * k)
        s = mp.mpf(float(time))
        if unit == "t/T":
            w0_t = s * four_k
        elif unit == "t/T0":
            w0_t = 2 * mp.pi * s
        else:
            w0_t = s * mp.sqrt(mp.mpf(float(G)) / mp.mpf(float(LENGTH)))
        if method == "harmonic":
            theta = theta0 * mp.cos(w0_t)
        else:
            u = mp.fmod(w0_t, four_k)
            theta = 2 * mp.asin(k * mp.ellipfun("cd", u, m=k * k))
        args = f"trajectory --theta0 {theta0_text}{extra} --time {unit} --at {time}"
        if method != "exact":
            args += f" --method {method}"
        if unit == "t/s":
            args += f" --length {LENGTH} --g {G}"
        rows.append([args, mp.nstr(theta, 25)])
    write_reference("huge_times.csv", __file__, ["arguments", "theta"], rows)


if __name__ == "__main__":
    main()
