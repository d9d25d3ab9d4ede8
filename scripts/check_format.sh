#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fails (and lists the files) when a tracked C++ source differs from what
# clang-format makes of it with the repository's .clang-format.
# Usage: scripts/check_format.sh [clang-format binary]
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=${1:-clang-format}
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find src tests bench -name '*.[ch]pp')
unformatted=()
for file in "${files[@]}"; do
  [ -f "$file" ] || continue
  "$formatter" --dry-run --Werror "$file" >/dev/null 2>&1 || unformatted+=("$file")
done
if ((${#unformatted[@]})); then
  echo "not clang-format clean (run: clang-format -i FILE):"
  printf '  %s\n' "${unformatted[@]}"
  exit 1
fi
echo "clang-format clean: ${#files[@]} files"
