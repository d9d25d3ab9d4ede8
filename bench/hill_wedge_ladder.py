#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Hill's frictionless wedge drawing on a ladder of uniform meshes, Newton to a
tight δ: what the discrete loads converge to (docs/validation.md, "What the wedge
ladders converge to"; docs/error-estimation.md step 5 (iv)).

    python3 bench/hill_wedge_ladder.py --binary build/formflow [--angles 15,30]
        [--sizes 0.5,0.25,0.125,0.0625,0.03125,0.015625] [--tolerance 1e-10]
        [--set KEY=VALUE ...]

For each angle: p_h, its difference from the previous rung, the ratio of
successive differences q, the error against Hill's 2k(1 + α) r, the limit the
geometric tail with max(½, q) gives from each rung (p_h + Δ q/(1 − q)) and the
ratio that the previous rung's tail |p_h − p_{2h}|/(1 − q) would have needed to
reach Hill's value exactly. Settings as bench/error_estimation.py (H_in = 1, entry and
exit parts 2 long, Q2, 2×2 volumetric rule, d = 1e-3, material.alpha = 1e-4).
The h = 1/64 rungs take 20–50 s each; the rest a few seconds.
"""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import forming_references as ref  # noqa: E402


def drawing_stress(binary, directory, degrees, size, tolerance, extra):
    r = ref.hill_special_reduction(math.radians(degrees))
    settings = {"process.type": '"drawing"', "geometry.die": '"wedge"',
                "geometry.die_angle": degrees, "geometry.entry_half_height": 1,
                "geometry.container_length": 2, "geometry.exit_length": 2,
                "geometry.exit_half_height": repr(1 - r), "mesh.element": '"Q2"',
                "mesh.size": size, "material.alpha": 1e-4, "solver.tolerance": tolerance}
    command = [binary, "run", "-q", "--set", "solver.load_error=none", "-o", str(directory)]
    for key, value in settings.items():
        command += ["--set", f"{key}={value}"]
    for setting in extra:
        command += ["--set", setting]
    if subprocess.run(command).returncode != 0:
        raise SystemExit(f"formflow failed or did not converge: {' '.join(command)}")
    summary = json.loads((directory / "summary.json").read_text())
    return summary["pressure"]["drawing_stress"], summary["mesh"]["dofs"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/formflow")
    parser.add_argument("--angles", default="15,30")
    parser.add_argument("--sizes", default="0.5,0.25,0.125,0.0625,0.03125,0.015625")
    parser.add_argument("--tolerance", default="1e-10")
    parser.add_argument("--set", action="append", default=[], help="extra KEY=VALUE overrides")
    args = parser.parse_args()
    sizes = [float(s) for s in args.sizes.split(",")]
    with tempfile.TemporaryDirectory() as scratch:
        for degrees in (float(a) for a in args.angles.split(",")):
            exact = ref.hill_wedge_stress(math.radians(degrees))
            print(f"\n{degrees:g}°: Hill 2k(1 + α) r = {exact:.6f}\n")
            print("| h | dofs | p_h | p_h − p_{2h} | ratio q | p_h − Hill |"
                  " tail limit p_h + Δ max(½,q)/(1 − max(½,q)) | q that rung 2h's tail needs |")
            print("|---|---|---|---|---|---|---|---|")
            loads = []
            for size in sizes:
                load, dofs = drawing_stress(args.binary, Path(scratch) / f"{degrees}-{size}",
                                            degrees, size, args.tolerance, args.set)
                loads.append(load)
                change = ratio = limit = needed = None
                if len(loads) >= 2:
                    change = loads[-1] - loads[-2]
                if len(loads) >= 3:
                    ratio = change / (loads[-2] - loads[-3])
                    q = max(0.5, ratio)
                    limit = load + change * q / (1 - q)
                    # The rung 2h's tail |Δ|/(1 − q), Δ = p_h − p_{2h} < 0, equals its
                    # error against Hill when q = 1 − |Δ|/(p_{2h} − Hill).
                    needed = 1 - abs(change) / (loads[-2] - exact)
                fmt = lambda x, spec: "—" if x is None else format(x, spec)  # noqa: E731
                print(f"| 1/{round(1 / size)} | {dofs} | {load:.7f} | {fmt(change, '+.7f')} | "
                      f"{fmt(ratio, '.4f')} | {load - exact:+.7f} | {fmt(limit, '.6f')} | "
                      f"{fmt(needed, '.4f')} |", flush=True)


if __name__ == "__main__":
    main()
