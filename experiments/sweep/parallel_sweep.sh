#!/bin/bash
# Runs a sweep as N shards under GNU parallel on one machine (or several,
# with parallel's --sshlogin), then merges the shards.
#
#   experiments/sweep/parallel_sweep.sh N [sweep options...]
# e.g.
#   experiments/sweep/parallel_sweep.sh 2 --preset default --threads 1
#
# References are rendered once first (--refs-only) so shards do not repeat
# them. Each shard writes OUT/study.shard-i-of-N.csv; the merge writes
# OUT/study.csv in canonical order. Rerunning resumes every shard.
# Environment: SWEEP (sweep binary, default build/bin/sweep), JOBS (parallel
# jobs at once, default N).
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

"$SWEEP" "$@" --refs-only
parallel --will-cite --halt now,fail=1 -j "${JOBS:-$N}" \
  "$SWEEP" "$@" --quiet --shard {}/"$N" --csv "$OUT"/study.shard-{}-of-"$N".csv ::: $(seq 0 $((N - 1)))
shards=()
for ((i = 0; i < N; ++i)); do shards+=("$OUT/study.shard-$i-of-$N.csv"); done
"$SWEEP" --merge "$OUT/study.csv" "${shards[@]}"
