#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs each benchmark size in its own process (so peak memory is per size) and
# writes bench/results/<name>.json. Usage: bench/run_benchmarks.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-bench}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFORMFLOW_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target formflow_bench -j"$(nproc)"
mkdir -p bench/results
for k in 1 2 4 8 16; do
  for name in secant_solve bare_factorization; do
    "$build/bench/formflow_bench" --benchmark_filter="^${name}/${k}(/|\$)" --benchmark_repetitions=3 \
      --benchmark_report_aggregates_only=true \
      --benchmark_out="bench/results/${name}_${k}.json" --benchmark_out_format=json
  done
done
# Secant vs Newton, whole solves: method_solve/k/10μ/method (0 secant, 1 Newton).
for k in 1 2 4 8 16; do
  "$build/bench/formflow_bench" --benchmark_filter="^method_solve/${k}/" \
    --benchmark_out="bench/results/method_solve_${k}.json" --benchmark_out_format=json
done
