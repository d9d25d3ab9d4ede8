#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Reruns every study shown in docs/verification.md (except the h = 1/16 benchmark
# ladders: see the commands there) and copies the pictures to docs/img/verification/.
# Usage: bench/verification_studies.sh BUILD_DIR OUTPUT_DIR
set -euo pipefail
build=${1:?build directory}
out=${2:?output directory}
here=$(cd "$(dirname "$0")/.." && pwd)
img="$here/docs/img/verification"
formflow="$build/formflow"
mkdir -p "$img" "$out"

study() {  # study NAME ARGS...: run, keep going on exit 3 (marked rungs are part of the story)
  local name=$1
  shift
  echo "== $name: formflow study $*"
  # The studies were taken with the paper's secant iteration (Newton, now the
  # default, stalls at a higher round-off floor for the tightest tolerances).
  "$formflow" study "$@" --set solver.method=secant --set solver.load_error=none -o "$out/$name" || [ $? -eq 3 ]
  cp "$out/$name/study.png" "$img/$name.png"
}

mms="--set verification.solution=smooth --set solver.tolerance=1e-8 --set solver.max_iterations=2000"
q1="--set mesh.element=Q1 --set integration.volumetric=1"
q2="--set mesh.element=Q2 --set integration.volumetric=2"
for law in power constant; do
  alpha=""
  [ $law = constant ] && alpha="--set material.alpha=1"
  for mesh in none smooth random; do
    study "mms-q1-$mesh-$law" --vary mesh.size=1/4,1/8,1/16,1/32,1/64 $mms $q1 $alpha \
      --set verification.distortion=$mesh
    study "mms-q2-$mesh-$law" --vary mesh.size=1/2,1/4,1/8,1/16,1/32 $mms $q2 $alpha \
      --set verification.distortion=$mesh
  done
done
# Locking: Q1 with the complete 2×2 volumetric rule.
study mms-q1-full-locking --vary mesh.size=1/4,1/8,1/16,1/32,1/64 $mms \
  --set mesh.element=Q1 --set integration.volumetric=2 --set material.alpha=1
study mms-q1-full-d-sweep --vary penalty.d=1,1e-1,1e-2,1e-3,1e-4 $mms \
  --set mesh.element=Q1 --set integration.volumetric=2 --set material.alpha=1 --set mesh.size=0.0625

# Penalty limit (Theorem 3.4) and conditioning on the benchmark, mesh II, Q2 2×2.
study penalty-d --vary penalty.d=1e-1,1e-2,1e-3,1e-4,1e-5,1e-7 \
  --set solver.tolerance=1e-10 --set solver.max_iterations=3000 --rcond
study penalty-d-rcond --vary penalty.d=1e-1,1e-2,1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9 \
  --set solver.tolerance=1e-8 --set solver.max_iterations=1000 --set penalty.dN=1e-2 --rcond
# Regularisation limit (Theorem 3.3) with friction, and the mollifier radius
# (descending: the last rung, the most local average, is the reference).
for mu in 0.1 0.2; do
  study "penalty-dT-mu$mu" --vary penalty.dT=1e-1,1e-2,1e-3,1e-4,1e-5,1e-8 \
    --set friction.mu=$mu --set friction.radius=1 --set solver.tolerance=1e-10 \
    --set solver.max_iterations=3000
done
study friction-radius --vary friction.radius=8,4,2,1,0.5,0.25 --set friction.mu=0.2 \
  --set solver.tolerance=1e-8 --set solver.max_iterations=2000
