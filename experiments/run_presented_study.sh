#!/usr/bin/env bash
# The full study (docs/science.md, "The bundled studies"): every bundled scene
# at 256 px on the larger side, every sampler and filter, radii 0.5, 1, 1.5, 2,
# spp 4, 16, 64, 8 seeds, references at 4096 spp (64 x the highest spp), three
# targets (area, gaussian:1.5, lanczos:3: one CSV row per configuration and
# target), no per-configuration images: `sweep --preset full`, sharded. Hours
# of work (results/study_speed.md); not committed. The study results/index.html
# presents is the smaller `sweep --preset presented` (5 scenes, radii 0.5, 1,
# 2; results/presented), sharded the same way with
#   experiments/sweep/parallel_sweep.sh N --preset presented --out results/presented --threads 1
#
#   bash experiments/run_full_study.sh [N] [extra sweep options...]
#       GNU parallel on this machine: N shards (default: the number of cores),
#       one thread each (use experiments/sweep/parallel_sweep.sh directly
#       with parallel's --sshlogin to spread shards over several machines).
#   SLURM=1 bash experiments/run_full_study.sh N [extra sweep options...]
#       a Slurm job array of N shards (experiments/sweep/slurm_sweep.sh;
#       SBATCH_EXTRA passes partition, account, time limit ...).
#
# Output: results/study_full/study.csv (shards study.shard-i-of-N.csv beside
# it), reference manifests in results/study_full/references, the reference
# cache in results/cache/refs. Rerunning the same command resumes every shard
# where it stopped; nothing finished is lost. Then, e.g.:
#   /usr/bin/python3 -m analysis report results/study_full --study results/study_full/study.csv --link
# Environment: SWEEP (sweep binary, default build/bin/sweep), JOBS (parallel
# jobs at once, default N).
set -euo pipefail
cd "$(dirname "$0")/.."
N=${1:-$(nproc)}
[[ $# -gt 0 ]] && shift
if [[ ! $N =~ ^[0-9]+$ || $N -lt 1 ]]; then
  echo "usage: $0 [N shards] [extra sweep options...]" >&2
  exit 2
fi
export SWEEP=${SWEEP:-build/bin/sweep}
if [[ ! -x $SWEEP ]]; then
  echo "$0: $SWEEP not found: build first (cmake --build build --target sweep)" >&2
  exit 2
fi
# The shard scripts need the output folder among the options (the preset's results/study_full unless given).
out=(--out results/study_full)
for a in "$@"; do [[ $a == --out || $a == --out=* ]] && out=(); done
start=$(date +%s)
if [[ -n ${SLURM:-} ]]; then
  exec bash experiments/sweep/slurm_sweep.sh "$N" --preset full "${out[@]}" "$@"
fi
# One thread per shard unless the options say otherwise (shards are the parallelism).
threads=(--threads 1)
for a in "$@"; do [[ $a == --threads || $a == --threads=* ]] && threads=(); done
bash experiments/sweep/parallel_sweep.sh "$N" --preset full "${out[@]}" "${threads[@]}" "$@"
echo "full study wall time: $(( $(date +%s) - start )) s"
