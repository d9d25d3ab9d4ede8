# SPDX-License-Identifier: MIT
"""Ctrl-C (SIGINT) in Python stops a solve at its next iteration: KeyboardInterrupt, and
the interpreter can solve again."""
import os
import signal
import subprocess
import sys
import textwrap
import time

CHILD = textwrap.dedent("""
    import time
    import formflow
    stamps = []
    def progress(record):
        stamps.append(time.monotonic())
        if len(stamps) == 1:
            print("solving", flush=True)
    try:
        # The secant loop on 5 000 dofs to a tolerance it approaches only slowly:
        # hundreds of iterations (solver.max_iterations = 500), seconds of solving.
        case = formflow.Case({"mesh.size": 0.5, "solver.method": "secant",
                              "solver.tolerance": 1e-13})
        formflow.run(case, on_iteration=progress)
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted", *stamps, flush=True)
    result = formflow.run(formflow.Case({"mesh.size": 10 / 6}))
    print("solved again", result.converged, flush=True)
""")


def test_sigint_interrupts_the_solve_cleanly():
    child = subprocess.Popen([sys.executable, "-c", CHILD], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ)
    try:
        assert child.stdout.readline().strip() == "solving"
        signalled = time.monotonic()  # CLOCK_MONOTONIC: one clock for both processes
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=300)
    finally:
        if child.poll() is None:
            child.kill()
    assert child.returncode == 0, err
    lines = out.splitlines()
    assert lines[0].startswith("interrupted "), out
    stamps = [float(value) for value in lines[0].split()[1:]]
    # The solve stops at the first iteration after the signal: that iteration's callback
    # raises before calling ours, so at most one stamp (a signal that lands while our
    # own callback runs) comes after it, however long the signal took to be sent.
    assert sum(stamp > signalled for stamp in stamps) <= 1, (signalled, stamps)
    assert len(stamps) < 500  # not the whole run
    assert lines[1] == "solved again True", out
