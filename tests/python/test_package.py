"""The package as users meet it: its docstring's example, its version, the names it exports."""
import doctest
import pathlib
import re

import conescan

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_docstring_example_runs():
    failures, tried = doctest.testmod(conescan)
    assert tried > 0 and failures == 0


def test_version_is_the_projects():
    project = re.search(r"project\(conescan VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    assert conescan.__version__ == project.group(1)


def test_every_function_has_a_docstring_with_its_arguments():
    for name in conescan.__all__:
        value = getattr(conescan, name)
        if type(value).__name__ != "builtin_function_or_method":
            continue
        # pybind11's signature line, then the binding's own text.
        signature, _, text = value.__doc__.partition("\n\n")
        assert signature.startswith(name + "(") and len(text) > 40, name


def test_result_types_are_named_tuples_of_the_package():
    for name in ("result", "crossings", "nadir_angle_roots", "scan_frame", "scan_angles",
                 "head_estimate", "roll_pitch"):
        cls = getattr(conescan, name)
        assert issubclass(cls, tuple) and cls.__module__ == "conescan" and cls._fields


def test_statuses():
    assert conescan.status_names[0] == "ok"
    assert conescan.Status.invalid == conescan.status_names.index("invalid")
    assert conescan.Status.__module__ == "conescan"
