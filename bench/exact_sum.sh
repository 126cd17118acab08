#!/usr/bin/env bash
# Cost of the order-free accumulator (solver/model/exact_sum.hpp, bench/exact_sum.cpp): ns per add against
# a plain double sum, and a check of 2^31 + 7 terms summed exactly.
# Usage: bench/exact_sum.sh [N] [REPS]   (defaults 100000 200; builds only radx_bench_exact_sum)
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx_bench_exact_sum >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
./build/bench/radx_bench_exact_sum "${1:-100000}" "${2:-200}"
