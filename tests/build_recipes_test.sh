#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's build recipes, GNU make's and ninja's, as printed there (the blocks after
# <!-- snippet: file Makefile --> and <!-- snippet: file build.ninja -->, with the style
# file and the document they use): the first build renders and compiles; the next says it
# is up to date; a comment added to the style file renders once and compiles nothing (the
# figure's bytes are the same), after which the build is up to date again; a real change
# of style renders and compiles again.
# Usage: build_recipes_test.sh PENDULUM_FIGURES SOURCE_DIR
set -euo pipefail
exe=$(realpath "$1")
source_dir=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The snippet files of the README, written as the README's own test writes them.
python3 - "$source_dir/README.md" "$work/snippets" <<'EOF'
import os, re, sys
lines = open(sys.argv[1], encoding="utf-8").read().split("\n")
os.makedirs(sys.argv[2])
i = 0
while i < len(lines):
    m = re.match(r"^\s*<!-- snippet: file (\S+) -->\s*$", lines[i])
    if m:
        j = i + 1
        while not lines[j].strip().startswith("```"):
            j += 1
        indent = len(lines[j]) - len(lines[j].lstrip())
        k, body = j + 1, []
        while not lines[k].strip().startswith("```"):
            body.append(lines[k][indent:])
            k += 1
        path = os.path.join(sys.argv[2], m.group(1))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        open(path, "w", encoding="utf-8").write("\n".join(body) + "\n")
        i = k
    i += 1
EOF
for f in Makefile build.ninja journal.toml paper.tex; do
    [ -f "$work/snippets/$f" ] || fail "the README has no block <!-- snippet: file $f -->"
done
[ "$failures" -eq 0 ] || exit 1

# The program and pdflatex on PATH, each counting its runs.
mkdir "$work/bin"
cat >"$work/bin/pendulum-figures" <<EOF
#!/bin/sh
echo run >>"$work/renders"
exec "$exe" "\$@"
EOF
pdflatex=$(command -v pdflatex)
cat >"$work/bin/pdflatex" <<EOF
#!/bin/sh
echo run >>"$work/compiles"
exec "$pdflatex" "\$@"
EOF
chmod +x "$work/bin/pendulum-figures" "$work/bin/pdflatex"
export PATH="$work/bin:$PATH"

count() { [ -f "$work/$1" ] && wc -l <"$work/$1" || echo 0; }

# check TOOL WHAT RENDERS COMPILES: the runs so far of the program and of pdflatex.
check() {
    local r c
    r=$(count renders)
    c=$(count compiles)
    [ "$r" -eq "$3" ] && [ "$c" -eq "$4" ] || fail "$1, $2: $r renders and $c compiles, expected $3 and $4"
}

# up_to_date TOOL: the tool says there is nothing to do.
up_to_date() {
    case $1 in
    make)
        make -q || fail "make -q exits $? after a build: not up to date" ;;
    ninja)
        local says
        says=$(ninja -n)
        [ "$says" = "ninja: no work to do." ] || fail "ninja -n after a build says: $says" ;;
    esac
}

for tool in make ninja; do
    dir="$work/$tool"
    mkdir "$dir"
    cp "$work/snippets/"{Makefile,build.ninja,journal.toml,paper.tex} "$dir/"
    cd "$dir"
    rm -f "$work/renders" "$work/compiles"
    start=$(date +%s%N)
    $tool >"$work/log" 2>&1 || { cat "$work/log"; fail "$tool: the first build fails"; continue; }
    first=$((($(date +%s%N) - start) / 1000000))
    check $tool "the first build" 1 1
    [ -f paper.pdf ] || fail "$tool: no paper.pdf"
    up_to_date $tool
    start=$(date +%s%N)
    $tool >"$work/log" 2>&1
    again=$((($(date +%s%N) - start) / 1000000))
    check $tool "a second build" 1 1
    # File times have a resolution of their own: an edit comes a second later.
    sleep 1
    echo '# a comment changes no figure' >>journal.toml
    $tool >"$work/log" 2>&1
    check $tool "after a comment in the style file" 2 1
    up_to_date $tool
    $tool >"$work/log" 2>&1
    check $tool "a build after the comment's" 2 1
    sleep 1
    echo 'line_width_pt = 1.1' >>journal.toml
    $tool >"$work/log" 2>&1
    check $tool "after a change of style" 3 2
    up_to_date $tool
    echo "$tool: first build ${first} ms, up-to-date build ${again} ms"
done

[ "$failures" -eq 0 ] && echo "build recipes: make and ninja build once, then are up to date"
[ "$failures" -eq 0 ]
