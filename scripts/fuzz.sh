#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (clang, with AddressSanitizer and UndefinedBehaviorSanitizer)
# in build-fuzz/ and runs each deck reader for a bounded time on a corpus seeded from decks/, and the model
# file target on changes to seed model files the fuzz build's starter writes from sample decks.
# Usage: scripts/fuzz.sh [SECONDS per reader, default 60]
# Without clang++ it prints a note and succeeds: fuzzing is an extra check, not a build requirement.
# A crash, sanitizer report, leak or hang fails the script; libFuzzer saves the input under
# build-fuzz/artifacts/ (reproduce: build-fuzz/tests/fuzz/radx_fuzz_starter FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
if ! command -v clang++ >/dev/null 2>&1; then
  echo "radx fuzz: clang++ not found, the fuzzing run is skipped (Debian: apt-get install clang libclang-rt-dev)"
  exit 0
fi
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DRADX_FUZZ=ON -DRADX_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz --target radx_fuzz_starter radx_fuzz_engine radx_fuzz_model radx-starter

# Seeds: every sample deck; engine decks (NAME_0001.rad) for the engine reader, the others (starter and
# one-file decks) for the starter reader. libFuzzer adds what it finds to the same folders, so later runs
# start from there.
mkdir -p build-fuzz/corpus/starter build-fuzz/corpus/engine build-fuzz/artifacts
while IFS= read -r -d '' deck; do
  name=$(echo "${deck#decks/}" | tr '/' '_')
  case "$deck" in
    *_0001.rad) dest="build-fuzz/corpus/engine/$name" ;;
    *) dest="build-fuzz/corpus/starter/$name" ;;
  esac
  # Tested first: cp -n's exit status on an existing file differs between coreutils versions.
  [ -e "$dest" ] || cp "$deck" "$dest"
done < <(find decks -name '*.rad' -size -64k -print0)
cp -n decks/one_file/*.rad build-fuzz/corpus/engine/ 2>/dev/null || true

# The model-file target changes valid models (tests/fuzz/fuzz_model_reader.cpp): small sample decks that
# between them hold every kind of object (contact, ties, rigid bodies and walls, springs, beams, trusses,
# loads, failure models, tabulated and foam laws), written by this build's starter. Its corpus starts
# empty: every input is a list of changes to one of them.
seeds=()
for deck in block_on_plate/BLOCK_ON_PLATE rigid_body/RIGID_BODY imposed_loads/IMPOSED_LOADS \
            spring_general/SPRING_GEN foam_block/FOAM_BLOCK beam_cantilever/BEAM_CANTILEVER \
            rigid_material/RIGID_MATERIAL fail_tab_strip/FAIL_TAB_STRIP truss_bar/TRUSS_BAR \
            block_on_plate_ctclaw/BLOCK_ON_PLATE_CTCLAW tied_beam/TIED_BEAM bar_rwall/BAR_RWALL; do
  name=$(basename "$deck")
  if ! build-fuzz/apps/radx-starter "decks/${deck}_0000.rad" --out build-fuzz/model-seeds >/dev/null 2>&1; then
    echo "radx fuzz: the starter failed on decks/${deck}_0000.rad" >&2
    exit 1
  fi
  seeds+=("build-fuzz/model-seeds/${name}_0000.hdf")
done
mkdir -p build-fuzz/corpus/model
export RADX_FUZZ_MODELS
RADX_FUZZ_MODELS=$(IFS=:; echo "${seeds[*]}")

status=0
# A sanitizer report names the function and line only with a stack; CI keeps no artifacts, so the log must.
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
for reader in starter engine model; do
  # A model-file input is at most 1 + 8 changes of 14 bytes (fuzz_model_reader.cpp): longer ones add nothing,
  # and shorter ones than a change do nothing, so libFuzzer tries every length from the start.
  max_len=65536
  extra=()
  if [ "$reader" = model ]; then max_len=113; extra=(-len_control=0); fi
  echo "radx fuzz: the $reader reader, $((seconds * 250)) inputs (about ${seconds} s)"
  # A fixed seed and a fixed number of inputs: from the same corpus (a clean clone's, seeded from decks/) the
  # same inputs are tried, so a submission's test run does not pass or fail by the luck of the draw; the
  # time limit (three times the budget) only guards a slow machine. RADX_FUZZ_SEED=0 draws a fresh seed.
  if ! build-fuzz/tests/fuzz/radx_fuzz_$reader build-fuzz/corpus/$reader -seed="${RADX_FUZZ_SEED:-1}" \
      -runs=$((seconds * 250)) -max_total_time=$((seconds * 3)) -max_len=$max_len "${extra[@]}" -timeout=20 -rss_limit_mb=2048 \
      -print_final_stats=1 \
      -artifact_prefix=build-fuzz/artifacts/$reader- >build-fuzz/fuzz_$reader.log 2>&1; then
    status=1
    echo "radx fuzz: the $reader reader failed; its input is in build-fuzz/artifacts/, the log:" >&2
    tail -n 60 build-fuzz/fuzz_$reader.log >&2
  fi
  grep -E '^#[0-9]+[[:space:]]+(DONE|INITED)|stat::number_of_executed_units|stat::peak_rss_mb' \
    build-fuzz/fuzz_$reader.log || true
done
exit $status
