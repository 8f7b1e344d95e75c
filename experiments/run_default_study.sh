#!/usr/bin/env bash
# README command (a): install what is missing, build, run the default study
# on every scene in scenes/, then draw its charts and the HTML report.
# Everything lands in results/ (results/study/ for the sweep itself).
#   bash experiments/run_default_study.sh [extra sweep options]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}
PY=/usr/bin/python3   # Debian's python3 sees python3-numpy/pandas/matplotlib

bash experiments/setup_debian.sh

echo "== build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DALIASLAB_TESTS=OFF >/dev/null
cmake --build build -j "$jobs"

echo "== default study (resumes if interrupted: rerun the same command)"
# A new run replaces the committed study's CSV; a run that was interrupted
# resumes it. results/study/.running marks a run in progress.
marker=results/study/.running
if [ -e "$marker" ]; then
  echo "resuming the interrupted run"
else
  mkdir -p results/study
  rm -f results/study/study.csv
  touch "$marker"
fi
start=$(date +%s)
build/bin/sweep --preset default --out results/study "$@"
rm -f "$marker"
echo "study wall time: $(( $(date +%s) - start )) s"

echo "== charts and report"
$PY analysis/charts.py results/study/study.csv --out results/charts
$PY analysis/report.py results --study results/study/study.csv
echo "done: open results/index.html"
