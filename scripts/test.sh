#!/usr/bin/env bash
# Builds everything, then runs the whole test suite (CTest: Catch2 unit and verification tests, deck
# checks, the model file read back with h5py).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure --parallel "$(nproc)" --timeout 900
