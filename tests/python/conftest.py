"""Shared by the tests of the module conescan: the C++ reference program and bitwise comparison.

ctest sets PYTHONPATH to <build>/python (the package as built) and CONESCAN_PYTHON_REFERENCE to
tests/python/reference.cpp's program: the core called from plain C++.
"""
import os
import subprocess
import sys
import threading

import numpy as np
import pytest


def flat_rows(result, rows):
    """The fields of a binding's result as one row per element, in field order: each field
    reshaped to (rows, -1), so vectors and matrices add 3 and 9 columns. Returns the columns
    and, for each, whether it is real (float64) or an integer (status, count)."""
    fields = result if isinstance(result, tuple) else (result,)
    columns, real = [], []
    for value in fields:
        value = np.asarray(value).reshape(rows, -1)
        for k in range(value.shape[1]):
            columns.append(value[:, k])
            real.append(value.dtype == np.float64)
    return columns, real


def same_bits(actual, expected):
    """Element-wise: the same float64 bits (so -0.0 differs from 0.0), or both NaN (the core
    makes no promise about a NaN's sign or payload)."""
    actual = np.asarray(actual, dtype=np.float64)
    expected = np.asarray(expected, dtype=np.float64)
    both_nan = np.isnan(actual) & np.isnan(expected)
    return both_nan | (actual.view(np.int64) == expected.view(np.int64))


def program(variable):
    """A runner of the program whose path the ctest environment gives in `variable`
    (CONESCAN_SIM, CONESCAN_FIT): run(args, check=True) -> subprocess.CompletedProcess."""
    path = os.environ.get(variable)
    if not path:
        pytest.fail(f"{variable} is not set: run the tests with ctest")

    def run(args, check=True):
        done = subprocess.run([path, *args], capture_output=True, text=True)
        if check:
            assert done.returncode == 0, done.stderr
        return done

    return run


@pytest.fixture(scope="session")
def reference_program():
    program = os.environ.get("CONESCAN_PYTHON_REFERENCE")
    if not program:
        pytest.fail("CONESCAN_PYTHON_REFERENCE is not set: run the tests with ctest, or set it to "
                    "<build>/tests/conescan_python_reference")
    return program


@pytest.fixture(scope="session")
def reference(reference_program):
    """reference(function, inputs) -> list of result rows (lists of tokens) from the C++
    program, one per row of the inputs (a list of arrays with the same first dimension)."""

    def text(value, is_real):
        return float.hex(float(value)) if is_real else str(int(value))

    def run(function, inputs):
        rows = len(inputs[0])
        columns = []
        for arg in inputs:
            arg = np.asarray(arg)
            is_real = arg.dtype.kind == "f"
            flat = arg.reshape(rows, -1)
            columns.extend((flat[:, k], is_real) for k in range(flat.shape[1]))
        lines = [" ".join(text(column[i], is_real) for column, is_real in columns)
                 for i in range(rows)]
        done = subprocess.run([reference_program, function], input="\n".join(lines) + "\n", text=True,
                              capture_output=True, check=True)
        return [line.split() for line in done.stdout.splitlines()]

    return run


def another_thread_runs_during(call, tries):
    """Whether a second Python thread runs while call() runs, i.e. call releases the GIL.

    Deterministic, with no time threshold: the switch interval is raised so far that a thread
    holding the GIL is never made to give it up, so the only way the waiting thread can run before
    the call returns is the call releasing the GIL itself. `tries` calls at most (a busy machine
    may not schedule the waiting thread in time)."""
    in_call, seen, go = [False], [], threading.Event()

    def worker():
        go.wait()  # blocks without the GIL; wakes wanting it
        seen.append(in_call[0])

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e6)
    try:
        thread = threading.Thread(target=worker)
        thread.start()
        go.set()  # from here the worker waits for the GIL, which this thread keeps...
        for _ in range(tries):  # ...unless the call releases it
            in_call[0] = True
            call()
            in_call[0] = False
            if seen:
                break
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    return seen == [True]

