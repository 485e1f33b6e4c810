"""The README's section "From Python" stays true: its example prints what its comments say, and
it lists every function of the module."""
import contextlib
import io
import pathlib
import re

import conescan

README = (pathlib.Path(__file__).resolve().parents[2] / "README.md").read_text()
SECTION = README[README.index("## From Python"):].split("\n## ", 1)[0]


def test_example_prints_what_its_comments_say():
    code = re.search(r"```python\n(.*?)```", SECTION, re.S).group(1)
    expected = [line.split("#", 1)[1].strip() for line in code.splitlines()
                if line.startswith("print(")]
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(code, {})
    assert printed.getvalue().splitlines() == expected


def test_every_function_is_listed():
    functions = {name for name in conescan.__all__
                 if type(getattr(conescan, name)).__name__ == "builtin_function_or_method"}
    listed = SECTION[SECTION.index("**Functions**"):SECTION.index("- **Arrays**")]
    assert set(re.findall(r"`([a-z_]+)`", listed)) == functions
