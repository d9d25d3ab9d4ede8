#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Where the iterative PETSc path beats CHOLMOD (issue 20, docs/benchmarks.md
"Crossover: CHOLMOD against the iterative PETSc path").

Runs one case at growing mesh sizes by
  cholmod    the default solve (penalty formulation, CHOLMOD, Newton with its coarse levels);
  cholmod-condensed  the same with the iterative path's discretisation (mixed Q2-P1disc,
             the pressure condensed cell by cell: the same discrete problem, so the same
             load to the loops' tolerance);
  iterative  the mixed Q2-P1disc problem kept as a saddle point, PETSc FGMRES + fieldsplit
             Schur with BoomerAMG on the velocity (the secant loop: the only loop that path
             has), its default options (docs/petsc.md).
Records the velocity dofs, the unknowns of the system solved, the nonlinear steps, the
Krylov iterations, CPU time (user + sys of the process, OPENBLAS_NUM_THREADS=1), peak RSS
(GNU time's maximum resident set) and the ram reaction. CPU times on a shared machine are
not timings: label them so. With --steps N both paths stop after N nonlinear steps
(exit 3) and the table gives the CPU per step as well, which is what extrapolates to a
larger mesh (the step counts of full runs are in the --steps-less rows).

  bench/crossover.py [--binary build/formflow] [--geometry 2d|3d] [--sizes 2.5 1.25 ...]
                     [--paths cholmod iterative] [--steps N] [--set key=value ...]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

GEOMETRIES = {
    # the paper's plane-strain channel (no case file) and the 3D round quarter
    "2d": ([], ["2.5", "1.25", "0.625", "0.3125", "0.15625"]),
    "3d": (["cases/round-rod-3d.toml"], ["0.5", "0.25", "0.125"]),
}
PATHS = {
    "cholmod": ["--set", "solver.linear=cholmod"],
    # the iterative path's discretisation (Q2-P1disc, d = 1e-3), condensed cell by cell
    "cholmod-condensed": ["--set", "solver.linear=cholmod", "--set", "formulation.type=mixed",
                          "--set", "formulation.pressure=P1disc"],
    "iterative": ["--set", "formulation.type=mixed", "--set", "formulation.pressure=P1disc",
                  "--set", "formulation.discontinuous_pressure=saddle_point",
                  "--set", "solver.linear=petsc", "--set", "solver.method=secant",
                  "--set", "solver.max_iterations=300"],
}


def run(binary, case, size, path, steps, extra, work):
    out = os.path.join(work, f"{path}-{size}")
    timing = out + ".time"
    command = ["/usr/bin/time", "-f", "%e %U %S %M", "-o", timing, binary, "run", "-q", "--set", "solver.load_error=none", *case,
               "-o", out, "--set", f"mesh.size={size}", *PATHS[path], *extra]
    if steps:
        command += ["--set", f"solver.max_iterations={steps}", "--set",
                    "solver.coarse_levels=0"]
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    finished = subprocess.run(command, env=env, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
    wall, user, system, rss_kb = open(timing).read().split()[-4:]
    try:
        summary = json.load(open(os.path.join(out, "summary.json")))
    except OSError:
        return {"path": path, "size": size, "failed": finished.stderr.strip()[:200]}
    algebra = summary["linear_algebra"]
    krylov = [n for n in (algebra.get("iterations_per_step") or []) if n is not None]
    cpu = float(user) + float(system)
    nonlinear = summary["iterations"]
    return {
        "path": path, "size": size, "exit": finished.returncode,
        "dofs": summary["mesh"]["dofs"], "steps": nonlinear,
        "stop": summary["stop_reason"], "factorizations": algebra.get("factorizations"),
        "krylov_median": sorted(krylov)[len(krylov) // 2] if krylov else None,
        "cpu_s": cpu, "wall_s": float(wall), "cpu_per_step_s": cpu / max(nonlinear, 1),
        "rss_mib": int(rss_kb) / 1024,
        "ram_reaction": summary["pressure"]["ram_reaction"],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default="build/formflow")
    parser.add_argument("--geometry", choices=GEOMETRIES, default="3d")
    parser.add_argument("--sizes", nargs="+")
    parser.add_argument("--paths", nargs="+", choices=PATHS, default=["cholmod-condensed", "iterative"])
    parser.add_argument("--steps", type=int, default=0)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    parser.add_argument("--json", help="also append every row to this file (JSON lines)")
    arguments = parser.parse_args()
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    case, sizes = GEOMETRIES[arguments.geometry]
    extra = [item for value in arguments.sets for item in ("--set", value)]
    print("CPU (user + sys, one BLAS thread) and wall times: say whether the machine was quiet")
    print("| geometry | h | path | velocity dofs | steps (stop) | factorisations | "
          "Krylov median | CPU | wall | CPU per step | peak RSS | ram reaction |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for size in arguments.sizes or sizes:
            for path in arguments.paths:
                row = run(arguments.binary, case, size, path, arguments.steps, extra, work)
                row["geometry"] = arguments.geometry
                if arguments.json:
                    with open(arguments.json, "a") as log:
                        log.write(json.dumps(row) + "\n")
                if "failed" in row:
                    print(f"| {arguments.geometry} | {size} | {path} | failed: {row['failed']} |")
                    continue
                print(f"| {arguments.geometry} | {size} | {path} | {row['dofs']:,} | "
                      f"{row['steps']} ({row['stop']}) | {row['factorizations']} | "
                      f"{row['krylov_median'] if row['krylov_median'] is not None else '—'} | "
                      f"{row['cpu_s']:.1f} s | {row['wall_s']:.1f} s | {row['cpu_per_step_s']:.2f} s | "
                      f"{row['rss_mib']:.0f} MiB | {row['ram_reaction']:.6f} |"
                      .replace(",", " "), flush=True)


if __name__ == "__main__":
    sys.exit(main())
