#!/usr/bin/env bash
# Configures and builds radx (Release, warnings as errors) into build/ with all cores, for the portable
# x86-64-v2 default. RADX_ARCH=x86-64-v3 in the environment builds the AVX2 + FMA variant into build-v3/
# instead (docs/build-arch.md); build/ always stays the default.
# RADX_TARGETS="radx radx-starter ..." builds only those targets and what they need (the README's first
# command builds the executables alone) and installs only the packages that needs; the configuration is the
# same either way, so a later full build compiles only what is left.
# Usage: [RADX_ARCH=x86-64-v3] [RADX_TARGETS="T..."] scripts/build.sh [extra cmake options]
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
read -r -a targets <<< "${RADX_TARGETS:-}"
if ((${#targets[@]})); then bash scripts/deps.sh run; else bash scripts/deps.sh; fi
arch="${RADX_ARCH:-x86-64-v2}"
dir=build
if [ "$arch" != x86-64-v2 ]; then dir="build-${arch#x86-64-}"; fi
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRADX_WERROR=ON -DRADX_ARCH="$arch" "$@" >/dev/null
if ((${#targets[@]})); then
  cmake --build "$dir" --parallel "$(nproc)" --target "${targets[@]}"
else
  cmake --build "$dir" --parallel "$(nproc)"
fi
