#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds formflow and its tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (GCC, its own build directory) and runs the default suite (ctest -LE long).
# Any report stops the process that made it (halt_on_error) and fails its test.
# Usage: scripts/sanitize.sh [BUILD_DIR (default build-sanitize)] [extra ctest arguments...]
# Takes a while on 2 cores: run it under `nice -n 15` on a shared machine.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-sanitize}
shift || true
# -O1 -g1: the usual sanitizer build (optimised enough to run the suite in minutes,
# line tables for the reports' stack traces), and half the compile time of -O2 -g
# on Eigen-heavy sources; NDEBUG as in ./test's build (FF_ASSERT stays on).
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
scripts/setup.sh "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1 -DNDEBUG" \
  -DFORMFLOW_WITH_GMSH=ON \
  -DFORMFLOW_ENABLE_ASSERTS=ON -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined"
# The suppression file lists reports inside third-party libraries only, each with its reason.
suppressions="$PWD/scripts/sanitize.supp"
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
[ -f "$suppressions" ] && export LSAN_OPTIONS="suppressions=$suppressions:print_suppressions=0"
# Sanitized code runs 2–4 times slower: a longer per-test timeout than ./test's.
ctest --test-dir "$build_dir" -j2 -LE long --output-on-failure --timeout 1800 "$@"
echo "sanitize: ASan + UBSan suite clean"
