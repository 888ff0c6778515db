#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes spec files whose labels try to reach into the LaTeX document that \\inputs their
overlays, and random labels made of the characters and macros that mean something to TeX.
Usage: make_hostile_labels.py DIR [COUNT] [SEED]: DIR/label-N.toml, one spec per label, the
label as the panel's title, x label and legend entry."""
import random
import sys

HOSTILE = [
    r"host: \input /etc/hostname \immediate\openout15=victim.tex",
    r"\immediate\write18[touch pwned.txt]",
    r"\immediate\write18{touch pwned.txt}",
    r"$\mathrm{\input /etc/hostname}$ $\text{\immediate\write18 touch pwned.txt}$",
    r"\openin1=/etc/passwd \read1 to\x \x",
    r"\catcode`\^^M=13 \def\x{\input /etc/hostname}\x",
    r"\csname input\endcsname /etc/hostname",
    r"\\input{/etc/hostname} \\$ \\",
    r"$\operatorname{\openout1=victim.tex}$",
    r"end with a backslash \\",
    r"\begin{document}\end{document}\bye\end",
    r"$x^{2}'$ $c''_1$ $\dot{\vartheta}'$ $T_{1}^{2}$",
    r"$\left( \frac{1}{2} \right)$",
    r"$\sqrt[\input /etc/hostname]{x} \frac{\write18{ls}}{2}$",
    r"$\left( \sqrt{\frac{T}{T_0}} \right)^2 \le \infty \approx \theta \ne \vartheta$",
    r"$\hat{\mathbf{F}} \vec{v} \overline{xy} \tilde{\psi} \bar{x} \hbar \ell \nabla \partial$",
    r"$\left\{ \sqrt[3]{\left. x \right|} \right\}$ $\frac{\mathbf{\input x}}{\text{\write18 ls}}$",
    r"100 % of & # _ ^ ~ { } | < > \$",
    "\u00e9t\u00e9 \u00b0 \u03c0 \u2013 \u2014",
]

# Pieces a random label is made of: text, TeX's special characters, the engine's macros,
# and macros that must never pass.
PIECES = [
    "a", "x", "T", "1", "0", " ", ".", ",", "(", ")", "[", "]", "+", "-", "=", "/", "*", "'", "!", "?", ":", ";",
    "$", "$", "{", "}", "_", "^", "\\", "%", "#", "&", "~", "|", "<", ">", "@", "\"", "`",
    r"\pi", r"\vartheta", r"\omega", r"\le", r"\cdot", r"\prime", r"\dot", r"\ddot", r"\,", r"\;", r"\!", r"\ ",
    r"\{", r"\}", r"\%", r"\$", r"\&", r"\#", r"\_", r"\|", r"\left", r"\right", r"\big", r"\quad", r"\mathrm{",
    r"\text{", r"\mathit{", r"\operatorname{", r"\input", r"\write", r"\openout", r"\immediate", r"\def",
    r"\catcode", r"\csname", r"\endcsname", r"\relax", r"\\", "\u03c0", "\u00b0",
]


TEXT = ["a", "T", "1", " ", ".", ",", "(", ")", "%", "#", "&", "~", "^", "_", "{", "}", "|", "<", ">", "\\",
        "\\$", "\\\\", "@", "\"", "`", "'", "\u00e9", "\u00fc", "\u03c0", "\u2013", r"\input", r"\write18"]
MATH = ["x", "T", "1", "2", " ", "+", "-", "=", "/", "(", ")", "'", ",", "|", "<", ">", r"\pi", r"\vartheta",
        r"\omega", r"\le", r"\cdot", r"\prime", r"\,", r"\;", r"\!", r"\ ", r"\{", r"\}", r"\%", r"\$", r"\&",
        r"\#", r"\_", r"\|", r"\quad", r"\infty", "\u03c0", r"\theta", r"\approx", r"\ne", r"\hbar"]


def math_group(rng, depth=0):
    """Balanced math: atoms, groups, scripts, accents and text arguments."""
    out = ""
    for _ in range(rng.randint(1, 6)):
        roll = rng.random()
        if roll < 0.15 and depth < 4:
            out += "{" + math_group(rng, depth + 1) + "}"
        elif roll < 0.3 and depth < 4:
            out += rng.choice("xT") + rng.choice("_^") + "{" + math_group(rng, depth + 1) + "}"
        elif roll < 0.38 and depth < 4:
            out += rng.choice([r"\dot", r"\ddot", r"\left", r"\right", r"\big"]) + "{" + math_group(rng, depth + 1) + "}"
        elif roll < 0.42 and depth < 4:
            out += rng.choice([r"\sqrt", r"\frac{1}", r"\left(", r"\sqrt[3]"]) + "{" + math_group(rng, depth + 1) + "}"
            out += r"\right)" if out.endswith("}") and r"\left(" in out[-200:] and rng.random() < 0.5 else ""
        elif roll < 0.47:
            inner = "".join(rng.choice(TEXT[:16] + [r"\input", r"\write18"]) for _ in range(rng.randint(0, 5)))
            inner = inner.replace("{", "").replace("}", "")
            out += rng.choice([r"\mathrm", r"\text", r"\operatorname", r"\mathit"]) + "{" + inner + "}"
        else:
            piece = rng.choice(MATH)
            # A macro name ends at the next non-letter: keep it apart from a following letter.
            out += piece + (" " if piece[0] == "\\" and piece[-1].isalpha() else "")
    return out


def random_label(rng):
    if rng.random() < 0.25:
        # Anything at all, mostly refused.
        return "".join(rng.choice(PIECES) for _ in range(rng.randint(1, 24)))
    out = ""
    for _ in range(rng.randint(1, 4)):
        if rng.random() < 0.5:
            out += "".join(rng.choice(TEXT) for _ in range(rng.randint(1, 8)))
        else:
            out += "$" + math_group(rng) + "$"
    return out


def toml_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def main():
    out = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    rng = random.Random(int(sys.argv[3]) if len(sys.argv) > 3 else 1303)
    labels = HOSTILE + [random_label(rng) for _ in range(count)]
    for n, label in enumerate(labels):
        with open(f"{out}/label-{n:03d}.toml", "w", encoding="utf-8") as f:
            f.write("[figure]\npanel_width_cm = 40\npanel_aspect = 0.3\n[[panel]]\n")
            f.write('plot = "period"\nmethods = ["exact", {method = "lowest", label = ' + toml_string(label) + "}]\n")
            f.write("title = " + toml_string(label) + "\nx_label = " + toml_string(label) + "\n")


main()
