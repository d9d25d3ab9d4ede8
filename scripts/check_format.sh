#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fails (and lists the files) when a tracked C++ source differs from what
# clang-format makes of it with the repository's .clang-format.
# Usage: scripts/check_format.sh [clang-format binary]
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=${1:-clang-format}
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find src tests bench -name '*.[ch]pp')
present=()
for file in "${files[@]}"; do [ -f "$file" ] && present+=("$file"); done
# One clang-format process for all files (one per file cost a minute of the suite in
# process start-up alone); --dry-run --Werror names each offending file in its messages.
if report=$("$formatter" --dry-run --Werror "${present[@]}" 2>&1); then
  echo "clang-format clean: ${#present[@]} files"
  exit 0
fi
echo "not clang-format clean (run: clang-format -i FILE):"
grep -oE '^[^:]+\.(c|h)pp:[0-9]+:[0-9]+: (error|warning)' <<<"$report" | cut -d: -f1 | sort -u |
  sed 's/^/  /'
exit 1
