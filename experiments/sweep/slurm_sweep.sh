#!/bin/bash
# Runs a sweep as a Slurm job array: N shards in parallel, then one merge.
#
#   experiments/sweep/slurm_sweep.sh N [sweep options...]
# e.g.
#   experiments/sweep/slurm_sweep.sh 16 --preset default --out results/study
#
# Submits three jobs: (1) the references, rendered once into the shared
# cache (--refs-only), (2) an array --array=0-(N-1) whose task i runs
# `sweep --shard i/N` into OUT/study.shard-i-of-N.csv, after (1), and (3) the
# merge into OUT/study.csv, after every array task succeeded. A failed or
# pre-empted task can be resubmitted as is: the sweep resumes its own CSV.
# Environment: SWEEP (path of the sweep binary, default build/bin/sweep),
# SBATCH_EXTRA (extra sbatch options: partition, account, time, ...).
set -euo pipefail
if [[ $# -lt 1 || ! $1 =~ ^[0-9]+$ || $1 -lt 1 ]]; then
  echo "usage: $0 N [sweep options...]" >&2
  exit 2
fi
N=$1
shift
SWEEP=${SWEEP:-build/bin/sweep}
OUT=results/study
args=("$@")
for ((k = 0; k < ${#args[@]}; ++k)); do
  [[ ${args[k]} == --out ]] && OUT=${args[k + 1]}
  [[ ${args[k]} == --out=* ]] && OUT=${args[k]#--out=}
done
# shellcheck disable=SC2086
quoted=$(printf '%q ' "$@")
mkdir -p "$OUT/slurm"

refs=$(sbatch --parsable ${SBATCH_EXTRA:-} --job-name=sweep-refs --cpus-per-task=2 \
  --output="$OUT/slurm/refs-%j.log" --wrap="$SWEEP $quoted --refs-only")

array=$(sbatch --parsable ${SBATCH_EXTRA:-} --job-name=sweep --cpus-per-task=2 \
  --dependency=afterok:$refs --array=0-$((N - 1)) --output="$OUT/slurm/shard-%a.log" \
  --wrap="$SWEEP $quoted --threads \${SLURM_CPUS_PER_TASK:-0} --shard \$SLURM_ARRAY_TASK_ID/$N --csv $OUT/study.shard-\$SLURM_ARRAY_TASK_ID-of-$N.csv")

shards=""
for ((i = 0; i < N; ++i)); do shards+=" $OUT/study.shard-$i-of-$N.csv"; done
merge=$(sbatch --parsable ${SBATCH_EXTRA:-} --job-name=sweep-merge --dependency=afterok:$array \
  --output="$OUT/slurm/merge-%j.log" --wrap="$SWEEP --merge $OUT/study.csv$shards")
echo "submitted: references $refs, shards $array (0-$((N - 1))), merge $merge -> $OUT/study.csv"
