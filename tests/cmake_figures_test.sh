#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The installed CMake package's pendulum_add_figures, in a small documentation project built
# with Ninja and with Unix Makefiles: the first build renders every figure, the next does
# nothing; a comment in the style file that a spec names (known to CMake only through the
# dependency file) renders that figure again, once; with Ninja, a document made from the
# figures is not made again when their bytes did not change.
# Usage: cmake_figures_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

DESTDIR="$work/stage" cmake --install "$build" --prefix /usr/local >/dev/null
root="$work/stage/usr/local"

mkdir -p "$work/src/specs"
cat >"$work/src/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(docs CXX)
find_package(pendulum REQUIRED)
pendulum_add_figures(TARGET figures ALL SPECS specs/period.toml c1-lowest FORMATS pdf_tex svg
                     OUTPUT_DIR figures OUTPUT_DIR_IGNORED_BELOW OUTPUTS_VARIABLE files)
CMAKE
# The same without the deliberate mistake, which must stop the configuration.
cat >"$work/src/CMakeLists.txt.good" <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(docs CXX)
find_package(pendulum REQUIRED)
pendulum_add_figures(TARGET figures ALL SPECS specs/period.toml c1-lowest FORMATS pdf_tex svg
                     OUTPUT_DIR figures OUTPUTS_VARIABLE files)
# A document made from the figures (as LaTeX would be), counting its runs.
add_custom_command(OUTPUT document.txt
                   COMMAND sh -c "echo run >> '${CMAKE_BINARY_DIR}/document-runs'; cat \"$@\" > document.txt" sh ${files}
                   DEPENDS ${files} VERBATIM)
add_custom_target(document ALL DEPENDS document.txt)
CMAKE
cat >"$work/src/specs/period.toml" <<'TOML'
[figure]
style = "styles/house.toml"

[[panel]]
plot = "period"
methods = ["exact", "lowest"]
TOML
# The style file inside the spec's directory tree, where a spec's inputs must be.
mkdir -p "$work/src/specs/styles"
cat >"$work/src/specs/styles/house.toml" <<'TOML'
# The house style.
base = "paper"
line_width_pt = 1.2
TOML

# A wrong argument is named.
if cmake -S "$work/src" -B "$work/bad" -DCMAKE_PREFIX_PATH="$root" >"$work/log" 2>&1; then
    fail "an unknown argument of pendulum_add_figures configures"
elif ! grep 'unknown arguments OUTPUT_DIR_IGNORED_BELOW' "$work/log" >/dev/null; then
    cat "$work/log"
    fail "the unknown argument is not named"
fi
mv "$work/src/CMakeLists.txt.good" "$work/src/CMakeLists.txt"

# renders LOG: how many figures a build rendered.
renders() { grep -c 'Rendering figure' "$1" || true; }
# runs DIR: how many times the document was made.
runs() { [ -f "$1/document-runs" ] && wc -l <"$1/document-runs" || echo 0; }

for generator in Ninja "Unix Makefiles"; do
    dir="$work/build-${generator// /-}"
    cp "$work/src/specs/styles/house.toml" "$work/house.toml.orig"
    cmake -S "$work/src" -B "$dir" -G "$generator" -DCMAKE_PREFIX_PATH="$root" >"$work/log" 2>&1 ||
        { cat "$work/log"; fail "$generator: cmake fails"; continue; }
    # The program of the package, not one on PATH.
    grep -x "PENDULUM_FIGURES_EXECUTABLE:FILEPATH=$root/bin/pendulum-figures" "$dir/CMakeCache.txt" >/dev/null ||
        fail "$generator: pendulum-figures is not the installed one"
    cmake --build "$dir" >"$work/log" 2>&1 || { cat "$work/log"; fail "$generator: the first build fails"; continue; }
    [ "$(renders "$work/log")" -eq 2 ] || fail "$generator: the first build renders $(renders "$work/log") figures, not 2"
    for f in period.pdf period.svg period.pdf_tex c1-lowest.pdf c1-lowest.svg c1-lowest.pdf_tex period.d c1-lowest.d; do
        [ -s "$dir/figures/$f" ] || fail "$generator: no figures/$f"
    done
    grep 'house.toml' "$dir/figures/period.d" >/dev/null || fail "$generator: period.d does not name house.toml"
    cmake --build "$dir" >"$work/log" 2>&1
    [ "$(renders "$work/log")" -eq 0 ] || fail "$generator: a second build renders again"
    [ "$(runs "$dir")" -eq 1 ] || fail "$generator: the document was made $(runs "$dir") times, not once"
    sleep 1
    echo '# a comment changes no figure' >>"$work/src/specs/styles/house.toml"
    cmake --build "$dir" >"$work/log" 2>&1
    [ "$(renders "$work/log")" -eq 1 ] ||
        fail "$generator: after a comment in the spec's style file, $(renders "$work/log") renders, not 1"
    cmake --build "$dir" >"$work/log" 2>&1
    [ "$(renders "$work/log")" -eq 0 ] || fail "$generator: the build after the comment's renders again"
    if [ "$generator" = Ninja ]; then
        # restat: the figures' bytes are the same, so the document is not made again.
        [ "$(runs "$dir")" -eq 1 ] || fail "Ninja: the document was made again for figures that did not change"
        [ "$(ninja -C "$dir" -n)" = "ninja: Entering directory \`$dir'"$'\n'"ninja: no work to do." ] ||
            fail "Ninja: ninja -n has work after the build"
    fi
    cp "$work/house.toml.orig" "$work/src/specs/styles/house.toml"
done

[ "$failures" -eq 0 ] && echo "pendulum_add_figures: Ninja and Unix Makefiles render once, then are up to date"
[ "$failures" -eq 0 ]
