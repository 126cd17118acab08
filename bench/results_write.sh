#!/usr/bin/env bash
# Results-writing benchmark. The requirement: "Writing a state must not dominate a run: at most 10 % of the
# wall time of the engine benchmark at 20 states, and a state of one million nodes in under 1 s."
#
# 1. The engine benchmark of bench/engine_plate.sh (N x N clamped Johnson-Cook shell plate, N = 200, about
#    1,500 cycles) with /ANIM/DT = Tstop / 20: 21 states (cycle 0, then one every Tstop / 20), run on 1 and
#    2 threads. Reported: the listing's RESULTS "writing time X s (Y % of the wall time)" (the states written
#    inside the engine's timed loop plus the time-history rows, over the engine's wall time; the mesh file
#    before the loop and a state written after it are in neither), and the same deck with the first and last
#    state only (/ANIM/DT 1e20; dT 0 is an input error) to show the difference in wall time directly.
#    Target: Y <= 10 %.
# 2. One state of a million nodes: the 1000 x 1000 plate (1,002,001 nodes, 1,000,000 shells) run 12 cycles
#    with /ANIM/ELEM/VONM, /ANIM/ELEM/EPSP, /ANIM/VECT/VEL, /ANIM/TENS/STRESS and /TFILE dt_his 1e20 (time-
#    history rows at the first and last cycle only, so the writing time is states), twice: 6 states (/ANIM/DT
#    Tstop / 4.5: 5 inside the timed loop, the last one at Tstop after it) and 2 states (/ANIM/DT 1e20: the
#    first inside the loop, the last after it). Seconds per state = the 6-state run's listing writing time /
#    the 5 states written inside the loop (also the 2-state run's writing time / 1), and independently
#    (process wall time with 6 states - with 2 states) / 4 and (engine wall 6 - engine wall 2) / 4 (the
#    engine's wall time holds the in-loop states only: 5 - 1 = 4 too). Target: < 1 s.
# Timings are repeated (--reps, default 3; the variants are interleaved): best / median / worst are printed,
# and a verdict is given on the best (the least disturbed by other load on the machine) and on the worst.
# All files go to a mktemp -d folder, removed at the end unless --keep; part 2 needs about 1.5 GB there.
#
# Usage: bench/results_write.sh [--keep] [--reps R] [--n N] [--n1m N] [--cycles1m K] [--threads1m T]
#                               [--skip-plate] [--skip-1m]
# Needs a built tree (scripts/build.sh): build/apps, or RADX_BUILD=DIR for DIR/apps (e.g. build-bench).
set -euo pipefail
cd "$(dirname "$0")/.."
keep=0 reps=3 n=200 n1m=1000 cycles1m=12 threads1m=$(nproc) do_plate=1 do_1m=1
while (($#)); do
  case $1 in
    --keep) keep=1 ;;
    --reps) reps=$2; shift ;;
    --n) n=$2; shift ;;
    --n1m) n1m=$2; shift ;;
    --cycles1m) cycles1m=$2; shift ;;
    --threads1m) threads1m=$2; shift ;;
    --skip-plate) do_plate=0 ;;
    --skip-1m) do_1m=0 ;;
    -h | --help) sed -n '2,/^set -euo/{/^set -euo/d; s/^# \{0,1\}//; p}' "$0"; exit 0 ;;
    *) echo "results_write.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done
bin=${RADX_BUILD:-build}/apps
for b in radx-starter radx-engine; do
  [[ -x $bin/$b ]] || { echo "results_write.sh: $bin/$b not found: build first (scripts/build.sh)" >&2; exit 1; }
done
py=/usr/bin/python3
[[ -x $py ]] || py=python3
helper=("$py" bench/results_write_deck.py)
work=$(mktemp -d)
if ((keep)); then trap 'echo "files kept in $work"' EXIT; else trap 'rm -rf "$work"' EXIT; fi
runs=$work/runs.txt
summary=$work/summary.txt
: > "$runs"
: > "$summary"
declare -A shown=()

say() { echo "$*" | tee -a "$summary"; }
# A value computed with awk: calc 'expression' (variables as -v name=value before it).
calc() { awk "$@" 'BEGIN { exit }'; }
# stats_of KEY FIELD: "best median worst" of FIELD over the runs recorded under KEY.
stats_of() {
  grep "^key=$1 " "$runs" | sed -n "s/.* $2=\([^ ]*\).*/\1/p" > "$work/stat.tmp"
  "${helper[@]}" stats "$work/stat.tmp"
}
# run_engine KEY DECK OUTDIR THREADS MODEL: one engine run; records process wall time, peak memory and what
# results_write_deck.py measure reads from the listing, summary and series; sets those as shell variables.
run_engine() {
  local key=$1 deck=$2 out=$3 threads=$4 model=$5
  local root cmd
  root=$(basename "$deck" _0001.rad)
  cmd=("$bin/radx-engine" "$deck" --model "$model" --out "$out" --threads "$threads" --no-plot)
  if [[ -z ${shown[$key]:-} ]]; then
    echo "    \$ /usr/bin/time -f '%e %M' ${cmd[*]}"
    shown[$key]=1
  fi
  if ! /usr/bin/time -f "%e %M" -o "$out/time" "${cmd[@]}" > "$out/run.log" 2>&1; then
    echo "results_write.sh: the engine failed ($key), see $out/run.log:" >&2
    tail -5 "$out/run.log" >&2
    exit 1
  fi
  local m
  m=$("${helper[@]}" measure "$out" "$root" "$deck")
  read -r proc peak < "$out/time"
  echo "key=$key rep=$rep proc=$proc peak=$peak $m" >> "$runs"
  eval "$m"
}

say "== results_write.sh: $(date -u '+%Y-%m-%d %H:%M UTC')"
say "machine: $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')), load average" \
    "$(cut -d' ' -f1-3 /proc/loadavg) at start, $(awk '/MemAvailable/ {printf "%.1f GB", $2 / 1048576}' \
    /proc/meminfo) memory available"
say "binaries: $bin (radx-engine built $(date -u -r "$bin/radx-engine" '+%Y-%m-%d %H:%M UTC');" \
    "tree $(git describe --always --dirty 2>/dev/null || echo '?'))"
say "work folder: $work ($(df -Pk "$work" | awk 'NR == 2 {printf "%.1f GB", $4 / 1048576}') free); $reps repetitions"

# ------------------------------------------------------------------------------------------------------------
if ((do_plate)); then
  echo
  echo "== 1. engine benchmark, ${n} x ${n} shells, 20 states, threads 1 and 2"
  p=$work/plate
  mkdir -p "$p/states" "$p/none"
  echo "    \$ $py bench/gen_shell_plate.py --n $n --out $p"
  "$py" bench/gen_shell_plate.py --n "$n" --out "$p" > /dev/null
  root=PLATE$n
  echo "    \$ $bin/radx-starter $p/${root}_0000.rad --out $p"
  "$bin/radx-starter" "$p/${root}_0000.rad" --out "$p" > "$p/starter.log"
  echo "    \$ ${helper[*]} deck $p/${root}_0001.rad $p/states/${root}_0001.rad --anim-states 20"
  "${helper[@]}" deck "$p/${root}_0001.rad" "$p/states/${root}_0001.rad" --anim-states 20 | sed 's/^/      /'
  echo "    \$ ${helper[*]} deck $p/${root}_0001.rad $p/none/${root}_0001.rad --anim-dt 1e20"
  "${helper[@]}" deck "$p/${root}_0001.rad" "$p/none/${root}_0001.rad" --anim-dt 1e20 | sed 's/^/      /'
  for ((rep = 1; rep <= reps; rep++)); do
    for t in 1 2; do
      order=(states none)
      ((rep % 2)) || order=(none states)
      for v in "${order[@]}"; do
        run_engine "plate.$v.$t" "$p/$v/${root}_0001.rad" "$p/$v" "$t" "$p/${root}_0000.hdf"
        printf '    rep %d, %d thread(s), %-6s: %2d states (%d in the loop), %d cycles, process %6.2f s,' \
          "$rep" "$t" "$v" "$states" "$in_run" "$cycles" "$proc"
        printf ' engine %6.2f s, writing %5.2f s (%4.1f %%)\n' "$eng_wall" "$write_s" "$write_pct"
        if [[ $v == states ]]; then s_proc=$proc s_eng=$eng_wall; else n_proc=$proc n_eng=$eng_wall; fi
        if [[ $v == "${order[1]}" ]]; then  # both variants of this repetition ran
          echo "key=plate.diff.$t rep=$rep dproc=$(calc -v a="$s_proc" -v b="$n_proc" 'BEGIN { printf "%.3f", a - b }')" \
               "deng=$(calc -v a="$s_eng" -v b="$n_eng" 'BEGIN { printf "%.4f", a - b }')" >> "$runs"
        fi
      done
    done
  done
  say
  say "== 1. engine benchmark ${n} x ${n} shells (bench/engine_plate.sh deck), /ANIM/DT = Tstop / 20"
  for t in 1 2; do
    line=$(grep "^key=plate.states.$t " "$runs" | head -1)
    eval "$(echo "$line" | sed 's/^key=[^ ]* //')"
    ns=$states nin=$in_run nafter=$after_run
    line=$(grep "^key=plate.none.$t " "$runs" | head -1)
    eval "$(echo "$line" | sed 's/^key=[^ ]* //')"
    nn=$states
    read -r pb pm pw <<< "$(stats_of "plate.states.$t" write_pct)"
    read -r wb wm ww <<< "$(stats_of "plate.states.$t" write_s)"
    read -r eb em ew <<< "$(stats_of "plate.states.$t" eng_wall)"
    read -r sb sm sw <<< "$(stats_of "plate.states.$t" proc)"
    read -r ob om ow <<< "$(stats_of "plate.none.$t" proc)"
    read -r db dm dw <<< "$(stats_of "plate.diff.$t" dproc)"
    read -r gb gm gw <<< "$(stats_of "plate.diff.$t" deng)"
    say "threads $t: $ns states ($nin written in the engine's timed loop, $nafter after it; $nn without /ANIM/DT)"
    say "$(calc -v b="$pb" -v m="$pm" -v w="$pw" -v wb="$wb" -v wm="$wm" -v ww="$ww" -v nin="$nin" \
      -v eb="$eb" -v ew="$ew" 'BEGIN {
        printf "  listing: writing time %.1f %% of the engine wall time (best; median %.1f, worst %.1f %%) =", b, m, w
        printf " %.3f s (median %.3f, worst %.3f s) for %d states + time-history rows, %.1f ms per state;", wb, wm, ww, nin, 1000 * wb / nin
        printf " engine wall %.2f-%.2f s", eb, ew }')"
    say "$(calc -v sb="$sb" -v sw="$sw" -v ob="$ob" -v ow="$ow" -v db="$db" -v dw="$dw" -v gb="$gb" \
      -v gw="$gw" -v k="$((ns - nn))" 'BEGIN {
        d = sb - ob
        printf "  direct:  process wall %.2f s with states (worst %.2f) vs %.2f s with 2 states (worst %.2f):", sb, sw, ob, ow
        printf " %+.2f s best-vs-best = %+.1f %% for %d more states (per repetition %+.2f..%+.2f s;", d, 100 * d / sb, k, db, dw
        printf " engine wall %+.3f..%+.3f s)", gb, gw }')"
    verdict=$(calc -v b="$pb" -v w="$pw" 'BEGIN { printf "%s (best %.1f %%), worst %s", b <= 10 ? "PASS" : "FAIL", b, w <= 10 ? "passes" : "FAILS" }')
    say "  => writing <= 10 % of the wall time, $t thread(s): $verdict"
  done
fi

# ------------------------------------------------------------------------------------------------------------
if ((do_1m)); then
  echo
  echo "== 2. one state of $(((n1m + 1) * (n1m + 1))) nodes (${n1m} x ${n1m} shells), $cycles1m cycles, $threads1m thread(s)"
  m=$work/m
  mkdir -p "$m/s6" "$m/s2"
  need_kb=$((1500 * 1024 * n1m / 1000 * n1m / 1000))
  free_kb=$(df -Pk "$m" | awk 'NR == 2 { print $4 }')
  if ((free_kb < need_kb)); then
    say
    say "== 2. SKIPPED: $((free_kb / 1024)) MB free in $work, about $((need_kb / 1024)) MB needed" \
        "(model file, mesh file and 8 states of ~81 MB)"
  else
    echo "    disk: $((free_kb / 1024)) MB free in $work, about $((need_kb / 1024)) MB needed"
    root=PLATE$n1m
    echo "    \$ $py bench/gen_shell_plate.py --n $n1m --out $m"
    "$py" bench/gen_shell_plate.py --n "$n1m" --out "$m" | sed 's/^/      /'
    echo "    \$ /usr/bin/time -f '%e %M' $bin/radx-starter $m/${root}_0000.rad --out $m"
    /usr/bin/time -f "%e %M" -o "$m/starter.time" "$bin/radx-starter" "$m/${root}_0000.rad" --out "$m" > "$m/starter.log"
    read -r st_wall st_peak < "$m/starter.time"
    echo "      starter: $st_wall s, peak $((st_peak / 1024)) MB"
    rm -f "$m/${root}_0000.rad"  # 120 MB not needed any more
    anim=(--anim /ANIM/ELEM/VONM --anim /ANIM/ELEM/EPSP --anim /ANIM/VECT/VEL --anim /ANIM/TENS/STRESS)
    common=(--cycles "$cycles1m" --n "$n1m" --tfile-dt 1e20 "${anim[@]}")
    echo "    \$ ${helper[*]} deck $m/${root}_0001.rad $m/s6/${root}_0001.rad ${common[*]} --anim-states 4.5"
    "${helper[@]}" deck "$m/${root}_0001.rad" "$m/s6/${root}_0001.rad" "${common[@]}" --anim-states 4.5 | sed 's/^/      /'
    echo "    \$ ${helper[*]} deck $m/${root}_0001.rad $m/s2/${root}_0001.rad ${common[*]} --anim-dt 1e20"
    "${helper[@]}" deck "$m/${root}_0001.rad" "$m/s2/${root}_0001.rad" "${common[@]}" --anim-dt 1e20 | sed 's/^/      /'
    for ((rep = 1; rep <= reps; rep++)); do
      order=(s6 s2)
      ((rep % 2)) || order=(s2 s6)
      for v in "${order[@]}"; do
        run_engine "m.$v" "$m/$v/${root}_0001.rad" "$m/$v" "$threads1m" "$m/${root}_0000.hdf"
        printf '    rep %d, %s: %d states (%d in the loop), %d cycles, process %6.2f s, engine %6.2f s,' \
          "$rep" "$v" "$states" "$in_run" "$cycles" "$proc" "$eng_wall"
        printf ' writing %5.2f s (%4.1f %%, printed %s), %.3f s per in-loop state, peak %d MB\n' \
          "$write_s" "$write_pct" "$write_text" "$(calc -v a="$write_s" -v k="$in_run" 'BEGIN { printf "%.4f", a / k }')" \
          "$((peak / 1024))"
        echo "key=m.$v.per rep=$rep per=$(calc -v a="$write_s" -v k="$in_run" 'BEGIN { printf "%.4f", a / k }')" >> "$runs"
        if [[ $v == s6 ]]; then s_proc=$proc s_eng=$eng_wall s_in=$in_run s_n=$states; else
          n_proc=$proc n_eng=$eng_wall n_in=$in_run n_n=$states
        fi
        if [[ $v == "${order[1]}" ]]; then  # both variants of this repetition ran
          echo "key=m.diff rep=$rep" \
               "dproc=$(calc -v a="$s_proc" -v b="$n_proc" -v k="$((s_n - n_n))" 'BEGIN { printf "%.4f", (a - b) / k }')" \
               "deng=$(calc -v a="$s_eng" -v b="$n_eng" -v k="$((s_in - n_in))" 'BEGIN { printf "%.4f", (a - b) / k }')" >> "$runs"
        fi
      done
    done
    line=$(grep "^key=m.s6 " "$runs" | head -1)
    eval "$(echo "$line" | sed 's/^key=[^ ]* //')"
    n6=$states in6=$in_run nodes6=$nodes elements6=$elements
    line=$(grep "^key=m.s2 " "$runs" | head -1)
    eval "$(echo "$line" | sed 's/^key=[^ ]* //')"
    n2=$states in2=$in_run
    size=$(stat -c %s "$m/s6/${root}_000001.hdf")
    read -r lb lm lw <<< "$(stats_of m.s6.per per)"
    read -r ob om ow <<< "$(stats_of m.s2.per per)"
    read -r pb pm pw <<< "$(stats_of m.s6 proc)"
    read -r qb qm qw <<< "$(stats_of m.s2 proc)"
    read -r db dm dw <<< "$(stats_of m.diff dproc)"
    read -r gb gm gw <<< "$(stats_of m.diff deng)"
    say
    say "== 2. one state of $nodes6 nodes / $elements6 shells ($n1m x $n1m plate, $cycles1m cycles, $threads1m thread(s))"
    say "  state file $(calc -v s="$size" 'BEGIN { printf "%.1f MB", s / 1e6 }'):" \
        "Points, displacement, velocity, von_mises, plastic_strain, stress (6), element_status"
    say "$(calc -v b="$lb" -v m="$lm" -v w="$lw" -v n="$n6" -v k="$in6" -v s="$size" 'BEGIN {
      printf "  listing, %d-state run: writing time / %d states written in the timed loop = %.3f s per state", n, k, b
      printf " (best; median %.3f, worst %.3f s; %.0f MB/s)", m, w, s / 1e6 / b }')"
    say "$(calc -v b="$ob" -v m="$om" -v w="$ow" -v n="$n2" -v k="$in2" 'BEGIN {
      printf "  listing, %d-state run: writing time / %d state written in the timed loop = %.3f s (median %.3f, worst %.3f s)", n, k, b, m, w }')"
    say "$(calc -v pb="$pb" -v pw="$pw" -v qb="$qb" -v qw="$qw" -v db="$db" -v dm="$dm" -v dw="$dw" \
      -v gb="$gb" -v gm="$gm" -v gw="$gw" -v k="$((n6 - n2))" 'BEGIN {
      printf "  wall difference: process %.2f s (worst %.2f) with %d more states than %.2f s (worst %.2f):", pb, pw, k, qb, qw
      printf " (best - best) / %d = %.3f s per state; per repetition %.3f / %.3f / %.3f s;", k, (pb - qb) / k, db, dm, dw
      printf " engine wall per state %.3f / %.3f / %.3f s (best / median / worst)", gb, gm, gw }')"
    verdict=$(calc -v b="$lb" -v w="$lw" -v d="$(calc -v a="$pb" -v b="$qb" -v k="$((n6 - n2))" 'BEGIN { printf "%.4f", (a - b) / k }')" \
      -v dw="$dw" 'BEGIN {
      printf "%s (listing: best %.3f s, worst %.3f s; process-wall difference: best-vs-best %.3f s,", (b < 1 && d < 1) ? "PASS" : "FAIL", b, w, d
      printf " worst repetition %.3f s)", dw }')
    say "  => a state of $nodes6 nodes in under 1 s: $verdict"
  fi
fi
say
say "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores). Other jobs on the machine slow some"
say "repetitions down (2-thread OpenMP runs most: a busy core stalls every barrier), hence best / median / worst."
echo
echo "==================================== SUMMARY ===================================="
cat "$summary"
