#!/usr/bin/env bash
# Whole-process timing of the figure catalog: every figure as PNG (300 dpi) and PDF.
# Prints each run and the median wall-clock time. Usage: time_render.sh EXE [RUNS]
set -euo pipefail
exe=${1:?usage: time_render.sh EXE [RUNS]}
runs=${2:-11}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
times=()
for ((i = 0; i < runs; i++)); do
  start=$(date +%s%N)
  "$exe" render --all -f png,pdf --dpi 300 -o "$out"
  end=$(date +%s%N)
  times+=("$(( (end - start) / 1000000 ))")
done
sorted=$(printf '%s\n' "${times[@]}" | sort -n)
median=$(printf '%s\n' "$sorted" | sed -n "$(( (runs + 1) / 2 ))p")
echo "render --all -f png,pdf --dpi 300: runs (ms): $(echo $sorted)"
echo "render --all -f png,pdf --dpi 300: median $median ms over $runs runs"
