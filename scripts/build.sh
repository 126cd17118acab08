#!/usr/bin/env bash
# Configures and builds radx (Release, warnings as errors) into build/ with all cores, for the portable
# x86-64-v2 default. RADX_ARCH=x86-64-v3 in the environment builds the AVX2 + FMA variant into build-v3/
# instead (docs/build-arch.md); build/ always stays the default.
# Usage: [RADX_ARCH=x86-64-v3] scripts/build.sh [extra cmake options]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
arch="${RADX_ARCH:-x86-64-v2}"
dir=build
if [ "$arch" != x86-64-v2 ]; then dir="build-${arch#x86-64-}"; fi
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRADX_WERROR=ON -DRADX_ARCH="$arch" "$@" >/dev/null
cmake --build "$dir" --parallel "$(nproc)"
