#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A browser shows our SVG and video as we draw them: headless Chromium draws a few built-in
# figures' SVGs, with text as glyph outlines and as <text> elements, and frames of an
# animation's WebM and MP4 videos seeked to, each onto a canvas of the size of our PNG of
# the same figure or frame; RGB RMS (0..255) against that PNG at most SVG_TOLERANCE (text
# as outlines), TEXT_TOLERANCE (<text>, set by the browser) and VIDEO_TOLERANCE (a frame of
# a lossy video).
# Chromium runs once, for every picture, driven by browser_grab.py: the page draws each into
# a canvas and returns the canvases as data: URLs. Without chromium the test is skipped
# (exit 77), except under CI=true, where it fails.
# Usage: browser_test.sh PENDULUM_FIGURES IMAGE_CHECK [SVG_TOLERANCE [TEXT_TOLERANCE [VIDEO_TOLERANCE]]]
set -euo pipefail
exe=$(realpath "$1")
check=$(realpath "$2")
here=$(cd "$(dirname "$0")" && pwd)
# Measured (RMS over 4 x 4 blocks at 192 dpi): outlines 2.9 to 4.1, <text> 4.7 to 5.6 (text
# set without its anchors: 11 to 14), video frames 1.6 (WebM) and 1.9 (MP4) (the frame
# before or after: 5.2 to 7.7).
svg_tolerance=${3:-6}
text_tolerance=${4:-8}
video_tolerance=${5:-3.5}
# shellcheck source=browser_prelude.sh
source "$here/browser_prelude.sh"

# Still figures at 192 dpi (two CSS pixels to the point and a half), on a white page.
figures="period c1-lowest phase-portrait"
dpi=192
items=""
for mode in path text; do
    mkdir -p "$mode"
    # shellcheck disable=SC2086
    "$exe" render $figures -f svg -o "$mode" --set svg_text=$mode --set opaque_vector_background=true
done
mkdir png
# shellcheck disable=SC2086
"$exe" render $figures -f png --dpi $dpi -o png
# A PNG's width and height, from its header.
size() { od -An -tu1 -j16 -N8 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4, $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'; }
for id in $figures; do
    read -r w h < <(size "png/$id.png")
    [ -n "$w" ] || fail "png/$id.png: no size"
    for mode in path text; do
        items="$items{name: '$mode-$id', kind: 'svg', src: '$mode/$id.svg', w: $w, h: $h},"
    done
done

# An animation's frames: a few of them as videos, and the same frames as PNGs.
mkdir video
"$exe" render swing -f webm,mp4,png --frames 1..4 -o video > /dev/null
fps=$("$exe" show swing | awk -F' *= *' '$1 == "fps" { print $2 }')
[ -n "$fps" ] || fps=30
frame=3
png_frame=$(printf 'video/swing-%04d.png' "$frame")
[ -f "$png_frame" ] || fail "no $png_frame: $(ls video)"
# The middle of the frame's time, counted from the video's first frame.
t=$(awk -v f="$frame" -v r="$fps" 'BEGIN { printf "%.6f", (f - 1 + 0.5) / r }')
status=0
for ext in webm mp4; do
    items="$items{name: 'video-$ext', kind: 'video', src: 'video/swing.$ext', t: $t},"
done

cat > page.html <<HTML
<!DOCTYPE html>
<html><head><meta charset="utf-8"><style>html, body { margin: 0; background: #fff; }</style></head>
<body><pre id="out"></pre>
<script>
const items = [$items];
async function grab(item) {
  const c = document.createElement('canvas');
  const g = c.getContext('2d');
  if (item.kind === 'svg') {
    const img = new Image();
    img.src = item.src;
    await img.decode();
    c.width = item.w;
    c.height = item.h;
    g.fillStyle = '#fff';
    g.fillRect(0, 0, c.width, c.height);
    g.drawImage(img, 0, 0, c.width, c.height);
  } else {
    const v = document.createElement('video');
    v.muted = true;
    v.preload = 'auto';
    await new Promise((ok, bad) => {
      v.onloadeddata = ok;
      v.onerror = () => bad(new Error('cannot play (MediaError ' + (v.error && v.error.code) + ')'));
      v.src = item.src;
    });
    // The frame at t, once it is presented: 'seeked' can come before the decoder has
    // handed the frame over (on a busy machine the previous frame would be drawn).
    const presented = new Promise((ok) => {
      if (!v.requestVideoFrameCallback) { ok(); return; }
      v.requestVideoFrameCallback(() => ok());
      setTimeout(ok, 5000);
    });
    await new Promise((ok) => { v.onseeked = ok; v.currentTime = item.t; });
    await presented;
    c.width = v.videoWidth;
    c.height = v.videoHeight;
    g.drawImage(v, 0, 0);
    v.removeAttribute('src');
    v.load();
  }
  return c.toDataURL('image/png');
}
async function grab_all() {
  const pictures = {};
  for (const item of items) {
    try {
      const late = new Promise((_, bad) => setTimeout(() => bad(new Error('not drawn within 30 s')), 30000));
      pictures[item.name] = await Promise.race([grab(item), late]);
    } catch (e) {
      pictures[item.name] = 'error: ' + e.message;
    }
  }
  return pictures;
}
</script></body></html>
HTML
mkdir shots
python3 "$here/browser_grab.py" "$browser" page.html shots || status=1
compare() {
    local name=$1 reference=$2 block=$3 tolerance=$4 line rms
    [ -f "shots/$name.png" ] || { echo "FAIL: $name: no picture"; status=1; return; }
    rms=$("$check" rms "$reference" "shots/$name.png" "$block") || { echo "FAIL: $name: cannot compare"; status=1; return; }
    echo "$name: RMS $rms (at most $tolerance)"
    if awk -v r="$rms" -v t="$tolerance" 'BEGIN { exit !(r > t) }'; then
        echo "FAIL: $name differs from $reference by RMS $rms (at most $tolerance)"
        status=1
    fi
}
for id in $figures; do
    compare "path-$id" "png/$id.png" 4 "$svg_tolerance"
    compare "text-$id" "png/$id.png" 4 "$text_tolerance"
done
for ext in webm mp4; do
    compare "video-$ext" "$png_frame" 4 "$video_tolerance"
done
exit $status
