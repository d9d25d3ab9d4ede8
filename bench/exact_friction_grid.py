#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Iterations of exact Coulomb friction by Newton over issue 16's grid.

Runs `formflow run` on the paper's channel (friction on container and die, local
threshold) for {sliding, sticking ram} x mesh.size x mu x {Q2 2x2, Q1 1x1} x
{plane, axisymmetric} with friction.regularization = "none", and with --regularised
also with the paper's d_T = 1e-6, and prints one Markdown row per case: Newton
iterations (coarse levels + fine), stop reason, ram reaction (and the regularised
one), the Coulomb residual, the stick lengths and the wall time of each run.
The exact runs take the exact law's default (since session 9 the semismooth Newton on
nodal contact points); --set friction.stick='"augmented"' runs the augmented loop on
face points, and with --regularised, --set contact.normals='"nodes"' puts the
regularised runs on the exact runs' points.
Usage: python3 bench/exact_friction_grid.py [--binary build-test/formflow]
           [--out /tmp/ff-grid] [--sizes 1 0.5] [--mus 0.1 0.2 0.3] [--elements Q2 Q1]
           [--symmetries plane axisymmetric] [--tolerance 1e-4] [--regularised] [--counts]
           [--set KEY=VALUE ...]   (extra case keys for every run, e.g. contact.normals='"nodes"';
                                    friction.stick is passed to the exact runs only)
Columns besides those: the total power / (u0 H) (equals the reaction in balance) and
the residual's power |u_f.R_f|/|u.f|_driven of summary.json (= |reaction - total power|/reaction).
"""
import argparse
import json
import subprocess
import time
from pathlib import Path


def run(binary, out, name, settings):
    directory = Path(out) / name
    command = [binary, "run", "-q", "--set", "solver.load_error=none", "-o", str(directory)]
    for key, value in settings.items():
        command += ["--set", f"{key}={value}"]
    start = time.monotonic()
    subprocess.run(command, check=False)  # exit 3 is reported in the table
    seconds = time.monotonic() - start
    return json.loads((directory / "summary.json").read_text()), seconds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default="build-test/formflow")
    parser.add_argument("--out", default="/tmp/ff-grid")
    parser.add_argument("--sizes", nargs="+", default=["1", "0.5", "0.25"])
    parser.add_argument("--mus", nargs="+", default=["0.05", "0.1", "0.2", "0.3", "0.5"])
    parser.add_argument("--elements", nargs="+", default=["Q2", "Q1"])
    parser.add_argument("--symmetries", nargs="+", default=["plane", "axisymmetric"])
    parser.add_argument("--rams", nargs="+", default=["sliding", "sticking"])
    parser.add_argument("--tolerance", default="1e-4")
    parser.add_argument("--regularised", action="store_true")
    parser.add_argument("--counts", action="store_true",
                        help="after the rows, one row per symmetry, element, ram and h with "
                             "the iterations (coarse + fine) of each mu")
    parser.add_argument("--set", nargs="*", default=[], dest="extra",
                        help="KEY=VALUE case settings added to every run")
    args = parser.parse_args()
    extra = dict(item.split("=", 1) for item in args.extra)
    counts = {}  # (symmetry, element, ram, h) -> {mu: "n" or "n stop_reason"}
    print("| ram | h | μ | element | symmetry | iterations (coarse + fine) | stop | reaction |"
          " total power | regularised reaction | Coulomb residual | residual's power |"
          " stick container | stick die | s exact | s regularised |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for symmetry in args.symmetries:
        for element in args.elements:
            for ram in args.rams:
                for size in args.sizes:
                    for mu in args.mus:
                        settings = {"process.ram": f'"{ram}"', "mesh.size": size,
                                    "friction.mu": mu, "mesh.element": f'"{element}"',
                                    "integration.volumetric": "2" if element == "Q2" else "1",
                                    "geometry.symmetry": f'"{symmetry}"',
                                    "solver.tolerance": args.tolerance,
                                    "solver.max_iterations": "200", **extra}
                        name = f"{symmetry}-{element}-{ram}-h{size}-mu{mu}"
                        exact, s_exact = run(args.binary, args.out, name + "-exact",
                                             {**settings, "friction.regularization": '"none"'})
                        coarse = sum(exact.get("coarse_iterations", []) or [])
                        total = coarse + exact["iterations"]
                        stop = exact["stop_reason"]
                        counts.setdefault((symmetry, element, ram, size), {})[mu] = (
                            f"{total}" if stop == "converged" else f"**{total} {stop}**")
                        contact = exact["contact"]
                        regularised_reaction, s_reg = "—", "—"
                        if args.regularised:
                            # friction.stick holds the exact law's stuck points only.
                            reg_settings = {k: v for k, v in settings.items()
                                            if k != "friction.stick"}
                            reg, seconds = run(args.binary, args.out, name + "-reg", reg_settings)
                            regularised_reaction = f'{reg["pressure"]["ram_reaction"]:.6f}'
                            s_reg = f"{seconds:.2f}"
                        print(f'| {ram} | {size} | {mu} | {element} | {symmetry} | '
                              f'{coarse} + {exact["iterations"]} = {coarse + exact["iterations"]} | '
                              f'{exact["stop_reason"]} | {exact["pressure"]["ram_reaction"]:.6f} | '
                              f'{exact["pressure"]["total_power"]:.6f} | '
                              f'{regularised_reaction} | {contact.get("friction_residual", 0):.1e} | '
                              f'{contact.get("power_residual", 0):.1e} | '
                              f'{contact["container"]["stick_length"]:.3f} | '
                              f'{contact["die"]["stick_length"]:.3f} | {s_exact:.2f} | {s_reg} |',
                              flush=True)

    if args.counts:
        print()
        print("| symmetry | element | ram | h | " + " | ".join(f"μ = {mu}" for mu in args.mus) +
              " |")
        print("|---|---|---|---|" + "---|" * len(args.mus))
        for (symmetry, element, ram, size), row in counts.items():
            print(f"| {symmetry} | {element} | {ram} | {size} | " +
                  " | ".join(row[mu] for mu in args.mus) + " |")


if __name__ == "__main__":
    main()
