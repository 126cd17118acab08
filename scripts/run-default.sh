#!/usr/bin/env bash
# Builds everything, then runs the main job (starter then engine) on the embedded default deck (block on
# plate) in out/default.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out/default
./build/apps/radx run --out out/default
