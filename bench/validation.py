#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates the tables of docs/validation.md: drawing and extrusion through
wedge (conical) dies against slip-line, upper-bound and slab results.

Runs formflow on each case (plane strip drawing, axisymmetric wire drawing and
rod extrusion), reads summary.json and prints Markdown tables. Stresses are in
units of the shear yield stress k = σ_p/√3 ≈ 1 (material.A = √3).
Usage: python3 bench/validation.py [--binary build/formflow] [--out /tmp/ff-validation]
                                   [--size 0.0625] [--alpha 1e-4] [--normals faces|nodes]
                                   [--method newton|secant]
"""
import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import forming_references as ref  # noqa: E402


class Runner:
    def __init__(self, binary, out, size, alpha, normals="faces", method="newton"):
        self.binary, self.out, self.size, self.alpha = binary, Path(out), size, alpha
        self.normals, self.method = normals, method

    def solve(self, name, settings):
        """Unit entry half height, entry part 2 long, exit part 2 long, Q2."""
        base = {"geometry.die": "wedge", "geometry.entry_half_height": 1,
                "geometry.container_length": 2, "geometry.exit_length": 2,
                "mesh.size": self.size, "mesh.element": "Q2", "material.alpha": self.alpha,
                "solver.max_iterations": 2000, "contact.normals": f'"{self.normals}"'}
        base.update(settings)
        directory = self.out / name
        # Newton (the default) by default: the secant iteration's stop at δ = 1e-4 on the
        # velocity change leaves the load 5e-4 (h = 1/16) to 1.5e-3 (1/32) above its
        # converged value on Hill's 15° wedge, more than the ladders' last differences
        # can afford (docs/validation.md, "What the wedge ladders converge to").
        command = [self.binary, "run", "-q", "--set", "solver.load_error=none", "-o", str(directory),
                   "--set", f'solver.method="{self.method}"']
        for key, value in base.items():
            command += ["--set", f"{key}={value}"]
        result = subprocess.run(command)
        if result.returncode not in (0, 3):
            raise SystemExit(f"{name}: formflow exited {result.returncode}")
        summary = json.loads((directory / "summary.json").read_text())
        pressure = summary["pressure"]
        value = pressure.get("drawing_stress", pressure["ram_reaction"])
        return value, summary["iterations"], summary["converged"]


def mark(converged):
    return "" if converged else " (not converged)"


def plane_slip_line_table(run):
    print("| α | r | ideal 2k ln(1/(1−r)) | slip line 2k(1+α)r | radial upper bound |"
          " ours, drawing σ_d | ours / slip line | ours, extrusion p | iterations |")
    print("|---|---|---|---|---|---|---|---|---|")
    for degrees in (5, 10, 15, 20, 30):
        alpha = math.radians(degrees)
        r = ref.hill_special_reduction(alpha)
        exit_height = 1 - r
        drawing, it_d, ok_d = run.solve(f"plane-draw-{degrees}", {
            "process.type": "drawing", "geometry.die_angle": degrees,
            "geometry.exit_half_height": repr(exit_height)})
        extrusion, it_e, ok_e = run.solve(f"plane-extrude-{degrees}", {
            "process.type": "extrusion", "process.ram": "sticking", "geometry.die_angle": degrees,
            "geometry.exit_half_height": repr(exit_height)})
        exact = ref.hill_wedge_stress(alpha)
        print(f"| {degrees}° | {r:.4f} | {ref.plane_ideal(r):.4f} | {exact:.4f} | "
              f"{ref.plane_radial_upper_bound(alpha, r):.4f} | {drawing:.4f}{mark(ok_d)} | "
              f"{drawing / exact:.4f} | {extrusion:.4f}{mark(ok_e)} | {it_d}, {it_e} |")


def plane_friction_table(run):
    print("| α | r | μ | ideal | radial upper bound (μ = 0) | Sachs slab | ours σ_d |"
          " ours − Sachs | iterations |")
    print("|---|---|---|---|---|---|---|---|---|")
    for degrees, r in ((10, 0.2), (10, 0.3), (15, 0.3)):
        alpha = math.radians(degrees)
        for mu in (0.0, 0.05, 0.1):
            value, iterations, ok = run.solve(f"plane-draw-{degrees}-{r}-{mu}", {
                "process.type": "drawing", "geometry.die_angle": degrees,
                "geometry.exit_half_height": repr(1 - r), "friction.mu": mu})
            sachs = ref.plane_sachs(alpha, r, mu)
            print(f"| {degrees}° | {r} | {mu} | {ref.plane_ideal(r):.4f} | "
                  f"{ref.plane_radial_upper_bound(alpha, r):.4f} | {sachs:.4f} | "
                  f"{value:.4f}{mark(ok)} | {value - sachs:+.4f} | {iterations} |")


def axisymmetric_table(run, process):
    print("| α | area reduction r | μ | ideal σ_0 ln(1/(1−r)) | Avitzur upper bound (m = 0) |"
          " Sachs slab | ours | ours / Avitzur | iterations |")
    print("|---|---|---|---|---|---|---|---|---|")
    cases = ((6, 0.2), (10, 0.2), (15, 0.3), (30, 0.3)) if process == "drawing" \
        else ((15, 0.5), (30, 0.5), (45, 0.5))
    for degrees, r in cases:
        alpha = math.radians(degrees)
        for mu in ((0.0, 0.05) if process == "drawing" else (0.0,)):
            settings = {"process.type": process, "geometry.symmetry": "axisymmetric",
                        "geometry.die_angle": degrees,
                        "geometry.exit_half_height": repr(math.sqrt(1 - r)), "friction.mu": mu}
            if process == "extrusion":
                settings["process.ram"] = "sticking"
                settings["friction.on"] = '["die"]'
            value, iterations, ok = run.solve(f"axi-{process}-{degrees}-{r}-{mu}", settings)
            bound = ref.avitzur_upper_bound(alpha, r)
            sachs = ref.axisymmetric_sachs(alpha, r, mu)
            print(f"| {degrees}° | {r} | {mu} | {ref.axisymmetric_ideal(r):.4f} | {bound:.4f} | "
                  f"{sachs:.4f} | {value:.4f}{mark(ok)} | {value / bound:.4f} | {iterations} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/formflow")
    parser.add_argument("--out", default="/tmp/ff-validation")
    parser.add_argument("--size", default="0.0625")
    parser.add_argument("--alpha", default="1e-4")
    parser.add_argument("--only", choices=["slip-line", "friction", "wire", "rod"])
    parser.add_argument("--normals", default="faces", choices=["faces", "nodes"],
                        help="contact.normals (docs/validation.md, contact normals)")
    parser.add_argument("--method", default="newton", choices=["newton", "secant"],
                        help="solver.method; the secant's δ = 1e-4 stop leaves the load ~1e-3 high")
    args = parser.parse_args()
    run = Runner(args.binary, args.out, args.size, args.alpha, args.normals, args.method)
    tables = {"slip-line": ("Plane-strain wedge dies, frictionless, Hill's special reduction",
                            lambda: plane_slip_line_table(run)),
              "friction": ("Plane-strain strip drawing with Coulomb friction",
                           lambda: plane_friction_table(run)),
              "wire": ("Axisymmetric wire drawing", lambda: axisymmetric_table(run, "drawing")),
              "rod": ("Axisymmetric rod extrusion (conical die)",
                      lambda: axisymmetric_table(run, "extrusion"))}
    for name, (title, table) in tables.items():
        if args.only and name != args.only:
            continue
        print(f"\n### {title} (mesh.size = {args.size}, material.alpha = {args.alpha}, "
              f"contact.normals = {args.normals})\n")
        table()


if __name__ == "__main__":
    main()
