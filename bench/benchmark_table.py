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
