#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Shared by ./run and ./test: install the Debian packages formflow needs (only
# those missing), then configure and build into the given directory.
# Usage: scripts/setup.sh BUILD_DIR [extra cmake arguments...]
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format
  libeigen3-dev libsuitesparse-dev libopenblas0-pthread
  libtoml11-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libcairo2-dev fonts-dejavu-core libgmsh-dev
  libgtest-dev libgmock-dev libbenchmark-dev numdiff python3-vtk9
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib python3-pil
  petsc-dev libopenmpi-dev
)
# The caller's own additions (./test: chromium for the report's browser test), in
# the same apt-get run.
read -r -a extra_packages <<<"${FORMFLOW_EXTRA_PACKAGES:-}"
packages+=("${extra_packages[@]}")
source "$(dirname "$0")/install_packages.sh"
install_missing_packages formflow "${packages[@]}"

build_dir=$1
shift
# ccache, when present, makes rebuilds and several worktrees cheap; never required.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$(dirname "$0")/.." -B "$build_dir" -G Ninja "${launcher[@]}" "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
