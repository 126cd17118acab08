#!/usr/bin/env bash
# Builds everything, then runs the whole test suite (CTest: Catch2 unit and verification tests, deck
# checks, the model file read back with h5py), then builds and tests the x86-64-v3 variant in build-v3/ and
# compares its results with the default build's (scripts/test-v3.sh; skipped with a note on a CPU without
# AVX2/FMA), then fuzzes each deck reader and the model-file reader for a minute when clang is there (scripts/fuzz.sh) and runs the sample
# decks and the x86-64-v3 kernel check through radx built in that same clang tree with AddressSanitizer and
# UndefinedBehaviorSanitizer (scripts/sanitize-decks.sh: the solver compiled by clang, any sanitizer report
# fails); both skipped with a note without clang.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure --parallel "$(nproc)" --timeout 900
cd ..
bash scripts/test-v3.sh
bash scripts/fuzz.sh 60
bash scripts/sanitize-decks.sh
