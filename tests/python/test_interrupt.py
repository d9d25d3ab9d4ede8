# SPDX-License-Identifier: MIT
"""Ctrl-C (SIGINT) in Python stops a solve at its next iteration: KeyboardInterrupt, and
the interpreter can solve again."""
import os
import signal
import subprocess
import sys
import textwrap

CHILD = textwrap.dedent("""
    import formflow
    seen = []
    def progress(record):
        seen.append(record.iteration)
        if len(seen) == 1:
            print("solving", flush=True)
    try:
        # The secant loop on 5 000 dofs to a tolerance it approaches only slowly:
        # hundreds of iterations (solver.max_iterations = 500), ten seconds or more.
        case = formflow.Case({"mesh.size": 0.5, "solver.method": "secant",
                              "solver.tolerance": 1e-13})
        formflow.run(case, on_iteration=progress)
        print("finished", len(seen), flush=True)
    except KeyboardInterrupt:
        print("interrupted", len(seen), flush=True)
    result = formflow.run(formflow.Case({"mesh.size": 10 / 6}))
    print("solved again", result.converged, flush=True)
""")


def test_sigint_interrupts_the_solve_cleanly():
    child = subprocess.Popen([sys.executable, "-c", CHILD], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ)
    try:
        assert child.stdout.readline().strip() == "solving"
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=300)
    finally:
        if child.poll() is None:
            child.kill()
    assert child.returncode == 0, err
    lines = out.splitlines()
    assert lines[0].startswith("interrupted "), out
    # Stopped within a second or so of the signal (tens of ms per iteration): far from
    # the 500 of a full run.
    assert int(lines[0].split()[1]) < 100, out
    assert lines[1] == "solved again True", out
