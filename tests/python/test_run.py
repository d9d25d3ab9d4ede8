# SPDX-License-Identifier: MIT
"""formflow.run: the CLI's numbers bit for bit, the callback, the arrays, not converged."""
import filecmp
import os
import threading
import time
import warnings

import numpy as np
import pytest

import formflow
from conftest import MESH_I, read_summary, run_cli, set_arguments, without_timings

FRICTION = {**MESH_I, "friction.mu": 0.1}


@pytest.fixture(scope="module")
def friction_run():
    iterations = []
    result = formflow.run(formflow.Case(FRICTION), on_iteration=iterations.append)
    return result, iterations


def test_python_gives_the_cli_numbers_bit_for_bit(friction_run, tmp_path):
    result, _ = friction_run
    cli_directory = tmp_path / "cli"
    completed = run_cli("run", *set_arguments(FRICTION), "-q", "-o", str(cli_directory))
    assert completed.returncode == 0, completed.stderr
    cli_summary = read_summary(cli_directory)
    # Every number but the wall times: exact equality, the same doubles.
    assert without_timings(result.summary) == without_timings(cli_summary)
    assert result.summary["timing_s"].keys() == cli_summary["timing_s"].keys()

    python_directory = tmp_path / "python"
    result.write(str(python_directory))
    assert sorted(os.listdir(python_directory)) == sorted(os.listdir(cli_directory))
    assert without_timings(read_summary(python_directory)) == without_timings(cli_summary)
    # The data files hold no times: the same bytes.
    for name in ("fields.vtu", "contact.csv"):
        assert filecmp.cmp(python_directory / name, cli_directory / name, shallow=False), name


def test_attributes_are_the_summary_numbers(friction_run):
    result, _ = friction_run
    summary = result.summary
    assert result.converged and result.stop_reason == "converged" and summary["converged"]
    assert result.method == summary["method"]
    assert result.iterations == summary["iterations"] == len(result.history)
    for name in ("ram_reaction", "power_balance", "total_power", "mean_hydrostatic_near_ram"):
        assert getattr(result.pressure, name) == summary["pressure"][name]
    for name in ("plastic_dissipation", "viscous_form", "volumetric_penalty", "contact_penalty",
                 "friction", "total"):
        assert getattr(result.power, name) == summary["power"][name]
    assert [record.relative_change for record in result.history] == summary["history"]
    assert [record.pressure for record in result.history] == summary["history_pressure"]
    assert result.timings == summary["timing_s"] and result.timings["total"] > 0


def test_the_load_error_bar_is_the_summarys(friction_run):
    # The default ("auto") estimate: mesh I admits no 2h, so the refined one, with
    # one indicator per cell summing to its refined change.
    result, _ = friction_run
    pressure = result.summary["pressure"]
    assert result.load_error is not None and result.load_error == pressure["ram_reaction_error"]
    assert pressure["error_estimate"]["method"] == "refined"
    indicators = result.cell_load_error
    assert indicators.shape == (result.summary["mesh"]["elements"],)
    change = pressure["error_estimate"]["refined_change"]
    # The same doubles summed in two orders (Eigen's and numpy's pairwise): each sum is
    # within (n − 1) eps Σ|η_K| of the exact one, and the JSON round trip is exact.
    rounding = 2 * (indicators.size - 1) * np.finfo(float).eps * np.abs(indicators).sum()
    assert abs(indicators.sum() - change) <= rounding
    unestimated = formflow.run(formflow.Case({**MESH_I, "solver.load_error": "none"}))
    assert unestimated.load_error is None and unestimated.cell_load_error is None


def test_the_callback_receives_every_iteration(friction_run):
    result, records = friction_run
    # The run's own iterations (no stage) are its history; the error estimate's solves
    # come after them, each record naming its level.
    iterations = [record for record in records if not record.stage]
    assert [record.iteration for record in iterations] == [r.iteration for r in result.history]
    assert [record.relative_change for record in iterations] == \
        [r.relative_change for r in result.history]
    assert len(iterations) == result.iterations > 0
    estimate = records[len(iterations):]
    assert result.load_error is not None and estimate
    assert all(record.stage.startswith("error estimate: ") for record in estimate)


def test_fields_are_numpy_arrays_of_the_mesh(friction_run):
    result, _ = friction_run
    mesh = result.summary["mesh"]
    n_nodes, n_cells = mesh["nodes"], mesh["elements"]
    assert result.nodes.shape == (n_nodes, 2) and result.nodes.dtype == np.float64
    assert result.cells.shape == (n_cells, 9)  # Q2: nine nodes per cell
    assert result.cells.min() == 0 and result.cells.max() == n_nodes - 1
    assert result.velocity.shape == (n_nodes, 2)
    for name in ("equivalent_strain_rate", "hydrostatic_stress", "contact_pressure",
                 "friction_stress"):
        assert getattr(result, name).shape == (n_nodes,), name
    for name in ("cell_equivalent_strain_rate", "cell_hydrostatic_stress"):
        assert getattr(result, name).shape == (n_cells,), name
    # Node-major order, checked by the boundary conditions: the ram (x = 0) pushes
    # with u0 = 1, the symmetry line y = 0 has u_y = 0 (both imposed exactly).
    ram = result.nodes[:, 0] == 0.0
    symmetry = result.nodes[:, 1] == 0.0
    assert ram.sum() > 1 and symmetry.sum() > 1
    assert np.all(result.velocity[ram, 0] == 1.0)
    assert np.all(result.velocity[symmetry, 1] == 0.0)
    contact = result.contact
    lengths = {len(column) for column in contact.values()}
    assert len(lengths) == 1 and lengths.pop() > 0
    assert np.all(np.diff(contact["arc_length"]) >= 0)  # ordered along Γ3
    with pytest.raises(ValueError):
        result.velocity[0, 0] = 5.0  # the run's numbers are read-only


def test_not_converged_is_an_attribute_and_a_warning():
    case = formflow.Case({**MESH_I, "solver.max_iterations": 2, "solver.coarse_levels": 0})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = formflow.run(case)
    assert not result.converged and result.stop_reason == "max_iterations"
    assert result.iterations == 2
    assert [w.category for w in caught] == [formflow.NotConvergedWarning]
    assert "NOT CONVERGED" in str(caught[0].message)


def test_an_exception_in_the_callback_stops_the_solve():
    seen = []

    def stop_at_second(record):
        seen.append(record.iteration)
        if len(seen) == 2:
            raise LookupError("enough")

    with pytest.raises(LookupError, match="enough"):
        formflow.run(formflow.Case(MESH_I), on_iteration=stop_at_second)
    assert len(seen) == 2


def test_a_friction_sweep_in_ten_lines():
    case = formflow.Case(MESH_I)
    loads = []
    for mu in (0.0, 0.1, 0.2):
        result = formflow.run(case.set("friction.mu", mu))
        assert result.converged
        loads.append(result.pressure.ram_reaction)
    # Friction only adds dissipation: the load grows with μ (SPEC §4, the paper's table).
    assert loads[0] < loads[1] < loads[2]


def test_the_gil_is_released_while_solving():
    # A Python thread that only stamps the time: while run() holds the GIL it cannot.
    stamps, done = [], threading.Event()

    def stamp():
        while not done.is_set():
            stamps.append(time.monotonic())
            time.sleep(0.001)

    thread = threading.Thread(target=stamp)
    thread.start()
    try:
        start = time.monotonic()
        formflow.run(formflow.Case({"solver.method": "secant"}))  # mesh II: a second or more
        end = time.monotonic()
    finally:
        done.set()
        thread.join()
    inside = [t for t in stamps if start <= t <= end]
    gaps = np.diff([start, *inside, end])
    # Held, the longest gap would be the whole solve; released, a few scheduler slices.
    assert gaps.max() < (end - start) / 2, (gaps.max(), end - start)
