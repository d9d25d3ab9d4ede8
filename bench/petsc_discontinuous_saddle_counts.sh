#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Krylov iterations per secant step of the mixed Q2–P1disc problem kept as a saddle
# point (formulation.discontinuous_pressure = "saddle_point", solver.linear = "petsc":
# FGMRES + fieldsplit Schur, the viscosity-scaled pressure mass for the Schur
# complement; docs/petsc.md), over three refinements: the 2D paper case, the 3D slab
# (cases/slab-extrusion-3d.toml) and the 3D round quarter (cases/round-rod-3d.toml),
# each with its own default friction, d = 1e-3 (default) and d = 0, δ = 1e-4.
# Velocity block: one GAMG V-cycle with the rigid-body near-null space, or one
# BoomerAMG V-cycle (the default; since session 11 on the velocity block laid out node
# by node, block size dim: hypre's systems AMG — `hypre-scalar` is the free numbering),
# and the 3D settings tried in session 11 (the table below). Counts only: they do not
# depend on the machine's load; each line also gives the run's CPU time and peak RSS
# (/usr/bin/time, one BLAS thread), which do (machine not quiet unless said).
# Usage: bench/petsc_discontinuous_saddle_counts.sh [BUILD_DIR] [VARIANTS] [d values] [--set ...]
#   (arguments after the third go to every run, e.g. --set geometry.die=wedge)
#   (defaults: build, "gamg hypre", "1e-3 0"); PLANE_SIZES and SLAB_SIZES (default
#   "2.5 1.25 0.625") and ROUND_SIZES (default "0.5 0.25 0.125") set each geometry's
#   mesh sizes, "" leaves it out. Since session 10 the Γ3 nodes' velocity dofs are
#   solved in their normal–tangent frame (assembly/contact_frames.hpp).
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build}/formflow
variants=${2:-gamg hypre}
penalties=${3:-1e-3 0}
extra=("${@:4}")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# The velocity block's AMG (session 11 added the BoomerAMG and GAMG settings for 3D;
# docs/benchmarks.md "Velocity AMG settings in 3D"). VARIANT_OPTIONS="name=options"
# adds one more by hand.
u=-fieldsplit_u_pc_hypre_boomeramg
declare -A options=(
  [gamg]="-fieldsplit_u_pc_type gamg"
  [hypre]=""
  [hypre-scalar]="-formflow_velocity_node_blocks 0"
  [hypre-st05]="$u""_strong_threshold 0.5"
  [hypre-st07]="$u""_strong_threshold 0.7"
  [hypre-hmis]="$u""_coarsen_type HMIS $u""_interp_type ext+i $u""_P_max 4"
  [hypre-hmis-st05]="$u""_coarsen_type HMIS $u""_interp_type ext+i $u""_P_max 4 $u""_strong_threshold 0.5"
  [hypre-pmis-st05]="$u""_coarsen_type PMIS $u""_interp_type ext+i $u""_P_max 4 $u""_strong_threshold 0.5"
  [hypre-blocks]="-formflow_velocity_node_blocks 1"
  [hypre-blocks-st05]="-formflow_velocity_node_blocks 1 $u""_strong_threshold 0.5"
  [hypre-blocks-hmis]="-formflow_velocity_node_blocks 1 $u""_coarsen_type HMIS $u""_interp_type ext+i $u""_P_max 4"
  [hypre-nodal]="-formflow_velocity_node_blocks 1 $u""_nodal_coarsen 1"
  [hypre-nodal-st05]="-formflow_velocity_node_blocks 1 $u""_nodal_coarsen 1 $u""_strong_threshold 0.5"
  [hypre-nodal-vec]="-formflow_velocity_node_blocks 1 $u""_nodal_coarsen 1 $u""_vec_interp_variant 2"
  [gamg-blocks]="-formflow_velocity_node_blocks 1 -fieldsplit_u_pc_type gamg"
  [gamg-blocks-t002]="-formflow_velocity_node_blocks 1 -fieldsplit_u_pc_type gamg -fieldsplit_u_pc_gamg_threshold 0.02"
  [gamg-t002]="-fieldsplit_u_pc_type gamg -fieldsplit_u_pc_gamg_threshold 0.02"
  [gamg-t005-sm0]="-fieldsplit_u_pc_type gamg -fieldsplit_u_pc_gamg_threshold 0.05 -fieldsplit_u_pc_gamg_agg_nsmooths 0"
)
if [ -n "${VARIANT_OPTIONS:-}" ]; then options[${VARIANT_OPTIONS%%=*}]=${VARIANT_OPTIONS#*=}; fi
saddle=(--set formulation.type=mixed --set formulation.pressure=P1disc
        --set formulation.discontinuous_pressure=saddle_point --set solver.linear=petsc
        --set solver.method=secant --set solver.tolerance=1e-4 --set solver.max_iterations=300)
report() { # label, then the arguments of formflow run
  local label=$1
  shift
  OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 /usr/bin/time -f "%U %S %M" -o "$scratch/time" \
    "$binary" run -q --set solver.load_error=none -o "$scratch/out" "$@" >/dev/null 2>"$scratch/err" || true
  /usr/bin/python3 - "$label" "$scratch/out/summary.json" "$scratch/err" "$scratch/time" <<'PY'
import json, sys
label, path, err, timing = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
user, system, rss = open(timing).read().split()[-3:]
try:
    s = json.load(open(path))
except OSError:
    print(f"{label}: no summary.json: {open(err).read().strip()[:200]}"); sys.exit(0)
steps = sorted(n for n in s["linear_algebra"]["iterations_per_step"] if n is not None)
print(f"{label}: dofs {s['mesh']['dofs']}, {s['stop_reason']} after {len(steps)} secant steps, "
      f"Krylov per step min {steps[0]} median {steps[len(steps)//2]} max {steps[-1]}, "
      f"ram reaction {s['pressure']['ram_reaction']:.6f}; CPU {float(user) + float(system):.1f} s "
      f"(AMG setups {s['timing_s'].get('factorization', 0):.1f} s, Krylov {s['timing_s'].get('solve', 0):.1f} s "
      f"wall; machine not quiet), peak RSS {int(rss) / 1024:.0f} MiB", flush=True)
PY
  rm -rf "$scratch/out"
}
for variant in $variants; do
  for d in $penalties; do
    run=("${saddle[@]}" --set penalty.d=$d --set "solver.petsc_options=${options[$variant]}"
         "${extra[@]}")
    for size in ${PLANE_SIZES-2.5 1.25 0.625}; do
      report "$variant d=$d 2D h=$size" "${run[@]}" --set mesh.size=$size
    done
    for size in ${SLAB_SIZES-2.5 1.25 0.625}; do
      report "$variant d=$d 3D slab h=$size" cases/slab-extrusion-3d.toml "${run[@]}" \
        --set mesh.size=$size
    done
    for size in ${ROUND_SIZES-0.5 0.25 0.125}; do
      report "$variant d=$d 3D round h=$size" cases/round-rod-3d.toml "${run[@]}" \
        --set mesh.size=$size
    done
  done
done
