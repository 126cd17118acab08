#!/usr/bin/env bash
# Builds the three executables (radx, radx-starter, radx-engine and the libraries they link; not the test
# suite, which scripts/test.sh builds), then runs the main job (starter then engine) on the embedded default
# deck (decks/block_impact) in out/default.
set -euo pipefail
cd "$(dirname "$0")/.."
RADX_TARGETS="radx radx-starter radx-engine" bash scripts/build.sh
mkdir -p out/default
./build/apps/radx run --out out/default
