#!/usr/bin/env bash
# Two radx-engine builds compared on one deck, run at the same time, one per core (taskset), swapping the
# cores after each pair. This host's speed drifts by 10 % or more between runs made one after the other (the
# same engine gave an element loop of 0.279 to 0.312 us per element-cycle in three runs within ten minutes),
# which hides a few-percent change; two engines running side by side see the same host, so their ratio holds.
# They share the memory bandwidth, as a 2-thread run's threads do, and each runs on 1 thread. The same engine
# against itself differs by -4 to +3 % in a pair (medians of 4 pairs 1.004 apart): a change below 2 % needs
# more pairs.
#
# For each pair: the listing's cost (us per element-cycle) and element loop of each engine; at the end the
# medians and the ratio B / A of the medians (below 1: B is faster).
#
# Usage: bench/ab_engines.sh [--pairs 4] ENGINE_A ENGINE_B ENGINE_DECK
#   ENGINE_DECK: a NAME_0001.rad whose starter output (NAME_0000.hdf) is beside it, e.g. from
#   bench/gen_shell_plate.py and radx-starter. Each engine runs in a directory of its own under a temporary one.
set -euo pipefail
pairs=4
while [[ $# -gt 0 ]]; do
  case "$1" in
    --pairs) pairs=${2-}; shift $(($# > 1 ? 2 : 1)) ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    -*) echo "ab_engines: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
[[ $pairs =~ ^[1-9][0-9]*$ ]] || { echo "ab_engines: --pairs takes a positive whole number, not '$pairs'" >&2; exit 2; }
if [[ $# -ne 3 ]]; then
  echo "usage: bench/ab_engines.sh [--pairs N] ENGINE_A ENGINE_B ENGINE_DECK" >&2
  exit 2
fi
engine_a=$(realpath "$1")
engine_b=$(realpath "$2")
deck=$(realpath "$3")
root=$(basename "$deck" _0001.rad)
model="$(dirname "$deck")/${root}_0000.hdf"
for f in "$engine_a" "$engine_b"; do [[ -x "$f" ]] || { echo "ab_engines: $f is not an executable" >&2; exit 2; }; done
[[ -f "$deck" && "$deck" == *_0001.rad ]] || { echo "ab_engines: $deck is not an engine deck NAME_0001.rad" >&2; exit 2; }
[[ -f "$model" ]] || { echo "ab_engines: $model (the starter's output for $deck) is missing: run radx-starter first" >&2; exit 2; }
taskset -c 0,1 true 2>/dev/null || { echo "ab_engines: needs cores 0 and 1 (taskset -c 0,1)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for side in a b; do
  mkdir -p "$work/$side"
  cp "$deck" "$model" "$work/$side/"
done

# run SIDE ENGINE CORE: one engine run in SIDE's directory, pinned to CORE.
run() {
  (cd "$work/$1" && taskset -c "$3" "$2" "${root}_0001.rad" --out . --threads 1 --no-plot > run.out 2>&1) ||
    { echo "ab_engines: $2 failed; the end of its listing:" >&2; tail -5 "$work/$1/run.out" >&2; exit 1; }
}
cost() { awk '/^ +cost/ {print $2}' "$work/$1/run.out"; }
loop() { sed -n 's/^ *element loop *\([0-9.e+-]*\) us.*/\1/p' "$work/$1/run.out"; }

echo "A: $engine_a"
echo "B: $engine_b"
echo "deck: $deck; load $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| pair | core of A | A us/element-cycle | A element loop | B us/element-cycle | B element loop |"
echo "|-----:|----------:|-------------------:|---------------:|-------------------:|---------------:|"
a_costs=() b_costs=() a_loops=() b_loops=()
for ((p = 1; p <= pairs; ++p)); do
  core_a=$(((p + 1) % 2))
  run a "$engine_a" "$core_a" &
  pid_a=$!
  run b "$engine_b" "$((1 - core_a))" &
  pid_b=$!
  failed=0  # both are waited for, so that neither outlives the script's clean-up
  wait "$pid_a" || failed=1
  wait "$pid_b" || failed=1
  ((failed == 0)) || exit 1
  for side in a b; do
    [[ -n "$(cost $side)" && -n "$(loop $side)" ]] ||
      { echo "ab_engines: no cost or element loop line in engine $side's listing; its end:" >&2; tail -5 "$work/$side/run.out" >&2; exit 1; }
  done
  a_costs+=("$(cost a)") b_costs+=("$(cost b)") a_loops+=("$(loop a)") b_loops+=("$(loop b)")
  echo "| $p | $core_a | $(cost a) | $(loop a) | $(cost b) | $(loop b) |"
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
ma=$(median "${a_costs[@]}") mb=$(median "${b_costs[@]}")
la=$(median "${a_loops[@]}") lb=$(median "${b_loops[@]}")
echo
echo "medians: A $ma us ($la element loop), B $mb us ($lb element loop);" \
  "B / A $(awk -v a="$ma" -v b="$mb" 'BEGIN {printf "%.3f", b / a}') (element loop" \
  "$(awk -v a="$la" -v b="$lb" 'BEGIN {printf "%.3f", b / a}'))"
