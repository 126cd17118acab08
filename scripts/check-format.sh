#!/usr/bin/env bash
# Fails when a tracked C++ file differs from what clang-format (the checked-in .clang-format) makes of it.
set -euo pipefail
cd "$(dirname "$0")/.."
bad=0
while IFS= read -r f; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || { echo "not clang-formatted: $f"; bad=1; }
done < <(git ls-files '*.cpp' '*.hpp' '*.cpp.in')
[[ $bad -eq 0 ]] && echo "all C++ files are clang-formatted"
exit $bad
