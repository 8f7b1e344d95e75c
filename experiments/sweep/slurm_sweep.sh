#!/bin/bash
# Runs a sweep as a Slurm job array: N shards in parallel, then one merge.
#
#   experiments/sweep/slurm_sweep.sh N [sweep options...]
# e.g.
#   SBATCH_EXTRA="--partition=short --time=2:00:00 --mem=4G" \
#     experiments/sweep/slurm_sweep.sh 16 --preset default --out results/study
#
# Submits three jobs: (1) the references, rendered once into the shared
# cache (--refs-only), (2) an array whose task i runs `sweep --shard i/N` into
# OUT/study.shard-i-of-N.csv, after (1) succeeded, and (3) the merge into
# OUT/study.csv (or OUT/study.csv.gz when only that exists), after every array task ended, whatever its state. A task
# that ends well leaves OUT/slurm/shard-i-of-N.done; the merge job refuses
# (exit 1) naming the shards without one (a task failed, was cancelled or
# ran out of time), so a partial shard CSV is never merged. Resubmit those
# shards with TASKS (the sweep resumes each shard's own CSV), e.g.
#   TASKS=3,7 experiments/sweep/slurm_sweep.sh 16 --preset default --out results/study
# A requeued task (scontrol requeue, pre-emption) resumes the same way.
# Jobs run in the submit directory (--chdir), so relative paths (OUT, the
# scenes, the cache) and SWEEP must be visible at the same path on the
# compute nodes: a shared filesystem. Logs: OUT/slurm/{refs-J,shard-i,merge-J}.log
# (shard logs are appended to, so a requeued or resubmitted task keeps both runs).
# Environment: SWEEP (sweep binary, default build/bin/sweep), SBATCH_EXTRA
# (extra sbatch options for all three jobs: partition, account, time, mem,
# ...), CPUS_PER_TASK (cores of the references job, and of each shard when
# the options give no --threads N > 0; default 2), TASKS (array indices to
# submit, sbatch --array syntax, each within 0..N-1; default 0-(N-1)). Without
# --out the preset's own folder is used (shard_args.sh). A missing sbatch or a
# refused submission ends the script non-zero with sbatch's message.
# shellcheck disable=SC2086,SC2016  # SBATCH_EXTRA splits into options; ${SLURM_...} expand in the job
set -euo pipefail
source "$(dirname "$0")/shard_args.sh" "$@"
# --wrap commands run under /bin/sh (dash on Debian): keep them POSIX, quote every path.
[[ -x $SWEEP ]] || { echo "$0: no sweep binary at '$SWEEP' (set SWEEP)" >&2; exit 2; }
SWEEP=$(realpath "$SWEEP")
q() { printf '%q ' "$@"; }  # words, each followed by a space
p() { printf '%q' "$1"; }   # one path, nothing after it
sweepArgs=$(q "${SWEEP_ARGS[@]}")
refArgs=$(q "${REF_ARGS[@]}")
mkdir -p "$OUT/slurm"
cpus=${CPUS_PER_TASK:-2}
# Each task uses the cores Slurm gives it, unless the options say how many.
threads='--threads ${SLURM_CPUS_PER_TASK:-0}'
[[ -n $THREADS_GIVEN ]] && threads=
[[ $THREADS =~ ^[1-9][0-9]*$ ]] && cpus=$THREADS
tasks=${TASKS:-0-$((N - 1))}
# TASKS: indices and ranges (3,7 or 0-3, sbatch --array syntax, an optional %limit), each within 0..N-1.
taskList=${tasks%\%*}
for part in ${taskList//,/ }; do
  if [[ ! $part =~ ^([0-9]{1,6})(-([0-9]{1,6}))?$ ]] || ((10#${BASH_REMATCH[1]} > N - 1)) ||
    { [[ -n ${BASH_REMATCH[3]} ]] && ((10#${BASH_REMATCH[3]} > N - 1 || 10#${BASH_REMATCH[3]} < 10#${BASH_REMATCH[1]})); }; then
    echo "$0: TASKS='$TASKS': '$part' is not a shard index or range within 0..$((N - 1)) (N = $N shards)" >&2
    exit 2
  fi
done
command -v sbatch > /dev/null || { echo "$0: sbatch not found on PATH: submit from a Slurm login node" >&2; exit 1; }
common=(--parsable --chdir="$PWD")
# Submits one job; prints its id (--parsable prints "id" or "id;cluster"). A refused submission ends the script
# with sbatch's own message (a command substitution passed as an argument would escape set -e).
submit() {
  local out rc=0
  out=$(sbatch "$@") || rc=$?
  if ((rc != 0)); then
    echo "$0: sbatch refused the job (exit $rc)${out:+: $out}; nothing more submitted" >&2
    return 1
  fi
  if [[ ! $out =~ ^[0-9]+(;.*)?$ ]]; then
    echo "$0: sbatch printed no job id ('$out'); nothing more submitted" >&2
    return 1
  fi
  echo "${out%%;*}"
}

refs=$(submit "${common[@]}" ${SBATCH_EXTRA:-} --job-name=sweep-refs --cpus-per-task="${CPUS_PER_TASK:-2}" \
  --output="$OUT/slurm/refs-%j.log" --wrap="$(p "$SWEEP") $refArgs--threads \${SLURM_CPUS_PER_TASK:-0} --refs-only")

# Task i: forget an earlier run's mark, run (resuming the shard's CSV), mark the shard done.
shard="$(p "$OUT")/study.shard-\$SLURM_ARRAY_TASK_ID-of-$N.csv"
mark="$(p "$OUT")/slurm/shard-\$SLURM_ARRAY_TASK_ID-of-$N.done"
array=$(submit "${common[@]}" ${SBATCH_EXTRA:-} --job-name=sweep --cpus-per-task="$cpus" \
  --dependency=afterok:"$refs" --kill-on-invalid-dep=yes --array="$tasks" \
  --output="$OUT/slurm/shard-%a.log" --open-mode=append \
  --wrap="rm -f $mark && $(p "$SWEEP") $sweepArgs$threads --shard \$SLURM_ARRAY_TASK_ID/$N --csv $shard && touch $mark")

# The merge: refused, naming the shards, unless every shard has its mark.
check="missing=; for i in $(seq -s ' ' 0 $((N - 1))); do [ -e $(p "$OUT")/slurm/shard-\$i-of-$N.done ] ||"
check+=" missing=\"\$missing \$i\"; done; if [ -n \"\$missing\" ]; then echo \"sweep-merge: shard(s)\$missing of $N"
check+=" did not finish (failed, cancelled or out of time: see $(p "$OUT")/slurm/shard-i.log); resubmit them with"
check+=" TASKS=\$(echo \$missing | tr ' ' ,) and the same options\" >&2; exit 1; fi"
merge=$(submit "${common[@]}" ${SBATCH_EXTRA:-} --job-name=sweep-merge --dependency=afterany:"$array" \
  --output="$OUT/slurm/merge-%j.log" --wrap="$check; $(p "$SWEEP") --merge $(q "$MERGED" "${SHARDS[@]}")")
echo "submitted: references $refs, shards $array ($tasks), merge $merge -> $MERGED"
