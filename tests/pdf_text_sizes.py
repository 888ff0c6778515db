# SPDX-License-Identifier: GPL-3.0-or-later
"""Prints the size at final size of every text a PDF shows, one line per text-showing
operator: "SIZE TEXT-HEX", SIZE in points to three decimals.

The size is read from the PDF's own operators, as a preflight tool reads it: the font
size of Tf times the scale of the text matrix (Tm) times the scale of the current
transformation matrix (cm, through q and Q), each scale the square root of the matrix's
determinant (a turned y label has the size of an upright one). Content streams and form
XObjects (Do) are followed from the pages; Flate-compressed streams are inflated.

Usage: pdf_text_sizes.py FILE.pdf
"""
import math
import re
import sys
import zlib

OBJ = re.compile(rb"(\d+)\s+0\s+obj\s*(.*?)\s*endobj", re.S)
TOKEN = re.compile(rb"<[0-9A-Fa-f\s]*>|\((?:\\.|[^\\)])*\)|\[|\]|/[^\s/\[\]()<>]+|[-+]?\d*\.?\d+|[A-Za-z'\"*]+")


def objects(data):
    """Object number -> (dictionary bytes, inflated stream bytes or None)."""
    out = {}
    for m in OBJ.finditer(data):
        body = m.group(2)
        s = body.find(b"stream")
        if s < 0:
            out[int(m.group(1))] = (body, None)
            continue
        head = body[:s]
        raw = body[s + len(b"stream"):]
        raw = raw[2:] if raw.startswith(b"\r\n") else raw[1:]
        end = raw.rfind(b"endstream")
        raw = raw[:end]
        if b"/FlateDecode" in head:
            raw = zlib.decompressobj().decompress(raw)
        out[int(m.group(1))] = (head, raw)
    return out


def mul(a, b):
    """a then b, PDF matrices [a b c d e f]."""
    return [a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3],
            a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3],
            a[4] * b[0] + a[5] * b[2] + b[4], a[4] * b[1] + a[5] * b[3] + b[5]]


def scale(m):
    return math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))


def names_of(head, kind):
    """The /Name N 0 R entries of a resource dictionary of `kind` (XObject)."""
    m = re.search(rb"/" + kind + rb"\s*<<(.*?)>>", head, re.S)
    return dict(re.findall(rb"/([^\s/]+)\s+(\d+)\s+0\s+R", m.group(1))) if m else {}


def resources(objs, head):
    m = re.search(rb"/Resources\s+(\d+)\s+0\s+R", head)
    return objs[int(m.group(1))][0] if m else head


def operators(content):
    """(operator, its operand tokens, their numbers) of each operator of a content stream."""
    operands = []
    for t in TOKEN.findall(content):
        if t[:1] in b"0123456789.-+" or t[:1] in b"</([]":
            operands.append(t)
            continue
        yield t, operands, [float(x) for x in operands if x[:1] in b"0123456789.-+"]
        operands = []


def run(objs, content, head, ctm, out, depth=0):
    xobjects = names_of(resources(objs, head), b"XObject")
    stack = []
    font_size, tm = 0.0, [1, 0, 0, 1, 0, 0]
    for op, operands, nums in operators(content):
        if op == b"q":
            stack.append(ctm)
        elif op == b"Q" and stack:
            ctm = stack.pop()
        elif op == b"cm" and len(nums) >= 6:
            ctm = mul(nums[-6:], ctm)
        elif op == b"BT":
            tm = [1, 0, 0, 1, 0, 0]
        elif op == b"Tf" and nums:
            font_size = nums[-1]
        elif op == b"Tm" and len(nums) >= 6:
            tm = nums[-6:]
        elif op in (b"Tj", b"TJ", b"'", b'"'):
            text = b"".join(x for x in operands if x[:1] in b"<(")
            out.append((font_size * scale(tm) * scale(ctm), text))
        elif op == b"Do" and operands and depth < 8:
            form = form_of(objs, xobjects, operands[-1])
            if form:
                run(objs, form[1], form[0], mul(form[2], ctm), out, depth + 1)


def form_of(objs, xobjects, name):
    """(dictionary, content, matrix) of the form XObject /name of a Do, or None."""
    ref = xobjects.get(name[1:])
    if ref is None:
        return None
    fhead, fdata = objs[int(ref)]
    if fdata is None or b"/Form" not in fhead:
        return None
    m = re.search(rb"/Matrix\s*\[([^\]]*)\]", fhead)
    return fhead, fdata, [float(x) for x in m.group(1).split()] if m else [1, 0, 0, 1, 0, 0]


def page_contents(objs):
    """(page dictionary, content stream) of every content stream of every page."""
    for head, _ in objs.values():
        if not re.search(rb"/Type\s*/Page\b", head):
            continue
        refs = re.search(rb"/Contents\s+(?:\[([^\]]*)\]|(\d+)\s+0\s+R)", head)
        if not refs:
            continue
        numbers = re.findall(rb"(\d+)\s+0\s+R", refs.group(1)) if refs.group(1) else [refs.group(2)]
        for n in numbers:
            yield head, objs[int(n)][1] or b""


def main():
    objs = objects(open(sys.argv[1], "rb").read())
    found = []
    for head, content in page_contents(objs):
        run(objs, content, head, [1, 0, 0, 1, 0, 0], found)
    for size, text in found:
        print("%.3f %s" % (size, text.hex()))


if __name__ == "__main__":
    main()
