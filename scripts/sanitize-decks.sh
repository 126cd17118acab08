#!/usr/bin/env bash
# The sample decks through radx built with clang, AddressSanitizer and UndefinedBehaviorSanitizer (with
# float-cast-overflow: a double converted to an integer it does not fit, which g++ does not check), so that
# scripts/test.sh compiles and runs the whole solver under clang: a GCC-only construct, an out-of-bounds access,
# an overflow or a leak on a deck's path fails the test command.
#
# It reuses the fuzz build (build-fuzz/, scripts/fuzz.sh: the parser and the model are compiled once for both)
# and adds radx, radx-starter, radx-engine and radx_kernel_isa_check to it. Then:
#   * radx_kernel_isa_check runs both instruction-set copies of the BT4 shell kernel (the baseline and the
#     x86-64-v3 one, when the processor has AVX2) and compares them bit for bit: the v3 copy compiled by clang;
#   * `radx regress` runs every deck of decks/ but the verification ones (skipped for time: the sample decks
#     hold every element, material, contact and output family, decks/invalid every refusal, decks/versions
#     the old layouts), each in its own process, against its reference. Every sanitizer report stops the
#     run that made it (-fno-sanitize-recover), which fails that deck; its report is printed from its log.
#     On a processor with AVX2 the shell decks run the x86-64-v3 kernel copy (the run-time dispatch).
# Without clang++ it prints a note and succeeds, as scripts/fuzz.sh does.
# Usage: scripts/sanitize-decks.sh [radx regress options, e.g. --filter taylor]
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang++ >/dev/null 2>&1; then
  echo "radx sanitize-decks: clang++ not found, the sanitizer run of the decks is skipped (Debian: apt-get install clang libclang-rt-dev)"
  exit 0
fi
start=$SECONDS
# The configuration of scripts/fuzz.sh, to the option: one build tree for both.
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DRADX_FUZZ=ON -DRADX_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz --target radx radx-starter radx-engine radx_kernel_isa_check
echo "radx sanitize-decks: built in $((SECONDS - start)) s"

# A report names the function and line only with a stack; CI keeps no artifacts, so the log must.
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
# Passive OpenMP waits (CHOLMOD, LAGDT) as under CTest: two decks share two cores.
export OMP_WAIT_POLICY=passive
status=0
build-fuzz/tests/fuzz/radx_kernel_isa_check --warn NoTests || status=1

work=build-fuzz/sanitize-decks
rm -rf "$work"
folders=()
while IFS= read -r -d '' dir; do folders+=("$dir"); done < <(find decks -mindepth 1 -maxdepth 1 -type d \
  ! -name verification -print0 | sort -z)
if ! build-fuzz/apps/radx regress "${folders[@]}" -j "$(nproc)" --timeout 1200 --work "$work" \
    --summary build-fuzz/sanitize-decks.json "$@" >build-fuzz/sanitize-decks.log 2>&1; then
  status=1
  echo "radx sanitize-decks: a deck failed under the sanitizers; radx regress said:" >&2
  tail -n 40 build-fuzz/sanitize-decks.log >&2
  # Each sanitizer report, from the failing decks' logs (radx regress keeps every run folder in --work).
  grep -l -E 'runtime error:|ERROR: (Address|Leak)Sanitizer' -r "$work" --include=run.log | while read -r log; do
    echo "---- $log" >&2
    grep -E -A 30 'runtime error:|ERROR: (Address|Leak)Sanitizer' "$log" | head -n 60 >&2
  done
fi
grep -E '^decks found|^wall time' build-fuzz/sanitize-decks.log || true
echo "radx sanitize-decks: $((SECONDS - start)) s in all"
exit $status
