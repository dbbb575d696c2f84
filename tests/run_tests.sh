#!/bin/bash
# `make test`'s runs after the build: the suite in SHARDS shards (tests/run_shards.sh), then the
# sanitizer runs (`make test-sanitizers`, the Makefile says what they check), each into a log under
# BUILD, and last one line with every count: the line a terminal shows when `make test` ends.
# --sanitizers-only: the sanitizer runs alone. Exits non-zero if anything failed.
# usage: tests/run_tests.sh [--sanitizers-only] BUILD SHARDS
set -u
only_sanitizers=0
[ "${1:-}" = --sanitizers-only ] && { only_sanitizers=1; shift; }
build=${1:?usage: tests/run_tests.sh [--sanitizers-only] BUILD SHARDS}
shards=${2:-2}
here=$(cd "$(dirname "$0")" && pwd)
rc=0 parts=() passed=0 failed=0

add() {  # add NAME PASSED FAILED
    passed=$((passed + $2)) failed=$((failed + $3))
    parts+=("$1 $2/$(($2 + $3))")
}

if [ $only_sanitizers -eq 0 ]; then
    shard_out=$("$here/run_shards.sh" "$build/dsr_tests" "$shards") || rc=1
    echo "$shard_out"
    read -r p f < <(echo "$shard_out" | sed -n 's/^run_shards: \([0-9]*\) passed, \([0-9]*\) failed.*/\1 \2/p' | tail -1)
    add "suite" "${p:-0}" "${f:-1}"
fi

# The loaders under AddressSanitizer + UBSan.
log=$build/asan/dsr_obj_tests.log
src=0
ASAN_OPTIONS=detect_leaks=1:fast_unwind_on_malloc=0 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions=$here/lsan.supp "$build/asan/dsr_obj_tests" --gtest_brief=1 > "$log" 2>&1 || src=$?
read -r p f < <("$here/count_gtest.sh" "$log" $src)
echo "ASan + UBSan loader tests: $p passed, $f failed (log: $log)"
[ $src -eq 0 ] || { rc=1; tail -n 60 "$log"; }
add "ASan+UBSan" "$p" "$f"

# One full render of a mesh scene under LeakSanitizer: one test, passed when it exits 0.
log=$build/asan/dsr_lsan.log
mkdir -p "$build/asan/out"
src=0
LSAN_OPTIONS=suppressions=$here/lsan.supp:print_suppressions=1 \
  "$build/asan/dsr_lsan" render data/mesh.scene --size 128x128 -o "$build/asan/out/mesh.png" > "$log" 2>&1 || src=$?
if [ $src -eq 0 ]; then
    echo "LeakSanitizer mesh render: no leak (log: $log)"
    add "leak check" 1 0
else
    rc=1
    tail -n 60 "$log"
    echo "LeakSanitizer mesh render: FAILED, exit status $src (log: $log)"
    add "leak check" 0 1
fi

what="make test"
[ $only_sanitizers -eq 1 ] && what="make test-sanitizers"
echo "$what: $passed passed, $failed failed ($(IFS=';'; echo "${parts[*]}" | sed 's/;/, /g') passed)"
exit $rc
