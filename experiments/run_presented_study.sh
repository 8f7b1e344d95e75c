#!/usr/bin/env bash
# The presented study (docs/science.md, "The bundled studies"): every bundled
# scene at 256 px on the larger side, every sampler and filter at radii 0.5,
# 1, 2 and each filter's natural radius, spp 4, 16, 64, 8 seeds, references at
# 4096 spp (64 x the highest spp), the fixed grid over 8 camera offsets, three
# targets (area, gaussian:1.5, lanczos:3: one CSV row per configuration and
# target), no per-configuration images: `sweep --preset presented`, sharded.
# About 43 minutes on 2 otherwise idle cores from an empty cache: 14 of
# references, 29 of rows (measured with their phases in
# results/study_speed.md).
#
#   bash experiments/run_presented_study.sh [N] [extra sweep options...]
#       GNU parallel on this machine: N shards (default: the number of cores),
#       one thread each (use experiments/sweep/parallel_sweep.sh directly
#       with parallel's --sshlogin to spread shards over several machines).
#   SLURM=1 bash experiments/run_presented_study.sh N [extra sweep options...]
#       a Slurm job array of N shards (experiments/sweep/slurm_sweep.sh;
#       SBATCH_EXTRA passes partition, account, time limit ...).
#
# Output: results/presented/study.csv.gz, the committed study, gzipped (or
# study.csv when no .gz is there; shards study.shard-i-of-N.csv beside
# it), reference manifests in results/presented/references, the reference
# cache in results/cache/refs. Rerunning the same command resumes every shard
# where it stopped; nothing finished is lost. Then, e.g.:
#   /usr/bin/python3 -m analysis report results --study results/presented/study.csv.gz
# Environment: SWEEP (sweep binary, default build/bin/sweep), JOBS (parallel
# jobs at once, default N).
set -euo pipefail
cd "$(dirname "$0")/.."
N=${1:-$(nproc)}
[[ $# -gt 0 ]] && shift
if [[ ! $N =~ ^[0-9]{1,6}$ ]] || ((10#$N < 1)); then
  echo "usage: $0 [N shards] [extra sweep options...]" >&2
  exit 2
fi
N=$((10#$N))  # decimal: a leading zero is not octal
export SWEEP=${SWEEP:-build/bin/sweep}
if [[ ! -x $SWEEP ]]; then
  echo "$0: $SWEEP not found: build first (cmake --build build --target sweep)" >&2
  exit 2
fi
# The shard scripts need the output folder among the options (the preset's results/presented unless given).
out=(--out results/presented)
for a in "$@"; do [[ $a == --out || $a == --out=* ]] && out=(); done
start=$(date +%s)
if [[ -n ${SLURM:-} ]]; then
  exec bash experiments/sweep/slurm_sweep.sh "$N" --preset presented "${out[@]}" "$@"
fi
# One thread per shard unless the options say otherwise (shards are the parallelism).
threads=(--threads 1)
for a in "$@"; do [[ $a == --threads || $a == --threads=* ]] && threads=(); done
bash experiments/sweep/parallel_sweep.sh "$N" --preset presented "${out[@]}" "${threads[@]}" "$@"
echo "presented study wall time: $(( $(date +%s) - start )) s"
