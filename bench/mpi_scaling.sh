#!/usr/bin/env bash
# MPI benchmark on this machine: the impact model without contact (bench/gen_shell_plate.py --impact
# --contact none: the N x N Johnson-Cook plate of shells and the block of B = N/10 bricks a side, 4 deep,
# edge 2000/N mm, all elements running; N = 400: 166,400 elements, N = 800: 665,600) run for a fixed number of
# cycles by
#   1x1  radx-engine --threads 1
#   1x2  radx-engine --threads 2
#   2x1  mpirun -np 2 radx-engine-mpi --threads 1 --comm-stats, in each Open MPI variant asked for:
#          default  --allow-run-as-root --oversubscribe (Open MPI binds each rank to a core when np <= 2)
#          core     ... --bind-to core
#          none     ... --bind-to none
#          yield    ... --mca mpi_yield_when_idle 1
# interleaved (1x1 1x2 2x1... 1x1 1x2 2x1...) for --rounds rounds (at least 3), so a drift of the host's speed
# hits every configuration alike; each one's median wall time is reported, the fastest 2x1 variant is named
# and the speed-ups of 2x1 over 1x1 (target >= 1.6) and over 1x2 (target: within 10 %) are those of its median.
#
# The end time is set so that the run takes --cycles cycles (default 100): a first short run measures the
# engine's step, Tstop = cycles x step (without contact the step hardly moves); the cycles each run made are
# printed. Outputs: animation states at t = 0 and at the end, and 10 time history records (each output cycle
# gathers the group state on every rank, so the usual 100 records of a short run would weigh on the MPI
# share); they are what the identity check compares.
#
# Prints: wall seconds per run and the medians; the listing's cost (us per element-cycle); for the 2x1 runs,
# per rank, the share of the wall time spent inside MPI (exchange and wait, from --comm-stats; target <= 5 %)
# and the peak resident memory (/usr/bin/time -v around each rank); the peak memory of the 1x1 and 1x2 runs;
# the element imbalance of the 2-rank split (heaviest rank's elements / mean, from radx-engine --decompose 2;
# target <= 1.05) and METIS's cost imbalance. Then checks that every 2x1 run gives the 1x1 results to the bit
# (h5diff without tolerance on the time history and the last state), so a fast wrong run cannot pass: exit 1
# when one differs.
#
# Usage: bench/mpi_scaling.sh N [CYCLES] [--rounds 3] [--variants "default core yield"] [--keep DIR]
# (builds radx-starter, radx-engine and radx-engine-mpi in build/ when needed)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=3
variants="default core yield"
keep=""
positional=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rounds) rounds=${2-}; shift $(($# > 1 ? 2 : 1)) ;;
    --variants) variants=${2-}; shift $(($# > 1 ? 2 : 1)) ;;
    --keep) keep=${2-}; shift $(($# > 1 ? 2 : 1)) ;;
    -h|--help) sed -n '2,32p' "$0"; exit 0 ;;
    -*) echo "mpi_scaling: unknown option $1" >&2; exit 2 ;;
    *) positional+=("$1"); shift ;;
  esac
done
if [[ ${#positional[@]} -lt 1 || ${#positional[@]} -gt 2 ]]; then
  echo "usage: bench/mpi_scaling.sh N [CYCLES] [--rounds R] [--variants \"default core none yield\"] [--keep DIR]" >&2
  exit 2
fi
n=${positional[0]}
cycles=${positional[1]:-100}
[[ $n =~ ^[0-9]+$ && $n -ge 20 ]] || { echo "mpi_scaling: N must be a whole number >= 20, not '$n'" >&2; exit 2; }
[[ $cycles =~ ^[1-9][0-9]*$ ]] || { echo "mpi_scaling: CYCLES must be a positive whole number, not '$cycles'" >&2; exit 2; }
[[ $rounds =~ ^[0-9]+$ && $rounds -ge 3 ]] || { echo "mpi_scaling: --rounds must be at least 3, not '$rounds'" >&2; exit 2; }
for v in $variants; do
  case "$v" in default|core|none|yield) ;; *) echo "mpi_scaling: unknown variant '$v' (default, core, none, yield)" >&2; exit 2 ;; esac
done
[[ -n "$variants" ]] || { echo "mpi_scaling: --variants names none" >&2; exit 2; }

[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target radx-starter radx-engine radx-engine-mpi >/dev/null
bin=$(pwd)/build/apps
mpirun=$(command -v mpirun) || { echo "mpi_scaling: mpirun not found (Debian: openmpi-bin)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[[ -n "$keep" ]] && mkdir -p "$keep"

block=$((n / 10))
brick=$(awk -v n="$n" 'BEGIN {print 2000 / n}')
root="PLATE${n}I_NOCONTACT"
model="$work/${root}_0000.hdf"
gen() {  # gen TSTOP DIR: the contact-free model's decks into DIR; 10 time history records, states at 0 and end
  /usr/bin/python3 bench/gen_shell_plate.py --n "$n" --impact --block "$block" --brick-size "$brick" \
    --contact none --th-records 10 --anim-states 1 --tstop "$1" --out "$2" >/dev/null
}
# The probe's end time: about 20 steps of the plate's shells (0.9 x (1000/N mm) / 5.2 km/s).
probe_tstop=$(awk -v n="$n" 'BEGIN {printf "%.4g", 20 * 1.7e-4 / n}')
gen "$probe_tstop" "$work"
"$bin/radx-starter" "$work/${root}_0000.rad" --out "$work" > "$work/starter.out" ||
  { echo "mpi_scaling: the starter failed:" >&2; tail -5 "$work/starter.out" >&2; exit 1; }
elements=$(awk -v n="$n" -v b="$block" 'BEGIN {print n * n + 4 * b * b}')

# The step: a run of about 20 steps. Its last step is cut to end on Tstop, so the step is taken as
# Tstop / (cycles - 1/2), within 1 / (2 (cycles - 1)) of the engine's.
mkdir -p "$work/probe"
"$bin/radx-engine" "$work/${root}_0001.rad" --model "$model" --out "$work/probe" --threads 1 --no-plot \
  > "$work/probe/run.out" 2>&1 || { echo "mpi_scaling: the probe run failed:" >&2; tail -5 "$work/probe/run.out" >&2; exit 1; }
dt=$(/usr/bin/python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); print("%.6g" % (s["time"] / (s["cycles"] - 0.5)))' "$work/probe/${root}_summary.json")
tstop=$(awk -v c="$cycles" -v dt="$dt" 'BEGIN {printf "%.6g", c * dt}')
mkdir -p "$work/deck"
gen "$tstop" "$work/deck"
deck="$work/deck/${root}_0001.rad"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "model: $root, $elements elements ($((n * n)) shells, $((4 * block * block)) bricks), step $dt s, Tstop $tstop s (about $cycles cycles)"

# The element imbalance of the 2-rank split: the same METIS partition radx-engine-mpi uses.
mkdir -p "$work/decompose"
"$bin/radx-engine" --decompose 2 "$deck" --model "$model" --out "$work/decompose" > "$work/decompose/out.txt"
element_imbalance=$(awk '/^rank +groups/ {t = 1; next} t && $1 ~ /^[0-9]+$/ {e[$1] = $3; s += $3; k++; if ($3 > m) m = $3} /^imbalance/ {t = 0}
  END {printf "%.4f", m / (s / k)}' "$work/decompose/out.txt")
cost_imbalance=$(sed -n 's/^imbalance (heaviest rank \/ mean): cost \([0-9.]*\).*/\1/p' "$work/decompose/out.txt")
elements_per_rank=$(awk '/^rank +groups/ {t = 1; next} t && $1 ~ /^[0-9]+$/ {printf "%s%s", (n++ ? "/" : ""), $3} /^imbalance/ {t = 0}' "$work/decompose/out.txt")

wall_of() { awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$1"; }
rss_mb() { awk -F': ' '/Maximum resident set size/ {printf "%.0f\n", $2 / 1024}' "$1"; }
summary_field() { /usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"; }

mpi_flags() {
  case "$1" in
    default) echo "--allow-run-as-root --oversubscribe" ;;
    core) echo "--allow-run-as-root --oversubscribe --bind-to core" ;;
    none) echo "--allow-run-as-root --oversubscribe --bind-to none" ;;
    yield) echo "--allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1" ;;
  esac
}

# run CONFIG ROUND: one run into its own folder; prints its wall seconds (outside: process start to end).
run() {
  local config=$1 dir="$work/$1.$2" t0 t1
  mkdir -p "$dir"
  t0=$(date +%s.%N)
  case "$config" in
    1x1|1x2)
      /usr/bin/time -v -o "$dir/time.0" "$bin/radx-engine" "$deck" --model "$model" --out "$dir" \
        --threads "${config#1x}" --no-plot > "$dir/run.out" 2>&1 ||
        { echo "mpi_scaling: $config failed; its listing's end:" >&2; tail -5 "$dir/run.out" >&2; return 1; }
      ;;
    2x1.*)
      # shellcheck disable=SC2046  # the flags are words
      # shellcheck disable=SC2016  # $0, $OMPI_COMM_WORLD_RANK and $@ are the inner shell's, one per rank
      "$mpirun" $(mpi_flags "${config#2x1.}") -np 2 sh -c 'exec /usr/bin/time -v -o "$0/time.$OMPI_COMM_WORLD_RANK" "$@"' \
        "$dir" "$bin/radx-engine-mpi" "$deck" --model "$model" --out "$dir" --threads 1 --no-plot --comm-stats \
        > "$dir/run.out" 2>&1 ||
        { echo "mpi_scaling: $config failed; its output's end:" >&2; tail -5 "$dir/run.out" >&2; return 1; }
      ;;
  esac
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f", b - a}' > "$dir/wall"
}

configs=(1x1 1x2)
for v in $variants; do configs+=("2x1.$v"); done
declare -A walls costs
echo
echo "| round | configuration | wall s | cycles | us/element-cycle | peak RSS MB per rank | MPI share per rank |"
echo "|------:|---------------|-------:|-------:|-----------------:|---------------------:|-------------------:|"
for ((r = 1; r <= rounds; ++r)); do
  for c in "${configs[@]}"; do
    run "$c" "$r"
    dir="$work/$c.$r"
    w=$(cat "$dir/wall")
    walls[$c]="${walls[$c]-} $w"
    rss=$(for f in "$dir"/time.*; do rss_mb "$f"; done | paste -sd/)
    share=-
    [[ $c == 2x1.* ]] && share=$(sed -n 's/^rank [0-9]*: wall .* (\([0-9.]*\) % of wall)$/\1 %/p' "$dir/run.out" | paste -sd/)
    cost=$(awk -v c="$(summary_field "$dir/${root}_summary.json" us_per_element_cycle)" 'BEGIN {printf "%.4f", c}')
    costs[$c]="${costs[$c]-} $cost"
    echo "| $r | $c | $w | $(summary_field "$dir/${root}_summary.json" cycles) | $cost | $rss | $share |"
  done
done

median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo
echo "medians over $rounds rounds (wall s of the whole run; the listing's us/element-cycle, without start-up):"
declare -A med_wall med_cost
best=""
for c in "${configs[@]}"; do
  # shellcheck disable=SC2086  # the walls and costs are words
  med_wall[$c]=$(median ${walls[$c]}) med_cost[$c]=$(median ${costs[$c]})
  echo "  $c: ${med_wall[$c]} s, ${med_cost[$c]} us/element-cycle"
  if [[ $c == 2x1.* ]] && { [[ -z "$best" ]] || awk -v a="${med_wall[$c]}" -v b="${med_wall[$best]}" 'BEGIN {exit !(a < b)}'; }; then
    best=$c
  fi
done
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.3f", a / b}'; }
echo "fastest 2-rank variant: ${best#2x1.} ($(mpi_flags "${best#2x1.}"))"
echo "speed-up 2x1 over 1x1: $(ratio "${med_wall[1x1]}" "${med_wall[$best]}") (target >= 1.6);" \
  "by the listing's cost $(ratio "${med_cost[1x1]}" "${med_cost[$best]}")"
echo "2x1 over 1x2: $(ratio "${med_wall[1x2]}" "${med_wall[$best]}") (target: 0.9 to 1.1, within 10 %);" \
  "by the listing's cost $(ratio "${med_cost[1x2]}" "${med_cost[$best]}")"
echo "element imbalance of 2 ranks: $element_imbalance (elements $elements_per_rank; target <= 1.05); METIS cost imbalance $cost_imbalance"
last="$work/$best.$rounds"
echo "MPI share per rank, fastest variant's last round (target <= 5 %):"
sed -n 's/^\(rank [0-9]*: wall .*\)$/  \1/p' "$last/run.out"
echo "comm statistics of that run:"
sed -n '/^| rank | collective/,/^$/p' "$last/run.out" | sed 's/^/  /'

# Identity: every 2-rank run against the first 1x1 run, on the time history and the last state.
reference="$work/1x1.1"
last_state=""
for f in "$reference/${root}"_[0-9][0-9][0-9][0-9][0-9][0-9].hdf; do  # the states, in order
  [[ -f "$f" ]] && last_state=$(basename "$f")
done
[[ -n "$last_state" ]] || { echo "mpi_scaling: no animation state in $reference" >&2; exit 1; }
failed=0
checked=0
for c in "${configs[@]}"; do
  [[ $c == 2x1.* ]] || continue
  for ((r = 1; r <= rounds; ++r)); do
    for f in "${root}_th.h5" "$last_state"; do
      checked=$((checked + 1))
      h5diff -q "$reference/$f" "$work/$c.$r/$f" >/dev/null 2>&1 || { echo "DIFFERS: $c round $r: $f" >&2; failed=1; }
    done
  done
done
if [[ -n "$keep" ]]; then
  for d in "$work"/1x* "$work"/2x1.* "$work/decompose"; do
    mkdir -p "$keep/$(basename "$d")"
    cp "$d"/run.out "$d"/time.* "$d"/wall "$d"/out.txt "$keep/$(basename "$d")/" 2>/dev/null || true
  done
fi
if ((failed)); then
  echo "identity: FAILED: a 2-rank run differs from the 1-rank run (see above)"
  exit 1
fi
echo "identity: the 2-rank runs give the 1-rank results to the bit ($checked h5diff comparisons without tolerance: ${root}_th.h5 and $last_state)"
