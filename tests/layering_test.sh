#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The layers include only what is below them: src/pendulum (the core) nothing of the others;
# src/plot nothing of src/pendulum, src/figures or src/cli; src/figures nothing of src/cli.
# src/common (header-only: the bad-input type, the edit distance) is below every layer: any
# may include it, and it includes none of them.
# The core's installed headers (the install(FILES ...) list of CMakeLists.txt) include no GSL
# header and no project header that is not installed with them.
# Usage: layering_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# forbid DIR LAYER...: no file of src/DIR includes "LAYER/..." (or <LAYER/...>).
forbid() {
    local dir=$1
    shift
    local layers
    layers=$(IFS='|'; echo "$*")
    local hits
    local files
    files=$(find src/"$dir" -maxdepth 1 \( -name '*.cpp' -o -name '*.hpp' \) | sort)
    [ -n "$files" ] || { fail "src/$dir has no source files"; return; }
    # shellcheck disable=SC2086 # one word per file name (no spaces in src/)
    hits=$(grep -nE "^[[:space:]]*#[[:space:]]*include[[:space:]]*[\"<]($layers)/" $files || true)
    [ -z "$hits" ] || fail "src/$dir includes from $*:"$'\n'"$hits"
}
forbid pendulum plot figures cli
forbid plot pendulum figures cli
forbid figures cli
forbid common pendulum plot figures cli
[ -z "$(find src/common -name '*.cpp')" ] || fail "src/common is header-only: $(find src/common -name '*.cpp')"

# The installed headers: the src/pendulum/*.hpp named in CMakeLists.txt's install(FILES ...).
installed=$(awk '/^install\(FILES/ { on = 1 } on { print } on && /\)/ { on = 0 }' CMakeLists.txt |
            grep -oE 'src/pendulum/[A-Za-z0-9_]+\.hpp' | sort -u || true)
[ -n "$installed" ] || fail "no src/pendulum header in the install(FILES ...) of CMakeLists.txt"
for h in $installed; do
    [ -f "$h" ] || { fail "installed header $h does not exist"; continue; }
    hits=$(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*<gsl/' "$h" || true)
    [ -z "$hits" ] || fail "installed header $h includes GSL:"$'\n'"$hits"
    for inc in $(sed -nE 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]+)".*/\1/p' "$h"); do
        grep -qx "src/$inc" <<<"$installed" || fail "installed header $h includes \"$inc\", which is not installed"
    done
done

[ "$failures" -eq 0 ] && echo "layering: $(echo "$installed" | wc -l) installed headers, every layer checked"
exit $((failures > 0))
