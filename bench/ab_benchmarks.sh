#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Before/after comparison of two formflow_bench binaries, run alternately so that
# the machine's state hits both alike: the cell loops (3 rounds × 5 repetitions),
# the secant solves (3 repetitions) and the whole solves (2 rounds).
# Usage: bench/ab_benchmarks.sh BEFORE_BENCH AFTER_BENCH OUT_DIR; then
#   python3 bench/assembly_table.py OUT_DIR/asm_before_*.json -- OUT_DIR/asm_after_*.json
#   python3 bench/ab_table.py OUT_DIR
# Build a binary of another commit with: git worktree add --detach DIR COMMIT;
# cmake -S DIR -B DIR/build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DFORMFLOW_BUILD_TESTS=OFF;
# cmake --build DIR/build-bench --target formflow_bench.
set -euo pipefail
before=$1 after=$2 out=$3
mkdir -p "$out"
bench() { [ "$1" = before ] && echo "$before" || echo "$after"; }
for round in 1 2 3; do
  for side in before after; do
    OPENBLAS_NUM_THREADS=1 "$(bench $side)" \
      --benchmark_filter='secant_assembly|newton_|dual_update|coupling_product' \
      --benchmark_repetitions=5 --benchmark_out="$out/asm_${side}_$round.json" \
      --benchmark_out_format=json >/dev/null
  done
done
for side in before after; do
  "$(bench $side)" --benchmark_filter='^(secant_solve|bare_factorization)/(1|2|4|8|16)(/|$)' \
    --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_out="$out/secant_${side}.json" --benchmark_out_format=json >/dev/null
done
for round in 1 2; do
  for side in before after; do
    "$(bench $side)" --benchmark_filter='^method_solve/' \
      --benchmark_out="$out/method_${side}_$round.json" --benchmark_out_format=json >/dev/null
  done
done
