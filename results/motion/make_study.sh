#!/bin/sh
# The committed motion study (issues 33 and 47): shimmer measured in the content's frame beside blur and noise,
# at 128 px, the one motion driver `sweep --frames F --motion dx,dy`.
#   1. sweep --frames 8 --motion 0.25,0 on gratings below (0.375) and above (0.9 cycles/pixel) Nyquist and the
#      zone plate: box, tent, gaussian and lanczos over their radii, grid (uniform), jittered and sobol at 1, 4
#      and 16 spp -> results/motion/study/study.csv
#   2. an 8-frame loop of the grating (raytracer -frames, point sampling with box r 0.5 and gaussian r 1.5,
#      and the pixel-area reference), each frame's error by imgdiff -> results/motion/study/loop.png and loop.csv
#      (analysis motion_loop.py)
#   3. x-t slices: one row over 32 frames registered to the content (raytracer -frames -register), for rows
#      chosen from the CSV (analysis xt_slice.py) -> results/motion/study/xt/ (xt-SCENE.png, xt.csv)
#   4. the page -> results/motion/index.html (python3 -m analysis report) and results/motion.md
# Run from the repository root after building (build/bin). About 9 minutes of CPU on 2 cores.
set -eu
BIN=${BIN:-build/bin}
OUT=results/motion
CACHE=${CACHE:-results/cache/refs}   # reference cache (git-ignored; per frame)
FRAMES=$(mktemp -d)
trap 'rm -rf "$FRAMES"' EXIT
"$BIN/sweep" --scenes scenes/motion/grating128.txt,scenes/motion/grating_above128.txt,scenes/zoneplate.txt \
  --size 128 128 --samplers uniform,jittered,sobol --spp 1,4,16 --filters box,tent,gaussian,lanczos \
  --radii 0.5,1,1.5,2 --target area --seeds 4 --ref-spp 1024 --frames 8 --motion 0.25,0 --no-images --quiet \
  --out "$OUT/study" --cache "$CACHE"
G="--input scenes/motion/grating128.txt --size 128 128 --frames 8 --motion 0.25,0"
"$BIN/raytracer" $G --sampler uniform --spp 1 --filter box --radius 0.5 --output "$FRAMES/box.exr"
"$BIN/raytracer" $G --sampler uniform --spp 1 --filter gaussian --radius 1.5 --output "$FRAMES/gauss.exr"
"$BIN/raytracer" $G --sampler sobol --spp 1024 --filter box --radius 0.5 --output "$FRAMES/ref.exr"
# each frame's error by the library (imgdiff's mse against the reference's frame), not recomputed in Python
echo "name,frame,mse" > "$FRAMES/errors.csv"
for name in box gauss; do
  for t in 0 1 2 3 4 5 6 7; do
    f=$(printf "%04d" "$t")
    mse=$("$BIN/imgdiff" "$FRAMES/${name}_$f.exr" "$FRAMES/ref_$f.exr" | awk '$1 == "mse" { print $2 }')
    echo "$name,$t,$mse" >> "$FRAMES/errors.csv"
  done
done
/usr/bin/python3 -m analysis.aliaslab_analysis.charts.motion_loop --frames "$FRAMES" --reference ref \
  --errors "$FRAMES/errors.csv" \
  --methods "box=uniform 1 spp box r 0.5,gauss=uniform 1 spp gaussian r 1.5" --out "$OUT/study/loop.png"
/usr/bin/python3 -m analysis.aliaslab_analysis.viewer.xt_slice --study "$OUT/study/study.csv" --bin "$BIN" --frames 32 \
  --out "$OUT/study/xt"
/usr/bin/python3 -m analysis report "$OUT" --study "$OUT/study/study.csv"
/usr/bin/python3 "$OUT/make_motion_md.py"
