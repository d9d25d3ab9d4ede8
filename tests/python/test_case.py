# SPDX-License-Identifier: MIT
"""formflow.Case: the CLI's validation and its messages, from a dict, a file and set()."""
import pytest

import formflow
from conftest import run_cli


def cli_error(*arguments):
    """The message `formflow check/run` prints for bad input (exit 2), without "error: "."""
    completed = run_cli(*arguments)
    assert completed.returncode == 2, completed.stderr
    line = completed.stderr.strip()
    assert line.startswith("error: "), line
    return line[len("error: "):]


def test_default_case_is_the_benchmark():
    case = formflow.Case()
    assert case.source == "<default>"
    assert case.get("friction.mu") == 0.0
    assert case.get("mesh.element") == "Q2"
    assert case.non_defaults == {}


def test_dotted_and_nested_dicts_are_the_same_case():
    dotted = formflow.Case({"friction.mu": 0.1, "mesh.element": "Q1"})
    nested = formflow.Case({"friction": {"mu": 0.1}, "mesh": {"element": "Q1"}})
    for case in (dotted, nested):
        assert case.get("friction.mu") == 0.1
        assert case.get("mesh.element") == "Q1"
        assert set(case.non_defaults) == {"friction.mu", "mesh.element"}


def test_set_validates_like_set_on_the_command_line(tmp_path):
    case = formflow.Case()
    assert case.set("friction.mu", 0.2) is case  # calls chain
    assert case.get("friction.mu") == 0.2
    with pytest.raises(formflow.InputError) as raised:
        case.set("friction.mu", -0.1)
    error = raised.value
    assert isinstance(error, ValueError)
    assert (error.file, error.line, error.key) == ("--set", 0, "friction.mu")
    assert str(error) == cli_error("run", "--set", "friction.mu=-0.1", "-o", str(tmp_path / "out"))
    # A refused value leaves the case as it was.
    assert case.get("friction.mu") == 0.2


def test_unknown_key_names_the_closest_one(tmp_path):
    with pytest.raises(formflow.InputError) as raised:
        formflow.Case({"friction": {"muu": 0.1}})
    assert raised.value.key == "friction.muu"
    assert "friction.mu" in raised.value.hint
    assert str(raised.value) == cli_error("run", "--set", "friction.muu=0.1", "-o",
                                          str(tmp_path / "out"))


def test_file_errors_name_the_file_and_line(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text("# a case with one bad value\n[friction]\nmu = -1.0\n", encoding="utf-8")
    with pytest.raises(formflow.InputError) as raised:
        formflow.Case.from_file(str(path))
    error = raised.value
    assert (error.file, error.line, error.key) == (str(path), 3, "friction.mu")
    assert str(error) == cli_error("check", str(path))


def test_a_file_case_takes_overrides_like_the_cli(tmp_path):
    path = tmp_path / "case.toml"
    path.write_text("[friction]\nmu = 0.1\n", encoding="utf-8")
    case = formflow.Case.from_file(str(path))
    assert case.non_defaults == {"friction.mu": f"{path}:2"}
    case.set("penalty.d", 1e-4)
    assert case.get("penalty.d") == 1e-4
    assert case.non_defaults["penalty.d"] == "--set"


def test_strings_are_values_never_toml_text():
    # Quoted as one TOML string: the newline and the quote cannot start another key.
    with pytest.raises(formflow.InputError) as raised:
        formflow.Case().set("mesh.element", 'Q1"\n[friction]\nmu = 5')
    assert raised.value.key == "mesh.element"
    assert formflow.Case().set("mesh.element", "Q1").get("mesh.element") == "Q1"


def test_values_that_are_no_case_value_are_type_errors():
    with pytest.raises(TypeError, match="friction.mu"):
        formflow.Case().set("friction.mu", None)
    with pytest.raises(TypeError):
        formflow.Case({1: 0.1})


def test_missing_file_is_an_input_error(tmp_path):
    missing = str(tmp_path / "missing.toml")
    with pytest.raises(formflow.InputError) as raised:
        formflow.Case.from_file(missing)
    assert str(raised.value) == cli_error("check", missing)


def test_a_nul_in_a_path_is_refused_by_key(tmp_path):
    # A C path ends at the NUL: "m.msh\0.txt" would read m.msh without a word.
    with pytest.raises(formflow.InputError) as raised:
        formflow.Case({"mesh": {"source": "file", "file": "m.msh\0.txt"}})
    assert raised.value.key == "mesh.file"
    assert "NUL" in raised.value.message
    with pytest.raises(formflow.InputError) as raised:
        formflow.Case.from_file(str(tmp_path / "case.toml") + "\0.txt")
    assert "NUL" in raised.value.message


def test_a_value_nested_too_deep_or_containing_itself_is_refused():
    deep = []
    for _ in range(100000):  # once a segfault: the conversion recursed to the stack's end
        deep = [deep]
    looped = []
    looped.append(looped)
    table = {}
    table["again"] = table
    for value in (deep, looped, table):
        with pytest.raises(formflow.InputError) as raised:
            formflow.Case({"geometry.profile": value})
        assert raised.value.key == "geometry.profile"
        assert "deep" in str(raised.value)
    # The deepest real value still passes: [x, y] points.
    points = [[-1, -1], [1, -1], [1, 1], [-1, 1]]
    case = formflow.Case({"geometry.dimension": 3, "geometry.section": "profile",
                          "geometry.profile": points})
    assert case.get("geometry.profile") == points
