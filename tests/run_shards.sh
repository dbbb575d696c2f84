#!/bin/bash
# Runs the GoogleTest binary $1 as $2 shards at once (GTEST_TOTAL_SHARDS / GTEST_SHARD_INDEX), each
# into its own log beside the binary, then prints every shard's log in order and exits non-zero if
# any shard failed. On 2 cores two shards took the suite from 7.2 to 4.1 minutes: most tests wait
# on one process (a render, a child dsr) at a time. Tests write only into their own temporary
# folders, so shards do not meet.
set -u
bin=${1:?usage: tests/run_shards.sh TEST_BINARY SHARDS}
shards=${2:-2}
[ "$shards" -ge 1 ] 2>/dev/null || { echo "run_shards: SHARDS '$shards': expected a whole number >= 1" >&2; exit 2; }
# At most 4: each shard holds a GL context whose rasteriser (llvmpipe) starts a thread per core;
# only 2 shards on 2 cores have been measured.
[ "$shards" -gt 4 ] && shards=4
logs=()
pids=()
for ((i = 0; i < shards; i++)); do
    log="$bin.shard$i.log"
    logs+=("$log")
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "$bin" > "$log" 2>&1 &
    pids+=($!)
done
rc=0
for ((i = 0; i < shards; i++)); do
    wait "${pids[$i]}" || rc=1
done
for ((i = 0; i < shards; i++)); do
    echo "==== shard $((i + 1)) of $shards ($(basename "$bin"))"
    cat "${logs[$i]}"
done
[ $rc -eq 0 ] && echo "run_shards: all $shards shards passed" || echo "run_shards: a shard failed (its log is above)"
exit $rc
