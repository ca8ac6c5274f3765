#!/usr/bin/env bash
# The animation at the top of the README, cut from the demo's video (run `bash scripts/demo.sh`
# first): 12 s from the stand-up into the walk, 640x360 at 15 fps, an animated WebP under 3 MB (a
# GIF of the same clip is over 13 MB: the follow camera moves the checkered floor every frame).
#   scripts/make_readme_animation.sh [VIDEO] [OUT.webp]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
video=${1:-$root/build/demo/demo.mp4}
out=${2:-$root/docs/images/demo.webp}
start_s=${ANIMATION_START_S:-3}
length_s=${ANIMATION_LENGTH_S:-12}
[[ -s "$video" ]] || { echo "no video at $video: run bash scripts/demo.sh first" >&2; exit 1; }
ffmpeg -loglevel error -y -ss "$start_s" -t "$length_s" -i "$video" \
  -vf "fps=15,scale=640:-2:flags=lanczos" -c:v libwebp_anim -lossless 0 -q:v 60 -loop 0 "$out"
bytes=$(stat -c %s "$out")
echo "animation: $out, $((bytes / 1024)) KiB"
if (( bytes >= 3 * 1024 * 1024 )); then
  echo "animation: over 3 MB; shorten it with ANIMATION_LENGTH_S" >&2
  exit 1
fi
