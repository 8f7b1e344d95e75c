#!/usr/bin/env bash
# README command (a): install what is missing, build, run the default study
# (the quick one: 48 px, references at 4096 spp, three targets; lib/study/presets.h)
# on every scene in scenes/, then draw its charts and the HTML report.
# A run writes only into its own folder, runs/default/ (git-ignored; set
# ALIASLAB_RUN_DIR for another), never into the committed reference study in
# results/: compare the two with `python3 -m analysis compare`. The reference cache
# results/cache/refs (git-ignored) is shared.
#   bash experiments/run_default_study.sh [extra sweep options]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}
PY=/usr/bin/python3   # Debian's python3 sees python3-numpy/pandas/matplotlib

bash experiments/setup_debian.sh

echo "== build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DALIASLAB_TESTS=OFF >/dev/null
cmake --build build -j "$jobs"

run=${ALIASLAB_RUN_DIR:-runs/default}
echo "== default study into $run/ (resumes if interrupted: rerun the same command)"
# A new run starts a fresh CSV in $run/study; a run that was interrupted
# resumes it. $run/study/.running marks a run in progress.
marker=$run/study/.running
if [ -e "$marker" ]; then
  echo "resuming the interrupted run"
else
  mkdir -p "$run/study"
  rm -f "$run/study/study.csv"
  touch "$marker"
fi
start=$(date +%s)
build/bin/sweep --preset default --out "$run/study" --cache results/cache/refs "$@"
rm -f "$marker"
echo "study wall time: $(( $(date +%s) - start )) s"

echo "== charts and report"
$PY -m analysis charts "$run/study/study.csv" --out "$run/charts"
$PY -m analysis report "$run" --study "$run/study/study.csv"
echo "done: open $run/index.html (the committed reference study: results/index.html)"
