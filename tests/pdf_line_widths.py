# SPDX-License-Identifier: GPL-3.0-or-later
"""Prints the width at final size of every stroke a PDF makes, one line per stroking
operator (S, s, B, B*, b, b*): "WIDTH" in points to three decimals.

The width is read from the PDF's own operators, as a preflight tool reads it: the line
width of the graphics state (w, kept through q and Q) times the scale of the current
transformation matrix (cm), the square root of its determinant. Content streams and form
XObjects (Do) are followed from the pages, with the reader of pdf_text_sizes.py.

Usage: pdf_line_widths.py FILE.pdf
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pdf_text_sizes import form_of, mul, names_of, objects, operators, page_contents, resources, scale  # noqa: E402

STROKES = {b"S", b"s", b"B", b"B*", b"b", b"b*"}


def run(objs, content, head, ctm, width, out, depth=0):
    xobjects = names_of(resources(objs, head), b"XObject")
    stack = []
    for op, operands, nums in operators(content):
        if op == b"q":
            stack.append((ctm, width))
        elif op == b"Q" and stack:
            ctm, width = stack.pop()
        elif op == b"cm" and len(nums) >= 6:
            ctm = mul(nums[-6:], ctm)
        elif op == b"w" and nums:
            width = nums[-1]
        elif op in STROKES:
            out.append(width * scale(ctm))
        elif op == b"Do" and operands and depth < 8:
            form = form_of(objs, xobjects, operands[-1])
            if form:
                run(objs, form[1], form[0], mul(form[2], ctm), width, out, depth + 1)


def main():
    objs = objects(open(sys.argv[1], "rb").read())
    found = []
    for head, content in page_contents(objs):
        run(objs, content, head, [1, 0, 0, 1, 0, 0], 1.0, found)
    for width in found:
        print("%.3f" % width)


if __name__ == "__main__":
    main()
