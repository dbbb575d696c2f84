#!/bin/bash
# Runs the GoogleTest binary $1 as $2 shards at once (GTEST_TOTAL_SHARDS / GTEST_SHARD_INDEX), each
# into its own log beside the binary (BINARY.shardK.log), then prints a line per shard, the failed
# tests' output where a shard failed, and last one line with the counts:
# "run_shards: P passed, F failed in N shards". Exits non-zero if any shard failed. Two shards on
# two cores: most tests wait on one process (a render, a child dsr) at a time. Tests write only
# into their own temporary folders, so shards do not meet.
set -u
bin=${1:?usage: tests/run_shards.sh TEST_BINARY SHARDS}
shards=${2:-2}
[ "$shards" -ge 1 ] 2>/dev/null || { echo "run_shards: SHARDS '$shards': expected a whole number >= 1" >&2; exit 2; }
# At most 4: each shard holds a GL context whose rasteriser (llvmpipe) starts a thread per core;
# only 2 shards on 2 cores have been measured.
[ "$shards" -gt 4 ] && shards=4
here=$(dirname "$0")
logs=()
pids=()
for ((i = 0; i < shards; i++)); do
    log="$bin.shard$i.log"
    logs+=("$log")
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "$bin" > "$log" 2>&1 &
    pids+=($!)
done
rc=0 passed=0 failed=0
for ((i = 0; i < shards; i++)); do
    src=0
    wait "${pids[$i]}" || src=$?
    [ $src -eq 0 ] || rc=1
    read -r p f < <("$here/count_gtest.sh" "${logs[$i]}" $src)
    passed=$((passed + p)) failed=$((failed + f))
    echo "shard $((i + 1)) of $shards: $p passed, $f failed (log: ${logs[$i]})"
    if [ $src -ne 0 ]; then
        # Each failed test's output, from its RUN line to its FAILED line; a crash's last lines.
        awk '/^\[ RUN      \]/ { buf = $0; keep = 1; next }
             keep { buf = buf "\n" $0 }
             /^\[       OK \]/ { keep = 0 }
             /^\[  FAILED  \] [^0-9]/ && keep { print buf; keep = 0 }
             END { if (keep) print buf }' "${logs[$i]}" | head -n 300
    fi
done
echo "run_shards: $passed passed, $failed failed in $shards shards"
exit $rc
