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
source "$(dirname "$0")/shard_args.sh" "$@"
# shellcheck disable=SC2086
quoted=$(printf '%q ' "${SWEEP_ARGS[@]}")
refQuoted=$(printf '%q ' "${REF_ARGS[@]}")
mkdir -p "$OUT/slurm"
# Each task uses the cores Slurm gives it, unless the options say otherwise.
threads='--threads ${SLURM_CPUS_PER_TASK:-0}'
[[ -n $THREADS_GIVEN ]] && threads=

refs=$(sbatch --parsable ${SBATCH_EXTRA:-} --job-name=sweep-refs --cpus-per-task=2 \
  --output="$OUT/slurm/refs-%j.log" --wrap="$SWEEP $refQuoted --threads \${SLURM_CPUS_PER_TASK:-0} --refs-only")

array=$(sbatch --parsable ${SBATCH_EXTRA:-} --job-name=sweep --cpus-per-task=2 \
  --dependency=afterok:$refs --array=0-$((N - 1)) --output="$OUT/slurm/shard-%a.log" \
  --wrap="$SWEEP $quoted $threads --shard \$SLURM_ARRAY_TASK_ID/$N --csv $OUT/study.shard-\$SLURM_ARRAY_TASK_ID-of-$N.csv")

merge=$(sbatch --parsable ${SBATCH_EXTRA:-} --job-name=sweep-merge --dependency=afterok:$array \
  --output="$OUT/slurm/merge-%j.log" --wrap="$SWEEP --merge $OUT/study.csv ${SHARDS[*]}")
echo "submitted: references $refs, shards $array (0-$((N - 1))), merge $merge -> $OUT/study.csv"
