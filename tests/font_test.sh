#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A style file may name any font fontconfig finds, the user's own too (~/.local/share/fonts),
# and a font it cannot find is bad input: exit status 2, the family named, and how to list
# the installed ones.
# Usage: font_test.sh PENDULUM_FIGURES
set -euo pipefail
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export HOME=$work/home XDG_CACHE_HOME=$work/cache
unset XDG_DATA_HOME FONTCONFIG_FILE FONTCONFIG_PATH
mkdir -p "$HOME" "$work/out"

# A font of TeX Live's (not in fontconfig's directories) as the user's font: the first whose
# family fontconfig does not know yet.
known=$(fc-list : family)
font="" family=""
while read -r f; do
    fam=$(fc-scan --format '%{family[0]}\n' "$f" 2>/dev/null | sed -n 1p) || continue
    if [ -n "$fam" ] && ! grep -qxF "$fam" <<<"$known" && ! grep -q "[,\"]" <<<"$fam"; then
        font=$f family=$fam
        break
    fi
done < <(find /usr/share/texlive /usr/share/texmf -name '*.otf' 2>/dev/null | sort)
[ -n "$font" ] || { echo "no font outside fontconfig's directories to install for the user"; exit 1; }

status=0
"$exe" render fig1 -f svg -o "$work/out" --set "font_family=$family, DejaVu Sans" 2>"$work/err" || status=$?
grep -qF "$family" "$work/err" || { echo "FAIL: the message does not name '$family': $(cat "$work/err")"; exit 1; }
grep -qF 'fc-list' "$work/err" || { echo "FAIL: the message does not say how to list the fonts: $(cat "$work/err")"; exit 1; }
[ "$status" -eq 2 ] || { echo "FAIL: a font fontconfig cannot find exits $status, not 2"; exit 1; }

mkdir -p "$HOME/.local/share/fonts"
cp "$font" "$HOME/.local/share/fonts/"
"$exe" render fig1 -f svg -o "$work/out" --set "font_family=$family, DejaVu Sans" ||
    { echo "FAIL: '$family', installed for the user, is refused"; exit 1; }
test -s "$work/out/c1-lowest.svg"
echo "ok: '$family' installed for the user ($(basename "$font")) is used; missing, it is exit status 2"
