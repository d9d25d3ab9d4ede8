#!/bin/sh
# SPDX-License-Identifier: MIT
# The iterative saddle point on 1 and 2 MPI ranks (issue 20, docs/benchmarks.md
# "Distributed saddle point"): the 3D round quarter (cases/round-rod-3d.toml) at mesh size
# H, the mixed Q2–P1disc problem kept as a saddle point with the settings of
# bench/petsc_scale_step.sh, run to convergence (solver.tolerance's default) by one process
# (systems BoomerAMG on the node layout, the default), one process without the layout
# (scalar BoomerAMG, -formflow_velocity_node_blocks 0), and two ranks with and without it
# (RUNS, default "np1 np1_scalar np2 np2_scalar", chooses). Prints per run: secant steps, Krylov total and per step (min /
# median / max), the ram reaction and its difference from the first run, CPU (user + sys
# of all ranks, one BLAS thread), the wall time and the largest rank's peak RSS.
#   bench/distributed_saddle_point.sh [H]     (FORMFLOW_BINARY, default build/formflow;
#                                              MPIEXEC, default mpirun)
set -eu
size=${1:-0.25}
binary=${FORMFLOW_BINARY:-build/formflow}
mpiexec=${MPIEXEC:-mpirun}
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags="--oversubscribe"
[ "$(id -u)" -eq 0 ] && flags="$flags --allow-run-as-root"
export OMPI_MCA_mpi_yield_when_idle=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
run() { # name, petsc options, launcher words and the binary
  name=$1
  options=$2
  shift 2
  /usr/bin/time -f "%e %U %S %M" -o "$work/$name.time" "$@" run -q --set solver.load_error=none cases/round-rod-3d.toml \
    -o "$work/$name" --set mesh.size="$size" --set "solver.petsc_options=$options" \
    --set formulation.type=mixed \
    --set formulation.pressure=P1disc --set formulation.discontinuous_pressure=saddle_point \
    --set solver.linear=petsc --set solver.method=secant --set solver.max_iterations=500 \
    >/dev/null 2>&1 || true
}
runs=${RUNS:-np1 np1_scalar np2 np2_scalar}
scalar="-formflow_velocity_node_blocks 0"
for name in $runs; do # one word per run
  # shellcheck disable=SC2086 # $flags are several words
  case $name in
  np1) run np1 "" "$binary" ;;
  np1_scalar) run np1_scalar "$scalar" "$binary" ;;
  np2) run np2 "" "$mpiexec" $flags -n 2 "$binary" ;;
  np2_scalar) run np2_scalar "$scalar" "$mpiexec" $flags -n 2 "$binary" ;;
  esac
done
# shellcheck disable=SC2086 # $runs: one argument per run
/usr/bin/python3 - "$work" $runs <<'PY'
import json, statistics, sys
work = sys.argv[1]
reference = None
for name in sys.argv[2:]:
    s = json.load(open(f"{work}/{name}/summary.json"))
    wall, user, system, rss = open(f"{work}/{name}.time").read().split()[-4:]
    steps = s["linear_algebra"]["iterations_per_step"]
    load = s["pressure"]["ram_reaction"]
    reference = reference if reference is not None else load
    print(f"{name}: dofs {s['mesh']['dofs']}, converged {s['converged']}, {s['iterations']} secant "
          f"steps (coarse {s['coarse_iterations']}), Krylov {s['linear_algebra']['iterations']} "
          f"(per step {min(steps)} / {statistics.median(steps):g} / {max(steps)}), ram reaction "
          f"{load:.10f} (rel. diff {abs(load - reference) / abs(reference):.1e}), CPU "
          f"{float(user) + float(system):.0f} s, wall {float(wall):.1f} s, peak RSS {int(rss) / 1024:.0f} MiB "
          f"(machine not quiet unless said)")
PY
