#!/bin/sh
# The committed motion study (issue 33): aliasing in motion beside blur and noise, at 128 px.
#   1. sweep --frames 8 --motion 0.25,0 on the 128-px grating and the zone plate -> results/motion/study/study.csv
#   2. an 8-frame loop of the grating (raytracer -frames, point sampling with box r 0.5 and gaussian r 1.5,
#      and the pixel-area reference) -> results/motion/study/loop.png and loop.csv (analysis motion_loop.py)
#   3. the page -> results/motion/index.html (python3 -m analysis report)
# Run from the repository root after building (build/bin). About 3 minutes of CPU on 2 cores.
set -eu
BIN=${BIN:-build/bin}
OUT=results/motion
CACHE=${CACHE:-results/cache/refs}   # reference cache (git-ignored; per frame)
FRAMES=$(mktemp -d)
trap 'rm -rf "$FRAMES"' EXIT
"$BIN/sweep" --scenes scenes/motion/grating128.txt,scenes/zoneplate.txt --size 128 128 \
  --samplers uniform,jittered --spp 1,4 --filters box,gaussian --radii 0.5,1,1.5,2 --target area \
  --seeds 4 --ref-spp 1024 --frames 8 --motion 0.25,0 --no-images --quiet \
  --out "$OUT/study" --cache "$CACHE"
G="--input scenes/motion/grating128.txt --size 128 128 --frames 8 --motion 0.25,0"
"$BIN/raytracer" $G --sampler uniform --spp 1 --filter box --radius 0.5 --output "$FRAMES/box.exr"
"$BIN/raytracer" $G --sampler uniform --spp 1 --filter gaussian --radius 1.5 --output "$FRAMES/gauss.exr"
"$BIN/raytracer" $G --sampler sobol --spp 1024 --filter box --radius 0.5 --output "$FRAMES/ref.exr"
/usr/bin/python3 -m analysis.aliaslab_analysis.motion_loop --frames "$FRAMES" --reference ref \
  --methods "box=uniform 1 spp box r 0.5,gauss=uniform 1 spp gaussian r 1.5" --out "$OUT/study/loop.png"
/usr/bin/python3 -m analysis report "$OUT" --study "$OUT/study/study.csv"
