# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by the browser tests: fail(), $browser (headless Chromium), and a work directory
# $dir that is the current one and goes at exit (KEEP=1 keeps it, to look at the pictures).
# Without Chromium a test is skipped (exit 77), except under CI=true, where it fails.
fail() { echo "FAIL: $*"; exit 1; }
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    [ "${CI:-}" != true ] || fail "chromium is missing (make deps installs it)"
    echo "SKIP: chromium is not installed"
    exit 77
fi
dir=$(mktemp -d)
if [ -n "${KEEP:-}" ]; then echo "pictures in $dir"; else trap 'rm -rf "$dir"' EXIT; fi
cd "$dir"
