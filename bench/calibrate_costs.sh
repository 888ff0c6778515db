#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The render's cost estimate against real renders: each probe spec is rendered with one
# worker, and its CPU seconds and peak memory (GNU time) are printed beside the estimate's
# seconds. The unit costs themselves come from calibrate_costs (the real functions, timed);
# the probes give the values a series takes, the drawing's costs and the bytes a point.
# Usage: calibrate_costs.sh EXE [PROBE...]   (see bench/calibrate_costs.md)
set -euo pipefail
exe=$(realpath "${1:?usage: calibrate_costs.sh EXE [PROBE...]}")
shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
command -v /usr/bin/time >/dev/null || { echo "calibrate_costs.sh: needs GNU time (/usr/bin/time)" >&2; exit 1; }

panel() { printf '[figure]\ntitle = "probe"\n\n[[panel]]\n%s\n' "$1"; }
methods12='["exact", "harmonic", "lowest", "first", "second", "polynomial", "order:2", "order:3", "order:4", "order:5", "order:6", "order:7"]'
declare -A spec args
spec[period-error-order2]=$(panel $'plot = "period"\ny = "error-log"\nmethods = ["order:2"]')
spec[period-value-order20]=$(panel $'plot = "period"\nmethods = ["order:20"]')
spec[coefficient-order10]=$(panel $'plot = "coefficient"\nharmonic = 3\nmethods = ["order:10"]')
spec[trajectory-near-pi-order10]=$(panel $'plot = "trajectory"\ntheta0 = "pi - 1e-300"\nmethods = ["order:10"]')
spec[convergence-near-pi-40]=$(panel $'plot = "convergence"\ntheta0 = ["pi - 1e-300"]\norders = [0, 40]')
spec[trajectory-100-periods]=$(panel $'plot = "trajectory"\ntheta0 = "3"\nrange = [0, 100]\nmethods = '"$methods12")
spec[large-png]=$(panel $'plot = "period"\nmethods = ["exact", "lowest"]')
args[large-png]="--size 10000x10000 -f png"
probes=("$@")
[ ${#probes[@]} -gt 0 ] || probes=("${!spec[@]}")
printf '%-30s %10s %10s %12s\n' probe "cpu (s)" "wall (s)" "peak (MiB)"
for p in "${probes[@]}"; do
  printf '%s\n' "${spec[$p]}" >"$out/$p.toml"
  # shellcheck disable=SC2086
  /usr/bin/time -f '%U %S %e %M' -o "$out/time" "$exe" render "$out/$p.toml" ${args[$p]:--f png,pdf} --jobs 1 \
    --force -o "$out" >/dev/null 2>"$out/err" || { echo "$p: $(cat "$out/err")" >&2; continue; }
  read -r user sys wall kb <"$out/time"
  awk -v p="$p" -v u="$user" -v s="$sys" -v w="$wall" -v k="$kb" \
    'BEGIN { printf "%-30s %10.2f %10.2f %12.0f\n", p, u + s, w, k / 1024 }'
done
# The worst built-in animation frame and the videos' memory (bench/calibrate_costs.md).
for size in 1920x1080 3840x2160; do
  for f in gif mp4 webm; do
    /usr/bin/time -f '%U %S %e %M' -o "$out/time" "$exe" render swing --size "$size" --frames 1..60 -f "$f" \
      --force -o "$out" >/dev/null 2>"$out/err" || { echo "swing $size $f: $(cat "$out/err")" >&2; continue; }
    read -r user sys wall kb <"$out/time"
    awk -v p="swing 60 frames $f $size" -v u="$user" -v s="$sys" -v w="$wall" -v k="$kb" \
      'BEGIN { printf "%-30s %10.2f %10.2f %12.0f\n", p, u + s, w, k / 1024 }'
  done
done
