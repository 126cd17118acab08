#!/usr/bin/env bash
# Starter benchmark: one million 4-node shells (1000 x 1000 plate), with and without a brick block and
# two TYPE7 interfaces. Prints the starter's wall time and peak memory (target: under 5 s and 2 GB).
# Usage: bench/starter_1m.sh [N]   (N x N shells, default 1000). Needs a built tree (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-1000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 bench/gen_shell_plate.py --n "$n" --out "$work/plain" >/dev/null
python3 bench/gen_shell_plate.py --n "$n" --out "$work/impact" --impact >/dev/null
for deck in "$work"/plain/*_0000.rad "$work"/impact/*_0000.rad; do
  echo "== $(basename "$deck")"
  /usr/bin/time -f "wall %e s, peak memory %M KiB" ./build/apps/radx-starter "$deck" --out "$(dirname "$deck")" \
    2>&1 | grep -E "nodes|interface|error|wall"
done
