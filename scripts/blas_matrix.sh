#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Reruns the default test suite (ctest -LE long) under each OpenBLAS kernel and
# thread count that a machine of our kind may pick, so that a tolerance tuned to
# one CPU's round-off shows up here rather than on someone else's machine.
# Usage: scripts/blas_matrix.sh [BUILD_DIR (default build-test)] [extra ctest arguments...]
# Prints one line per configuration (variables, pass/fail, failed tests, seconds)
# and exits 1 if any configuration failed. Run it under `nice` on a shared machine.
set -uo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-test}
shift || true
[ -d "$build_dir" ] || { echo "no build in $build_dir: run ./test or scripts/setup.sh first"; exit 2; }

# Kernels: unset (OpenBLAS picks this CPU's), the AVX-512 one, the AVX2 one, the
# oldest AVX one and an SSE3 one (Prescott: on this EPYC it is the kernel that
# exposed the tuned 1e-12 of ExactFriction.WithZeroCoefficient…/Newton);
# threads: unset (all cores), 1 and 2 with the CPU's own kernel.
configurations=(
  ""
  "OPENBLAS_CORETYPE=SkylakeX"
  "OPENBLAS_CORETYPE=Haswell"
  "OPENBLAS_CORETYPE=Sandybridge"
  "OPENBLAS_CORETYPE=Prescott"
  "OPENBLAS_NUM_THREADS=1"
  "OPENBLAS_NUM_THREADS=2"
)
status=0
for variables in "${configurations[@]}"; do
  log=$(mktemp)
  start=$(date +%s)
  # shellcheck disable=SC2086  # $variables is a list of NAME=value words
  env -u OPENBLAS_CORETYPE -u OPENBLAS_NUM_THREADS $variables \
    ctest --test-dir "$build_dir" -j2 -LE long --output-on-failure "$@" >"$log" 2>&1
  result=$?
  seconds=$(($(date +%s) - start))
  failed=$(grep -E '^\s+[0-9]+ - ' "$log" | sed -E 's/^\s+[0-9]+ - //; s/ \(.*//' | tr '\n' ' ')
  summary=$(grep -E 'tests passed' "$log" | tail -1)
  printf '%-32s %s  %4ss  %s %s\n' "${variables:-(defaults)}" \
    "$([ $result -eq 0 ] && echo pass || echo FAIL)" "$seconds" "$summary" "$failed"
  [ $result -eq 0 ] || status=1
  rm -f "$log"
done
exit $status
