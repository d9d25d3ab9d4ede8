#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates the tables of docs/paper-benchmark.md.

Runs build/formflow on every variant of the paper's benchmark (SPEC §4) and on
the mesh ladders, reads each summary.json and prints Markdown tables.
Usage: python3 bench/paper_table.py [--binary build/formflow] [--out /tmp/ff-paper]
"""
import argparse
import json
import math
import subprocess
from pathlib import Path

# The paper's p_av (frictionless) where it reports one: (element, rule, mesh) -> value.
PAPER = {("Q1", 2, "II"): "3.7", ("Q1", 1, "II"): "2.573", ("Q2", 1, "I"): "2.795",
         ("Q2", 2, "I"): "2.65", ("Q2", 2, "II"): "2.675"}
MESH_SIZE = {"I": "1.6666666666666667", "II": "1"}
VARIANTS = [("Q1", 2), ("Q1", 1), ("Q2", 1), ("Q2", 2), ("Q2", 3)]


def solve(binary, out, name, settings):
    directory = Path(out) / name
    # The paper's method: docs/paper-benchmark.md reports the secant iteration's counts.
    command = [binary, "run", "-q", "--set", "solver.load_error=none", "-o", str(directory), "--set", 'solver.method="secant"']
    for key, value in settings.items():
        command += ["--set", f"{key}={value}"]
    subprocess.run(command, check=True)
    return json.loads((directory / "summary.json").read_text())


def variant_table(binary, out):
    print("| mesh | element | vol. rule | μ | paper p_av | ram reaction | power balance |"
          " total power | mean −σ_H near ram | iterations | converged |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for mesh in ("I", "II"):
        for element, rule in VARIANTS:
            for mu in ("0", "0.1", "0.2"):
                s = solve(binary, out, f"{mesh}-{element}-{rule}-{mu}",
                          {"mesh.size": MESH_SIZE[mesh], "mesh.element": element,
                           "integration.volumetric": rule, "friction.mu": mu})
                paper = PAPER.get((element, rule, mesh), "—") if mu == "0" else "—"
                p = s["pressure"]
                print(f"| {mesh} | {element} | {rule}×{rule} | {mu} | {paper} | "
                      f"{p['ram_reaction']:.4f} | {p['power_balance']:.4f} | "
                      f"{p['total_power']:.4f} | {p['mean_hydrostatic_near_ram']:.4f} | "
                      f"{s['iterations']} | {s['converged']} |")


def ladder_table(binary, out, ram):
    print(f"\nLadder, Q2 with 2×2 volumetric rule, {ram} ram, μ = 0:\n")
    print("| h | dofs | iterations | ram reaction | power balance | total power |")
    print("|---|---|---|---|---|---|")
    reactions = []
    for size in ("1", "0.5", "0.25", "0.125"):
        s = solve(binary, out, f"ladder-{ram}-{size}",
                  {"mesh.size": size, "process.ram": f'"{ram}"'})
        p = s["pressure"]
        reactions.append(p["ram_reaction"])
        print(f"| {size} | {s['mesh']['dofs']} | {s['iterations']} | {p['ram_reaction']:.4f} |"
              f" {p['power_balance']:.4f} | {p['total_power']:.4f} |")
    p1, p2, p3 = reactions[-3:]
    limit = p3 - (p3 - p2) ** 2 / ((p3 - p2) - (p2 - p1))
    order = math.log2((p2 - p1) / (p3 - p2))
    print(f"\nRichardson (Aitken) limit of the ram reaction from the last three rungs: "
          f"**{limit:.4f}**, observed order {order:.2f}.")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default="build/formflow")
    parser.add_argument("--out", default="/tmp/formflow-paper-table")
    args = parser.parse_args()
    variant_table(args.binary, args.out)
    ladder_table(args.binary, args.out, "sticking")
    ladder_table(args.binary, args.out, "sliding")


if __name__ == "__main__":
    main()
