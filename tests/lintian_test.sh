#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Debian's own checker reports nothing on either package of make deb, at the levels error,
# warning and info (a tag overridden in packaging/debian/*.lintian-overrides needs its reason
# there), and the packages hold what they should.
# Usage: lintian_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v lintian >/dev/null || { echo "lintian is not installed (make deps installs it)"; exit 1; }
"$2/packaging/build-deb.sh" "$build" "$work" > "$work/debs"
failures=0
for deb in $(cat "$work/debs"); do
    # Every tag down to info (-I); lintian's word on running as root is no tag.
    report=$(lintian -I --tag-display-limit 0 "$deb" 2>&1 | grep -v '^running with root privileges' || true)
    if [ -n "$report" ]; then
        echo "FAIL: lintian on $(basename "$deb"):"
        echo "$report"
        failures=$((failures + 1))
    fi
done
tool=$(grep '/pendulum-figures_' "$work/debs")
dev=$(grep '/libpendulum-dev_' "$work/debs")
contents() { dpkg-deb --contents "$1" | awk '{ print $6 }'; }
for f in ./usr/bin/pendulum-figures ./usr/share/man/man1/pendulum-figures.1.gz ./usr/share/man/man5/pendulum-figures-spec.5.gz \
         ./usr/share/bash-completion/completions/pendulum-figures ./usr/share/pendulum-figures/specs/period.toml \
         ./usr/share/doc/pendulum-figures/copyright; do
    contents "$tool" | grep -xF "$f" >/dev/null || { echo "FAIL: pendulum-figures lacks $f"; failures=$((failures + 1)); }
done
for f in ./usr/include/pendulum/exact.hpp ./usr/share/doc/libpendulum-dev/copyright; do
    contents "$dev" | grep -xF "$f" >/dev/null || { echo "FAIL: libpendulum-dev lacks $f"; failures=$((failures + 1)); }
done
for pattern in '/pkgconfig/pendulum.pc$' '/libpendulum.a$' '/cmake/pendulum/pendulumConfig.cmake$'; do
    contents "$dev" | grep -E "^\./usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)$pattern" >/dev/null ||
        { echo "FAIL: libpendulum-dev lacks $pattern in the multiarch directory"; failures=$((failures + 1)); }
done
if contents "$tool" | grep -E '/include/|\.a$' >/dev/null; then
    echo "FAIL: pendulum-figures holds files of the library"; failures=$((failures + 1))
fi
dpkg-deb --field "$dev" Depends | grep -w libgsl-dev >/dev/null || { echo "FAIL: libpendulum-dev does not depend on libgsl-dev"; failures=$((failures + 1)); }
[ "$failures" -eq 0 ] || exit 1
echo "ok: lintian reports nothing on $(xargs -n1 basename < "$work/debs" | tr '\n' ' ')"
