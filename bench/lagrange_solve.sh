#!/usr/bin/env bash
# Lagrange-multiplier contact benchmark (bench/lagrange_solve.cpp): assemble, factorise and solve the switched
# rows of a synthetic N x N node-on-quadrangle contact on one thread, with the symbolic analysis reused
# (first call, median and min of the later calls, split assembly / factorisation / solve) and without it (the
# pattern changed every call). Target: 10,000 rows (N = 100) in under 20 ms with reuse. Runs N = 100 (50
# calls) and N = 200 (40,000 rows, 20 calls).
# Usage: bench/lagrange_solve.sh   (configures build/ if needed; builds only radx_bench_lagrange)
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx_bench_lagrange >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
./build/bench/radx_bench_lagrange 100 50
echo
./build/bench/radx_bench_lagrange 200 20
