#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The swing animation as a GIF (1280 x 720, 30 fps, three periods: 441 frames), timed and
# measured against matplotlib's FuncAnimation and Pillow writer doing the same
# (bench/matplotlib_swing.py), run by run in turn so that a busy machine slows both alike.
# Usage: time_animation.sh EXE [RUNS]
set -euo pipefail
exe=${1:?usage: time_animation.sh EXE [RUNS]}
runs=${2:-3}
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python=${PYTHON:-$(command -v /usr/bin/python3 || command -v python3 || true)}
compare=0
if [ -n "$python" ] && "$python" -c 'import matplotlib, scipy, PIL' 2>/dev/null; then compare=1; fi

# Prints "seconds max_rss_kB" of a command.
measure() {
  /usr/bin/time -f '%e %M' -o "$out/time" "$@" >/dev/null 2>&1
  cat "$out/time"
}
median() { printf '%s\n' "$@" | sort -n | sed -n "$(( ($# + 1) / 2 ))p"; }

ours=(); ours_mem=(); theirs=(); theirs_mem=()
frames=441
for ((i = 0; i < runs; i++)); do
  read -r s m < <(measure "$exe" render swing --theme slides -f gif -o "$out")
  ours+=("$s"); ours_mem+=("$m")
  if [ "$compare" = 1 ]; then
    read -r s m < <(measure "$python" "$here/matplotlib_swing.py" "$out/matplotlib.gif")
    theirs+=("$s"); theirs_mem+=("$m")
  fi
done
t=$(median "${ours[@]}")
echo "pendulum-figures render swing -f gif (1280x720, $frames frames): median $t s," \
     "$(awk -v t="$t" -v n="$frames" 'BEGIN { printf "%.0f", n / t }') frames/s," \
     "$(( $(median "${ours_mem[@]}") / 1024 )) MB peak, $(( $(stat -c %s "$out/swing.gif") / 1024 )) kB"
if [ "$compare" = 1 ]; then
  u=$(median "${theirs[@]}")
  echo "matplotlib FuncAnimation + PillowWriter, the same:  median $u s," \
       "$(awk -v t="$u" -v n="$frames" 'BEGIN { printf "%.1f", n / t }') frames/s," \
       "$(( $(median "${theirs_mem[@]}") / 1024 )) MB peak, $(( $(stat -c %s "$out/matplotlib.gif") / 1024 )) kB"
  echo "ratio: $(awk -v a="$u" -v b="$t" 'BEGIN { printf "%.1f", a / b }') times the frames per second"
else
  echo "(install python3-matplotlib, python3-scipy and python3-pil to compare with matplotlib)"
fi
