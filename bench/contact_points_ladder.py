#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Nodal against face contact points under refinement (docs/friction.md "Session 9").

The exact law's default (friction.stick = "auto": the semismooth Newton) puts Γ3's
points on the nodes (nodal face rule); the augmented loop and the paper's law use the
faces' Gauss points. Both are quadratures of the same boundary integrals: this runs
one case of issue 16's grid at mesh.size = h for each h, with
  exact, nodes        the default (friction.regularization = "none")
  exact, faces        friction.stick = "augmented", contact.normals = "faces"
  regularised, nodes  d_T = 1e-6, contact.normals = "nodes"
  regularised, faces  d_T = 1e-6, the paper's discretisation
and prints one Markdown row per h with the ram reactions (the total power where a run
did not converge) and the relative differences nodes − faces.
Usage: python3 bench/contact_points_ladder.py [--binary build-test/formflow]
           [--out /tmp/ff-points] [--sizes 1 0.5 0.25 0.125] [--mu 0.5]
           [--ram sticking] [--symmetry axisymmetric] [--tolerance 1e-8]
"""
import argparse
import json
import subprocess
from pathlib import Path


def run(binary, out, name, settings):
    directory = Path(out) / name
    command = [binary, "run", "-q", "--set", "solver.load_error=none", "-o", str(directory)]
    for key, value in settings.items():
        command += ["--set", f"{key}={value}"]
    subprocess.run(command, check=False)  # exit 3 shows in the stop column
    return json.loads((directory / "summary.json").read_text())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default="build-test/formflow")
    parser.add_argument("--out", default="/tmp/ff-points")
    parser.add_argument("--sizes", nargs="+", default=["1", "0.5", "0.25", "0.125"])
    parser.add_argument("--mu", default="0.5")
    parser.add_argument("--ram", default="sticking")
    parser.add_argument("--symmetry", default="axisymmetric")
    parser.add_argument("--tolerance", default="1e-8")
    args = parser.parse_args()
    variants = {
        "exact, nodes": {"friction.regularization": '"none"'},
        "exact, faces": {"friction.regularization": '"none"', "friction.stick": '"augmented"',
                         "contact.normals": '"faces"'},
        "regularised, nodes": {"contact.normals": '"nodes"'},
        "regularised, faces": {},
    }
    print("| h | " + " | ".join(f"{v}: reaction (iterations, stop)" for v in variants) +
          " | exact: nodes/faces − 1 | regularised: nodes/faces − 1 |")
    print("|---|" + "---|" * (len(variants) + 2))
    for size in args.sizes:
        base = {"process.ram": f'"{args.ram}"', "mesh.size": size, "friction.mu": args.mu,
                "geometry.symmetry": f'"{args.symmetry}"', "solver.tolerance": args.tolerance,
                "solver.max_iterations": "200"}
        loads, cells = {}, []
        for name, settings in variants.items():
            tag = name.replace(", ", "-")
            summary = run(args.binary, args.out, f"h{size}-{tag}", {**base, **settings})
            iterations = sum(summary.get("coarse_iterations", []) or []) + summary["iterations"]
            converged = summary["stop_reason"] == "converged"
            load = summary["pressure"]["ram_reaction" if converged else "total_power"]
            loads[name] = load
            cells.append(f'{load:.6f} ({iterations}, {summary["stop_reason"]})')
        exact = loads["exact, nodes"] / loads["exact, faces"] - 1
        regularised = loads["regularised, nodes"] / loads["regularised, faces"] - 1
        print(f"| {size} | " + " | ".join(cells) + f" | {exact:+.2e} | {regularised:+.2e} |",
              flush=True)


if __name__ == "__main__":
    main()
