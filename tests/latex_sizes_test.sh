#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The sizes LaTeX sets an overlay's text at: relative sizes follow the document (\small of a
# 10 pt document is 9 pt, of a 12 pt one 10.95 pt), absolute ones are the theme's points in
# any document. Measured as the height of the panel letter "(a)" (the theme's 9 pt label
# size) in the PDF, with pdftotext -bbox.
# Usage: latex_sizes_test.sh PENDULUM_FIGURES
set -euo pipefail
exe=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }

# One document per case: the directory, the render options, the class options.
height() {
    local case=$1 render_options=$2 class_options=$3
    mkdir "$case"
    # shellcheck disable=SC2086
    "$exe" render period -f pdf_tex -o "$case" $render_options
    printf '\\documentclass[%s]{article}\n\\usepackage{mathptmx}\n\\usepackage{graphicx}\n\\begin{document}\n\\input{period.pdf_tex}\n\\end{document}\n' \
        "$class_options" > "$case/doc.tex"
    (cd "$case" && pdflatex -interaction=nonstopmode -halt-on-error doc.tex > log.txt 2>&1) ||
        { tail -20 "$case/log.txt"; fail "pdflatex, $case"; }
    pdftotext -bbox "$case/doc.pdf" - | awk -F'"' '/>\(a\)</ && !done { print $8 - $4; done = 1 }'
}
relative10=$(height relative10 "" 10pt)
relative12=$(height relative12 "--tex-font-size 12" 12pt)
absolute10=$(height absolute10 "--tex-sizes absolute" 10pt)
absolute12=$(height absolute12 "--tex-sizes absolute" 12pt)
[ -n "$relative10" ] && [ -n "$absolute12" ] || fail "no (a) in the documents"
# The ratio of two heights is the ratio of their sizes, to 0.5 %.
check() {
    awk -v a="$2" -v b="$3" -v want="$4" 'BEGIN { r = a / b; exit !(r > want * 0.995 && r < want * 1.005) }' ||
        fail "$1: height ratio $2 / $3, want $4"
}
check "\\small at 12 pt / at 10 pt" "$relative12" "$relative10" "$(awk 'BEGIN { print 10.95 / 9 }')"
check "9 pt / \\small at 10 pt" "$absolute10" "$relative10" 1
check "absolute at 12 pt / at 10 pt" "$absolute12" "$absolute10" 1
echo "ok: (a) is $relative10 pt high at \\small of 10 pt, $relative12 at 12 pt, $absolute10 and $absolute12 at 9 pt"
