#!/bin/sh
# SPDX-License-Identifier: MIT
# Scale of the iterative PETSc path (issue 20, docs/benchmarks.md "Scale"): the 3D round
# quarter (cases/round-rod-3d.toml) at mesh size H, the mixed Q2–P1disc problem kept as a
# saddle point (FGMRES + fieldsplit Schur, systems BoomerAMG on the velocity), stopped
# after STEPS secant steps (exit 3: max_iterations). Prints the velocity dofs, the Krylov
# iterations of each step, CPU (user + sys, one BLAS thread), peak RSS and the phases'
# wall times. Mind the memory: about 34 kB per velocity dof (h = 1/12: 156 k dofs, 5 GiB).
# Further arguments KEY=VALUE are passed on as --set KEY=VALUE after the script's own
# (a later --set wins), e.g. solver.acceleration=anderson.
#   bench/petsc_scale_step.sh [H] [STEPS] [KEY=VALUE ...]   (FORMFLOW_BINARY, default build/formflow)
set -eu
size=${1:-0.0833333333}
steps=${2:-2}
[ $# -ge 2 ] && shift 2 || shift $#
extra=""
for setting in "$@"; do extra="$extra --set $setting"; done
binary=${FORMFLOW_BINARY:-build/formflow}
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 /usr/bin/time -f "%U %S %M" -o "$work/time" \
  "$binary" run -q --set solver.load_error=none cases/round-rod-3d.toml -o "$work/out" --set mesh.size="$size" \
  --set formulation.type=mixed --set formulation.pressure=P1disc \
  --set formulation.discontinuous_pressure=saddle_point --set solver.linear=petsc \
  --set solver.method=secant --set solver.max_iterations="$steps" $extra >/dev/null 2>&1 || true
/usr/bin/python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
user, system, rss = open(f"{work}/time").read().split()[-3:]
s = json.load(open(f"{work}/out/summary.json"))
t = s["timing_s"]
la = s["linear_algebra"]
print(f"velocity dofs {s['mesh']['dofs']}, {s['iterations']} secant steps ({s['stop_reason']}; "
      f"coarse levels {s['coarse_iterations']}, acceleration {s['acceleration']}), "
      f"Krylov per step {la['iterations_per_step']} (total {la['iterations']}, "
      f"{la['factorizations']} factorisations: AMG setups and the coarse levels' CHOLMOD); ram reaction {s['pressure']['ram_reaction']:.7f}; CPU {float(user) + float(system):.0f} s, "
      f"peak RSS {int(rss) / 1024 / 1024:.2f} GiB ({int(rss) * 1024 / s['mesh']['dofs'] / 1000:.0f} kB per "
      f"velocity dof); wall: setup {t.get('setup', 0):.0f} s, AMG setups {t.get('factorization', 0):.0f} s, "
      f"Krylov {t.get('solve', 0):.0f} s (machine not quiet unless said)")
PY
