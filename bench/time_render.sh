#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Whole-process timing of the figure catalog: every figure as PNG (300 dpi) and PDF, the
# median of RUNS runs. When python3 has matplotlib and scipy, the same work done with them
# (bench/matplotlib_catalog.py) is timed too, interleaved run by run so that a busy machine
# slows both alike, and the ratio of the medians is printed.
# Usage: time_render.sh EXE [RUNS]
set -euo pipefail
exe=${1:?usage: time_render.sh EXE [RUNS]}
runs=${2:-11}
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

ms_of() {
  local start end
  start=$(date +%s%N)
  "$@" >/dev/null
  end=$(date +%s%N)
  echo $(( (end - start) / 1000000 ))
}
median() { printf '%s\n' "$@" | sort -n | sed -n "$(( ($# + 1) / 2 ))p"; }

# Debian's python3 is where python3-matplotlib installs; PYTHON overrides.
python=${PYTHON:-$(command -v /usr/bin/python3 || command -v python3 || true)}
compare=0
if [ -n "$python" ] && "$python" -c 'import matplotlib, scipy' 2>/dev/null; then compare=1; fi
ours=()
theirs=()
for ((i = 0; i < runs; i++)); do
  ours+=("$(ms_of "$exe" render --all -f png,pdf --dpi 300 -o "$out")")
  if [ "$compare" = 1 ]; then theirs+=("$(ms_of "$python" "$here/matplotlib_catalog.py" "$out/matplotlib")"); fi
done
m=$(median "${ours[@]}")
echo "pendulum-figures render --all -f png,pdf --dpi 300: median $m ms over $runs runs ($(printf '%s ' $(printf '%s\n' "${ours[@]}" | sort -n))ms)"
if [ "$compare" = 1 ]; then
  t=$(median "${theirs[@]}")
  echo "matplotlib + scipy, the same figures:               median $t ms over $runs runs"
  echo "ratio: $(awk -v a="$t" -v b="$m" 'BEGIN { printf "%.1f", a / b }') times faster"
else
  echo "(install python3-matplotlib and python3-scipy to compare with matplotlib)"
fi
