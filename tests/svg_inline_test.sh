#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Two of the tool's SVGs inlined in one HTML page each look as they do alone: headless
# Chromium shows a page with two different figures' SVGs inlined, and a page with the same
# files as images; each inlined figure is compared with its image (RGB RMS, 0..255, over
# 4 x 4 blocks). The same two SVGs with their ids' prefixes taken away (every file's ids
# as Cairo writes them, glyph0-1, clip1, ...) must differ: the test would otherwise prove
# nothing. Without chromium the test is skipped (exit 77), except under CI=true.
# Usage: svg_inline_test.sh PENDULUM_FIGURES IMAGE_CHECK [TOLERANCE]
set -euo pipefail
exe=$(realpath "$1")
check=$(realpath "$2")
here=$(cd "$(dirname "$0")" && pwd)
# Measured: 0 (the same pixels); without the prefixes 20 and more.
tolerance=${3:-1}
# shellcheck source=browser_prelude.sh
source "$here/browser_prelude.sh"

# Two figures with different glyphs at the same ids: a period plot and a phase portrait.
"$exe" plot period --methods exact,harmonic -f svg --name a --set opaque_vector_background=true > /dev/null
"$exe" plot phase --theta0 'pi/3,2pi/3' --methods exact --title 'Phase $\theta$ against $\dot\theta$' -f svg --name b \
    --set opaque_vector_background=true > /dev/null
# The figures' sizes in CSS pixels (the SVGs' width and height in pt: 4/3 px each).
px() { sed -n 's/.*<svg[^>]* '"$2"'="\([0-9.]*\)pt".*/\1/p' "$1" | head -1 | awk '{ printf "%d", $1 * 4 / 3 + 0.5 }'; }
for f in a b; do
    [ -n "$(px $f.svg width)" ] || fail "$f.svg: no width in pt: $(head -c 300 $f.svg)"
done
# Inline SVG without the XML declaration.
body() { sed '1{/^<?xml/d}' "$1"; }
page() {  # PAGE A.svg B.svg: both inlined, then both as images
    {
        echo '<!DOCTYPE html><html><head><meta charset="utf-8">'
        echo '<style>html, body { margin: 0; background: #fff; } div { line-height: 0; } svg, img { display: block; }</style>'
        echo '</head><body>'
        for f in "$2" "$3"; do
            echo "<div id=\"inline-$(basename "$f" .svg)\" style=\"width: $(px "$f" width)px\">"
            body "$f" | sed "s/<svg /<svg style=\"width: $(px "$f" width)px; height: $(px "$f" height)px\" /"
            echo '</div>'
        done
        for f in "$2" "$3"; do
            echo "<img id=\"alone-$(basename "$f" .svg)\" src=\"$f\" width=\"$(px "$f" width)\" height=\"$(px "$f" height)\">"
        done
        echo '</body></html>'
    } > "$1"
}
# The same files with the ids Cairo writes, the same in both.
for f in a b; do sed -E 's/f[0-9a-f]{12}-//g' $f.svg > plain-$f.svg; done
for f in plain-a.svg plain-b.svg; do
    grep -q 'id="glyph0-1"' "$f" || fail "$f lacks glyph0-1: the control would show nothing"
done
page page.html a.svg b.svg
page plain.html plain-a.svg plain-b.svg
mkdir shots plain
python3 "$here/svg_inline_grab.py" "$browser" page.html shots 1600 2400 inline-a inline-b alone-a alone-b
python3 "$here/svg_inline_grab.py" "$browser" plain.html plain 1600 2400 inline-plain-a inline-plain-b alone-plain-a alone-plain-b
status=0
for f in a b; do
    rms=$("$check" rms "shots/alone-$f.png" "shots/inline-$f.png" 4) || fail "cannot compare $f"
    echo "$f inlined beside the other: RMS $rms (at most $tolerance)"
    awk -v r="$rms" -v t="$tolerance" 'BEGIN { exit !(r > t) }' && { echo "FAIL: $f.svg inlined differs from it alone"; status=1; }
done
worst=0
for f in a b; do
    rms=$("$check" rms "plain/alone-plain-$f.png" "plain/inline-plain-$f.png" 4) || fail "cannot compare plain $f"
    echo "control, $f with Cairo's ids: RMS $rms"
    worst=$(awk -v r="$rms" -v w="$worst" 'BEGIN { print (r > w ? r : w) }')
done
awk -v w="$worst" -v t="$tolerance" 'BEGIN { exit !(w > 4 * t) }' ||
    { echo "FAIL: the SVGs with Cairo's shared ids look right inlined together: the test shows nothing"; status=1; }
exit $status
