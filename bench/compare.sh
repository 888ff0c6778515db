#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# pendulum-figures against the usual tools, in one interleaved run: each round runs every
# row's two commands in turn, so that a busy machine slows both alike, and each row prints
# the medians over the rounds and their ratio. Then callgrind's instruction counts (the
# paper's figures, the catalog, one animation frame) and the peak memory of the swing GIF
# for 1 and 30 periods at 720p and 4K.
# Last, the worst accepted spec (bench/worst_accepted.toml, estimated just under the render
# bound): its time and peak memory.
# Usage: compare.sh EXE [ROUNDS]   (BENCH_MEMORY=0 leaves out the memory rows, BENCH_WORST=0
# the worst accepted spec, which takes minutes; BENCH_ROWS="paper fig7 ..." runs only those
# rows of the table, BENCH_INSTRUCTIONS=0 leaves out callgrind)
set -euo pipefail
exe=$(realpath "${1:?usage: compare.sh EXE [ROUNDS]}")
rounds=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python=${PYTHON:-/usr/bin/python3}
"$python" -c 'import matplotlib, scipy, PIL' 2>/dev/null ||
  { echo "compare.sh: needs python3-matplotlib, python3-scipy and python3-pil" >&2; exit 1; }
command -v gnuplot >/dev/null || { echo "compare.sh: needs gnuplot (gnuplot-nox)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "compare.sh: needs valgrind" >&2; exit 1; }

median() { printf '%s\n' "$@" | sort -g | sed -n "$(( ($# + 1) / 2 ))p"; }
# Seconds of a command (its output thrown away).
seconds() {
  local start end
  start=$(date +%s%N)
  "$@" >/dev/null 2>&1
  end=$(date +%s%N)
  awk -v n=$((end - start)) 'BEGIN { printf "%.3f", n / 1e9 }'
}

paper="fig1 fig2 fig3 fig4 fig5 fig6 fig7"
mkdir -p "$out/ours" "$out/theirs" "$out/gnuplot"
# Fig. 7's curves for gnuplot, one file per series (not timed).
"$exe" data fig7 | awk -F, -v d="$out/gnuplot" 'NR > 1 { print $3 "," $4 > (d "/" $1 "-" $2 ".csv") }'
# A million amplitudes for eval (not timed).
awk 'BEGIN { srand(1); for (i = 0; i < 1000000; i++) printf "%.17g\n", 0.01 + 3.09 * rand() }' >"$out/amplitudes"

# Fifty one-panel specs, for one render of 50 figures against 50 renders of one (not timed).
mkdir -p "$out/fifty" "$out/ours50"
for i in $(seq -w 1 50); do
  printf '[[panel]]\nplot = "period"\nmethods = ["exact", "lowest", "second"]\n' >"$out/fifty/f$i.toml"
done

# Each row: two commands, ours and a peer's, run in turn in every round.
rows=(${BENCH_ROWS:-paper catalog fig7 swing mp4 eval startup-gnuplot startup-matplotlib fifty})
declare -A label ours theirs peer
label[paper]="7 paper figures, PNG 300 dpi + PDF"; peer[paper]="matplotlib script"
label[catalog]="render --all, PNG 300 dpi + PDF"; peer[catalog]="bench/matplotlib_catalog.py"
label[fig7]="Fig. 7, PNG + PDF, same pixels"; peer[fig7]="gnuplot pngcairo + pdfcairo"
label[swing]="swing GIF, 381 frames 1280x720"; peer[swing]="matplotlib FuncAnimation"
label[mp4]="MP4, 30 s at 1080p, two pendulums"; peer[mp4]="ffmpeg decode + x264 veryfast"
label[eval]="eval of 1e6 amplitudes (theta0, period_exact)"; peer[eval]="numpy/scipy + savetxt"
label[startup-gnuplot]="start-up (--version), 10 runs"; peer[startup-gnuplot]="gnuplot -e exit, 10 runs"
label[startup-matplotlib]="start-up (--version), 10 runs"; peer[startup-matplotlib]="python3 import matplotlib, 10 runs"
label[fifty]="50 one-panel figures in one render, PNG"; peer[fifty]="50 renders of one figure"
ten() { for _ in 1 2 3 4 5 6 7 8 9 10; do "$@"; done; }
run_ours() {
  case $1 in
    paper) "$exe" render $paper -f png,pdf --dpi 300 --force -o "$out/ours" ;;
    catalog) "$exe" render --all -f png,pdf --dpi 300 --force -o "$out/ours" ;;
    fig7) "$exe" render fig7 -f png,pdf --dpi 300 --force -o "$out/ours" ;;
    swing) "$exe" render swing --theme slides -f gif --force -o "$out/ours" ;;
    mp4) rm -f "$out/ours/pendulum.mp4"; "$exe" plot pendulum "${mp4_args[@]}" -o "$out/ours" ;;
    eval) "$exe" eval --theta0 @"$out/amplitudes" --columns theta0,period_exact >"$out/ours/eval.csv" ;;
    startup-*) ten "$exe" --version ;;
    fifty) "$exe" render "$out"/fifty/*.toml -f png --force -o "$out/ours50" ;;
  esac
}
run_theirs() {
  case $1 in
    paper) "$python" "$here/matplotlib_catalog.py" "$out/theirs" --paper ;;
    catalog) "$python" "$here/matplotlib_catalog.py" "$out/theirs" ;;
    fig7) gnuplot -e "dir='$out/gnuplot'" "$here/gnuplot_fig7.gp" ;;
    swing) "$python" "$here/matplotlib_swing.py" "$out/theirs/swing.gif" ;;
    mp4) ffmpeg -nostdin -v error -y -i "$out/mp4/pendulum.mp4" -c:v libx264 -preset veryfast "$out/theirs/pendulum.mp4" ;;
    eval) "$python" "$here/numpy_eval.py" "$out/amplitudes" "$out/theirs/eval.csv" ;;
    startup-gnuplot) ten gnuplot -e exit ;;
    startup-matplotlib) ten "$python" -c 'import matplotlib' ;;
    fifty) for f in "$out"/fifty/*.toml; do "$exe" render "$f" -f png --force -o "$out/ours50" || return 1; done ;;
  esac
}
# The video row's floor: ffmpeg decoding our video and encoding its frames again (x264's
# veryfast preset, ffmpeg's own threads); the video it decodes is made first (not timed).
mp4_args=(--theta0 1,2.5 --methods exact --apart --length 1 --duration 30 --size 1920x1080 -f mp4)
mkdir -p "$out/mp4"
"$exe" plot pendulum "${mp4_args[@]}" -o "$out/mp4" 2>/dev/null
for ((i = 0; i < rounds; i++)); do
  for r in "${rows[@]}"; do
    ours[$r]+="$(seconds run_ours "$r") "
    theirs[$r]+="$(seconds run_theirs "$r") "
  done
done
echo "Medians of $rounds interleaved rounds ($(nproc) CPUs usable):"
printf '%-48s %10s  %-30s %10s  %s\n' "work" "ours (s)" "peer" "peer (s)" "ratio"
for r in "${rows[@]}"; do
  # shellcheck disable=SC2086
  a=$(median ${ours[$r]}); b=$(median ${theirs[$r]})
  printf '%-48s %10s  %-30s %10s  %s\n' "${label[$r]}" "$a" "${peer[$r]}" "$b" \
    "$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.1fx", b / a }')"
done

/usr/bin/time -f '%M' -o "$out/rss" "$exe" render "$out"/fifty/*.toml -f png --force -o "$out/ours50" >/dev/null
printf '%-48s %6d MB (max RSS, %d workers)\n' "50 one-panel figures in one render, PNG" $(( $(cat "$out/rss") / 1024 )) "$(nproc)"

[ "${BENCH_INSTRUCTIONS:-1}" = 0 ] || {
# Instructions, one worker (callgrind counts every thread; one keeps the count steady).
instructions() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 >/dev/null |
    sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
echo
echo "Instructions (callgrind, --jobs 1):"
n=$(instructions "$exe" render $paper -f png,pdf --dpi 300 --force --jobs 1 -o "$out/ours")
printf '%-48s %6.0f M\n' "7 paper figures, PNG 300 dpi + PDF" "$(awk -v n="$n" 'BEGIN { print n / 1e6 }')"
n=$(instructions "$exe" render --all -f png,pdf --dpi 300 --force --jobs 1 -o "$out/ours")
printf '%-48s %6.0f M\n' "render --all, PNG 300 dpi + PDF" "$(awk -v n="$n" 'BEGIN { print n / 1e6 }')"
n=$(instructions "$exe" render fig7 -f png,pdf --dpi 300 --force --jobs 1 -o "$out/ours")
printf '%-48s %6.0f M\n' "Fig. 7, PNG + PDF" "$(awk -v n="$n" 'BEGIN { print n / 1e6 }')"
one=$(instructions "$exe" render swing --theme slides -f gif --force --jobs 1 --frames 1..1 -o "$out/ours")
more=$(instructions "$exe" render swing --theme slides -f gif --force --jobs 1 --frames 1..31 -o "$out/ours")
printf '%-48s %6.1f M\n' "swing GIF 1280x720, per frame" "$(awk -v a="$one" -v b="$more" 'BEGIN { print (b - a) / 30 / 1e6 }')"
}

[ "${BENCH_MEMORY:-1}" = 0 ] && exit 0
# The 30-s 1080p MP4's peak memory.
rm -f "$out/ours/pendulum.mp4"
/usr/bin/time -f '%M' -o "$out/rss" "$exe" plot pendulum "${mp4_args[@]}" -o "$out/ours" >/dev/null 2>&1
printf '%-48s %6d MB\n' "MP4 30 s 1080p, peak memory (max RSS)" $(( $(cat "$out/rss") / 1024 ))

# Peak memory of the GIF at any length: the swing for 1 and 30 periods, at 720p and 4K. A GIF
# longer than its bytes' bound allows (30 periods at 4K) is refused before work, its message
# naming the most frames of its size: that many are measured (--frames 1..N).
echo
echo "Peak memory of the swing GIF (max RSS) and its size:"
for periods in 1 30; do
  sed "s/^periods = .*/periods = $periods/" "$here/../src/figures/specs/swing.toml" >"$out/swing$periods.toml"
done
for size in 1280x720 3840x2160; do
  for periods in 1 30; do
    most=
    gif=("$exe" render "$out/swing$periods.toml" --theme slides --size "$size" -f gif --force -o "$out/ours")
    if ! err=$(/usr/bin/time -f '%M' -o "$out/rss" "${gif[@]}" 2>&1 >/dev/null); then
      # Refused: by the GIF's bound, or first by every animation's (then 2400 frames, under it, get the GIF's).
      most=$(printf '%s\n%s\n' "$err" "$("${gif[@]}" --frames 1..2400 2>&1 >/dev/null)" |
        sed -n 's/.*(at most \([0-9]*\) frames of this size).*/\1/p' | head -n 1)
      [ -n "$most" ] || { printf '%s\n' "$err" >&2; exit 1; }
      /usr/bin/time -f '%M' -o "$out/rss" "${gif[@]}" --frames "1..$most" >/dev/null
    fi
    printf '%-48s %6d MB, file %.1f MB\n' "$size, $periods period(s)${most:+ (frames 1..$most, the most accepted)}" \
      $(( $(cat "$out/rss") / 1024 )) "$(awk -v n="$(stat -c %s "$out/ours/swing$periods.gif")" 'BEGIN { print n / 1e6 }')"
  done
done

[ "${BENCH_WORST:-1}" = 0 ] && exit 0
# The most a render may cost: a spec estimated just under the bound (bench/calibrate_costs.md).
echo
echo "The worst accepted spec (bench/worst_accepted.toml, png + pdf, $(nproc) CPUs usable):"
/usr/bin/time -f '%e %U %S %M' -o "$out/worst" "$exe" render "$here/worst_accepted.toml" -f png,pdf --force \
  -o "$out/ours" >/dev/null
read -r wall user sys kb <"$out/worst"
printf '%-48s %6.0f s (%.0f s of CPU), %d MB\n' "15 trajectory panels, 12 x order:100 close to pi" "$wall" \
  "$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" $((kb / 1024))
