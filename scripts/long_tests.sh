#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds and runs the long studies (tests/long, ctest label long) in a build
# directory ./test made (or any other): ./test does not build them, so this turns
# FORMFLOW_WITH_LONG_TESTS back on there first. Extra arguments go to ctest
# (e.g. -R RoundIsAxisymmetricLadder -V).
# Usage: scripts/long_tests.sh [BUILD_DIR] [ctest arguments...]
set -euo pipefail
build_dir=${1:-build-test}
shift || true
cmake -S "$(dirname "$0")/.." -B "$build_dir" -DFORMFLOW_WITH_LONG_TESTS=ON >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
ctest --test-dir "$build_dir" --output-on-failure -L long "$@"
