#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Krylov iterations per secant step of the Taylor–Hood saddle point (formulation
# mixed, pressure Q1, sticking ram, δ = 1e-4, at most 150 secant steps) under PETSc's fieldsplit Schur
# preconditioner (docs/petsc.md), over mesh refinements, 2D channel and 3D slab.
# Counts only: they do not depend on the machine's load (times must be taken on a
# quiet machine). Variants: velocity block by one GAMG V-cycle (A), one BoomerAMG
# V-cycle (E) or exactly (D, the Schur preconditioner's own quality); the Schur
# complement preconditioned by selfp (B diag(A)⁻¹ Bᵀ + C), Jacobi (A) or exact LU of
# selfp (D, E).
# Usage: bench/petsc_saddle_point_counts.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build}/formflow
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
schur="-ksp_type fgmres -ksp_rtol 1e-10 -ksp_max_it 1000 -pc_type fieldsplit
 -pc_fieldsplit_type schur -pc_fieldsplit_schur_fact_type full
 -pc_fieldsplit_schur_precondition selfp"
declare -A variants=(
  [A]="$schur -fieldsplit_u_ksp_type preonly -fieldsplit_u_pc_type gamg
       -fieldsplit_p_ksp_type preonly -fieldsplit_p_pc_type jacobi"
  [E]="$schur -fieldsplit_u_ksp_type preonly -fieldsplit_u_pc_type hypre
       -fieldsplit_p_ksp_type preonly -fieldsplit_p_pc_type lu"
  [D]="$schur -fieldsplit_u_ksp_type preonly -fieldsplit_u_pc_type lu
       -fieldsplit_p_ksp_type preonly -fieldsplit_p_pc_type lu"
)
taylor_hood=(--set formulation.type=mixed --set formulation.pressure=Q1 --set process.ram=sticking
             --set solver.linear=petsc --set solver.tolerance=1e-4 --set solver.max_iterations=150)
report() { # label, then the arguments of formflow run
  local label=$1
  shift
  "$binary" run -q --set solver.load_error=none -o "$scratch/out" "$@" >/dev/null 2>"$scratch/err" || true
  /usr/bin/python3 - "$label" "$scratch/out/summary.json" <<'PY'
import json, sys
label, path = sys.argv[1], sys.argv[2]
try:
    s = json.load(open(path))
except OSError:
    print(f"{label}: no summary.json"); sys.exit(0)
steps = sorted(n for n in s["linear_algebra"]["iterations_per_step"] if n is not None)
print(f"{label}: dofs {s['mesh']['dofs']}, {s['stop_reason']} after {len(steps)} secant steps, "
      f"Krylov per step min {steps[0]} median {steps[len(steps)//2]} max {steps[-1]}, "
      f"ram reaction {s['pressure']['ram_reaction']:.6f}")
PY
  rm -rf "$scratch/out"
}
for variant in A E D; do
  for size in 2.5 1.25 0.625; do
    report "$variant 2D h=$size" "${taylor_hood[@]}" --set mesh.size=$size \
      --set "solver.petsc_options=${variants[$variant]}"
  done
  for size in 2.5 1.25; do
    report "$variant 3D slab h=$size" cases/slab-extrusion-3d.toml "${taylor_hood[@]}" \
      --set mesh.size=$size --set "solver.petsc_options=${variants[$variant]}"
  done
done
