#!/usr/bin/env bash
# Brick benchmark: a clamped steel block of N x N x N/2 one-point bricks (default N = 40: 32,000 bricks,
# Johnson-Cook) sheared at 10 m/s, about 1000 cycles (bench/gen_brick_block.py), once with Isolid 1 (viscous
# hourglass, Jaumann rate) and once with Isolid 24 (HEPH: physical hourglass, co-rotational frame), each on 1
# and 2 threads in the same session. Prints the engine's cost in microseconds per element per cycle, the
# machine and its load.
# Usage: bench/engine_bricks.sh [N]   (needs a built tree: scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-40}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
for isolid in 1 24; do
  root=$(/usr/bin/python3 bench/gen_brick_block.py --n "$n" --isolid "$isolid" --out "$work")
  ./build/apps/radx-starter "$work/${root}_0000.rad" --out "$work" >/dev/null
  for threads in 1 2; do
    ./build/apps/radx-engine "$work/${root}_0001.rad" --out "$work" --threads "$threads" --no-plot \
      > "$work/run.$isolid.$threads" 2>&1
    cost=$(grep -E "^ +cost" "$work/run.$isolid.$threads" | awk '{print $2}')
    cycles=$(grep -E "^ +cycles" "$work/run.$isolid.$threads" | awk '{print $2}')
    err=$(grep -E "error 100" "$work/run.$isolid.$threads" | awk '{print $(NF-1), $NF}')
    echo "Isolid $isolid, threads $threads: $cost us/element/cycle, $cycles cycles, energy error $err"
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
