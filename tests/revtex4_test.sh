#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The paper's figures in the paper's own class: revtex4 [prb,preprint] (12 pt), each figure's
# --paper-files panels placed side by side and one above the other as the paper's source
# places them (minipages of 6, 4.3 and 4.2 cm). In the compiled PDF, rasterised at 600 dpi,
# the panels of a row must have their frames' tops and bottoms level to 0.1 mm, those of a
# column their left and right sides, and no two words may overprint (pdftotext -bbox).
# Usage: revtex4_test.sh PENDULUM_FIGURES IMAGE_CHECK pdf|pdf_tex [TEX_FONT_SIZE]
# (pdf_tex without TEX_FONT_SIZE: rendered for the default 10 pt, compiled at 12 pt)
set -euo pipefail
exe=$1
check=$2
route=$3
size=${4:-}
dir=$(mktemp -d)
[ -n "${KEEP:-}" ] && echo "dir $dir" || trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
for tool in pdflatex pdftoppm pdftotext kpsewhich; do
    command -v "$tool" > /dev/null || fail "$tool is missing (make deps installs it)"
done
kpsewhich revtex4.cls > /dev/null || fail "revtex4.cls is missing (Debian's texlive-publishers; make deps installs it)"

if [ "$route" = pdf ]; then
    "$exe" render --all --paper-files -f pdf -o .
else
    # Without a size, laid out for a 10 pt document: the text must keep that room here too.
    "$exe" render --all --paper-files -f pdf_tex ${size:+--tex-font-size "$size"} -o .
fi

# One panel: WIDTH NAME.
panel() {
    if [ "$route" = pdf ]; then
        printf '\\includegraphics[width=%s]{%s.pdf}' "$1" "$2"
    else
        printf '{\\def\\figurewidth{%s}\\input{%s.pdf_tex}}' "$1" "$2"
    fi
}
# A column of panels: WIDTH NAME...
column() {
    local w=$1
    shift
    printf '\\begin{minipage}[b]{%s}\\centering\n' "$w"
    for name in "$@"; do
        panel "$w" "$name"
        printf '\n'
    done
    printf '\\end{minipage}'
}
# A figure on a page of its own: the space between columns (beyond a word space), then
# COLUMNS, each "WIDTH NAME...", and a caption after them.
figure() {
    local gap=$1
    shift
    printf '\\begin{figure}[!ht]\n'
    local first=1
    for col in "$@"; do
        [ $first = 1 ] || printf '\n\\hspace*{%s}\n' "$gap"
        first=0
        # shellcheck disable=SC2086
        column $col
    done
    printf '\n\\caption{The panels of one figure, as the paper places them.}\n\\end{figure}\n\\clearpage\n'
}
{
    printf '\\documentclass[prb,preprint]{revtex4}\n\\usepackage{graphicx}\n\\begin{document}\n'
    figure 0mm "6cm Fig.C1.Lowest"
    figure 5mm "6cm Fig.Comparison.LowestA Fig.Comparison.LowestC" "6cm Fig.Comparison.LowestB Fig.Comparison.LowestD"
    figure 5mm "6cm Fig.C1.First" "6cm Fig.C3.First"
    figure 5mm "6cm Fig.Comparison.FirstA Fig.Comparison.FirstC" "6cm Fig.Comparison.FirstB Fig.Comparison.FirstD"
    # Figs. 5 and 6: the minipages a word space apart, as in the paper.
    figure 0mm "4.3cm Fig.C1.Second" "4.3cm Fig.C3.Second" "4.3cm Fig.C5.Second"
    figure 0mm "4.2cm Fig.Lamb.4a" "4.2cm Fig.Lamb.4b" "4.2cm Fig.Lamb.4c"
    figure 5mm "6cm Fig.Comparison.PeriodA" "6cm Fig.Comparison.PeriodB"
    printf '\\end{document}\n'
} > doc.tex
pdflatex -interaction=nonstopmode -halt-on-error doc.tex > log.txt 2>&1 || { tail -30 log.txt; fail "pdflatex"; }
! grep -q 'Overfull \\hbox' log.txt || fail "a figure is wider than the minipage that holds it: $(grep 'Overfull' log.txt)"
pages=$(pdfinfo doc.pdf | awk '/^Pages:/ { print $2 }')
[ "$pages" = 7 ] || fail "expected 7 pages, one a figure, got $pages"

# Rows and columns of each figure, in order.
grids=("1 1" "2 2" "1 2" "2 2" "1 3" "1 3" "1 2")
worst=0
status=0
for page in 1 2 3 4 5 6 7; do
    read -r rows cols <<< "${grids[$((page - 1))]}"
    pdftoppm -r 600 -gray -png -f "$page" -l "$page" -x 0 -y 0 -W 5100 -H 3400 doc.pdf page
    png=$(ls page-*"$page".png)
    "$check" frames "$png" 600 > "frames-$page.txt"
    rm -f "$png"
    # Rows are the frames in order of their tops, `cols` at a time; within a row, by left.
    result=$(awk -v rows="$rows" -v cols="$cols" -v page="$page" '
        { l[NR] = $1; t[NR] = $2; r[NR] = $3; b[NR] = $4 }
        END {
            if (NR != rows * cols) { printf "figure %d: %d frames found, want %d\n", page, NR, rows * cols; exit 1 }
            for (i = 0; i < rows; ++i) {
                # Sort the row by left (insertion sort of indices).
                for (j = 1; j <= cols; ++j) idx[i, j] = i * cols + j
                for (j = 2; j <= cols; ++j)
                    for (k = j; k > 1 && l[idx[i, k]] < l[idx[i, k - 1]]; --k) { s = idx[i, k]; idx[i, k] = idx[i, k - 1]; idx[i, k - 1] = s }
            }
            worst = 0
            for (i = 0; i < rows; ++i)
                for (j = 2; j <= cols; ++j) {
                    a = idx[i, 1]; c = idx[i, j]
                    d = t[a] - t[c]; if (d < 0) d = -d; if (d > worst) { worst = d; what = sprintf("tops of row %d", i + 1) }
                    d = b[a] - b[c]; if (d < 0) d = -d; if (d > worst) { worst = d; what = sprintf("bottoms of row %d", i + 1) }
                }
            for (j = 1; j <= cols; ++j)
                for (i = 1; i < rows; ++i) {
                    a = idx[0, j]; c = idx[i, j]
                    d = l[a] - l[c]; if (d < 0) d = -d; if (d > worst) { worst = d; what = sprintf("left sides of column %d", j) }
                    d = r[a] - r[c]; if (d < 0) d = -d; if (d > worst) { worst = d; what = sprintf("right sides of column %d", j) }
                }
            printf "%.3f %s\n", worst, what
        }' "frames-$page.txt") || { echo "$result"; cat "frames-$page.txt"; fail "frames of figure $page"; }
    read -r mm what <<< "$result"
    echo "figure $page: frames in line to $mm mm${what:+ (worst: $what)}"
    if awk -v d="$mm" 'BEGIN { exit !(d > 0.1) }'; then
        echo "FAIL: figure $page: $what differ by $mm mm (at most 0.1)"
        cat "frames-$page.txt"
        status=1
    fi
    worst=$(awk -v a="$worst" -v b="$mm" 'BEGIN { print (b > a ? b : a) }')
done

# No word overprints another: the middle of their boxes (pdftotext's boxes are the fonts'
# whole height, so neighbours' boxes overlap a little when their ink does not) do not
# intersect. Primes alone are left out: they stand over a subscript by design.
pdftotext -bbox doc.pdf words.html
overprints=$(awk -F'"' '
    /<page / { ++page }
    /<word / {
        w = $0; sub(/.*">/, "", w); sub(/<\/word>.*/, "", w)
        if (w ~ /^[ʹʺ′″]+$/) next
        n = ++count[page]
        h = $8 - $4
        x0[page, n] = $2 + 0.3; y0[page, n] = $4 + 0.3 * h; x1[page, n] = $6 - 0.3; y1[page, n] = $8 - 0.3 * h
        word[page, n] = w
        for (i = 1; i < n; ++i)
            if (x0[page, i] < x1[page, n] && x0[page, n] < x1[page, i] && y0[page, i] < y1[page, n] && y0[page, n] < y1[page, i])
                printf "figure %d: \"%s\" and \"%s\" overprint\n", page, word[page, i], w
    }' words.html)
[ -z "$overprints" ] || { echo "$overprints"; status=1; }
[ "$status" = 0 ] || fail "route $route"
echo "ok: $route route${size:+ at --tex-font-size $size}, panels in line to $worst mm at most, no text overprints"
