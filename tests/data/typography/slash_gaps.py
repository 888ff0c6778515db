#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The ink gaps of slash.tex as pdfTeX sets it: run in a scratch directory,
   /usr/bin/python3 slash_gaps.py PATH/slash.tex
prints each line's gaps between runs of inked columns, in ems (pdfTeX 2023, Computer Modern:
t/T 0.085 0.08; T_N/T 0.08 0.08). The layout's slash_gap is the gap after the slash."""
import subprocess
import sys

import numpy as np
from PIL import Image

subprocess.run(["pdflatex", "-interaction=nonstopmode", sys.argv[1]], check=True, capture_output=True)
subprocess.run(["pdftoppm", "-r", "144", "-gray", "slash.pdf", "p"], check=True)
ink = np.array(Image.open("p-1.pgm")) < 128
em = 100 * 144 / 72  # pixels in an em of the 100 pt text
rows = np.where(ink.any(axis=1))[0]
lines, start = [], rows[0]
for a, b in zip(rows, rows[1:]):
    if b != a + 1:
        lines.append((start, a))
        start = b
lines.append((start, rows[-1]))
for y0, y1 in lines:
    cols = np.where(ink[y0:y1 + 1].any(axis=0))[0]
    gaps = [(b - a - 1) / em for a, b in zip(cols, cols[1:]) if b != a + 1]
    print(" ".join(f"{g:.3f}" for g in gaps))
