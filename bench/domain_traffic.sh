#!/usr/bin/env bash
# Bytes per cycle of the domain exchange on the impact model (bench/domain_traffic.cpp): writes the model
# (bench/gen_shell_plate.py --n N --impact --block N/10, as bench/cycle_traffic.sh), runs the starter, and
# prints, for P ranks and three splits of the element groups (blocks, round robin, METIS), the shared nodes,
# the busiest rank's ghosts and its bytes per cycle for the shared-node sums and the ghost update.
# Usage: bench/domain_traffic.sh [N] [P ...]   (N = 200 by default; builds what it needs in build/)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-200}
shift || true
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx-starter radx_bench_domain >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 bench/gen_shell_plate.py --n "$n" --impact --block $((n / 10)) --brick-size "$(awk -v n="$n" 'BEGIN {print 2000 / n}')" \
  --tstop 1e-5 --out "$work" >/dev/null
./build/apps/radx-starter "$work/PLATE${n}I_0000.rad" --out "$work" >/dev/null
./build/bench/radx_bench_domain "$work/PLATE${n}I_0000.hdf" "$@"
