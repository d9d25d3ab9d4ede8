#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Several formflow binaries (or settings) on one adaptive case, run in turn, round after
# round, so that a noisy host's drift falls on all of them alike (docs/benchmarks.md
# "Cheap cycles by default"). Prints each run's wall time, final dofs, load and bar, then
# each variant's median and range.
#
#   python3 bench/adaptive_alternating.py 5 cases/adaptive-sticking-ram.toml \
#       --variant "old=/path/to/old/checkout:build/formflow" \
#       --variant "full=.:build/formflow:--set solver.load_error=refined" \
#       --variant "default=.:build/formflow"
#
# A variant is LABEL=ROOT:BINARY[:EXTRA ARGS]: the binary and the case file are taken
# from ROOT (a checkout), so an older binary runs its own version of the case.
import argparse
import json
import shlex
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("rounds", type=int)
    parser.add_argument("case", help="the case file, relative to each variant's ROOT")
    parser.add_argument("--variant", action="append", required=True)
    parser.add_argument("--set", action="append", default=[], dest="overrides",
                        help="a key override for every variant (formflow's --set)")
    args = parser.parse_args()
    variants = []
    for text in args.variant:
        label, rest = text.split("=", 1)
        parts = rest.split(":", 2)
        root, binary = Path(parts[0]), parts[1]
        extra = shlex.split(parts[2]) if len(parts) > 2 else []
        variants.append((label, root / binary, root / args.case, extra))
    common = [item for key in args.overrides for item in ("--set", key)]
    times = {label: [] for label, *_ in variants}
    with tempfile.TemporaryDirectory() as work:
        for round_ in range(args.rounds):
            for label, binary, case, extra in variants:
                out = Path(work) / f"{label}-{round_}"
                start = time.monotonic()
                code = subprocess.run([str(binary), "run", "-q", str(case), *common, *extra,
                                       "-o", str(out)], stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL).returncode
                wall = time.monotonic() - start
                times[label].append(wall)
                summary = json.loads((out / "summary.json").read_text())
                cycles = summary["adapt"]["cycles"]
                last = cycles[-1]
                print(f"{round_} {label:10s} {wall:6.2f} s  exit {code}  {len(cycles)} entries  "
                      f"{last['dofs']} dofs  p = {last['load']:.6f} ± {last['estimate']:.5f}  "
                      f"{summary['adapt']['stop']}", flush=True)
    for label, values in times.items():
        print(f"{label}: median {statistics.median(values):.2f} s "
              f"({min(values):.2f} … {max(values):.2f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
