#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The fuzzers still build from the program's library targets, and each runs briefly on its
# seed corpus without a crash: a build of their own (clang, PENDULUM_BUILD_FUZZERS=ON) in
# SCRATCH_DIR, kept between runs so that only what changed is compiled again.
# Usage: fuzz_test.sh SOURCE_DIR SCRATCH_DIR [SECONDS]. Exit 77 (skipped) without clang.
set -euo pipefail
src=$1
dir=$2
seconds=${3:-5}
if ! command -v clang++ >/dev/null 2>&1; then
    # CI installs what make deps lists: there a missing clang is a failure, not a skip.
    [ "${CI:-}" != true ] || { echo "FAIL: clang++ is missing (make deps installs clang)"; exit 1; }
    echo "clang++ not found: the fuzzers are not built"
    exit 77
fi

# -O1 as make fuzz, with line tables only: the quickest build that still gives file and
# line in a crash's stack (about 3 minutes on 2 cores the first time, seconds after).
mkdir -p "$dir"
cmake -S "$src" -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DPENDULUM_BUILD_FUZZERS=ON \
      -DPENDULUM_BUILD_TESTS=OFF -DPENDULUM_BUILD_BENCH=OFF >"$dir/configure.log" 2>&1 ||
    { cat "$dir/configure.log"; exit 1; }
cmake --build "$dir" --target fuzzers -j "${JOBS:-2}" >"$dir/build.log" 2>&1 || { tail -n 60 "$dir/build.log"; exit 1; }

# LeakSanitizer as make check-sanitizers runs it: fontconfig's configuration and caches,
# which live as long as the process, are not leaks (tests/sanitizers/lsan.supp).
export LSAN_OPTIONS=suppressions=$src/tests/sanitizers/lsan.supp:print_suppressions=0
failures=0
names=$(cat "$dir/fuzzers.txt")
[ -n "$names" ] || { echo "no fuzzers in $dir/fuzzers.txt"; exit 1; }
for name in $names; do
    work=$dir/run-$name
    rm -rf "$work"
    mkdir -p "$work/new"
    # New inputs go to work/new; the seed corpus in the source tree is only read.
    # -max_len: inputs as large as a spec file may be (1 MiB), as make fuzz runs them.
    if "$dir/fuzz/${name}_fuzzer" -max_total_time="$seconds" -max_len=1048576 -artifact_prefix="$work/" \
           "$work/new" "$src/fuzz/corpus/$name" >"$work/log" 2>&1; then
        echo "$name: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$work/log" || tail -n 1 "$work/log")"
    else
        echo "FAIL: ${name}_fuzzer"
        tail -n 40 "$work/log"
        failures=$((failures + 1))
    fi
done
exit $((failures > 0))
