# SPDX-License-Identifier: MIT
"""examples/friction_sweep.py runs as documented and writes its plot."""
import os
import re
import subprocess
import sys


def test_friction_sweep_example_plots_the_load_against_mu(tmp_path):
    script = os.path.join(os.environ["FORMFLOW_SOURCE_DIR"], "examples", "friction_sweep.py")
    output = tmp_path / "sweep.png"
    completed = subprocess.run([sys.executable, script, str(output)], capture_output=True,
                               text=True, timeout=600, check=False)
    assert completed.returncode == 0, completed.stderr
    loads = [float(value) for value in re.findall(r"ram reaction ([0-9.]+)", completed.stdout)]
    assert len(loads) == 5
    assert loads == sorted(loads) and loads[0] < loads[-1]  # friction adds dissipation
    with open(output, "rb") as picture:
        assert picture.read(8) == b"\x89PNG\r\n\x1a\n"
    assert output.stat().st_size > 10_000  # axes, two curves and labels, not an empty canvas
