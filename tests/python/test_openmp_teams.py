# SPDX-License-Identifier: MIT
"""CHOLMOD's OpenMP teams are capped in the Python module too (the module exports the
interposed GOMP_parallel, src/formflow/solvers/openmp_team_limit.hpp): a run starts no
threads. Without the cap CHOLMOD 3 opens a team of four (its compiled size), whatever
OMP_NUM_THREADS says, and libgomp keeps those threads for the life of the process.
Its own file, so ctest runs it in a process of its own: nothing before it can have
started libgomp's pool."""
import os

import formflow
from conftest import MESH_I


def threads_of_this_process():
    return len(os.listdir("/proc/self/task"))


def test_a_cholmod_run_starts_no_threads():
    before = threads_of_this_process()
    result = formflow.run(formflow.Case(MESH_I))
    assert result.converged
    assert result.summary["linear_algebra"]["solver"] == "cholmod-supernodal"
    assert threads_of_this_process() == before
