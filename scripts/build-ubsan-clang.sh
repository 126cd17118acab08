#!/usr/bin/env bash
# Release-like build with clang++ and UndefinedBehaviorSanitizer in build-ubsan/, then its tests. It adds
# to scripts/build-sanitize.sh (g++, ASan + UBSan) the checks only clang has, float-cast-overflow first:
# a double converted to an integer it does not fit is undefined, and g++ does not check it. Every report
# stops the program (-fno-sanitize-recover), so a finding fails its test.
# Usage: scripts/build-ubsan-clang.sh [ctest options, e.g. -R lexer]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
flags="-fsanitize=undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-ubsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" >/dev/null
cmake --build build-ubsan --parallel "$(nproc)"
cd build-ubsan
UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure --parallel "$(nproc)" --timeout 1800 "$@"
