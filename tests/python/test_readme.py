"""The Python of README.md and docs/*.md stays true: every ```python example prints what its
comments say, and docs/PYTHON.md lists every function of the module. (The shell commands of the
same pages run in tests/doc_examples.py.)"""
import contextlib
import io
import pathlib
import re

import pytest

import conescan

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
EXAMPLES = [(page, code) for page in PAGES
            for code in re.findall(r"^```python\n(.*?)^```", page.read_text(), re.S | re.M)]
PYTHON_PAGE = (ROOT / "docs" / "PYTHON.md").read_text()


def needs_scenes(code):
    return re.search(r"conescan\.(simulate|summary|fit|predict)\(", code) is not None


@pytest.mark.parametrize("page, code", EXAMPLES,
                         ids=[f"{p.relative_to(ROOT)}-{k}" for k, (p, _) in enumerate(EXAMPLES)])
def test_examples_print_what_their_comments_say(monkeypatch, page, code):
    if needs_scenes(code) and not hasattr(conescan._conescan, "_simulate"):
        pytest.skip("built without the scene layer")
    monkeypatch.chdir(ROOT)  # the examples name files of the repository
    expected = [line.split("#", 1)[1].strip() for line in code.splitlines()
                if line.lstrip().startswith("print(")]
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(code, {})
    assert printed.getvalue().splitlines() == expected


def test_the_pages_hold_the_examples():
    assert len([1 for page, _ in EXAMPLES if page.name == "PYTHON.md"]) == 3  # core, scenes, fit
    assert any(page.name == "README.md" for page, _ in EXAMPLES)


def test_every_function_is_listed():
    functions = {name for name in conescan.__all__
                 if type(getattr(conescan, name)).__name__ == "builtin_function_or_method"}
    listed = PYTHON_PAGE[PYTHON_PAGE.index("**Functions**"):PYTHON_PAGE.index("- **Arrays**")]
    assert set(re.findall(r"`([a-z_]+)`", listed)) == functions
