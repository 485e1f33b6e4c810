#!/usr/bin/env python3
"""Documentation that runs: every command of README.md and docs/*.md, every output they show and
every list they give, checked against the programs (ctest docs.examples).

What a page may hold, and what is checked:
- ```sh blocks: every command runs, in the page's order, under bash, in a temporary directory
  holding links to the repository's build/, data/, docs/, examples/, scripts/ and tests/ (so
  that what a command writes lands there, never in the tree), with a timeout. It must exit 0,
  or with the status its expectation names. An expectation is a comment `# -> TEXT` at the end
  of the command or on the lines after it (`#   more` lines continue it): TEXT must appear in
  the command's standard output and error together, blanks normalised, `...` standing for any
  text; `# -> (exit N) TEXT` expects exit status N.
- ```console blocks: commands after `$ ` that a test cannot run (root, a second build, an hour
  of CPU). Each must be in NOT_RUN below with the reason; an entry of NOT_RUN that no page holds
  any more is an error too. Other fenced blocks (output, C++, CMake, Python) may hold no `$ `
  command and no line starting with build/ or scripts/.
- `<!-- output of: CMD -->` before a fenced block or a Markdown table: the block is CMD's
  standard output, exactly. `doc_examples.py ... --update` rewrites such blocks.
- `<!-- list: NAME -->` ... `<!-- /list -->`: the backticked names between the markers are, in
  order, the program's own list NAME (program_lists below: statuses, statistics, sweepable
  options, head keys, ...); `<!-- list-column: NAME -->` before a table takes the first cell of
  each row.
- Links: every relative link names a file of the repository, and its #section a heading there
  (none leaves it; PENDING lists the pages other work is writing); no page cites a path outside
  the repository or an issue number; every backticked path (`src/...`) and source file name (`foo.hpp`) names a file
  that exists (a file that moved leaves no stale claim).
- README.md has at most 200 lines, links every page of docs/, and its ```cpp block that holds
  `int main` is compiled against include/ and run (`// -> TEXT`: what it prints).

Usage: doc_examples.py SOURCE_DIR BUILD_DIR [--python] [--update] [PAGE...]
  --python: the Python module is built (build/python); without it the commands that use it are
  listed as not run. PAGE: only these pages (paths relative to SOURCE_DIR).
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

# Commands shown in ```console blocks, by page and the command's start, with why no test runs
# them. Keep this short: a command that can run belongs in a ```sh block.
NOT_RUN = {
    ("README.md", "scripts/paper-scene.sh"):
        "installs packages (root) and builds; the docs' sh blocks run its conescan-sim and "
        "scripts/max-errors.sh, which print its last line",
    ("README.md", "scripts/test.sh"): "installs packages and runs this very test suite",
    ("docs/CAMPAIGNS.md", "build/conescan-sim --config data/scenes/monte-carlo.toml >"):
        "the full campaign: 86.4 million rows, about 2 min of CPU; the sh blocks run it shortened",
    ("docs/CAMPAIGNS.md", "scripts/slurm/campaign.sbatch"): "needs a Slurm cluster",
    ("docs/CAMPAIGNS.md", "scripts/slurm/local-cluster.sh"): "starts Slurm's daemons as root",
    ("docs/CAMPAIGNS.md", "bench/campaign_speed.sh"): "a benchmark: minutes, on an idle machine",
    ("docs/CAMPAIGNS.md", "SLURM=1 bench/campaign_times.sh"): "a benchmark with Slurm, as root",
    ("docs/CLI.md", "scripts/make-figures.sh"): "rewrites the repository's docs/fig2*.png",
    ("docs/PYTHON.md", "sudo cmake --install build"): "installs into /usr/local as root",
    ("docs/PYTHON.md", "cmake --install build --prefix"):
        "installs the build tree; ctest package.python_install does it into a fresh prefix",
    ("docs/PYTHON.md", "cmake --build build --target conescan_python conescan-sim &&"):
        "a benchmark: about a minute, pauses to let memory go cold",
    ("docs/API.md", "cmake -S . -B build-core"):
        "a second build tree; ctest package.find_package configures, installs and uses it",
    ("docs/API.md", "cmake --install build-core"): "installs the core into /opt as root",
    ("docs/SENSOR_PHYSICS.md", "A=\"--earth wgs84"):
        "the options of the day's scenes below, which are not run",
    ("docs/SENSOR_PHYSICS.md", "/usr/bin/time -f \"%U s\" build/conescan-sim $A"):
        "a day's scene timed: with a field some 10 to 20 s of CPU, a timing on an idle machine",
    ("docs/SENSOR_PHYSICS.md", "/usr/bin/time -f \"%U s\" build/conescan-sim --earth wgs84"):
        "the geometric day the others are measured against: a timing, on an idle machine",
    ("docs/SENSOR_PHYSICS.md", "build/bench/conescan-sensor-physics-speed --ellipsoid"):
        "a benchmark of the chain on WGS84: minutes, tens of minutes with a field",
    ("docs/PERFORMANCE.md", "BUILD_DIR=build scripts/make-charts.sh"):
        "about 10 minutes: the 50-digit reference; rewrites docs/data and the charts",
    ("docs/PERFORMANCE.md", "BUILD_DIR=build bench/cli_speed.sh"): "a benchmark, on an idle machine",
    ("docs/PERFORMANCE.md", "BUILD_DIR=build-bench bench/cli_speed.sh"):
        "a benchmark, on an idle machine",
    ("docs/PERFORMANCE.md", "BUILD_DIR=build bench/scan_speed.sh"): "a benchmark, on an idle machine",
    ("docs/PERFORMANCE.md", "cmake --build build --target conescan_python conescan-half-chord-loop"):
        "a benchmark, on an idle machine",
    ("docs/PERFORMANCE.md", "cmake --build build --target conescan_python conescan-sim"):
        "a benchmark: about a minute, pauses to let memory go cold",
    ("docs/PERFORMANCE.md", "RUNS=7 bench/scan_speed.sh"): "a benchmark, on an idle machine",
    ("docs/PERFORMANCE.md", "CCACHE_DISABLE=1 cmake -S . -B /tmp/cold"):
        "a second build tree, configured",
    ("docs/PERFORMANCE.md", "CCACHE_DISABLE=1 /usr/bin/time cmake --build /tmp/cold"):
        "a first build without ccache: 7 minutes of CPU",
    ("docs/PERFORMANCE.md", "CCACHE_DISABLE=1 /usr/bin/time ctest --test-dir /tmp/cold"):
        "the whole suite, this test included",
    ("docs/RELIABILITY.md", "scripts/reliability.sh"):
        "about 20 minutes, and a second build tree (build-release)",
    ("docs/RELIABILITY.md", "FUZZ_SECONDS=300 scripts/reliability.sh"): "about 45 minutes",
    ("docs/RELIABILITY.md", "ROWS=1000000 SKIP_FUZZ=1 SKIP_SANITIZERS=1 scripts/reliability.sh"):
        "builds a second tree (build-release) before its 20 s",
    ("docs/SOURCES.md", "build/tests/conescan_"):
        "these Catch2 tests run in ctest, each on its own (seconds each, under a minute together)",
    ("docs/SOURCES.md", "build/bench/conescan-sources-bench   "): "a benchmark, on an idle machine",
    ("docs/SOURCES.md", "build/bench/conescan-sources-bench --make-oem"):
        "writes a 1.03 GB file",
    ("docs/SOURCES.md", "/usr/bin/time -v build/bench/conescan-sources-bench --read-oem"):
        "reads that 1.03 GB file: a minute",
}

# Pages that a link may name before they exist: other work writes them.
PENDING: dict = {}

# A hang's bound, not a speed test: the mission study's examples run the sensor physics on every
# row of an orbit (tens of ms a row) and take 15-60 s on two idle cores, minutes under load.
COMMAND_TIMEOUT_S = 300
README_MAX_LINES = 200

FENCE = re.compile(r"^( *)```([A-Za-z0-9_+-]*)\s*$")
OUTPUT_MARK = re.compile(r"^<!-- output of: (.*) -->\s*$")
LIST_MARK = re.compile(r"<!-- list(-column)?: ([a-z-]+) -->(.*?)<!-- /list -->", re.S)
LINK = re.compile(r"\]\(([^)\s]+)\)")


class Page:
    """A Markdown page: its lines, fenced blocks and what it asks to be checked."""

    def __init__(self, root, relative):
        self.relative = relative
        self.path = root / relative
        self.text = self.path.read_text()
        self.lines = self.text.split("\n")

    def blocks(self):
        """(language, first content line index, end line index (the closing fence), indent)."""
        out = []
        i = 0
        while i < len(self.lines):
            m = FENCE.match(self.lines[i])
            if not m:
                i += 1
                continue
            indent, language = len(m.group(1)), m.group(2)
            j = i + 1
            while j < len(self.lines) and self.lines[j].strip() != "```":
                j += 1
            if j == len(self.lines):
                raise SystemExit(f"{self.relative}:{i + 1}: a fence that is never closed")
            out.append((language, i + 1, j, indent))
            i = j + 1
        return out

    def block_text(self, start, end, indent):
        return [line[indent:] if line[:indent].strip() == "" else line
                for line in self.lines[start:end]]


# --- Shell blocks --------------------------------------------------------------------------

def split_comment(line):
    """A shell line's command and its trailing comment (after an unquoted ' #')."""
    quote = None
    for k, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c == "#" and (k == 0 or line[k - 1] in " \t"):
            return line[:k].rstrip(), line[k + 1:].strip()
    return line.rstrip(), ""


def shell_commands(lines, first_line):
    """[(line number, command, [expectation texts])] of a ```sh block."""
    commands = []
    pending = ""
    start = None
    continuing_expectation = False
    for offset, raw in enumerate(lines):
        number = first_line + offset
        if pending:
            pending += "\n" + raw
            if raw.rstrip().endswith("\\"):
                continue
            command, comment = split_comment(pending)
            commands.append([start, command, []])
            pending = ""
            if comment.startswith("->"):
                commands[-1][2].append(comment[2:].strip())
            continue
        stripped = raw.strip()
        if not stripped:
            continuing_expectation = False
            continue
        if stripped.startswith("#"):
            body = stripped[1:]
            if body.lstrip().startswith("->") and commands:
                commands[-1][2].append(body.lstrip()[2:].strip())
                continuing_expectation = True
            elif continuing_expectation and body.startswith("   ") and commands:
                commands[-1][2][-1] += " " + body.strip()
            else:
                continuing_expectation = False
            continue
        continuing_expectation = False
        start = number
        if raw.rstrip().endswith("\\"):
            pending = raw
            continue
        command, comment = split_comment(raw)
        commands.append([number, command, []])
        if comment.startswith("->"):
            commands[-1][2].append(comment[2:].strip())
            continuing_expectation = True
    if pending:
        raise SystemExit(f"line {start}: a command that ends with a backslash")
    return commands


def normalised(text):
    return " ".join(text.split())


def shows(output, expectation):
    """Whether the output holds the expectation's pieces, in order (`...`: any text)."""
    position = 0
    haystack = normalised(output)
    for piece in expectation.split("..."):
        piece = normalised(piece)
        if not piece:
            continue
        found = haystack.find(piece, position)
        if found < 0:
            return False
        position = found + len(piece)
    return True


def run(command, cwd, env, timeout=COMMAND_TIMEOUT_S):
    return subprocess.run(["bash", "-c", command], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=timeout)


def check_command(where, command, expectations, cwd, env, problems, timings):
    expected_status = 0
    texts = []
    for e in expectations:
        m = re.match(r"\(exit (\d+)\)\s*(.*)", e, re.S)
        if m:
            expected_status = int(m.group(1))
            e = m.group(2)
        if e:
            texts.append(e)
    start = time.monotonic()
    try:
        done = run(command, cwd, env)
    except subprocess.TimeoutExpired:
        problems.append(f"{where}: timed out after {COMMAND_TIMEOUT_S} s: {command}")
        return
    timings.append((time.monotonic() - start, where))
    output = done.stdout + done.stderr
    if done.returncode != expected_status:
        problems.append(f"{where}: exit {done.returncode}, expected {expected_status}: {command}\n"
                        f"{output[-2000:]}")
        return
    for text in texts:
        if not shows(output, text):
            problems.append(f"{where}: the output does not show {text!r}: {command}\n"
                            f"{output[-2000:]}")


# --- Lists the programs print --------------------------------------------------------------

def program_lists(cwd, env):
    """The programs' own lists, by the name a page's list marker gives."""
    def out(command):
        done = run(command, cwd, env)
        return done.stdout + done.stderr

    def after(text, marker, end="\n"):
        tail = text[text.index(marker) + len(marker):]
        return tail[:tail.index(end)] if end in tail else tail

    summary_header = out("build/conescan-sim --summary --duration-s 0").split("\n")[0].split(",")
    statistics = [c for c in summary_header if c.endswith("_deg")]
    statuses = summary_header[summary_header.index("rows") + 1:summary_header.index(statistics[0])]
    sweep = after(out("build/conescan-sim --sweep none=0:1:1"), "options: ")
    sweep = sweep.replace(" (K = 1, 2, ...)", "").split(", ")
    keys = re.sub(r" \([^)]*\)", "", after(out("build/conescan-sim --head none=1"), "keys: "))
    keys = keys.split(", ")
    columns = out("build/conescan-sim --duration-s 0").split("\n")[0].replace("h1_", "hK_")
    budget = out("build/conescan-sim --budget --summary --duration-s 0 --earth wgs84 --model scan "
                 "--horizon-preset co2-15um --processing-horizon-km 30 --radiance-season 0.1 "
                 "--head noise=0.01,lsb=0.01,dgamma=0.01,fov=1,spin-hz=1,tau-ms=0.5")
    budget = [line.split(",")[0] for line in budget.strip().split("\n")[1:]]
    free = after(out("build/conescan-fit --telemetry /dev/null --free none"), "allowed: ")
    free = [name for name in free.split(", ") if name != "(K a head number)"]
    scenes = sorted(f"data/scenes/{p.name}" for p in (cwd / "data/scenes").glob("*.toml"))
    return {
        "statuses": statuses,
        "statistics": statistics,
        "summary-columns": summary_header,
        "sweepable": sweep,
        "head-keys": keys,
        "columns": columns.split(","),
        "budget-sources": budget,
        "free-parameters": free,
        "scene-files": scenes,
    }


def check_lists(page, lists, problems):
    for m in LIST_MARK.finditer(page.text):
        name, body = m.group(2), m.group(3)
        line = page.text[:m.start()].count("\n") + 1
        if m.group(1):  # a table: the first cell of each row
            body = " ".join(row.split("|")[1] for row in body.split("\n")
                            if row.startswith("|") and not row.startswith("|---"))
        shown = [t.rstrip("=") for t in re.findall(r"`([^`]+)`", body)]
        if name not in lists:
            problems.append(f"{page.relative}:{line}: no program list named {name!r} "
                            f"(known: {', '.join(sorted(lists))})")
        elif shown != lists[name]:
            problems.append(f"{page.relative}:{line}: the list {name} shows {shown}; "
                            f"the programs give {lists[name]}")


# --- Generated blocks ----------------------------------------------------------------------

def generated_blocks(page):
    """[(command, first line index, end line index, kind)] of the page's `output of` blocks."""
    out = []
    for i, line in enumerate(page.lines):
        m = OUTPUT_MARK.match(line)
        if not m:
            continue
        j = i + 1
        if j < len(page.lines) and FENCE.match(page.lines[j]):
            k = j + 1
            while page.lines[k].strip() != "```":
                k += 1
            out.append((m.group(1), j + 1, k, "fenced"))
        elif j < len(page.lines) and page.lines[j].startswith("|"):
            k = j
            while k < len(page.lines) and page.lines[k].startswith("|"):
                k += 1
            out.append((m.group(1), j, k, "table"))
        else:
            out.append((m.group(1), j, j, "missing"))
    return out


def check_generated(page, cwd, env, update, problems):
    changed = False
    for command, start, end, kind in reversed(generated_blocks(page)):
        if kind == "missing":
            problems.append(f"{page.relative}:{start}: `output of` marks no block or table")
            continue
        done = run(command, cwd, env)
        if done.returncode != 0:
            problems.append(f"{page.relative}:{start}: exit {done.returncode}: {command}\n"
                            f"{done.stderr[-2000:]}")
            continue
        produced = done.stdout.rstrip("\n").split("\n")
        if page.lines[start:end] != produced:
            if update:
                page.lines[start:end] = produced
                changed = True
            else:
                problems.append(f"{page.relative}:{start + 1}: the block is not what `{command}` "
                                f"prints (regenerate: tests/doc_examples.py . build --update)")
    if changed:
        page.path.write_text("\n".join(page.lines))
        page.text = page.path.read_text()


# --- Links and citations -------------------------------------------------------------------

def anchors(path):
    """The anchors of a Markdown file's headings, as GitHub spells them."""
    out = set()
    for line in path.read_text().split("\n"):
        m = re.match(r"#+ (.*)", line)
        if m:
            slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
            out.add(slug)
    return out


TREE = ("apps", "bench", "cmake", "data", "docs", "examples", "include", "python", "scripts",
        "src", "tests")


def repository_file_names(root):
    return {p.name for top in TREE for p in (root / top).rglob("*")} | {
        p.name for p in root.iterdir()}


def check_names(page, root, names, problems):
    """Stale claims: a backticked path of the repository, or a backticked source file's name,
    that names nothing (a file that moved or went away)."""
    for number, line in enumerate(page.lines, start=1):
        for token in re.findall(r"`([^`\s]+)`", line):
            token = token.rstrip(".,;:")
            if any(c in token for c in "*{}<>$"):
                continue
            if re.match(r"(%s)/[\w./+-]*$" % "|".join(TREE), token):
                if not (root / token).exists() and token not in PENDING:
                    problems.append(f"{page.relative}:{number}: `{token}` names no file")
            elif re.match(r"[\w-]+\.(hpp|cpp|py|sh|toml)$", token) and token not in names:
                problems.append(f"{page.relative}:{number}: `{token}` is no file of the repository")


def check_links(page, root, problems):
    for number, line in enumerate(page.lines, start=1):
        where = f"{page.relative}:{number}"
        # Any relative path that climbs out of the repository (links are checked below too).
        outside = [p for p in re.findall(r"(?:\.\./)+[\w.-]+", line)
                   if os.path.relpath((page.path.parent / p).resolve(),
                                      root.resolve()).startswith("..")]
        if outside or re.search(r"\bSPEC\.md\b", line):
            problems.append(f"{where}: cites a file outside the repository")
        if re.search(r"\bissues? \d+\b", line, re.I):
            problems.append(f"{where}: cites an issue number, which a clone does not hold")
        for target in LINK.findall(line):
            if re.match(r"[a-z]+:", target):
                continue
            target, _, anchor = target.partition("#")
            resolved = (page.path.parent / target).resolve() if target else page.path
            relative = os.path.relpath(resolved, root.resolve())
            if relative.startswith(".."):
                problems.append(f"{where}: the link {target} leaves the repository")
            elif not resolved.exists():
                if relative not in PENDING:
                    problems.append(f"{where}: the link {target} names no file")
            elif anchor and resolved.suffix == ".md" and anchor not in anchors(resolved):
                problems.append(f"{where}: {target or page.relative} has no section #{anchor}")


# --- The README's C++ example --------------------------------------------------------------

def check_cpp_example(page, root, work, problems, timings):
    for language, start, end, indent in page.blocks():
        code = "\n".join(page.block_text(start, end, indent))
        if language != "cpp" or "int main" not in code:
            continue
        source = work / "readme_example.cpp"
        source.write_text(code + "\n")
        expected = [line.split("// ->", 1)[1].strip() for line in code.split("\n") if "// ->" in line]
        # At two optimisation levels: what it prints must not be float noise that moves with
        # them (the example printed roll -3.1e-06 at -O2, 1.5e-06 at -O3).
        for level in ("-O1", "-O3"):
            binary = work / f"readme_example{level}"
            begin = time.monotonic()
            compiled = subprocess.run(
                [os.environ.get("CXX", "c++"), "-std=c++20", level, "-Wall", "-Wextra",
                 "-Wpedantic", "-Wshadow", "-Wconversion", "-Werror",
                 "-I", str(root / "include"), str(source), "-o", str(binary)],
                capture_output=True, text=True, timeout=120)
            if compiled.returncode != 0:
                problems.append(f"{page.relative}:{start}: the C++ example does not compile "
                                f"({level}):\n{compiled.stderr[-3000:]}")
                continue
            ran = subprocess.run([str(binary)], capture_output=True, text=True, timeout=10)
            timings.append((time.monotonic() - begin, f"{page.relative}:{start} (C++ {level})"))
            if ran.returncode != 0:
                problems.append(f"{page.relative}:{start}: the C++ example exits "
                                f"{ran.returncode} ({level})")
            for text in expected:
                if not shows(ran.stdout, text):
                    problems.append(f"{page.relative}:{start}: the C++ example does not print "
                                    f"{text!r} ({level}):\n{ran.stdout}")


# --- The pages -----------------------------------------------------------------------------

def workspace(root, build):
    work = pathlib.Path(tempfile.mkdtemp(prefix="conescan-docs-"))
    (work / "build").symlink_to(build)
    for name in ("data", "docs", "examples", "scripts", "tests", "bench"):
        (work / name).symlink_to(root / name)
    return work


def check_page(page, root, build, python, update, lists, names, problems, timings, not_run,
               consoles):
    work = workspace(root, build)
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1", MPLBACKEND="Agg", LC_ALL="C")
    try:
        check_generated(page, work, env, update, problems)
        check_lists(page, lists, problems)
        check_links(page, root, problems)
        check_names(page, root, names, problems)
        for language, start, end, indent in page.blocks():
            lines = page.block_text(start, end, indent)
            if language == "sh":
                for number, command, expectations in shell_commands(lines, start + 1):
                    where = f"{page.relative}:{number}"
                    if "build/python" in command and not python:
                        not_run.append((where, command, "the Python module is not built"))
                        continue
                    check_command(where, command, expectations, work, env, problems, timings)
            elif language == "console":
                commands = [line[2:] for line in lines if line.startswith("$ ")]
                if not commands:
                    problems.append(f"{page.relative}:{start}: a console block without `$ ` commands")
                for command in commands:
                    keys = [key for key in NOT_RUN if key[0] == page.relative
                            and command.startswith(key[1])]
                    if not keys:
                        problems.append(f"{page.relative}:{start}: `{command}` is in a console "
                                        f"block (not run) without a reason in NOT_RUN")
                        continue
                    key = max(keys, key=lambda k: len(k[1]))
                    consoles.add(key)
                    not_run.append((f"{page.relative}:{start}", command, NOT_RUN[key]))
            else:
                for offset, line in enumerate(lines):
                    if re.match(r"\s*(\$ |build/|scripts/)", line):
                        problems.append(f"{page.relative}:{start + offset + 1}: a command in a "
                                        f"```{language} block: use ```sh (run by this test) or "
                                        f"```console (listed in NOT_RUN)")
        if page.relative == "README.md":
            if len(page.lines) - 1 > README_MAX_LINES:
                problems.append(f"README.md: {len(page.lines) - 1} lines, more than "
                                f"{README_MAX_LINES}: it is the front door, docs/ is the house")
            check_cpp_example(page, root, work, problems, timings)
            linked = set(re.findall(r"\]\(docs/([A-Z0-9_]+\.md)", page.text))
            for doc in sorted(p.name for p in (root / "docs").glob("*.md")):
                if doc not in linked:
                    problems.append(f"README.md: its map of docs/ does not link docs/{doc}")
    finally:
        subprocess.run(["rm", "-rf", str(work)])


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    flags = {a for a in argv[1:] if a.startswith("--")}
    root, build = pathlib.Path(args[0]).resolve(), pathlib.Path(args[1]).resolve()
    pages = args[2:] or ["README.md"] + sorted(
        str(p.relative_to(root)) for p in (root / "docs").glob("*.md"))
    problems, timings, not_run, consoles = [], [], [], set()
    start = time.monotonic()
    lists_work = workspace(root, build)
    try:
        lists = program_lists(lists_work, dict(os.environ, LC_ALL="C"))
    finally:
        subprocess.run(["rm", "-rf", str(lists_work)])
    names = repository_file_names(root)
    for relative in pages:
        check_page(Page(root, relative), root, build, "--python" in flags, "--update" in flags,
                   lists, names, problems, timings, not_run, consoles)
    if len(pages) > 1 or not argv[2:]:
        for key in sorted(set(NOT_RUN) - consoles):
            if key[0] in pages:
                problems.append(f"NOT_RUN lists `{key[1]}` for {key[0]}, which no longer shows it")
    print(f"doc_examples: {len(timings)} commands run in {time.monotonic() - start:.1f} s; "
          f"slowest:")
    for seconds, where in sorted(timings, reverse=True)[:5]:
        print(f"  {seconds:6.2f} s  {where}")
    print(f"not run ({len(not_run)}), each with its reason:")
    for where, command, reason in not_run:
        print(f"  {where}: {command}\n      -- {reason}")
    for p in problems:
        print("doc_examples:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
