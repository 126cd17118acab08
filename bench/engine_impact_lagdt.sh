#!/usr/bin/env bash
# LAGDT impact benchmark: the impact benchmark deck of bench/engine_impact.sh (an N x N Johnson-Cook
# plate, default N = 200, hit at 10 m/s by a 10 x 10 x 4 aluminium block through two interfaces) in three
# variants, each on one thread:
#   type7    plain /INTER/TYPE7: the contact pairs set the step once the block touches;
#   lagdt    /INTER/LAGDT/TYPE7 with /DT/INTER/CST Tmin (default 8e-7 s, just below the 8.7e-7 s shell step):
#            the pairs whose step would fall below Tmin are solved with Lagrange multipliers;
#   addmass  plain /INTER/TYPE7 with the same /DT/INTER/CST: mass is added to keep the step at Tmin.
# Prints for each: cycles, wall time, cost in us per element per cycle, the share of the wall time in contact
# (search and forces) and in the multiplier solve (assembly + factorisation + solve), switched pairs, added
# mass and the energy error. Target: the multiplier solve at most 10 % of the cycle.
# Usage: bench/engine_impact_lagdt.sh [N] [TMIN]   (needs a built tree: scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-200}
tmin=${2:-8e-7}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
for contact in type7 lagdt addmass; do
  /usr/bin/python3 bench/gen_shell_plate.py --n "$n" --impact --contact "$contact" --tmin "$tmin" --out "$work" >/dev/null
  root="$work/PLATE${n}I"
  [ "$contact" = type7 ] || root="${root}_${contact^^}"
  ./build/apps/radx run "${root}_0000.rad" --out "$work/out_$contact" --threads 1 --no-plot > "$work/run.$contact" 2>&1
  /usr/bin/python3 - "$work/out_$contact" "$contact" <<'PY'
import glob, json, sys
s = json.load(open(glob.glob(sys.argv[1] + "/*_summary.json")[0]))
lag = s.get("lagrange_solver") or {}
t_lag = sum(lag.get(k, 0.0) for k in ("seconds_assembly", "seconds_factorization", "seconds_solve"))
switched = sum(i["switched_pairs_total"] for i in s["interfaces"])
print("%-8s %6d cycles  wall %6.2f s  %.4f us/element/cycle  multiplier solve %5.2f %% of the wall time  "
      "switched pair-cycles %7d  added mass %.3g %%  energy error %.2f %%"
      % (sys.argv[2], s["cycles"], s["wall_seconds"], s["us_per_element_cycle"],
         100 * t_lag / s["wall_seconds"], switched, 100 * s["added_mass"] / s["initial_mass"],
         s["energy"]["error_percent"]))
PY
  grep -E "^ +contact \(search and forces\)" "$work/run.$contact" | sed 's/^ */         /'
done
