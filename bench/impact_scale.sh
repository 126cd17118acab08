#!/usr/bin/env bash
# Scale series of the impact benchmark: the N x N Johnson-Cook plate of Belytschko-Tsay shells
# (5 points) hit at 10 m/s by a block of one-point bricks through two TYPE7 interfaces
# (bench/gen_shell_plate.py --impact), at N = 200, 400, 800 and 1600 (about 40 k, 160 k, 640 k and 2.6 M
# elements). The block keeps its share of the elements and its footprint: B = N/10 bricks a side, 4 deep,
# edge 2000/N mm (10, 5, 2.5, 1.25 mm), a 200 x 200 mm block: 4 % bricks beside the shells (N = 200 is the
# impact model of the other benchmarks). Each run lasts 0.6 x --cycles (default 150) of the plate's shell
# steps: about --cycles cycles, as contact, once it acts, halves the step (the table gives the cycles run).
# The block starts 20 cycles of travel (at 10 m/s) above the larger computed gap (interface 1: min(t, h/2);
# interface 2: a tenth of the brick edge), measured from the plate's mid-surface (the generator's --gap), so
# contact acts from about cycle 20 at every size. Animation output is taken out of the engine deck (the run
# measures the cycle, not the HDF5 writer); the time history stays.
#
# For each size: the starter's wall time and peak memory; for each thread count: the engine's wall and CPU
# seconds (user + system: the figure that holds when other jobs share the cores), microseconds per
# element-cycle and contact share (both from its listing), its peak resident memory (/usr/bin/time -v) per
# element, the bytes moved per element-cycle (bench/cycle_traffic.cpp, from the engine's arrays) and the ratio
# of the measured cost to the traffic limit (bytes / triad bandwidth of bench/stream_bandwidth.cpp on as many
# threads, measured at the start), for the whole cycle and for the element loop alone (the listing's element
# loop row: the passes the byte count covers, without contact and the time history). A size whose memory
# would not fit (estimated from the previous size's bytes per element, against MemAvailable) is skipped with
# a note.
#
# The interfaces' search margin factor is Bumult 0.2 at every size (--bumult; 0 takes Radioss's default by
# model size, which doubles it to 0.4 above 2.5 M nodes, that is at N = 1600: three times the candidate pairs
# per element on interface 2, whose enlarged boxes then reach a whole plate element further).
#
# Usage: bench/impact_scale.sh [--sizes "200 400 800 1600"] [--threads "1 2"] [--cycles 150] [--bumult 0.2]
#                              [--keep DIR]
# (builds radx-starter, radx-engine and the two bench programs in build/, configuring it if needed)
set -euo pipefail
cd "$(dirname "$0")/.."
sizes="200 400 800 1600"
bumult=0.2
threads_list="1 2"
cycles=150
keep=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sizes) sizes=$2; shift 2 ;;
    --threads) threads_list=$2; shift 2 ;;
    --cycles) cycles=$2; shift 2 ;;
    --bumult) bumult=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
    *) echo "impact_scale: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx-starter radx-engine radx_bench_stream radx_bench_traffic >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[[ -n "$keep" ]] && mkdir -p "$keep"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
# Triad bandwidth per thread count (GB/s), the denominator of the traffic limit.
./build/bench/radx_bench_stream 50000000 6 2 > "$work/stream.txt"
declare -A triad
for t in $threads_list; do
  triad[$t]=$(awk -F'|' -v t="$t" '$2+0 == t && $3 ~ /triad/ {gsub(/ /, "", $4); print $4}' "$work/stream.txt")
  [[ -n "${triad[$t]}" ]] || triad[$t]=$(awk -F'|' '$2+0 == 2 && $3 ~ /triad/ {gsub(/ /, "", $4); print $4}' "$work/stream.txt")
  echo "triad bandwidth on $t thread(s): ${triad[$t]} GB/s"
done

# rss_kb FILE: the Maximum resident set size of a /usr/bin/time -v report; wall_s FILE: its elapsed seconds;
# cpu_s FILE: its user + system seconds (what to compare when other jobs share the cores).
rss_kb() { awk -F': ' '/Maximum resident set size/ {print $2}' "$1"; }
cpu_s() { awk -F': ' '/User time|System time/ {s += $2} END {printf "%.1f", s}' "$1"; }
wall_s() { awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$1"; }

rows=()
starter_rows=()
notes=()
prev_bytes_per_elem=""
for n in $sizes; do
  block=$((n / 10))
  read -r brick gap tstop < <(/usr/bin/python3 - "$n" "$cycles" <<'EOF'
import math, sys
n, cycles = int(sys.argv[1]), int(sys.argv[2])
h = 1000.0 / n                       # plate element size, mm
c = math.sqrt(210000.0 / 7.85e-9)    # steel bar speed, mm/s
dt = 0.9 * h / c                     # the plate's shell step
gap1 = min(1.0, h / 2)               # interface 1's computed gap (Igap 0): min(t, lmin/2)
gap2 = (2000.0 / n) / 10             # interface 2's: a tenth of the block's brick edge
d = max(gap1, gap2) + 20 * dt * 1e4  # block bottom above the mid-surface: 20 cycles at 10 m/s to the gap
# contact halves the step once it acts (its stiffness vote): 0.6 x cycles shell steps run about `cycles`
print("%.6g %.6g %.4g" % (2000.0 / n, d - 0.5, 0.6 * cycles * dt))
EOF
)
  elems=$((n * n + block * block * 4))
  avail_kb=$(awk '/MemAvailable/ {print $2}' /proc/meminfo)
  if [[ -n "$prev_bytes_per_elem" ]]; then
    need_kb=$(awk -v b="$prev_bytes_per_elem" -v e="$elems" 'BEGIN {printf "%d", 1.5 * b * e / 1024}')
    if (( need_kb > avail_kb * 8 / 10 )); then
      notes+=("N = $n ($elems elements) skipped: about $((need_kb / 1024)) MB needed (1.5 x the previous size's peak per element), $((avail_kb / 1024)) MB available")
      continue
    fi
  fi
  dir="$work/n$n"
  mkdir -p "$dir"
  t0=$(date +%s.%N)
  /usr/bin/python3 bench/gen_shell_plate.py --n "$n" --impact --block "$block" --brick-size "$brick" --gap "$gap" \
    --tstop "$tstop" --bumult "$bumult" --out "$dir" >/dev/null
  gen_s=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}')
  root="$dir/PLATE${n}I"
  # No animation states: the run measures the cycle.
  awk '/^\/ANIM/ {skip = 1; next} /^\// {skip = 0} !skip' "${root}_0001.rad" > "$dir/e.rad" && mv "$dir/e.rad" "${root}_0001.rad"
  /usr/bin/time -v ./build/apps/radx-starter "${root}_0000.rad" --out "$dir" > "$dir/starter.out" 2> "$dir/starter.time"
  s_wall=$(wall_s "$dir/starter.time")
  s_rss=$(rss_kb "$dir/starter.time")
  deck_mb=$(du -m "${root}_0000.rad" | cut -f1)
  starter_rows+=("| $n | $elems | $deck_mb | $gen_s | $s_wall | $((s_rss / 1024)) | $(awk -v r="$s_rss" -v e="$elems" 'BEGIN {printf "%.0f", r * 1024 / e}') |")
  traffic=$(./build/bench/radx_bench_traffic "${root}_0001.rad" "${root}_0000.hdf")
  echo "$traffic" > "$dir/traffic.txt"
  bytes=$(echo "$traffic" | awk '/^bytes per element-cycle:/ {print $4}')
  for t in $threads_list; do
    /usr/bin/time -v ./build/apps/radx-engine "${root}_0001.rad" --out "$dir" --threads "$t" --no-plot \
      > "$dir/run.$t" 2> "$dir/time.$t" || { echo "N = $n, $t thread(s): the engine failed (see $dir)" >&2; tail -5 "$dir/run.$t" >&2; exit 1; }
    cost=$(awk '/^ +cost/ {print $2}' "$dir/run.$t")
    ncyc=$(awk '/^ +cycles/ {print $2}' "$dir/run.$t")
    wall=$(wall_s "$dir/time.$t")
    cpu=$(cpu_s "$dir/time.$t")
    contact=$(sed -n 's/^ *contact (search and forces) *\([0-9.]*\) %.*/\1/p' "$dir/run.$t")
    rss=$(rss_kb "$dir/time.$t")
    per_elem=$(awk -v r="$rss" -v e="$elems" 'BEGIN {printf "%.0f", r * 1024 / e}')
    prev_bytes_per_elem=$per_elem
    limit=$(awk -v b="$bytes" -v bw="${triad[$t]}" 'BEGIN {printf "%.4f", b / (bw * 1e3)}')
    ratio=$(awk -v c="$cost" -v l="$limit" 'BEGIN {printf "%.2f", c / l}')
    # The element loop alone (element forces, their sums, assembly, integration): the passes the byte count
    # covers, so its ratio compares like with like (the whole cycle adds contact and the time history).
    loop=$(sed -n 's/^ *element loop *\([0-9.e+-]*\) us.*/\1/p' "$dir/run.$t")
    loop_ratio=-
    [[ -n "$loop" ]] && loop_ratio=$(awk -v c="$loop" -v l="$limit" 'BEGIN {printf "%.2f", c / l}')
    pairs=$(awk '/^  interface [0-9]+: active pairs/ {sub(",", "", $5); p = p (p == "" ? "" : "/") $5} END {print p}' "$dir/run.$t")
    # Candidate pairs per element: the interfaces' mean candidate pairs per cycle (listing), summed.
    cands=$(awk -v e="$elems" '/^  interface [0-9]+: active pairs/ {for (i = 1; i < NF; ++i) if ($i == "cycle") s += $(i + 1)} END {printf "%.3f", s / e}' "$dir/run.$t")
    rows+=("| $n | $elems | $t | $ncyc | $wall | $cpu | $cost | ${contact:-0} % | ${pairs:--} | $cands | $((rss / 1024)) | $per_elem | $bytes | $limit | $ratio | ${loop:--} | $loop_ratio |")
    echo "N = $n, $t thread(s): $cost us/element-cycle, $ncyc cycles, contact ${contact:-0} %, peak $((rss / 1024)) MB" >&2
  done
  grep -E "^  interface" "$dir/run.1" | sed "s/^/  N = $n: /" >&2 || true
  if [[ -n "$keep" ]]; then
    for f in "$dir"/starter.out "$dir"/starter.time "$dir"/traffic.txt "$dir"/run.* "$dir"/time.*; do
      cp "$f" "$keep/n$n.$(basename "$f")"
    done
  fi
  rm -rf "$dir"
done

echo
echo "Engine (load at the end $(cut -d' ' -f1-3 /proc/loadavg)):"
echo
echo "| N | elements | threads | cycles | wall s | CPU s | us/element-cycle | contact share | active pairs at the end (if 1/2) | candidate pairs per element | peak RSS MB | peak bytes/element | bytes moved/element-cycle | traffic limit us | ratio to limit | element loop us/element-cycle | element loop ratio to limit |"
echo "|--:|---------:|--------:|-------:|-------:|------:|-----------------:|--------------:|-----:|-----:|------------:|-------------------:|--------------------------:|-----------------:|---------------:|------:|------:|"
printf '%s\n' "${rows[@]}"
echo
echo "Starter:"
echo
echo "| N | elements | deck MB | deck generation s | starter wall s | starter peak RSS MB | starter peak bytes/element |"
echo "|--:|---------:|--------:|------------------:|---------------:|--------------------:|---------------------------:|"
printf '%s\n' "${starter_rows[@]}"
for note in "${notes[@]+"${notes[@]}"}"; do echo "note: $note"; done
