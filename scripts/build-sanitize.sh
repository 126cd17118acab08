#!/usr/bin/env bash
# Debug build with AddressSanitizer and UndefinedBehaviorSanitizer in build-asan/, then its tests.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DRADX_SANITIZE=ON -DRADX_WERROR=ON >/dev/null
cmake --build build-asan --parallel "$(nproc)"
cd build-asan && ctest --output-on-failure --parallel "$(nproc)"
