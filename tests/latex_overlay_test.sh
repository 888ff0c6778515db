#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# pdf_tex and eps_tex: a Times document inputs every figure's overlay and LaTeX sets the text.
# Usage: latex_overlay_test.sh PENDULUM_FIGURES pdf|eps
set -euo pipefail
exe=$1
kind=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }

"$exe" render --all -f "${kind}_tex" -o . --tex-font-size 10
ids=$(ls *."${kind}_tex" | sed "s/\.${kind}_tex\$//")
[ "$(echo "$ids" | wc -w)" -ge 12 ] || fail "expected every figure, got: $ids"
{
    echo '\documentclass{article}'
    echo '\usepackage{mathptmx}'
    echo '\usepackage{graphicx}'
    echo '\usepackage[margin=1cm]{geometry}'
    echo '\begin{document}'
    for id in $ids; do echo "\\input{$id.${kind}_tex}\\par"; done
    # \figurewidth scales the drawing of one figure, not its text.
    echo '\def\figurewidth{8.6cm}\input{trajectory-lowest.'"$kind"'_tex}'
    echo '\end{document}'
} > doc.tex

if [ "$kind" = pdf ]; then
    # The drawings carry no text at all: no font, CMU or other.
    for id in $ids; do
        fonts=$(pdffonts "$id.pdf" | tail -n +3)
        [ -z "$fonts" ] || fail "$id.pdf has fonts: $fonts"
    done
    pdflatex -interaction=nonstopmode -halt-on-error doc.tex > log.txt 2>&1 || { tail -30 log.txt; fail "pdflatex"; }
else
    for id in $ids; do
        ! grep -q '/FontName\|findfont' "$id.eps" || fail "$id.eps has fonts"
    done
    latex -interaction=nonstopmode -halt-on-error doc.tex > log.txt 2>&1 || { tail -30 log.txt; fail "latex"; }
    dvips -q doc.dvi -o doc.ps
    ps2pdf doc.ps doc.pdf
fi
fonts=$(pdffonts doc.pdf)
grep -q NimbusRomNo9L <<<"$fonts" || fail "the text is not in the document's Times: $fonts"
! grep -qi cmu <<<"$fonts" || fail "a CMU font in the document: $fonts"
text=$(pdftotext doc.pdf -)
for label in "lowest order" "first order" "harmonic" "separatrix" "order N of the iteration" "relative error" \
             "Kidd–Fogg" "0.5" "0.1 % (the paper" "0.2 % (its conclusion)"; do
    grep -qF -- "$label" <<<"$text" || fail "label '$label' is not in the document"
done
# Unicode that a pdflatex document cannot set never reaches the overlay.
! LC_ALL=C grep -l $'[\x80-\xff]' *."${kind}_tex" || fail "non-ASCII characters in an overlay"
echo "ok: $(echo "$ids" | wc -w) figures as ${kind}_tex in a Times document"
