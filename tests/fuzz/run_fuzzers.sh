#!/usr/bin/env bash
# Runs one libFuzzer target with its seed corpus and dictionary.
#   bash tests/fuzz/run_fuzzers.sh TARGET LIMIT [extra libFuzzer flags]
#     TARGET  fuzz_scene | fuzz_obj | fuzz_cli | all (one after the other)
#     LIMIT   600s / 15m / 1h: a time budget;  10000000: a number of runs
# Build first:
#   cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ \
#         -DALIASLAB_FUZZ=ON -DALIASLAB_TESTS=OFF && cmake --build build-fuzz -j2 \
#         --target fuzz_scene fuzz_obj fuzz_cli
# FUZZ_BUILD (default build-fuzz) selects the build. The growing corpus lives
# in FUZZ_BUILD/corpus/TARGET, crash/timeout/oom inputs in
# FUZZ_BUILD/artifacts/TARGET/; a finding is turned into a regression by
# copying it to tests/fuzz/regressions/TARGET/ (tests/programs/fuzz_regression_test.cpp).
# The fuzzers run in a scratch folder and never write outputs of their own.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${FUZZ_BUILD:-$root/build-fuzz}" && pwd)"
[ $# -ge 2 ] || { sed -n '2,6p' "$0"; exit 2; }
target=$1 limit=$2
shift 2

if [ "$target" = all ]; then
  for t in fuzz_scene fuzz_obj fuzz_cli; do bash "$0" "$t" "$limit" "$@"; done
  exit 0
fi

# Limit: time or runs
case "$limit" in
  *s) budget=(-max_total_time="${limit%s}") ;;
  *m) budget=(-max_total_time=$(( ${limit%m} * 60 ))) ;;
  *h) budget=(-max_total_time=$(( ${limit%h} * 3600 ))) ;;
  *[!0-9]*|'') echo "LIMIT must be 600s, 15m, 1h or a run count" >&2; exit 2 ;;
  *) budget=(-runs="$limit") ;;
esac

# Seeds and per-target settings
corpus="$build/corpus/$target"
artifacts="$build/artifacts/$target"
mkdir -p "$corpus" "$artifacts"
case "$target" in
  fuzz_scene) seeds=("$root"/scenes/*.txt "$here"/regressions/fuzz_scene/*); dict=scene.dict; maxlen=2200 ;;
  fuzz_obj)   seeds=("$root"/scenes/meshes/*.obj "$here"/seeds/obj/* "$here"/regressions/fuzz_obj/*); dict=obj.dict; maxlen=4096 ;;
  fuzz_cli)   seeds=("$here"/seeds/cli/* "$here"/regressions/fuzz_cli/*); dict=cli.dict; maxlen=512 ;;
  *) echo "unknown target '$target' (fuzz_scene, fuzz_obj, fuzz_cli, all)" >&2; exit 2 ;;
esac
for s in "${seeds[@]}"; do
  [ -f "$s" ] && cp -n "$s" "$corpus/seed_$(basename "$s")"
done

# Sanitizer settings: no malloc stack traces (they cost ~10% of the time),
# a report on the first error; override by exporting ASAN_OPTIONS/UBSAN_OPTIONS.
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=0:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

# Run in a scratch folder (relative paths in fuzzed input point nowhere useful)
scratch=$(mktemp -d /dev/shm/aliaslab_fuzz.XXXXXX)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
echo "== $target ${budget[*]} max_len=$maxlen corpus=$corpus"
"$build/bin/$target" "$corpus" -dict="$here/dict/$dict" -max_len="$maxlen" \
  -artifact_prefix="$artifacts/" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  "${budget[@]}" "$@"
