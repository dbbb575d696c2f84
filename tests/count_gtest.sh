#!/bin/bash
# Prints "PASSED FAILED" for one GoogleTest log ($1) of a run that exited with status $2: the
# counts its summary gives, or, where the run ended before its summary (a crash, a sanitizer
# abort), the tests it saw pass and fail plus one failure for the run itself.
set -u
log=${1:?usage: tests/count_gtest.sh LOG EXIT_STATUS}
rc=${2:-0}
if grep -q '^\[==========\] .* ran' "$log"; then
    passed=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) tests\{0,1\}\..*/\1/p' "$log" | tail -1)
    failed=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) tests\{0,1\}, listed below.*/\1/p' "$log" | tail -1)
    passed=${passed:-0} failed=${failed:-0}
    # A run that reports every test passed but exits non-zero (a leak report at exit) failed.
    [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ] && failed=1
else
    passed=$(grep -c '^\[       OK \]' "$log")
    failed=$(( $(grep -c '^\[  FAILED  \] [^0-9]' "$log") + 1 ))
fi
echo "$passed $failed"
