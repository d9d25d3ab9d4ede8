#!/bin/sh
# SPDX-License-Identifier: MIT
# Issue 20's "same answers" (docs/petsc.md "Same answers"): the ram reaction of a case
# run with the default method (Newton, its coarse levels) by one CHOLMOD process, and by
# PETSc on np = 1, 2 and 4 MPI ranks (4 oversubscribed on a 2-core machine; np > 1 with
# solver.linear left unset, which is PETSc there); prints one table row per run with
# the relative difference from CHOLMOD's reaction.
#   bench/distributed_agreement.sh [CASE] [--set key=value ...]
#     CASE: a case file, or "paper" (default) for the paper's benchmark
#   (FORMFLOW_BINARY, default build/formflow; MPIEXEC, default mpirun)
set -eu
case_file=${1:-paper}
[ $# -gt 0 ] && shift
binary=${FORMFLOW_BINARY:-build/formflow}
mpiexec=${MPIEXEC:-mpirun}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case_arg=""
[ "$case_file" != paper ] && case_arg=$case_file
# As root OpenMPI wants its switch; more ranks than cores want --oversubscribe; ranks
# that yield while they wait do not steal each other's core (changes no number).
flags="--oversubscribe"
[ "$(id -u)" -eq 0 ] && flags="$flags --allow-run-as-root"
export OMPI_MCA_mpi_yield_when_idle=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
# shellcheck disable=SC2086 # $case_arg is empty for the paper's case
"$binary" run -q --set solver.load_error=none $case_arg "$@" -o "$work/cholmod" >/dev/null || true
# shellcheck disable=SC2086
"$mpiexec" $flags -n 1 "$binary" run -q --set solver.load_error=none $case_arg "$@" --set solver.linear=petsc \
  -o "$work/np1" >/dev/null || true
for ranks in 2 4; do
  # shellcheck disable=SC2086
  "$mpiexec" $flags -n "$ranks" "$binary" run -q --set solver.load_error=none $case_arg "$@" -o "$work/np$ranks" \
    >/dev/null || true
done
/usr/bin/python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
runs = {name: json.load(open(f"{work}/{name}/summary.json"))
        for name in ("cholmod", "np1", "np2", "np4")}
reference = runs["cholmod"]["pressure"]["ram_reaction"]
print("| run | solver | ranks | dofs | method | iterations | converged | ram reaction | relative difference |")
print("|---|---|---|---|---|---|---|---|---|")
for name, run in runs.items():
    reaction = run["pressure"]["ram_reaction"]
    algebra = run["linear_algebra"]
    print(f"| {name} | {algebra['solver']} | {algebra['ranks']} | {run['mesh']['dofs']} | "
          f"{run['method']} | {run['iterations']} | {run['converged']} | {reaction:.12g} | "
          f"{abs(reaction - reference) / abs(reference):.1e} |")
PY
