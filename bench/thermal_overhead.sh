#!/bin/sh
# SPDX-License-Identifier: MIT
# Hot forming's cost (issue 18, docs/benchmarks.md "Hot forming"): the AA6063 case run
# isothermal (the same law at the billet's 450 °C) and coupled, REPEAT times each on the
# same mesh; prints the median total time of each, the coupled run's thermal phases and
# the ratio. Run it on a quiet machine: build/formflow must exist.
#   bench/thermal_overhead.sh [REPEAT] [MESH_SIZE]
set -eu
repeat=${1:-5}
size=${2:-2.5}
binary=${FORMFLOW_BINARY:-build/formflow}
case_file=cases/aa6063-hot-extrusion.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { # $1 = label, rest = --set overrides
  label=$1
  shift
  i=0
  while [ "$i" -lt "$repeat" ]; do
    "$binary" run -q --set solver.load_error=none "$case_file" --set mesh.size="$size" "$@" -o "$work/$label$i" >/dev/null
    i=$((i + 1))
  done
}
run isothermal --set thermal.enabled=false
run coupled
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
def times(label, key):
    return [json.load(open(f"{work}/{label}{i}/summary.json"))["timing_s"].get(key, 0.0)
            for i in range(repeat)]
iso = statistics.median(times("isothermal", "total"))
hot = statistics.median(times("coupled", "total"))
heat = statistics.median(a + s for a, s in zip(times("coupled", "thermal_assembly"),
                                              times("coupled", "thermal_solve")))
print(f"isothermal total {iso:.3f} s, coupled total {hot:.3f} s (x{hot / iso:.2f}), "
      f"heat assembly + solve {heat:.3f} s ({100 * heat / iso:.0f} % of the isothermal run)")
# The counts do not depend on the machine's load: Newton iterations on the fine mesh
# (every coupling step's) and factorisations (coarse levels and heat solves included).
def counts(label):
    d = json.load(open(f"{work}/{label}0/summary.json"))
    return d["iterations"], d["linear_algebra"]["factorizations"], d.get("thermal", {})
for label in ("isothermal", "coupled"):
    its, facts, thermal = counts(label)
    steps = thermal.get("coupling", {}).get("flow_iterations") if thermal else None
    print(f"{label}: {its} Newton iterations, {facts} factorizations"
          + (f", flow iterations per coupling step {steps}" if steps else ""))
PY
