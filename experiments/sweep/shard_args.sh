# Sourced by parallel_sweep.sh and slurm_sweep.sh with "N [sweep options...]":
# sets N (shards, a decimal number: 08 is 8), SWEEP (the sweep binary: $SWEEP,
# default build/bin/sweep), OUT (the --out folder; without one, the preset's
# own folder: --preset default results/study, --preset presented
# results/presented, else results/study; with --config, --out must be given on
# the command line), SWEEP_ARGS (the options),
# THREADS_GIVEN (1 when the options set --threads, else empty), THREADS (the
# value they set, when they do), REF_ARGS (the
# options without --threads, for the reference pass: it uses every core, and
# references do not depend on the thread count) and SHARDS (the shard CSV
# paths OUT/study.shard-i-of-N.csv, i = 0..N-1), MERGED (what the merge writes: OUT/study.csv, or
# OUT/study.csv.gz when only that exists, as the sweep's own default: a study kept gzipped stays so).
if [[ $# -lt 1 || ! $1 =~ ^[0-9]{1,6}$ ]] || ((10#$1 < 1)); then
  echo "usage: $0 N [sweep options...] (N: the number of shards, 1 or more)" >&2
  exit 2
fi
N=$((10#$1))  # decimal: a leading zero is not octal
shift
SWEEP=${SWEEP:-build/bin/sweep}
OUT=
PRESET=
CONFIG=
THREADS_GIVEN=
THREADS=
SWEEP_ARGS=("$@")
for ((k = 0; k < ${#SWEEP_ARGS[@]}; ++k)); do
  [[ ${SWEEP_ARGS[k]} == --threads ]] && THREADS_GIVEN=1 && THREADS=${SWEEP_ARGS[k + 1]:-}
  [[ ${SWEEP_ARGS[k]} == --threads=* ]] && THREADS_GIVEN=1 && THREADS=${SWEEP_ARGS[k]#--threads=}
  [[ ${SWEEP_ARGS[k]} == --out ]] && OUT=${SWEEP_ARGS[k + 1]:-}
  [[ ${SWEEP_ARGS[k]} == --out=* ]] && OUT=${SWEEP_ARGS[k]#--out=}
  [[ ${SWEEP_ARGS[k]} == --preset ]] && PRESET=${SWEEP_ARGS[k + 1]:-}
  [[ ${SWEEP_ARGS[k]} == --preset=* ]] && PRESET=${SWEEP_ARGS[k]#--preset=}
  [[ ${SWEEP_ARGS[k]} == --config || ${SWEEP_ARGS[k]} == --config=* ]] && CONFIG=1
done
if [[ -z $OUT && -n $CONFIG ]]; then
  echo "$0: with --config, give --out on the command line too (the shards, their marks and the merge are found" \
    "there; a folder set in the file is not seen here)" >&2
  exit 2
fi
if [[ -z $OUT ]]; then  # the sweep's own default: the preset's folder (lib/study/presets.cpp)
  case $PRESET in
    presented) OUT=results/presented ;;
    *) OUT=results/study ;;
  esac
fi
REF_ARGS=()
for ((k = 0; k < ${#SWEEP_ARGS[@]}; ++k)); do
  if [[ ${SWEEP_ARGS[k]} == --threads ]]; then ((++k)); continue; fi
  [[ ${SWEEP_ARGS[k]} == --threads=* ]] && continue
  REF_ARGS+=("${SWEEP_ARGS[k]}")
done
SHARDS=()
for ((i = 0; i < N; ++i)); do SHARDS+=("$OUT/study.shard-$i-of-$N.csv"); done
MERGED=$OUT/study.csv
if [[ ! -e $MERGED && -e $MERGED.gz ]]; then MERGED=$MERGED.gz; fi
