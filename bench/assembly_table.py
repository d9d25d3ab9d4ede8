#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Before/after table of the cell-loop benchmarks (bench/bench_assembly.cpp).

Usage: assembly_table.py BEFORE.json [BEFORE.json ...] -- AFTER.json [AFTER.json ...]
Each file is a --benchmark_out JSON of formflow_bench; each file's median (of
its 5 repetitions) is one sample, and the table shows the median of the samples
(run the two binaries alternately, so that the load of a shared machine hits
both alike). Prints the median wall and CPU time per pass.
"""
import json
import statistics
import sys


def samples(paths):
    times = {}
    dofs = {}
    for path in paths:
        with open(path) as f:
            for b in json.load(f)["benchmarks"]:
                if b.get("aggregate_name") != "median":
                    continue
                name = b["run_name"]
                times.setdefault(name, []).append((b["real_time"], b["cpu_time"]))
                dofs[name] = int(b.get("dofs", 0))
    return times, dofs


def main(argv):
    split = argv.index("--")
    before, dofs = samples(argv[:split])
    after, _ = samples(argv[split + 1:])
    print("| pass | dofs | runs | before wall [ms] | after wall [ms] | before CPU [ms] | after CPU [ms] | speed-up (CPU) |")
    print("|---|---|---|---|---|---|---|---|")
    for name in before:
        if name not in after:
            continue
        bw = statistics.median(t[0] for t in before[name])
        bc = statistics.median(t[1] for t in before[name])
        aw = statistics.median(t[0] for t in after[name])
        ac = statistics.median(t[1] for t in after[name])
        label = name.split("/")[0]
        print(f"| {label} | {dofs[name]} | {len(before[name])}+{len(after[name])} | {bw:.1f} | {aw:.1f} | "
              f"{bc:.1f} | {ac:.1f} | {bc / ac:.2f}× |")


if __name__ == "__main__":
    main(sys.argv[1:])
