#!/usr/bin/env bash
# The default build (build/, x86-64-v2) against the x86-64-v3 build (build-v3/, AVX2 + FMA; docs/build-arch.md)
# on the impact benchmark: the 200 x 200 Johnson-Cook shell plate hit by a 20 x 20 x 4 brick block through two
# TYPE7 interfaces (bench/gen_shell_plate.py --impact --block 20), run to 0.2 ms on one thread. The two engines
# run back to back, alternating, RUNS times each (default 3); prints each run's cost in microseconds per element
# per cycle as the engine's listing reports it, the best of each, and the machine's load before and after.
# Usage: bench/engine_arch.sh [RUNS]   (needs both trees: scripts/build.sh, RADX_ARCH=x86-64-v3 scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 bench/gen_shell_plate.py --n 200 --impact --block 20 --tstop 2e-4 --out "$work" >/dev/null
./build/apps/radx-starter "$work/PLATE200I_0000.rad" --out "$work" >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
declare -A best
for ((r = 1; r <= runs; r++)); do
  for tree in build build-v3; do
    ./$tree/apps/radx-engine "$work/PLATE200I_0001.rad" --out "$work/$tree" --model "$work/PLATE200I_0000.hdf" \
      --threads 1 --no-plot > "$work/run.$tree" 2>&1
    arch=$(head -1 "$work/run.$tree" | sed 's/.*(\(.*\))/\1/')
    cost=$(grep -E "^ +cost" "$work/run.$tree" | awk '{print $2}')
    cycles=$(grep -E "^ +cycles" "$work/run.$tree" | awk '{print $2}')
    echo "run $r $tree ($arch): $cost us/element/cycle, $cycles cycles, load $(cut -d' ' -f1 /proc/loadavg)"
    if [[ -z "${best[$tree]:-}" ]] || awk "BEGIN{exit !($cost < ${best[$tree]})}"; then best[$tree]=$cost; fi
  done
done
echo "best of $runs: build (x86-64-v2) ${best[build]}, build-v3 (x86-64-v3) ${best[build-v3]} us/element/cycle;" \
  "v3/v2 $(awk "BEGIN{printf \"%.3f\", ${best[build-v3]} / ${best[build]}}")"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
