#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The man pages keep up with the program:
# - pendulum-figures(1) has every command of --help in COMMANDS and in SYNOPSIS, and every
#   option of each command's --help in that command's part of OPTIONS (or "Every command");
# - pendulum-figures-spec(5) has every key the spec and style file readers accept, as the
#   tag of an entry: the keys are those the program lists when it meets an unknown one;
# - man reads both without a warning.
# Usage: man_test.sh PENDULUM_FIGURES SOURCE_DIR
set -euo pipefail
exe=$1
page1=$2/man/pendulum-figures.1
page5=$2/man/pendulum-figures-spec.5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

for page in "$page1" "$page5"; do
    warnings=$(LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -l "$page" 2>&1 >/dev/null)
    [ -z "$warnings" ] || fail "$(basename "$page"): man warns: $warnings"
done

# The pages' headers carry the program's version.
version=$("$exe" --version | sed -n '1s/^pendulum-figures //p')
for page in "$page1" "$page5"; do
    grep "^\.TH .* \"pendulum-figures $version\"" "$page" >/dev/null ||
        fail "$(basename "$page"): .TH does not say pendulum-figures $version"
done

# The page as text, wide enough that no option is hyphenated at a line end.
# (Pipelines end in a reader that reads everything, grep >/dev/null, not grep -q: with
# pipefail, a writer cut off early would fail the test by chance.)
text=$(LC_ALL=C.UTF-8 MANWIDTH=250 man -l "$page1" 2>/dev/null | col -bx | sed -E 's/([^ ])  +/\1 /g')
# Lines of section NAME (a heading at the margin) or subsection NAME (three spaces in).
# (awk reads to the end: one that exits early cuts off the echo, which pipefail reports.)
section() { echo "$text" | awk -v h="$1" '$0 == h && !done { on = 1; next } on && /^[A-Z]/ { on = 0; done = 1 } on { print }'; }
subsection() { echo "$text" | awk -v h="   $1" '$0 == h && !done { on = 1; next } on && /^ {0,3}[^ ]/ { on = 0; done = 1 } on { print }'; }
for s in NAME SYNOPSIS DESCRIPTION COMMANDS OPTIONS "EXIT STATUS" ENVIRONMENT FILES EXAMPLES "SEE ALSO"; do
    [ -n "$(section "$s")" ] || fail "pendulum-figures.1: no section $s"
done
[[ $(section ENVIRONMENT) == *SOURCE_DATE_EPOCH* ]] || fail "pendulum-figures.1: ENVIRONMENT lacks SOURCE_DATE_EPOCH"
commands=$("$exe" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 } on && /^$/ { on = 0 }')
[ "$(echo "$commands" | wc -w)" -ge 8 ] || fail "too few commands in --help: $commands"
every=$(subsection "Every command")
for o in $("$exe" --help | grep -oE '^ +(-[a-z],)?--[a-z0-9-]+' | grep -oE -- '--[a-z0-9-]+'); do
    [[ $every == *"$o"* ]] || fail "pendulum-figures.1: $o not under 'Every command'"
done
for c in $commands; do
    section COMMANDS | grep "^       $c\b" >/dev/null || fail "pendulum-figures.1: command $c not in COMMANDS"
    section SYNOPSIS | grep "pendulum-figures $c\b" >/dev/null || fail "pendulum-figures.1: command $c not in SYNOPSIS"
    # Each option as its names, "-o,--output-dir" or "--theme".
    options=$("$exe" "$c" --help | grep -oE '^ +(-[a-z],)?--[a-z0-9-]+')
    part=$(subsection "$c")
    synopsis=$(section SYNOPSIS | awk -v c="pendulum-figures $c" 'index($0, c) && !done { on = 1 } on && /^$/ { on = 0; done = 1 } on { print }')
    for names in $options; do
        case $names in *--help|*--help-all) continue ;; esac
        in_synopsis=no
        for o in ${names//,/ }; do
            [[ $part == *"$o"* ]] || fail "pendulum-figures.1: $c $o not in OPTIONS"
            [[ $synopsis == *"$o"[\ \]]* ]] && in_synopsis=yes
        done
        [ $in_synopsis = yes ] || fail "pendulum-figures.1: $c $names not in SYNOPSIS"
    done
done

# Keys of the spec and style file readers, from the program's own "keys: a, b, c" message
# for an unknown key in each kind of table.
keys_of() {  # FILE COMMAND...: the keys the program lists for FILE's unknown key zzzzzzzzzzzzzzzzzzzz
    local file=$1
    shift
    local message
    message=$("$@" 2>&1 >/dev/null || true)
    if ! echo "$message" | grep "unknown key 'zzzzzzzzzzzzzzzzzzzz'" >/dev/null; then
        echo "FAIL: no list of keys for $file: $message" >&2
        touch "$work/failed"
        return
    fi
    echo "$message" | grep "unknown key 'zzzzzzzzzzzzzzzzzzzz'" | sed -n 's/.*; keys: //p' | tr ',' '\n' | sed 's/^ *//; s/^and //; s/ *$//'
}
spec() { printf '%s\n' "$@" > "$work/spec.toml"; keys_of spec.toml "$exe" data "$work/spec.toml"; }
style() { printf '%s\n' "$@" > "$work/style.toml"; keys_of style.toml "$exe" render fig1 --theme "$work/style.toml" -o "$work"; }
panel='[[panel]]'
{
    spec 'zzzzzzzzzzzzzzzzzzzz = 1' "$panel" 'plot = "period"' 'methods = ["exact"]'
    spec '[figure]' 'zzzzzzzzzzzzzzzzzzzz = 1' "$panel" 'plot = "period"' 'methods = ["exact"]'
    spec '[pendulum]' 'length_m = 1' 'zzzzzzzzzzzzzzzzzzzz = 1' "$panel" 'plot = "period"' 'methods = ["exact"]'
    spec '[animation]' 'zzzzzzzzzzzzzzzzzzzz = 1' "$panel" 'plot = "pendulum"' 'theta0 = 1' 'methods = ["exact"]'
    for kind in $("$exe" list --markdown | awk '/^\| plot \|/ { on = 1; next } on && /^\| `/ { print } on && /^$/ { on = 0 }' |
                  sed -n 's/^| `\([^`]*\)`.*/\1/p'); do
        spec "$panel" "plot = \"$kind\"" 'zzzzzzzzzzzzzzzzzzzz = 1'
    done
    spec "$panel" 'plot = "period"' 'methods = [{ method = "exact", zzzzzzzzzzzzzzzzzzzz = 1 }]'
    spec "$panel" 'plot = "period"' 'methods = ["exact"]' '[[panel.line]]' 'y = 1' 'zzzzzzzzzzzzzzzzzzzz = 1'
    style 'zzzzzzzzzzzzzzzzzzzz = 1'
    style '[styles]' 'exact = { zzzzzzzzzzzzzzzzzzzz = 1 }'
} | sort -u > "$work/keys"
[ ! -e "$work/failed" ] || failures=$((failures + 1))
[ "$(wc -l < "$work/keys")" -ge 40 ] || fail "too few keys found: $(tr '\n' ' ' < "$work/keys")"
while read -r key; do
    [ -n "$key" ] || continue
    # An entry's tag (.TP, then .B KEY), or for a table its subsection (.SS "[KEY]" or "[[KEY]]").
    awk -v k=".B $key" -v t1=".SS \"[$key]\"" -v t2=".SS \"[[$key]]\"" \
        '(prev == ".TP" && $0 == k) || $0 == t1 || $0 == t2 { found = 1 } { prev = $0 } END { exit !found }' "$page5" ||
        fail "pendulum-figures-spec.5: key $key has no entry (.TP, .B $key)"
done < <(sort -u "$work/keys")

[ "$failures" -eq 0 ] || exit 1
echo "ok: man pages have $(echo "$commands" | wc -w) commands with their options and $(sort -u "$work/keys" | wc -l) spec and style keys"
