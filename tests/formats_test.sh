#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One layout in every format and at every resolution: each built-in still figure, in every
# theme, as PDF, SVG and EPS rasterised by readers that share no code with the tool
# (poppler's pdftoppm, librsvg's rsvg-convert, ghostscript), must look like our PNG at the
# same resolution, and our PNG at 100 dpi like it averaged down: RGB RMS (0..255) at most
# TOLERANCE and PNG_TOLERANCE.
# A legend in another place, or text of another width, is far more than that; the readers'
# own anti-aliasing and glyph rendering are less. Vector pages are transparent by default,
# so they are rendered here with opaque_vector_background = true to compare on the theme's
# background; that the default is transparent is checked too.
# Usage: formats_test.sh PENDULUM_FIGURES IMAGE_CHECK [TOLERANCE [PNG_TOLERANCE]]
set -euo pipefail
exe=$1
check=$2
tolerance=${3:-7}
png_tolerance=${4:-9}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
for tool in pdftoppm rsvg-convert gs; do
    command -v "$tool" > /dev/null || fail "$tool is missing (make deps installs poppler-utils, librsvg2-bin, ghostscript)"
done

themes=$("$exe" list --markdown | awk -F'`' '/^\| theme \|/ { on = 1; next } on && /^\| `/ { print $2 }')
[ "$(echo "$themes" | wc -w)" -ge 3 ] || fail "expected three themes or more in list, got: $themes"
# A theme's own PNG resolution: its dpi key, or its base theme's.
theme_dpi() {
    local t=$1 d
    while [ -n "$t" ]; do
        d=$("$exe" show --theme "$t" | awk -F' *= *' '$1 == "dpi" { print $2 }')
        [ -z "$d" ] || { echo "${d%.*}"; return; }
        t=$("$exe" show --theme "$t" | awk -F'"' '/^base *=/ { print $2 }')
    done
    fail "no dpi in the themes"
}
status=0
worst=0
# RMS of A against B (averaged over BLOCK x BLOCK pixels), against TOLERANCE; WHAT names it.
compare() {
    local a=$1 b=$2 block=$3 tol=$4 what=$5 rms
    rms=$("$check" rms "$a" "$b" "$block") || fail "$what: cannot compare"
    line="$line $(echo "$what" | awk '{ print $NF }') $rms"
    if awk -v r="$rms" -v t="$tol" 'BEGIN { exit !(r > t) }'; then
        echo "FAIL: $what differs by RMS $rms (at most $tol)"
        status=1
    fi
    worst=$(awk -v a="$worst" -v b="$rms" 'BEGIN { print (b > a ? b : a) }')
}
for theme in $themes; do
    mkdir -p "$theme/100" "$theme/hi" "$theme/vector"
    # Readers compare at a resolution where their font hinting no longer shows, 40 to 60
    # pixels to the em: twice the theme's own PNG resolution, rounded down to hundreds (the
    # 100 dpi PNG is compared with it averaged down), averaged over 6 x 6 pixels.
    dpi=$(( 2 * $(theme_dpi "$theme") / 100 * 100 ))
    "$exe" render --all --theme "$theme" -f png --dpi 100 -o "$theme/100"
    "$exe" render --all --theme "$theme" -f png --dpi "$dpi" -o "$theme/hi"
    "$exe" render --all --theme "$theme" -f pdf,svg,eps --set opaque_vector_background=true -o "$theme/vector"
    ids=$(cd "$theme/vector" && ls *.svg | sed 's/\.svg$//')
    [ "$(echo "$ids" | wc -w)" -ge 12 ] || fail "expected every still figure, got: $ids"
    for id in $ids; do
        v=$theme/vector/$id
        pdftoppm -r "$dpi" -png -singlefile "$v.pdf" "$v.poppler"
        rsvg-convert --dpi-x "$dpi" --dpi-y "$dpi" -o "$v.rsvg.png" "$v.svg"
        gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=png16m -r"$dpi" -dTextAlphaBits=4 -dGraphicsAlphaBits=4 -dEPSCrop \
            -sOutputFile="$v.gs.png" "$v.eps"
        line="$theme $id:"
        compare "$theme/100/$id.png" "$theme/hi/$id.png" 2 "$png_tolerance" "$theme $id: our PNG at $dpi dpi against 100 dpi, png$dpi"
        for reader in poppler rsvg gs; do
            compare "$theme/hi/$id.png" "$v.$reader.png" 6 "$tolerance" "$theme $id: $reader against our PNG at $dpi dpi, $reader"
        done
        echo "$line"
    done
done

# Without the key, a vector page is transparent: nothing under it is covered.
mkdir transparent
"$exe" render fig6 -f pdf,svg -o transparent
gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pngalpha -r50 -sOutputFile=transparent/pdf.png transparent/trajectory-second.pdf
rsvg-convert --dpi-x 50 --dpi-y 50 -o transparent/svg.png transparent/trajectory-second.svg
for f in pdf svg; do
    a=$("$check" alpha "transparent/$f.png")
    [ "$a" = 0 ] || { echo "FAIL: the $f page's corner has opacity $a, want 0 (transparent)"; status=1; }
done
[ "$status" = 0 ] || fail "formats differ"
echo "ok: every format and resolution within RMS $worst of the 100 dpi PNG (at most $tolerance)"
