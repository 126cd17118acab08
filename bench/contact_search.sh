#!/usr/bin/env bash
# TYPE7 candidate search benchmark: voxel sorts of 250k, 500k and 1M segments against as many secondary
# nodes (hidden Catch2 case in tests/unit/contact/test_type7_search.cpp). Prints the best of five sort times, the
# ratio to the previous size (about 2 when the sort is linear, 4 if it were quadratic) and the cost per
# tracked node of the per-cycle "is a sort due" check.
# Usage: bench/contact_search.sh [build-dir]   (default build; needs radx_unit_tests built in Release)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
"$build/tests/radx_unit_tests" "type7 search scaling benchmark" --use-colour no | grep -vE "^(=+|~+)$|passed|^$"
