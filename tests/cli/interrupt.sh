#!/bin/sh
# SIGTERM to a single run of collapse2d: it stops at its next step with status
# 143 and a message, and keeps its outputs under "interrupted" names (no .part
# left, nothing under the names of a completed run).
# usage: interrupt.sh COLLAPSE2D DECK (tests/cli/endless.inp)
exe=$1
deck=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$exe" -q -o "$dir" "$deck" 2>"$dir/err" &
pid=$!
i=0
while [ ! -e "$dir/endless_0001.vtu" ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
kill -TERM $pid
wait $pid
st=$?
fail() { echo "interrupt.sh: $*"; cat "$dir/err"; ls "$dir"; exit 1; }
[ $st -eq 143 ] || fail "exit status $st, not 143"
grep -q "interrupted by SIGTERM at step" "$dir/err" || fail "no message"
grep -q "computed results kept: " "$dir/err" || fail "no list of the kept files"
[ -e "$dir/endless.interrupted.out" ] || fail "no endless.interrupted.out"
[ -e "$dir/endless_tplot.interrupted.csv" ] || fail "no endless_tplot.interrupted.csv"
[ -e "$dir/endless.interrupted.pvd" ] || fail "no endless.interrupted.pvd"
[ ! -e "$dir/endless.out" ] || fail "endless.out looks complete"
[ ! -e "$dir/endless.pvd" ] || fail "endless.pvd looks complete"
ls "$dir" | grep -q '\.part$' && fail ".part files left"
exit 0
