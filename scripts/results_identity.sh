#!/usr/bin/env bash
# Whether a change that is meant to keep every result keeps it to the bit.
#
#   capture BIN OUT   runs every sample deck under decks/ (radx regress --keep, 2 at a time) and the impact
#                     benchmark model of bench/gen_shell_plate.py (N = 40, Isolid 1 and 24) with the radx,
#                     radx-starter and radx-engine found in BIN, and keeps their outputs in OUT.
#   compare A B       compares two captures: every HDF5 file (model files, states, time histories) with
#                     h5diff and no tolerance, every NAME_summary.json with its timings and host figures
#                     left out, and every listing (.out) with its timing lines left out. Prints each file
#                     that differs; exit 1 when one does, or when a deck ran in one capture and not the other.
#
# Copy the executables of the reference build to BIN before changing the code (the script runs them from
# there), for example: mkdir -p /tmp/ref && cp build/apps/radx build/apps/radx-starter build/apps/radx-engine
# /tmp/ref/.
# Usage: scripts/results_identity.sh capture BIN OUT | compare A B
set -euo pipefail
cd "$(dirname "$0")/.."

usage() {
  sed -n '2,/^# Usage/p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
}

capture() {
  local bin=$1 out=$2
  for exe in radx radx-starter radx-engine; do
    [[ -x "$bin/$exe" ]] || { echo "error: $bin/$exe is not an executable" >&2; exit 2; }
  done
  [[ -e "$out" ]] && { echo "error: $out exists; give a new folder" >&2; exit 2; }
  mkdir -p "$out/decks" "$out/impact"
  out=$(cd "$out" && pwd)
  pwd > "$out/source_root"  # listings name the decks by their path: compare maps it away
  # regress exits 1 when a deck misses its reference; the outputs are what is compared here, so go on.
  "$bin/radx" regress decks -j 2 --keep --work "$out/decks" > "$out/regress.log" 2>&1 || true
  for isolid in 1 24; do
    local dir="$out/impact/isolid$isolid"
    mkdir -p "$dir"
    /usr/bin/python3 bench/gen_shell_plate.py --n 40 --impact --isolid "$isolid" --out "$dir" > /dev/null
    local root
    root=$(ls "$dir"/*_0000.rad)
    "$bin/radx" run "$root" --out "$dir" --threads 2 --no-plot > "$dir/run.log" 2>&1
  done
  echo "captured $(find "$out" -name '*.h5' -o -name '*.hdf' | wc -l) HDF5 files in $out"
}

compare() {
  local a=$1 b=$2 bad=0 n=0
  local src_a src_b
  src_a=/nonexistent src_b=/nonexistent
  if [[ -f "$a/source_root" && -f "$b/source_root" ]]; then
    src_a=$(cat "$a/source_root") src_b=$(cat "$b/source_root")
  fi
  while IFS= read -r rel; do
    n=$((n + 1))
    if [[ ! -e "$b/$rel" ]]; then
      echo "only in $a: $rel"; bad=1; continue
    fi
    case "$rel" in
      *.h5 | *.hdf)
        # h5diff exits 0 on objects it cannot compare (a dataset or attribute whose shape changed, e.g. a
        # group that gained columns): -c lists them, and they count as differences. Empty datasets are listed
        # as not comparable too ("... is an empty dataset"), even against themselves: those lines are left out.
        local h5out
        if ! h5out=$(h5diff -c -q "$a/$rel" "$b/$rel" 2>&1) ||
          grep "Not comparable" <<< "$h5out" | grep -qv "is an empty dataset"; then
          echo "differs: $rel"; bad=1
        fi ;;
      *_summary.json)
        if ! /usr/bin/python3 - "$a/$rel" "$b/$rel" << 'EOF'; then
import json, re, sys
# Timings, the host, the thread count and the build (version, commit, instruction set) are not results.
skip = re.compile(r"seconds|wall|_us|us_per|cost|timing|elapsed|date|host|started|finished|threads|cpu|version|path|file|^commit$|^arch$")
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if not skip.search(k)}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
a, b = (strip(json.load(open(p))) for p in sys.argv[1:3])
sys.exit(0 if a == b else 1)
EOF
          echo "differs: $rel"; bad=1
        fi ;;
      *.out)
        # A listing names its folder and the source tree's decks, and times its stages: none is a result.
        local timing='wall time|starter time|writing time|us per element per cycle|% of the wall time|elapsed|seconds'
        if ! diff -q <(sed "s#$a#ROOT#g; s#$src_a#SRC#g" "$a/$rel" | grep -Ev "$timing") \
          <(sed "s#$b#ROOT#g; s#$src_b#SRC#g" "$b/$rel" | grep -Ev "$timing") > /dev/null; then
          echo "differs: $rel"; bad=1
        fi ;;
    esac
  done < <(cd "$a" && find . -type f \( -name '*.h5' -o -name '*.hdf' -o -name '*_summary.json' -o -name '*.out' \) | sort)
  while IFS= read -r rel; do
    [[ -e "$a/$rel" ]] || { echo "only in $b: $rel"; bad=1; }
  done < <(cd "$b" && find . -type f \( -name '*.h5' -o -name '*.hdf' \) | sort)
  if ((bad)); then
    echo "results differ ($n files compared)"
    return 1
  fi
  echo "identical: $n files (HDF5 to the bit, summaries and listings apart from timings)"
}

case "${1:-}" in
  capture) [[ $# -eq 3 ]] || usage; capture "$2" "$3" ;;
  compare) [[ $# -eq 3 ]] || usage; compare "$2" "$3" ;;
  *) usage ;;
esac
