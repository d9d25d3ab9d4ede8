#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Prints the Markdown table of docs/benchmarks.md from bench/results/*.json
(written by bench/run_benchmarks.sh). Medians of the repetitions."""
import json
from pathlib import Path


def median(name, k):
    path = Path("bench/results") / f"{name}_{k}.json"
    if not path.exists():
        return None
    runs = json.loads(path.read_text())["benchmarks"]
    return next(r for r in runs if r.get("aggregate_name") == "median")


print("| refinement | dofs | iterations | per iteration [ms] | assembly/it [ms] |"
      " factorisation/it [ms] | bare factorisation [ms] | per it / bare | peak memory [MiB] |")
print("|---|---|---|---|---|---|---|---|---|")
for k in (1, 2, 4, 8, 16):
    solve, bare = median("secant_solve", k), median("bare_factorization", k)
    if not solve or not bare:
        continue
    bare_ms = bare["real_time"]  # reported in ms
    per_it = solve["per_iteration_s"] * 1e3
    print(f"| {k} | {int(solve['dofs'])} | {int(solve['iterations'])} | {per_it:.2f} |"
          f" {solve['assembly_per_it_s'] * 1e3:.2f} | {solve['factorization_per_it_s'] * 1e3:.2f} |"
          f" {bare_ms:.2f} | {per_it / bare_ms:.2f} | {solve['peak_mib']:.0f} |")


# Secant vs Newton (bench/run_benchmarks.sh: method_solve/k/10μ/method).
print()
print("| refinement | dofs | μ | secant its | secant solver [s] | Newton its (+ coarse) |"
      " factorisations | GMRES its | Newton solver [s] | Newton total [s] |"
      " Newton factorisation [s] | bare factorisation [s] | Newton / bare |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for k in (1, 2, 4, 8, 16):
    path = Path("bench/results") / f"method_solve_{k}.json"
    if not path.exists():
        continue
    runs = {r["name"]: r for r in json.loads(path.read_text())["benchmarks"]}
    bare = median("bare_factorization", k)
    for mu in (0, 1, 2):
        secant = runs.get(f"method_solve/{k}/{mu}/0/iterations:1")
        newton = runs.get(f"method_solve/{k}/{mu}/1/iterations:1")
        if not newton:
            continue
        sec_its = f"{int(secant['iterations'])}" if secant else "—"
        coarse = int(newton.get("coarse_iterations", 0))
        newton_its = f"{int(newton['iterations'])}" + (f" (+{coarse})" if coarse else "")
        sec_time = f"{secant['solver_s']:.3f}" if secant else "—"
        # The bare factorisation timed in the solve's own process right after it
        # (median of 3); older result files only have the separate benchmark.
        bare_s = newton.get("bare_factorization_s") or (bare["real_time"] / 1e3 if bare else None)
        ratio = f"{newton['solver_s'] / bare_s:.1f}" if bare_s else "—"
        bare_text = f"{bare_s:.3f}" if bare_s else "—"
        counts = (f" {int(newton['factorizations'])} | {int(newton['krylov_iterations'])} |"
                  if "factorizations" in newton else " — | — |")
        print(f"| {k} | {int(newton['dofs'])} | {mu / 10:g} | {sec_its} | {sec_time} |"
              f" {newton_its} |{counts} {newton['solver_s']:.3f} | {newton['total_s']:.2f} |"
              f" {newton['factorization_s']:.3f} | {bare_text} | {ratio} |")
