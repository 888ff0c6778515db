#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the build into a scratch tree (make install's way) and checks what a user gets:
# the tool, its man pages, completions, examples, and the core library used from a small
# program both through CMake's find_package (which gives C++20 with pendulum::core) and
# through pkg-config. With "deb", the same from make deb's two packages, unpacked with dpkg -x.
# Usage: install_test.sh BUILD_DIR [deb]
set -euo pipefail
# Pipelines end in a reader that reads everything (grep >/dev/null, not grep -q or head):
# with pipefail, a writer cut off early fails the test by chance.
build=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [ "${2:-}" = deb ]; then
    # make deb's packages, unpacked together: the tool runs, and a program builds with the library.
    "$(dirname "$0")/../packaging/build-deb.sh" "$build" "$work/package" >/dev/null
    tool=$(ls "$work"/package/pendulum-figures_*.deb)
    dev=$(ls "$work"/package/libpendulum-dev_*.deb)
    dpkg-deb --field "$tool" Depends | grep 'libcairo' >/dev/null
    dpkg-deb --field "$tool" Depends | grep 'libavcodec[0-9]' | grep 'libavformat[0-9]' >/dev/null
    dpkg -x "$tool" "$work/root"
    dpkg -x "$dev" "$work/root"
    "$work/root/usr/bin/pendulum-figures" --version | sed -n 1p | grep -x 'pendulum-figures [0-9.]*' >/dev/null
    "$work/root/usr/bin/pendulum-figures" render fig1 -f svg -o - | grep '<svg' >/dev/null
    man -l "$work/root/usr/share/man/man1/pendulum-figures.1.gz" | grep 'render' >/dev/null
    man -l "$work/root/usr/share/man/man5/pendulum-figures-spec.5.gz" | grep 'panel_width_cm' >/dev/null
    root="$work/root/usr"
    echo "deb: $(basename "$tool") and $(basename "$dev") unpack and run"
else
    DESTDIR="$work/stage" cmake --install "$build" --prefix /usr/local >/dev/null
    root="$work/stage/usr/local"
    "$root/bin/pendulum-figures" --version | sed -n 1p | grep -x 'pendulum-figures [0-9.]*' >/dev/null
    man -l "$root/share/man/man1/pendulum-figures.1" | grep 'render' >/dev/null
    man -l "$root/share/man/man5/pendulum-figures-spec.5" | grep 'panel_width_cm' >/dev/null
    bash -n "$root/share/bash-completion/completions/pendulum-figures"
    test -f "$root/share/zsh/vendor-completions/_pendulum-figures"
    test -f "$root/share/pendulum-figures/specs/period.toml"
    test -f "$root/share/pendulum-figures/themes/slides.toml"
fi
test -f "$root/include/pendulum/exact.hpp"


cat > "$work/main.cpp" <<'CPP'
#include <pendulum/exact.hpp>
#include <cmath>
#include <cstdio>
int main() {
    const double t = pendulum::period_ratio(M_PI / 2);
    const pendulum::exact_solution e(M_PI / 2);
    std::printf("%.16g\n", t);
    return std::fabs(t / 1.1803405990160962 - 1) < 1e-15 && e.period_ratio() == t ? 0 : 1;
}
CPP
mkdir "$work/cmake"
cat > "$work/cmake/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(uses_pendulum CXX)
find_package(pendulum REQUIRED)
add_executable(uses_pendulum ../main.cpp)
target_link_libraries(uses_pendulum PRIVATE pendulum::core)
CMAKE
cmake -S "$work/cmake" -B "$work/cmake/build" -DCMAKE_PREFIX_PATH="$root" >/dev/null
cmake --build "$work/cmake/build" >/dev/null
"$work/cmake/build/uses_pendulum"

pc_dir=$(dirname "$(find "$root" -name pendulum.pc | head -n 1)")
g++ -std=c++20 "$work/main.cpp" -o "$work/with_pkgconfig" $(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs pendulum)
"$work/with_pkgconfig"
echo "install: tool, man page, completions, examples; core library through CMake and pkg-config"
