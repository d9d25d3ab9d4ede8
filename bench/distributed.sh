#!/bin/sh
# SPDX-License-Identifier: MIT
# Strong scaling of a distributed run (issue 20, docs/petsc.md "Distributed runs"):
# the 3D round quarter (cases/round-rod-3d.toml, the secant iteration, direct MUMPS)
# on 1 and 2 MPI ranks, REPEAT times each; prints ranks, dofs, secant iterations, the
# median factorisation and total times, the speed-up over one rank and the largest
# peak memory of one rank (GNU time's maximum resident set of mpirun's children is
# not what time sees: each rank is timed by its own /usr/bin/time). Run it on a
# quiet machine (the lead does): two ranks on two cores leave nothing for anyone else.
#   bench/distributed.sh [REPEAT] [MESH_SIZE]   (FORMFLOW_BINARY, default build/formflow;
#                                                MPIEXEC, default mpirun)
set -eu
repeat=${1:-3}
size=${2:-0.25}
binary=${FORMFLOW_BINARY:-build/formflow}
mpiexec=${MPIEXEC:-mpirun}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
root_flags=""
[ "$(id -u)" -eq 0 ] && root_flags="--allow-run-as-root"
row() { # $1 = ranks
  ranks=$1
  i=0
  while [ "$i" -lt "$repeat" ]; do
    # One time file per rank: OMPI_COMM_WORLD_RANK names it.
    "$mpiexec" $root_flags -n "$ranks" sh -c \
      '/usr/bin/time -f "%M" -o "$0.mem.${OMPI_COMM_WORLD_RANK:-0}" "$@"' \
      "$work/$ranks.$i" "$binary" run -q --set solver.load_error=none cases/round-rod-3d.toml \
      --set mesh.size="$size" --set solver.method=secant --set solver.linear=petsc \
      -o "$work/$ranks.$i" >/dev/null
    i=$((i + 1))
  done
}
row 1
row 2
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import glob, json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
print("| ranks | dofs | secant iterations | factorisation | total | speed-up | peak memory per rank |")
print("|---|---|---|---|---|---|---|")
base = None
for ranks in (1, 2):
    runs = [json.load(open(f"{work}/{ranks}.{i}/summary.json")) for i in range(repeat)]
    memory = max(int(open(f).read().split()[-1]) for f in glob.glob(f"{work}/{ranks}.*.mem.*"))
    median = lambda key: statistics.median(r["timing_s"].get(key, 0.0) for r in runs)
    total = median("total")
    base = base or total
    first = runs[0]
    print(f"| {ranks} | {first['mesh']['dofs']:,} | {first['iterations']} | "
          f"{median('factorization'):.2f} s | {total:.2f} s | {base / total:.2f} | "
          f"{memory / 1024:.0f} MiB |".replace(",", " "))
PY
