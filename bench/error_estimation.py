#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reliability of the load's error estimate (docs/error-estimation.md).

For the sticking-ram benchmark (exact (1 + pi/2) k = 2.5708) and Hill's
frictionless wedge-die drawing (exact 2k(1 + alpha) r at Hill's reduction), on
uniform meshes: the load p_h, the estimate of |p_h - p|, the true error, the
effectivity index (estimate / true error) and whether p_h +- estimate holds p.

    python3 bench/error_estimation.py --binary build/formflow [--sizes 1,0.5,0.25]
        [--only ram|wedge15|wedge30] [--method refined|coarser|auto|linearized]

With "coarser" the two differences are p_h − p_{2h} and p_{2h} − p_{4h}; with
"refined" p_{h/2} − p_h and p_h − p_{2h} (or p_{h/4} − p_{h/2} where 2h is not made).

Prints a Markdown table. Timings are in the table only as the run's own
summary.json numbers; take them on a quiet machine.
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


def wedge_settings(degrees):
    alpha = math.radians(degrees)
    r = ref.hill_special_reduction(alpha)
    return ({"process.type": '"drawing"', "geometry.die": '"wedge"',
             "geometry.die_angle": degrees, "geometry.entry_half_height": 1,
             "geometry.container_length": 2, "geometry.exit_length": 2,
             "geometry.exit_half_height": repr(1 - r)},
            ref.hill_wedge_stress(alpha))


CASES = {
    # The benchmark, rate-insensitive (docs/validation.md), sticking ram, d = 1e-4.
    "ram": ({"process.ram": '"sticking"', "penalty.d": 1e-4}, 1 + math.pi / 2,
            [1, 0.5, 0.25]),
    "wedge15": (*wedge_settings(15), [0.25, 0.125, 0.0625]),
    "wedge30": (*wedge_settings(30), [0.25, 0.125, 0.0625]),
}


def run(binary, directory, settings, extra):
    command = [binary, "run", "-q", "-o", str(directory)]
    for key, value in settings.items():
        command += ["--set", f"{key}={value}"]
    for setting in extra:
        command += ["--set", setting]
    result = subprocess.run(command)
    if result.returncode not in (0, 3):
        raise SystemExit(f"formflow exited {result.returncode}: {' '.join(command)}")
    return json.loads((directory / "summary.json").read_text())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/formflow")
    parser.add_argument("--only", choices=sorted(CASES))
    parser.add_argument("--sizes", help="comma-separated mesh sizes (default: per case)")
    parser.add_argument("--method", default="refined", choices=["refined", "coarser", "auto", "linearized"])
    parser.add_argument("--set", action="append", default=[], help="extra KEY=VALUE overrides")
    args = parser.parse_args()
    print("| case | h | dofs | p_h | method | estimate | p_h − p | effectivity | p in p_h ± est |"
          " Δ | previous Δ | ratio q | tail | penalties p(2ε) − p(ε) |"
          " run s | estimate s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        for name, (settings, exact, sizes) in CASES.items():
            if args.only and name != args.only:
                continue
            if args.sizes:
                sizes = [float(s) for s in args.sizes.split(",")]
            for size in sizes:
                case = {"material.alpha": 1e-4, "mesh.element": '"Q2"', "mesh.size": size,
                        "solver.load_error": f'"{args.method}"', **settings}
                summary = run(args.binary, Path(scratch) / f"{name}-{size}", case, args.set)
                pressure = summary["pressure"]
                load = pressure.get("drawing_stress", pressure["ram_reaction"])
                estimate = pressure["ram_reaction_error"]
                info = pressure["error_estimate"]
                error = load - exact
                timing = summary["timing_s"]
                if estimate is None:
                    print(f"| {name} | {size:g} | {summary['mesh']['dofs']} | {load:.4f} | — | "
                          f"none ({info['unavailable']}) | {error:+.4f} | | | | | | | | | |")
                    continue
                contained = "yes" if abs(error) <= estimate else "no"
                if info["method"] == "coarser":
                    change = info["coarser_change"]
                    previous = f"{info['coarsest_change']:+.4f}"
                else:
                    change = info["refined_change"]
                    coarser = info["coarser_change"]
                    finer = info.get("finer_change")
                    # The third level: 2h where the channel admits it, else h/4.
                    previous = (f"{coarser:+.4f}" if coarser is not None
                                else f"(h/4: {finer:+.4f})" if finer is not None else "—")
                print(f"| {name} | {size:g} | {summary['mesh']['dofs']} | {load:.4f} | "
                      f"{info['method']} | {estimate:.4f} | {error:+.4f} | "
                      f"{estimate / abs(error):.2f} | {contained} | {change:+.4f} | {previous} | "
                      f"{info['tail_ratio']:.3f} | {info['discretisation']:.4f} | "
                      f"{info['penalty_change']:+.5f} | {timing['total']:.2f} | "
                      f"{timing.get('error estimate', 0):.2f} |", flush=True)


if __name__ == "__main__":
    main()
