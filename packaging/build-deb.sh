#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes the Debian packages pendulum-figures and libpendulum-dev from a built tree (make deb).
# Usage: packaging/build-deb.sh BUILD_DIR OUT_DIR
#
# The packages are assembled with dpkg-deb from a tree staged by cmake --install, one
# install component per package, rather than by debhelper: debhelper's sequence builds the
# source again in a tree of its own (minutes on two cores, and the tests again), while this
# packages what make has built, with the flags of dpkg-buildflags (see the Makefile). The
# steps debhelper would take are Debian's own tools here: dpkg-shlibdeps and dpkg-gencontrol
# write the control files from packaging/debian/control and changelog, strip removes what
# dh_strip removes, gzip -9n compresses as dh_compress does, and lintian checks the result
# (tests/lintian_test.sh).
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
out=$(cd "$2" && pwd)
source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
umask 022

# dpkg-shlibdeps and dpkg-gencontrol read debian/control and debian/changelog of a source tree.
mkdir -p "$work/src"
cp -r "$source_dir/packaging/debian" "$work/src/debian"
version=$(cd "$work/src" && dpkg-parsechangelog -S Version)
# File dates of the packages: the changelog's, so that the same tree gives the same packages.
SOURCE_DATE_EPOCH=$(cd "$work/src" && dpkg-parsechangelog -S Timestamp)
export SOURCE_DATE_EPOCH
project_version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
if [ "${version%-*}" != "$project_version" ]; then
    echo "packaging/debian/changelog is at $version, the project at $project_version: add a changelog entry" >&2
    exit 1
fi

# package component
stage() {
    local package=$1 component=$2 root=$work/src/debian/$1
    DESTDIR=$root cmake --install "$build" --prefix /usr --component "$component" >/dev/null
    local doc=$root/usr/share/doc/$package
    mkdir -p "$doc"
    install -m 644 "$work/src/debian/copyright" "$doc/copyright"
    gzip -9n -c "$work/src/debian/changelog" > "$doc/changelog.Debian.gz"
    if [ -f "$work/src/debian/$package.lintian-overrides" ]; then
        install -D -m 644 "$work/src/debian/$package.lintian-overrides" "$root/usr/share/lintian/overrides/$package"
    fi
    # Man pages compressed, as Debian policy asks (12.3).
    if [ -d "$root/usr/share/man" ]; then
        find "$root/usr/share/man" -type f -name '*.[0-9]' -exec gzip -9n {} +
    fi
    # Programs stripped of symbols and notes, static libraries of debugging information,
    # with dh_strip's options.
    if [ -d "$root/usr/bin" ]; then
        strip --remove-section=.comment --remove-section=.note --strip-unneeded "$root"/usr/bin/*
    fi
    # The video module likewise; a shared object is not executable (Debian policy 8.1).
    find "$root" -type f -name '*.so' -exec strip --remove-section=.comment --remove-section=.note \
         --strip-unneeded {} + -exec chmod 644 {} +
    find "$root" -type f -name '*.a' -exec strip --strip-debug --remove-section=.comment \
         --remove-section=.note '--remove-section=.gnu.lto_*' '--remove-section=.gnu.debuglto_*' \
         --enable-deterministic-archives {} +
    find "$root" -type d -exec chmod 755 {} +
    find "$root" -type f ! -perm -u+x -exec chmod 644 {} +
}
stage pendulum-figures tool
stage libpendulum-dev dev

cd "$work/src"
mkdir -p debian/pendulum-figures/DEBIAN debian/libpendulum-dev/DEBIAN
# The program and its video module: the packages of FFmpeg's libraries come from the module.
dpkg-shlibdeps -Tdebian/pendulum-figures.substvars debian/pendulum-figures/usr/bin/pendulum-figures \
    $(find debian/pendulum-figures/usr/lib -name '*.so')
for package in pendulum-figures libpendulum-dev; do
    root=debian/$package
    mkdir -p "$root/DEBIAN"
    substvars=()
    [ -f "debian/$package.substvars" ] && substvars=(-Tdebian/$package.substvars)
    dpkg-gencontrol -p"$package" -P"$root" "${substvars[@]}" -Vmisc:Depends= -fdebian/files
    (cd "$root" && find usr -type f -print0 | LC_ALL=C sort -z | xargs -0 md5sum > DEBIAN/md5sums)
    chmod 644 "$root/DEBIAN/control" "$root/DEBIAN/md5sums"
    dpkg-deb --root-owner-group -Zxz --build "$root" "$out" >/dev/null
done
arch=$(dpkg-architecture -qDEB_HOST_ARCH)
for package in pendulum-figures libpendulum-dev; do
    echo "$out/${package}_${version}_${arch}.deb"
done
