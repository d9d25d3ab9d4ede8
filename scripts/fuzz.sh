#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the libFuzzer targets of tests/fuzz (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer, assertions on) into build-fuzz/ and runs each for
# SECONDS (default 60), starting from its committed corpus tests/fuzz/corpus/<target>/.
# New inputs go to build-fuzz/corpus/<target>/, never into the repository; a
# crash, leak, sanitizer report or an input slower than 1 s stops the script with
# the reproducer in build-fuzz/. Usage: scripts/fuzz.sh [SECONDS] [TARGET...];
# FUZZ_RUNS=N also stops each target after N executions. FUZZ_TIMEOUT (default
# 1) is the per-input limit in wall-clock seconds: on a loaded machine a niced
# fuzzer can wait longer than that for the CPU; raise it there and check
# stat::slowest_unit_time_sec and any reproducer's own time instead.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(case_file case_override msh_header msh_data study_vary petsc_options)

# Fuzz-only packages: ./run and ./test never need them.
packages=(clang libclang-rt-14-dev)
source scripts/install_packages.sh
install_missing_packages fuzz.sh "${packages[@]}"
compiler=$(command -v clang++-14 || command -v clang++)

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Gmsh stays out: the fuzzers never hand bytes to Gmsh's script interpreter.
cmake -S . -B build-fuzz -G Ninja "${launcher[@]}" -DCMAKE_CXX_COMPILER="$compiler" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DFORMFLOW_BUILD_FUZZERS=ON -DFORMFLOW_ENABLE_ASSERTS=ON \
  -DFORMFLOW_WITH_GMSH=OFF -DFORMFLOW_BUILD_TESTS=OFF -DFORMFLOW_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)"

# Short allocation stacks: recording full ones cost a third of the time of small inputs.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:malloc_context_size=4
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in "${targets[@]}"; do
  work=build-fuzz/corpus/$target
  mkdir -p "$work"
  echo "fuzz.sh: $target for ${seconds} s"
  # -timeout: any input taking longer is reported as a hang.
  status=0
  runs=()
  [ -n "${FUZZ_RUNS:-}" ] && runs=(-runs="$FUZZ_RUNS")
  (cd build-fuzz && "tests/fuzz/fuzz_$target" -max_total_time="$seconds" "${runs[@]}" \
    -timeout="${FUZZ_TIMEOUT:-1}" \
    -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 -artifact_prefix="$target-" \
    "corpus/$target" "../tests/fuzz/corpus/$target") >"build-fuzz/$target.log" 2>&1 || status=$?
  grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|stat::average_exec_per_sec)" \
    "build-fuzz/$target.log" || true
  if ((status)); then
    tail -n 40 "build-fuzz/$target.log"
    echo "fuzz.sh: $target failed (exit $status); reproducer build-fuzz/$target-*"
    exit 1
  fi
done
