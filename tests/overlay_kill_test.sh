#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A LaTeX overlay and its drawing change together. Both are on disk under temporary names
# before the first is renamed, so only a kill between the two renames (microseconds) can
# leave a torn pair, and the next run that completes repairs it (it rewrites the file that
# differs; both when either differs). Renders of one figure at two aspect ratios are killed (SIGKILL) at random
# moments; after each, a render that completes leaves a matching pair. A render whose
# overlay is a link is refused and leaves the drawing as it was, and no temporary behind.
# Usage: overlay_kill_test.sh PENDULUM_FIGURES [KILLS]
set -euo pipefail
exe=$1
kills=${2:-60}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$dir"

# One figure, p, at two aspect ratios.
mkdir wide tall
for kind in wide:0.5 tall:0.9; do
    printf '[figure]\npanel_aspect = %s\n[[panel]]\nplot = "period"\nmethods = ["exact", "lowest"]\n' \
        "${kind#*:}" > "${kind%%:*}/p.toml"
done

# height/width of the drawing: the PDF's media box, and the picture the overlay declares.
pdf_ratio() { pdfinfo p.pdf | awk '/^Page size:/ { printf "%.4f\n", $5 / $3 }'; }
tex_ratio() { sed -n 's/^\\begin{picture}(1,\([0-9.]*\)).*/\1/p' p.pdf_tex | awk '{ printf "%.4f\n", $1 }'; }

"$exe" render wide/p.toml -f pdf_tex -o .
torn=0
for i in $(seq 1 "$kills"); do
    spec=$([ $((i % 2)) = 0 ] && echo wide || echo tall)/p.toml
    "$exe" render "$spec" -f pdf_tex -o . &
    pid=$!
    # Somewhere in the run: it takes some tens of milliseconds.
    sleep "0.0$(( (RANDOM % 60) + 10 ))"
    kill -9 "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    [ "$(pdf_ratio)" = "$(tex_ratio)" ] || torn=$((torn + 1))
    # The next run that completes repairs whatever a kill left.
    "$exe" render "$spec" -f pdf_tex -o .
    [ "$(pdf_ratio)" = "$(tex_ratio)" ] ||
        fail "kill $i: after a complete run, drawing $(pdf_ratio) and overlay $(tex_ratio)"
done
[ -s p.pdf ] && [ -s p.pdf_tex ] || fail "no pair was written"
# Fault injection, the killed runs' temporaries out of the way: the overlay cannot be
# written (it is a link into a directory that does not exist, which is refused as bad input
# before any work: no output is written through a link), so the drawing must not change
# either.
rm -f .pendulum-figures-*
"$exe" render wide/p.toml -f pdf_tex -o .
before=$(cksum < p.pdf)
rm p.pdf_tex
ln -s "$dir/missing/p.pdf_tex" p.pdf_tex
set +e
message=$("$exe" render tall/p.toml -f pdf_tex -o . 2>&1)
status=$?
set -e
[ "$status" = 2 ] || fail "an overlay that is a dangling link: exit $status, not 2"
case $message in *"'./p.pdf_tex' is a symbolic link"*) ;; *) fail "the refusal does not name p.pdf_tex: $message" ;; esac
[ ! -e "$dir/missing" ] || fail "the link's target was created"
[ "$(cksum < p.pdf)" = "$before" ] || fail "the drawing changed though its overlay could not be written"
[ -z "$(find . -name '.pendulum-figures-*')" ] || fail "a failed write left a temporary"
rm p.pdf_tex

echo "ok: $kills kills ($torn left a torn pair, each repaired by the next complete run); an overlay that is a link is refused and leaves its drawing alone"
