#!/usr/bin/env bash
# Engine benchmark: a clamped 1 m steel plate of N x N Johnson-Cook shells (default N = 200: 5 mm
# elements, 40,000 shells), 1 mm thick, 5 points through the thickness, every node starting at 1 m/s,
# about 1,500 cycles. Prints the cost in microseconds per element per cycle on 1 and 2 threads, the
# speed-up and the peak memory per element. Targets: <= 0.2 us/element/cycle on one thread,
# >= 1.8x on 2 threads, <= 2 KB per element.
# Usage: bench/engine_plate.sh [N] [ISHELL]   (needs a built tree: scripts/build.sh)
#   ISHELL: the plate's shell formulation, 1 (default, Belytschko-Tsay), 24 (QEPH) or 12 (QBAT), so that the
#   formulations can be compared on the same plate in the same session.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-200}
ishell=${2:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 bench/gen_shell_plate.py --n "$n" --ishell "$ishell" --out "$work" >/dev/null
case "$ishell" in
  24) suffix=_QEPH ;;
  12) suffix=_QBAT ;;
  *) suffix= ;;
esac
echo "plate $n x $n, Ishell $ishell"
root="$work/PLATE$n$suffix"
./build/apps/radx-starter "${root}_0000.rad" --out "$work" >/dev/null
for threads in 1 2; do
  /usr/bin/time -f "peak %M KiB" -o "$work/time.$threads" \
    ./build/apps/radx-engine "${root}_0001.rad" --out "$work" --threads "$threads" > "$work/run.$threads" 2>&1
  cost=$(grep -E "^ +cost" "$work/run.$threads" | awk '{print $2}')
  wall=$(grep -E "^ +wall time" "$work/run.$threads" | sed 's/ *wall time *//')
  cycles=$(grep -E "^ +cycles" "$work/run.$threads" | awk '{print $2}')
  peak=$(sed 's/peak //; s/ KiB//' "$work/time.$threads")
  echo "threads $threads: $cost us/element/cycle, $cycles cycles, wall $wall, peak $peak KiB" \
       "($(( peak * 1024 / (n * n) )) bytes per element)"
  echo "$cost" > "$work/cost.$threads"
done
awk -v a="$(cat "$work/cost.1")" -v b="$(cat "$work/cost.2")" 'BEGIN { printf "speed-up on 2 threads: %.2fx\n", a / b }'
grep -E "error 100|NORMAL|ERROR TERM" "$work/run.1" | head -3
