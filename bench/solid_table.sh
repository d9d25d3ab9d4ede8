#!/bin/sh
# SPDX-License-Identifier: MIT
# The 3D table of docs/benchmarks.md ("3D with CHOLMOD"): each ready 3D case (and the
# round rod at two mesh sizes) run REPEAT times; prints dofs, Newton iterations,
# factorisations, the matrix and factor nonzeros and the fill (factor / matrix:
# CHOLMOD's counts, which do not depend on the load), the median factorisation
# and total times and the largest peak memory (GNU time's maximum resident set).
# Run it on a quiet machine (the counts are the same on any).
#   bench/solid_table.sh [REPEAT]        (FORMFLOW_BINARY, default build/formflow)
set -eu
repeat=${1:-3}
binary=${FORMFLOW_BINARY:-build/formflow}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
row() { # $1 = label, $2 = case file, rest = --set overrides
  label=$1 case_file=$2
  shift 2
  i=0
  while [ "$i" -lt "$repeat" ]; do
    /usr/bin/time -f "%M" -o "$work/$label.$i.mem" \
      "$binary" run -q --set solver.load_error=none "$case_file" "$@" -o "$work/$label.$i" >/dev/null
    i=$((i + 1))
  done
  /usr/bin/python3 - "$work" "$label" "$repeat" <<'PY'
import json, statistics, sys
work, label, repeat = sys.argv[1], sys.argv[2], int(sys.argv[3])
runs = [json.load(open(f"{work}/{label}.{i}/summary.json")) for i in range(repeat)]
memory = max(int(open(f"{work}/{label}.{i}.mem").read().split()[-1]) for i in range(repeat))
first = runs[0]
median = lambda key: statistics.median(r["timing_s"].get(key, 0.0) for r in runs)
algebra = first['linear_algebra']
matrix, factor = algebra.get('matrix_nonzeros'), algebra.get('factor_nonzeros')
fill = f"{factor / matrix:.1f}" if matrix and factor else "—"
count = lambda n: f"{n:,}" if n is not None else "—"
print(f"| {label} | {first['mesh']['dofs']:,} | {first['iterations']} | "
      f"{algebra['factorizations']} | {count(matrix)} | {count(factor)} | {fill} | "
      f"{median('factorization'):.2f} s | "
      f"{median('total'):.2f} s | {memory / 1024:.0f} MiB |".replace(",", " "))
PY
}
echo "| case | dofs | Newton iterations | factorisations | matrix nonzeros | factor nonzeros | fill | factorisation | total | peak memory |"
echo "|---|---|---|---|---|---|---|---|---|---|"
row slab cases/slab-extrusion-3d.toml
row rectangle cases/rectangle-bar-3d.toml
row round-h0.25 cases/round-rod-3d.toml --set mesh.size=0.25
row round-h0.125 cases/round-rod-3d.toml
