#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates the tables of docs/friction.md.

Runs build/formflow on the paper's benchmark (Q2, 2x2 volumetric rule, mesh II)
with Coulomb friction on the container and the die, for mu = 0.1 and 0.2 and
mollifier radius 0 (local) and 1 (one cell), with exact friction
(friction.regularization = "none") and with the regularised law on the ladder
d_T = 1e-1 ... 1e-6 (relative to the ram speed u0 = 1). Every solve is iterated to
solver.tolerance = 1e-8 so the differences to the exact solution are not
iteration error. A first table compares exact and regularised (d_T = 1e-6)
friction at the paper's tolerance 1e-4. Prints Markdown tables. All of these run
the paper's secant iteration (solver.method = "secant").

With --newton-cost, prints instead the cost table of exact friction by Newton
(solver.method = "newton", solvers/augmented_newton.hpp) against the secant loop,
at delta = 1e-4 and 1e-8, for the same four cases.
Usage: python3 bench/friction_table.py [--binary build/formflow] [--out /tmp/ff-friction]
                                       [--newton-cost]
"""
import argparse
import json
import math
import re
import subprocess
from pathlib import Path

LADDER = ["1e-1", "1e-2", "1e-3", "1e-4", "1e-5", "1e-6"]
TOLERANCE = "1e-8"


def solve(binary, out, name, settings, tolerance=TOLERANCE, method="secant"):
    directory = Path(out) / name
    command = [binary, "run", "-q", "--set", "solver.load_error=none", "-o", str(directory), "--set", f"solver.tolerance={tolerance}",
               "--set", "solver.max_iterations=100000", "--set", f'solver.method="{method}"']
    for key, value in settings.items():
        command += ["--set", f"{key}={value}"]
    subprocess.run(command, check=False)  # exit 3 is reported in the table
    summary = json.loads((directory / "summary.json").read_text())
    return summary, nodal_velocity(directory / "fields.vtu")


def nodal_velocity(vtu):
    """The velocity point array of fields.vtu (ASCII), flattened."""
    text = vtu.read_text()
    match = re.search(r'<DataArray[^>]*Name="velocity"[^>]*>(.*?)</DataArray>', text, re.S)
    return [float(value) for value in match.group(1).split()]


def relative_difference(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / sum(y * y for y in b))


def zones(summary):
    contact = summary["contact"]
    return contact["container"]["stick_length"], contact["die"]["stick_length"]


def base_settings(mu, radius):
    return {"mesh.size": "1", "mesh.element": "Q2", "integration.volumetric": "2",
            "friction.mu": mu, "friction.radius": radius, "friction.on": '["container","die"]'}


def paper_tolerance_table(binary, out):
    print("| μ | radius h | friction | ram reaction | total power | stick container |"
          " stick die | slip die | iterations | multiplier updates | stop |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for mu in ("0.1", "0.2"):
        for radius in ("0", "1"):
            for law in ("regularized", "none"):
                summary, _ = solve(binary, out, f"paper-mu{mu}-h{radius}-{law}",
                                   {**base_settings(mu, radius),
                                    "friction.regularization": law}, tolerance="1e-4")
                contact = summary["contact"]
                updates = contact.get("augmented_lagrangian", {}).get("outer_iterations", "—")
                name = "exact" if law == "none" else "d_T = 1e-6"
                print(f"| {mu} | {radius} | {name} | {summary['pressure']['ram_reaction']:.5f} |"
                      f" {summary['pressure']['total_power']:.5f} |"
                      f" {contact['container']['stick_length']:.3f} |"
                      f" {contact['die']['stick_length']:.3f} | {contact['die']['slip_length']:.3f} |"
                      f" {summary['iterations']} | {updates} | {summary['stop_reason']} |")


def table(binary, out, mu, radius):
    base = base_settings(mu, radius)
    exact, exact_velocity = solve(binary, out, f"mu{mu}-h{radius}-exact",
                                  {**base, "friction.regularization": "none"})
    print(f"\n**μ = {mu}, radius h = {radius}** (container length 10, die face length 5)\n")
    print("| friction | ram reaction | p − p_exact | ‖u − u_exact‖/‖u_exact‖ |"
          " stick length container | stick length die | iterations | stop |")
    print("|---|---|---|---|---|---|---|---|")
    pressure = exact["pressure"]["ram_reaction"]
    stick = zones(exact)
    outer = exact["contact"]["augmented_lagrangian"]["outer_iterations"]
    print(f"| exact (none), {outer} multiplier updates | {pressure:.6f} | — | — | {stick[0]:.3f} |"
          f" {stick[1]:.3f} | {exact['iterations']} | {exact['stop_reason']} |")
    for d_t in LADDER:
        summary, velocity = solve(binary, out, f"mu{mu}-h{radius}-dT{d_t}",
                                  {**base, "friction.regularization": "regularized",
                                   "penalty.dT": d_t})
        stick = zones(summary)
        difference = summary["pressure"]["ram_reaction"] - pressure
        print(f"| d_T = {d_t} | {summary['pressure']['ram_reaction']:.6f} | {difference:+.2e} |"
              f" {relative_difference(velocity, exact_velocity):.2e} | {stick[0]:.3f} |"
              f" {stick[1]:.3f} | {summary['iterations']} | {summary['stop_reason']} |")


def newton_cost_table(binary, out):
    print("| μ | radius h | δ | Newton iterations | multiplier updates | ram reaction |"
          " total power | stick die | secant iterations | secant updates | secant ram reaction |"
          " secant stick die | Newton s | secant s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for tolerance in ("1e-4", "1e-8"):
        for mu in ("0.1", "0.2"):
            for radius in ("0", "1"):
                settings = {**base_settings(mu, radius), "friction.regularization": "none"}
                runs = [solve(binary, out, f"cost-{method}-mu{mu}-h{radius}-tol{tolerance}",
                              settings, tolerance=tolerance, method=method)[0]
                        for method in ("newton", "secant")]
                cells = []
                for summary in runs:
                    updates = summary["contact"]["augmented_lagrangian"]["outer_iterations"]
                    cells.append((summary["iterations"], updates,
                                  summary["pressure"]["ram_reaction"],
                                  summary["pressure"]["total_power"],
                                  summary["contact"]["die"]["stick_length"],
                                  summary["timing_s"]["total"], summary["stop_reason"]))
                newton, secant = cells
                print(f"| {mu} | {radius} | {tolerance} | {newton[0]} | {newton[1]} | {newton[2]:.6f} |"
                      f" {newton[3]:.6f} | {newton[4]:.3f} | {secant[0]} | {secant[1]} |"
                      f" {secant[2]:.6f} | {secant[4]:.3f} | {newton[5]:.2f} | {secant[5]:.2f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/formflow")
    parser.add_argument("--out", default="/tmp/ff-friction")
    parser.add_argument("--newton-cost", action="store_true",
                        help="print only the Newton-vs-secant cost table of exact friction")
    args = parser.parse_args()
    if args.newton_cost:
        newton_cost_table(args.binary, args.out)
        return
    paper_tolerance_table(args.binary, args.out)
    for mu in ("0.1", "0.2"):
        for radius in ("0", "1"):
            table(args.binary, args.out, mu, radius)


if __name__ == "__main__":
    main()
