#!/usr/bin/env bash
# Contact benchmark: the engine benchmark plate (N x N Johnson-Cook shells, default N = 200) at rest,
# hit at 10 m/s by an aluminium block of 10 x 10 x 4 bricks through two TYPE7 interfaces (block nodes on the
# plate, plate nodes on the block; bench/gen_shell_plate.py --impact). Prints, on 1 and 2 threads, the cost in
# microseconds per element per cycle and the share of the wall time spent in contact (search and forces), as
# the engine's listing reports them. Targets: contact <= 15 % of the cycle; the whole run <= 0.2125 us per
# element per cycle (half of the mature Fortran code's 0.425 on this machine).
# ISOLID 24 runs the block in HEPH bricks (Isolid 24) instead of Isolid 1.
# Usage: bench/engine_impact.sh [N] [ISOLID]   (needs a built tree: scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-200}
isolid=${2:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 bench/gen_shell_plate.py --n "$n" --impact --isolid "$isolid" --out "$work" >/dev/null
root="$work/PLATE${n}I"
[[ "$isolid" == 24 ]] && root="${root}_HEPH"
./build/apps/radx-starter "${root}_0000.rad" --out "$work" >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
for threads in 1 2; do
  ./build/apps/radx-engine "${root}_0001.rad" --out "$work" --threads "$threads" --no-plot > "$work/run.$threads" 2>&1
  cost=$(grep -E "^ +cost" "$work/run.$threads" | awk '{print $2}')
  contact=$(grep -E "^ +contact \(search and forces\)" "$work/run.$threads" | sed 's/ *contact (search and forces) *//')
  cycles=$(grep -E "^ +cycles" "$work/run.$threads" | awk '{print $2}')
  err=$(grep -E "error 100" "$work/run.$threads" | awk '{print $(NF-1), $NF}')
  echo "threads $threads: $cost us/element/cycle, $cycles cycles, contact $contact, energy error $err"
done
grep -E "^  interface" "$work/run.1"
