#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the build into a scratch tree (make install's way) and checks what a user gets:
# the tool, its man page, completions, examples, and the core library used from a small
# program both through CMake's find_package and through pkg-config. With "deb", builds
# the Debian package, unpacks it with dpkg -x and runs the tool from it.
# Usage: install_test.sh BUILD_DIR [deb]
set -euo pipefail
# Pipelines end in a reader that reads everything (grep >/dev/null, not grep -q or head):
# with pipefail, a writer cut off early fails the test by chance.
build=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [ "${2:-}" = deb ]; then
  (cd "$build" && cpack -G DEB -B "$work/package" >/dev/null)
  deb=$(ls "$work"/package/pendulum-figures_*.deb)
  dpkg-deb --field "$deb" Depends | grep 'libgsl' >/dev/null
  dpkg -x "$deb" "$work/root"
  "$work/root/usr/bin/pendulum-figures" --version | sed -n 1p | grep -x 'pendulum-figures [0-9.]*' >/dev/null
  "$work/root/usr/bin/pendulum-figures" render fig1 -f svg -o - | grep '<svg' >/dev/null
  man -l "$work/root/usr/share/man/man1/pendulum-figures.1" | grep 'render' >/dev/null
  echo "deb: $(basename "$deb") unpacks and runs"
  exit 0
fi

DESTDIR="$work/stage" cmake --install "$build" --prefix /usr/local >/dev/null
root="$work/stage/usr/local"
"$root/bin/pendulum-figures" --version | sed -n 1p | grep -x 'pendulum-figures [0-9.]*' >/dev/null
man -l "$root/share/man/man1/pendulum-figures.1" | grep 'render' >/dev/null
bash -n "$root/share/bash-completion/completions/pendulum-figures"
test -f "$root/share/zsh/vendor-completions/_pendulum-figures"
test -f "$root/share/pendulum-figures/specs/period.toml"
test -f "$root/share/pendulum-figures/themes/slides.toml"
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
set(CMAKE_CXX_STANDARD 20)
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
