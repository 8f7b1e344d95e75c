#!/usr/bin/env bash
# README command (b): install what is missing, build everything and run the
# whole test suite. Exits non-zero on the first failure.
#   bash tests/run_all.sh      # release build + tests, then the whole suite
#                              # again under AddressSanitizer + UBSan
#   ALIASLAB_SANITIZE_TESTS=0 bash tests/run_all.sh   # release only (quicker)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}

bash experiments/setup_debian.sh

echo "== release build and tests"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DALIASLAB_TESTS=ON >/dev/null
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 900

if [ "${ALIASLAB_SANITIZE_TESTS:-1}" != 0 ]; then
  echo "== AddressSanitizer + UBSan build and tests"
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DALIASLAB_TESTS=ON -DALIASLAB_SANITIZE=ON >/dev/null
  cmake --build build-asan -j "$jobs"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j "$jobs" --timeout 1800
fi
