#!/usr/bin/env bash
# Builds everything, then runs the whole test suite (CTest: Catch2 unit and verification tests, deck
# checks, the model file read back with h5py), then fuzzes each deck reader for a minute when clang is
# there (scripts/fuzz.sh; skipped with a note without clang).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure --parallel "$(nproc)" --timeout 900
cd ..
bash scripts/fuzz.sh 60
