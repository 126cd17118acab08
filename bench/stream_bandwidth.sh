#!/usr/bin/env bash
# Memory bandwidth of this machine, STREAM-like: copy, scale, add and triad on three double
# arrays of 400 MB each (beyond the 508 MB last-level cache this machine reports) (bench/stream_bandwidth.cpp), best of 10 repetitions, on 1 and 2 threads, in GB/s
# (bytes counted as STREAM counts them; the write-allocate read is in a separate column). The triad figure is
# the bandwidth the traffic limit of the engine cycle uses (bench/cycle_traffic.sh, docs/performance.md).
# Usage: bench/stream_bandwidth.sh [N] [REPS] [MAX_THREADS]   (defaults 50000000 10 2; builds only
# radx_bench_stream, configuring build/ if needed)
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx_bench_stream >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
./build/bench/radx_bench_stream "${1:-50000000}" "${2:-10}" "${3:-2}"
