#!/usr/bin/env bash
# radx beside OpenRadioss on the impact model (bench/gen_shell_plate.py --n 200 --impact --block 20
# --tstop 7e-4: a 200 x 200 Johnson-Cook plate of Belytschko-Tsay shells hit by a 20 x 20 x 4 block of
# one-point bricks through two TYPE7 interfaces, 0.7 ms, the deck's animation and time-history output kept),
# on 1 and 2 threads, on an idle machine and with one core kept busy by `yes > /dev/null` (started before the
# run, killed after it). Prints for each run the engine's wall time, its cycles, the microseconds per
# element-cycle (wall time / (elements x cycles), the same formula for both codes), the peak resident memory
# and the ratio of radx's wall time to OpenRadioss's.
#   radx: radx-starter once, then radx-engine --threads T under /usr/bin/time -v (wall time and peak memory of
#   the engine process); the listing's cost (the time loop alone) is printed beside it.
#   OpenRadioss: /tmp/openradioss-ref/run_case.sh DIR ROOT with OMP_NUM_THREADS=T (its starter, then its
#   engine, whose wall time it writes to DIR/engine.time); cycles from its listing ROOT_0001.out ("TOTAL
#   NUMBER OF CYCLES"); peak memory from /usr/bin/time -v around run_case.sh, the larger of its starter's and
#   engine's, and the engine's own "TOTAL MEMORY USED" line.
# OpenRadioss is built outside the repository (the project ships no recipe that builds it): OPENRADIOSS_ROOT
# names the build (exec/engine_linux64_gf under it), OPENRADIOSS_RUN_CASE the wrapper run_case.sh DIR ROOT that
# runs DIR/ROOT_0000.rad and DIR/ROOT_0001.rad through it and writes the engine's wall time to DIR/engine.time.
# Without them (no engine, no wrapper) only radx runs, and the script says so.
#
# Usage: bench/impact_vs_openradioss.sh [--radx-only] [--threads "1 2"] [--load "idle busy"] [--keep DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
threads_list="1 2"
loads="idle busy"
radx_only=0
keep=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --radx-only) radx_only=1; shift ;;
    --threads) threads_list=$2; shift 2 ;;
    --load) loads=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "impact_vs_openradioss: unknown argument $1" >&2; exit 2 ;;
  esac
done
or_root=${OPENRADIOSS_ROOT:-/tmp/openradioss-ref/OpenRadioss}
run_case=${OPENRADIOSS_RUN_CASE:-/tmp/openradioss-ref/run_case.sh}
if [[ $radx_only == 0 && ( ! -x "$or_root/exec/engine_linux64_gf" || ! -f "$run_case" ) ]]; then
  echo "OpenRadioss is absent ($or_root/exec/engine_linux64_gf or $run_case missing; set OPENRADIOSS_ROOT" \
       "and OPENRADIOSS_RUN_CASE to a build of it and its run_case.sh): radx only"
  radx_only=1
fi
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx-starter radx-engine >/dev/null

work=$(mktemp -d)
busy_pid=""
cleanup() {
  if [[ -n "$busy_pid" ]]; then kill "$busy_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
[[ -n "$keep" ]] && mkdir -p "$keep"

root=PLATE200I
/usr/bin/python3 bench/gen_shell_plate.py --n 200 --impact --block 20 --tstop 7e-4 --out "$work/deck" >/dev/null
elems=$((200 * 200 + 20 * 20 * 4))
./build/apps/radx-starter "$work/deck/${root}_0000.rad" --out "$work/deck" >/dev/null

rss_mb() { awk -F': ' '/Maximum resident set size/ {printf "%d", $2 / 1024}' "$1"; }
wall_s() { awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$1"; }
per_ec() { awk -v w="$1" -v e="$elems" -v c="$2" 'BEGIN {printf "%.3f", 1e6 * w / (e * c)}'; }

start_load() {
  if [[ "$1" == busy ]]; then
    yes > /dev/null &
    busy_pid=$!
  fi
}
stop_load() {
  if [[ -n "$busy_pid" ]]; then
    kill "$busy_pid" 2>/dev/null || true
    wait "$busy_pid" 2>/dev/null || true
    busy_pid=""
  fi
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
rows=()
for load in $loads; do
  for t in $threads_list; do
    # radx
    d="$work/radx_${load}_$t"
    mkdir -p "$d"
    cp "$work/deck/${root}"_000[01].rad "$work/deck/${root}_0000.hdf" "$d/"
    start_load "$load"
    /usr/bin/time -v ./build/apps/radx-engine "$d/${root}_0001.rad" --out "$d" --threads "$t" --no-plot \
      > "$d/run.out" 2> "$d/time.txt" || { stop_load; echo "radx failed ($load, $t thread(s))" >&2; tail -5 "$d/run.out" >&2; exit 1; }
    stop_load
    r_wall=$(wall_s "$d/time.txt")
    r_cyc=$(awk '/^ +cycles/ {print $2}' "$d/run.out")
    r_cost=$(awk '/^ +cost/ {print $2}' "$d/run.out")
    r_rss=$(rss_mb "$d/time.txt")
    echo "radx $load, $t thread(s): ${r_wall} s, $r_cyc cycles, $(per_ec "$r_wall" "$r_cyc") us/element-cycle (loop $r_cost), $r_rss MB" >&2
    [[ -n "$keep" ]] && cp "$d/run.out" "$keep/radx_${load}_$t.out"
    if [[ $radx_only == 1 ]]; then
      rows+=("| $load | $t | $r_wall | $r_cyc | $(per_ec "$r_wall" "$r_cyc") ($r_cost) | $r_rss | - | - | - | - | - |")
      continue
    fi
    # OpenRadioss
    o="$work/or_${load}_$t"
    mkdir -p "$o"
    cp "$work/deck/${root}"_000[01].rad "$o/"
    start_load "$load"
    OMP_NUM_THREADS=$t /usr/bin/time -v bash "$run_case" "$o" "$root" > "$o/run.log" 2> "$o/time.txt" ||
      { stop_load; echo "OpenRadioss failed ($load, $t thread(s)): see $o/engine.log" >&2; tail -5 "$o/engine.log" >&2; exit 1; }
    stop_load
    o_wall=$(tail -1 "$o/engine.time")
    o_cyc=$(awk -F: '/TOTAL NUMBER OF CYCLES/ {gsub(/ /, "", $2); c = $2} END {print c}' "$o/${root}_0001.out")
    o_rss=$(rss_mb "$o/time.txt")
    o_mem=$(awk -F: '/TOTAL MEMORY USED/ {gsub(/[ MB]/, "", $2); print $2}' "$o/${root}_0001.out")
    echo "OpenRadioss $load, $t thread(s): ${o_wall} s, $o_cyc cycles, $o_rss MB" >&2
    [[ -n "$keep" ]] && cp "$o/${root}_0001.out" "$keep/or_${load}_$t.out"
    ratio=$(awk -v a="$r_wall" -v b="$o_wall" 'BEGIN {printf "%.2f", a / b}')
    rows+=("| $load | $t | $r_wall | $r_cyc | $(per_ec "$r_wall" "$r_cyc") ($r_cost) | $r_rss | $o_wall | $o_cyc | $(per_ec "$o_wall" "$o_cyc") | $o_rss ($o_mem) | $ratio |")
  done
done
echo
echo "Model: $elems elements (40,000 shells, 1,600 bricks), Tstop 0.7 ms; load at the end $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| load | threads | radx wall s | radx cycles | radx us/element-cycle (loop) | radx peak RSS MB | OpenRadioss wall s | OpenRadioss cycles | OpenRadioss us/element-cycle | OpenRadioss peak RSS MB (own count) | wall ratio radx/OpenRadioss |"
echo "|------|--------:|------------:|------------:|-----------------------------:|-----------------:|-------------------:|-------------------:|-----------------------------:|------------------------------------:|----------------------------:|"
printf '%s\n' "${rows[@]}"
