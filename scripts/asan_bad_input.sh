#!/usr/bin/env bash
# Periodic job (weekly and before a release; too slow for every CI run): the
# bad-input corpus, the failed-write, fuzzing and sanity-warning tests under
# AddressSanitizer + UndefinedBehaviorSanitizer (preset asan, build/asan).
# A full asan build takes about 45 min on 2 cores; the tests about 2 min.
#   bash scripts/asan_bad_input.sh          # configure, build, run
# Exit status: non-zero when a test fails or a sanitizer reports.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${JOBS:-2}"
cmake --preset asan > /dev/null
cmake --build --preset asan -j "$jobs"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
tags='[bad_input],[write],[fuzz],[sanity]'
status=0
# Every test executable of the build (one per test folder, tests/CMakeLists.txt).
for bin in $(find build/asan/tests -type f -name 'test_*' -perm -u+x | sort); do
  t="${bin#build/asan/tests/}"
  # Suites without a test of these tags are skipped (Catch2 exits 2 on "no tests matched").
  if [ -z "$("$bin" --list-test-names-only "$tags" | grep -v '^$' || true)" ]; then continue; fi
  echo "== $t $tags"
  "$bin" "$tags" || status=1
done
exit $status
