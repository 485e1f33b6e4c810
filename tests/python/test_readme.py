"""The README's section "From Python" stays true: its examples print what their comments say, and
it lists every function of the module."""
import contextlib
import io
import pathlib
import re

import conescan

README_PATH = pathlib.Path(__file__).resolve().parents[2] / "README.md"
README = README_PATH.read_text()
SECTION = README[README.index("## From Python"):].split("\n## ", 1)[0]


def test_examples_print_what_their_comments_say(monkeypatch):
    monkeypatch.chdir(README_PATH.parent)  # the examples name files of the repository
    examples = re.findall(r"```python\n(.*?)```", SECTION, re.S)
    assert len(examples) == 3  # the core, scenes, a fit
    if not hasattr(conescan._conescan, "_simulate"):  # built without the scene layer
        examples = examples[:1]
    for code in examples:
        expected = [line.split("#", 1)[1].strip() for line in code.splitlines()
                    if line.lstrip().startswith("print(")]
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            exec(code, {})
        assert printed.getvalue().splitlines() == expected


def test_every_function_is_listed():
    functions = {name for name in conescan.__all__
                 if type(getattr(conescan, name)).__name__ == "builtin_function_or_method"}
    listed = SECTION[SECTION.index("**Functions**"):SECTION.index("- **Arrays**")]
    assert set(re.findall(r"`([a-z_]+)`", listed)) == functions
