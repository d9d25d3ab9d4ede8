# SPDX-License-Identifier: MIT
"""Shared by the Python module's tests: the CLI binary, and running it."""
import json
import os
import subprocess

# A small case every test can afford (mesh I of the paper: 10/6-wide squares, Q2,
# 2x2 volumetric rule): a second or less per solve.
MESH_I = {"mesh.size": 10 / 6}


def formflow_binary():
    return os.environ["FORMFLOW_BINARY"]


def run_cli(*arguments):
    """Runs `formflow arguments...`; returns the CompletedProcess (text output)."""
    return subprocess.run([formflow_binary(), *arguments], capture_output=True, text=True,
                          timeout=600, check=False)


def set_arguments(entries):
    """--set key=value for each entry of a dotted-key dict, numbers as Python writes them."""
    arguments = []
    for key, value in entries.items():
        arguments += ["--set", f"{key}={value!r}" if isinstance(value, float) else f"{key}={value}"]
    return arguments


def read_summary(directory):
    with open(os.path.join(directory, "summary.json"), encoding="utf-8") as stream:
        return json.load(stream)


def without_timings(summary):
    """summary.json without what differs between two runs of one case: the wall times."""
    return {key: value for key, value in summary.items() if key != "timing_s"}
