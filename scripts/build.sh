#!/usr/bin/env bash
# Configures and builds radx (Release, warnings as errors) into build/ with all cores.
# Usage: scripts/build.sh [extra cmake options]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DRADX_WERROR=ON "$@" >/dev/null
cmake --build build --parallel "$(nproc)"
