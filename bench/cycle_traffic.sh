#!/usr/bin/env bash
# Bytes moved per element-cycle on the impact model (bench/cycle_traffic.cpp): writes the model
# (bench/gen_shell_plate.py --n N --impact --block N/10, the impact benchmark at N = 200), runs the starter, and
# prints every array each pass of a cycle reads or writes with its bytes, the total per element-cycle and the
# traffic limit (bytes / bandwidth). The bandwidth is --bandwidth GB/s, or else the 1-thread triad of
# bench/stream_bandwidth.cpp measured here; --us gives a measured cost (us per element-cycle, from an engine
# listing) to compare with the limit.
# Usage: bench/cycle_traffic.sh [N] [--bandwidth GB/s] [--us US]   (builds what it needs in build/)
set -euo pipefail
cd "$(dirname "$0")/.."
n=200
extra=()
bandwidth=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --bandwidth) bandwidth=$2; shift 2 ;;
    --us) extra+=(--us "$2"); shift 2 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) n=$1; shift ;;
  esac
done
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx-starter radx_bench_traffic radx_bench_stream >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ -z "$bandwidth" ]]; then
  bandwidth=$(./build/bench/radx_bench_stream 50000000 6 1 | awk -F'|' '$3 ~ /triad/ {gsub(/ /, "", $4); print $4}')
  echo "triad bandwidth on 1 thread, measured now: $bandwidth GB/s (load $(cut -d' ' -f1-3 /proc/loadavg))"
fi
/usr/bin/python3 bench/gen_shell_plate.py --n "$n" --impact --block $((n / 10)) --brick-size "$(awk -v n="$n" 'BEGIN {print 2000 / n}')" \
  --tstop 1e-5 --out "$work" >/dev/null
./build/apps/radx-starter "$work/PLATE${n}I_0000.rad" --out "$work" >/dev/null
./build/bench/radx_bench_traffic "$work/PLATE${n}I_0001.rad" "$work/PLATE${n}I_0000.hdf" --bandwidth "$bandwidth" "${extra[@]}"
