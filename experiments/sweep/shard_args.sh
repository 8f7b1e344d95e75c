# Sourced by parallel_sweep.sh and slurm_sweep.sh with "N [sweep options...]":
# sets N (shards), SWEEP (the sweep binary: $SWEEP, default build/bin/sweep),
# OUT (the --out folder, default results/study), SWEEP_ARGS (the options),
# THREADS_GIVEN (1 when the options set --threads, else empty), THREADS (the
# value they set, when they do), REF_ARGS (the
# options without --threads, for the reference pass: it uses every core, and
# references do not depend on the thread count) and SHARDS (the shard CSV
# paths OUT/study.shard-i-of-N.csv, i = 0..N-1).
if [[ $# -lt 1 || ! $1 =~ ^[0-9]+$ || $1 -lt 1 ]]; then
  echo "usage: $0 N [sweep options...]" >&2
  exit 2
fi
N=$1
shift
SWEEP=${SWEEP:-build/bin/sweep}
OUT=results/study
THREADS_GIVEN=
THREADS=
SWEEP_ARGS=("$@")
for ((k = 0; k < ${#SWEEP_ARGS[@]}; ++k)); do
  [[ ${SWEEP_ARGS[k]} == --threads ]] && THREADS_GIVEN=1 && THREADS=${SWEEP_ARGS[k + 1]:-}
  [[ ${SWEEP_ARGS[k]} == --threads=* ]] && THREADS_GIVEN=1 && THREADS=${SWEEP_ARGS[k]#--threads=}
  [[ ${SWEEP_ARGS[k]} == --out ]] && OUT=${SWEEP_ARGS[k + 1]}
  [[ ${SWEEP_ARGS[k]} == --out=* ]] && OUT=${SWEEP_ARGS[k]#--out=}
done
REF_ARGS=()
for ((k = 0; k < ${#SWEEP_ARGS[@]}; ++k)); do
  if [[ ${SWEEP_ARGS[k]} == --threads ]]; then ((++k)); continue; fi
  [[ ${SWEEP_ARGS[k]} == --threads=* ]] && continue
  REF_ARGS+=("${SWEEP_ARGS[k]}")
done
SHARDS=()
for ((i = 0; i < N; ++i)); do SHARDS+=("$OUT/study.shard-$i-of-$N.csv"); done
