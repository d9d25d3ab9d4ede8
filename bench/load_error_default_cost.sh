#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# What the default load error bar (solver.load_error = "auto") costs: each case run
# with "none" and with "auto", N times each (default 3), the median wall time of each,
# the method auto took and its share ("error estimate" in summary.json timing_s).
#   FORMFLOW_BINARY=build/formflow bench/load_error_default_cost.sh [N] [case.toml ...]
# Run it on a quiet machine; one BLAS and OpenMP thread, as ./test does.
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${FORMFLOW_BINARY:-build/formflow}
runs=${1:-3}
shift || true
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(cases/paper-q2-2x2-mesh2.toml cases/sticking-ram-q2.toml
  cases/wedge-die-drawing.toml cases/conical-die-rod-extrusion.toml
  cases/slab-extrusion-3d.toml cases/rectangle-bar-3d.toml cases/round-rod-3d.toml)
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
echo "| case | dofs | none s | auto s | method | estimate s (auto) | bar |"
echo "|---|---|---|---|---|---|---|"
for case in "${cases[@]}"; do
  declare -A median=()
  for method in none auto; do
    times=()
    for _ in $(seq "$runs"); do
      start=$(date +%s.%N)
      "$binary" run -q -o "$scratch/out" "$case" --set solver.load_error="$method" >/dev/null
      times+=("$(awk -v start="$start" -v end="$(date +%s.%N)" 'BEGIN { print end - start }')")
    done
    median[$method]=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  done
  python3 - "$scratch/out/summary.json" "$(basename "$case")" "${median[none]}" "${median[auto]}" <<'PY'
import json, sys
summary = json.load(open(sys.argv[1]))
estimate = summary["pressure"]["error_estimate"]
bar = summary["pressure"]["ram_reaction_error"]
print(f"| {sys.argv[2]} | {summary['mesh']['dofs']} | {float(sys.argv[3]):.2f} | "
      f"{float(sys.argv[4]):.2f} | {estimate['method'] or 'none: ' + estimate['unavailable'][:60]} | "
      f"{summary['timing_s'].get('error estimate', 0):.2f} | "
      f"{'—' if bar is None else format(bar, '.4f')} |")
PY
done
