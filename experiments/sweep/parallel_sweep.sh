#!/bin/bash
# Runs a sweep as N shards under GNU parallel on one machine (or several,
# with parallel's --sshlogin), then merges the shards.
#
#   experiments/sweep/parallel_sweep.sh N [sweep options...]
# e.g.
#   experiments/sweep/parallel_sweep.sh 2 --preset default --threads 1
#
# References are rendered once first (--refs-only, on every core whatever
# --threads says) so shards do not repeat them. Each shard writes OUT/study.shard-i-of-N.csv; the merge writes
# OUT/study.csv (OUT/study.csv.gz when only that exists) in canonical order. Rerunning resumes every shard.
# Environment: SWEEP (sweep binary, default build/bin/sweep), JOBS (parallel
# jobs at once, default N).
set -euo pipefail
source "$(dirname "$0")/shard_args.sh" "$@"

"$SWEEP" "${REF_ARGS[@]}" --refs-only
parallel --will-cite --halt now,fail=1 -j "${JOBS:-$N}" \
  "$SWEEP" "${SWEEP_ARGS[@]}" --quiet --shard {}/"$N" --csv "$OUT"/study.shard-{}-of-"$N".csv ::: $(seq 0 $((N - 1)))
"$SWEEP" --merge "$MERGED" "${SHARDS[@]}"
