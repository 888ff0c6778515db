#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Labels from strangers: spec labels that try to read, write or run something through the
# LaTeX document that \inputs their overlays, and random labels of TeX's special characters
# and macros. Every label the tool accepts is set in one document compiled without shell
# escape; pdflatex's -recorder list of the files it opened shows that nothing outside the
# TeX installation was read and nothing outside the sandbox written.
# Usage: latex_hostile_test.sh PENDULUM_FIGURES SOURCE_DIR [COUNT]
set -euo pipefail
exe=$1
src=$2
count=${3:-300}
dir=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; [ -z "${KEEP:-}" ] || echo "kept $dir"; exit 1; }
mkdir "$dir/specs" "$dir/doc"
python3 "$src/tests/make_hostile_labels.py" "$dir/specs" "$count"
echo "untouched" > "$dir/doc/victim.tex"

accepted=0
refused=0
inputs=""
for spec in "$dir"/specs/label-*.toml; do
    id=$(basename "$spec" .toml)
    set +e
    "$exe" render "$spec" -f pdf_tex -o "$dir/doc" > "$dir/out.txt" 2>&1
    status=$?
    set -e
    case $status in
        0) accepted=$((accepted + 1)); inputs="$inputs $id" ;;
        2) refused=$((refused + 1))
           [ ! -e "$dir/doc/$id.pdf_tex" ] || fail "$id refused (exit 2) but its overlay was written" ;;
        *) cat "$dir/out.txt"; fail "$id: exit $status (a label is accepted or refused with exit 2)" ;;
    esac
done
[ "$accepted" -ge 100 ] || fail "only $accepted labels accepted: the test would prove little"

cd "$dir/doc"
{
    echo '\documentclass{article}'
    echo '\usepackage{mathptmx}'
    echo '\usepackage{graphicx}'
    echo '\usepackage[margin=1cm]{geometry}'
    echo '\begin{document}'
    for id in $inputs; do echo "\\def\\figurewidth{\\linewidth}\\input{$id.pdf_tex}\\par"; done
    echo '\end{document}'
} > doc.tex
pdflatex -no-shell-escape -recorder -interaction=nonstopmode -halt-on-error doc.tex > log.txt 2>&1 ||
    { grep -A5 '^!' doc.log | head -30; fail "the document with $accepted accepted labels does not compile"; }

# What pdflatex opened: reads only from the TeX trees (and the sandbox), writes only here.
sandbox=$(pwd -P)
texmf_var=$(kpsewhich -var-value=TEXMFVAR 2>/dev/null || echo /nonexistent)
tex_fonts=$(kpsewhich -var-value=VARTEXFONTS 2>/dev/null || echo /nonexistent)
texmf_local=$(kpsewhich -var-value=TEXMFLOCAL 2>/dev/null || echo /nonexistent)
while IFS=' ' read -r kind path; do
    case $kind in
        PWD) continue ;;
        INPUT)
            case $path in
                /usr/share/texlive/* | /usr/share/texmf/* | /usr/share/texmf-dist/* | /var/lib/texmf/* | \
                    /etc/texmf/* | /usr/share/fonts/* | /usr/share/texlive-*/*) ;;
                "$texmf_var"/* | "$tex_fonts"/* | "$texmf_local"/*) ;;  # fonts TeX made for itself, local trees
                /*) [[ $path == "$sandbox"/* ]] || fail "pdflatex read $path" ;;
                *) [[ $path != */* || $path == ./* ]] || fail "pdflatex read $path" ;;
            esac ;;
        OUTPUT)
            case $path in
                doc.* | ./doc.* | "$sandbox"/doc.*) ;;
                *) fail "pdflatex wrote $path" ;;
            esac ;;
    esac
done < doc.fls
grep -q '^INPUT .*victim' doc.fls && fail "the document read victim.tex"
[ "$(cat victim.tex)" = untouched ] || fail "victim.tex was changed"
[ ! -e pwned.txt ] && [ ! -e "$src/pwned.txt" ] || fail "a label ran a command"
text=$(pdftotext doc.pdf -)
host=$(cat /etc/hostname 2>/dev/null || true)
if [ -n "$host" ] && [ "${#host}" -ge 4 ]; then
    ! grep -qF -- "$host" <<<"$text" || fail "the host name is in the document"
fi
# The hostile text is shown as text, not run.
grep -qF 'input /etc/hostname' <<<"$text" || fail "the hostile labels' text is not shown"
echo "ok: $accepted labels accepted and compiled without reading or writing outside, $refused refused with exit 2"
