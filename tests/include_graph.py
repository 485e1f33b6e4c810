#!/usr/bin/env python3
"""The include graph against the tier table of docs/ARCHITECTURE.md, and the table against the
links of src/CMakeLists.txt; the tests' folders (tests/<tier>/) against the same table. Exit 1,
naming each offending include, link or test file, when they disagree.

Usage: include_graph.py SOURCE_DIR
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
problems = []

# The table: library -> (folder, set of libraries it may include).
table = {}
in_table = False
for line in (root / "docs/ARCHITECTURE.md").read_text().splitlines():
    if line.startswith("<!-- tiers:"):
        in_table = True
        continue
    if in_table and not line.startswith("|"):
        if table:
            break
        continue
    if in_table and line.startswith("| ") and not line.startswith("| library") and "---" not in line:
        cells = [c.strip() for c in line.strip("|").split("|")]
        name, folder, may = cells[0], cells[1].strip("`"), cells[2]
        allowed = set() if may == "—" else {m.strip() for m in may.split(",")}
        table[name] = (folder, allowed)
if "core" not in table or len(table) < 5:
    sys.exit("include_graph: no tier table found in docs/ARCHITECTURE.md")

folder_of_prefix = {"conescan": "core"}
for name, (folder, _) in table.items():
    if folder.startswith("src/"):
        folder_of_prefix[folder[len("src/"):].strip("/")] = name

# 1. Every quoted include of a tier's files is its own or one the table allows.
include = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/[^"]+"', re.M)
for name, (folder, allowed) in table.items():
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h"):
            continue
        for match in include.finditer(path.read_text()):
            target = folder_of_prefix.get(match.group(1))
            if target is None or target == name:
                continue
            if target not in allowed:
                problems.append(f"{path.relative_to(root)} includes {match.group(0).strip()}: "
                                f"{name} may include {', '.join(sorted(allowed)) or 'nothing'}")

# 2. The table's may-include sets are the closures of the CMake links.
cmake = (root / "src/CMakeLists.txt").read_text()
links = {}
for match in re.finditer(r"conescan_layer\((\w+)(.*?)\)\n", cmake, re.S):
    name, body = match.group(1), match.group(2)
    public = re.search(r"PUBLIC([^A-Z]*)", body)
    deps = set(re.findall(r"conescan_(\w+)", public.group(1))) if public else set()
    links[name] = deps | {"core"}
def closure(name, seen=()):
    out = set()
    for dep in links.get(name, set()):
        out |= {dep} | (closure(dep) if dep in links else set())
    return out
for name, (folder, allowed) in table.items():
    if not folder.startswith("src/"):
        continue
    if name not in links:
        problems.append(f"docs/ARCHITECTURE.md lists {name}, which src/CMakeLists.txt does not build")
        continue
    if closure(name) != allowed:
        problems.append(f"{name}: the table says it may include {sorted(allowed)}, its links give "
                        f"{sorted(closure(name))}")
for name in links:
    if name not in table:
        problems.append(f"src/CMakeLists.txt builds {name}, which docs/ARCHITECTURE.md does not list")

# 3. A test in tests/<tier>/ includes what its tier may, also through the shared helpers it
# includes (tests/support/, tests/fuzz/, bench/accuracy/: followed to what they include); running
# the programs (tests/support/cli.hpp) is the programs' tier. A folder is named by its library
# (tests/scene/) or by its library's folder (tests/apps/).
test_folder = {}
for name, (folder, _) in table.items():
    top = pathlib.PurePath(folder).parts[0]
    test_folder[name] = name if top in ("src", "include") else top
tier_of_folder = {folder: name for name, folder in test_folder.items()}
helper_dirs = {"support": root / "tests/support", "fuzz": root / "tests/fuzz",
               "accuracy": root / "bench/accuracy"}
runs_programs = root / "tests/support/cli.hpp"
programs = tier_of_folder.get("apps")


def tier_includes(path, seen):
    """(tier, include, helpers it came through) for each tier include of path and its helpers."""
    out = []
    for match in include.finditer(path.read_text()):
        prefix, text = match.group(1), match.group(0).strip()
        if prefix in folder_of_prefix:
            out.append((folder_of_prefix[prefix], text, []))
            continue
        if prefix not in helper_dirs:
            continue
        helper = helper_dirs[prefix] / text.split('"')[1].split("/", 1)[1]
        if helper == runs_programs and programs:
            out.append((programs, text + " (it runs the programs)", []))
        if helper.exists() and helper not in seen:
            seen.add(helper)
            for tier, inner, chain in tier_includes(helper, seen):
                out.append((tier, inner, [helper.relative_to(root)] + chain))
    return out


for path in sorted((root / "tests").glob("test_*.cpp")):
    problems.append(f"{path.relative_to(root)}: a test goes in tests/<tier>/ "
                    "(docs/ARCHITECTURE.md)")
for directory in sorted(p for p in (root / "tests").iterdir() if p.is_dir()):
    if directory.name not in tier_of_folder:
        for path in sorted(directory.glob("test_*.cpp")):
            problems.append(f"{path.relative_to(root)}: tests/{directory.name}/ is no tier of "
                            "docs/ARCHITECTURE.md")
        continue
    name = tier_of_folder[directory.name]
    may = table[name][1] | {name}
    for path in sorted(directory.glob("*.[ch]pp")):
        needs = {"core"}
        for target, text, chain in tier_includes(path, set()):
            needs.add(target)
            if target not in may:
                through = "".join(f" through {c}" for c in chain)
                problems.append(f"{path.relative_to(root)} includes {text}{through}: a test of "
                                f"{name} may include {', '.join(sorted(may))}")
        # The lowest tier that holds what it needs: a test of the programs' tier that runs no
        # program, or of scene that needs orbit alone, belongs lower.
        fits = {other: allowed | {other} for other, (_, allowed) in table.items()
                if needs <= (allowed | {other}) < may}
        lower = [other for other, its in fits.items() if not any(m < its for m in fits.values())]
        if path.name.startswith("test_") and needs <= may and lower:
            homes = " or ".join(f"tests/{test_folder[t]}/" for t in sorted(lower))
            problems.append(f"{path.relative_to(root)} needs {', '.join(sorted(needs))}: it "
                            f"belongs lower, in {homes}")

# 4. Inside a library no arrow runs back up: its files (a header and its .cpp one unit) include
# one another without a cycle, so that they stand in an order, each on those below it. A library
# in `back_up_pending` still has such arrows (listed in docs/ARCHITECTURE.md): it must show one,
# and leaves the list when it has none.
back_up_pending = {"orbit", "calibration"}
for name, (folder, _) in table.items():
    prefix = "conescan" if name == "core" else folder[len("src/"):].strip("/")
    if not (root / folder).is_dir() or not (name == "core" or folder.startswith("src/")):
        continue
    own = re.compile(r'^\s*#\s*include\s+"' + re.escape(prefix) + r'/([A-Za-z0-9_/]+)\.h(?:pp)?"',
                     re.M)
    arrows = {}
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h"):
            continue
        unit = path.relative_to(root / folder).with_suffix("").as_posix()
        arrows.setdefault(unit, set()).update(
            u for u in own.findall(path.read_text()) if u != unit)
    # Each cycle once, by a depth-first search from every unit in order.
    state, cycles = {}, []

    def visit(unit, stack):
        state[unit] = "open"
        stack.append(unit)
        for nxt in sorted(arrows.get(unit, ())):
            if state.get(nxt) == "open":
                cycles.append(stack[stack.index(nxt):] + [nxt])
            elif nxt in arrows and nxt not in state:
                visit(nxt, stack)
        stack.pop()
        state[unit] = "done"

    for unit in sorted(arrows):
        if unit not in state:
            visit(unit, [])
    if name in back_up_pending:
        if not cycles:
            problems.append(f"{name} has no arrow back up any more: drop it from back_up_pending "
                            "(tests/include_graph.py) and from docs/ARCHITECTURE.md")
        continue
    for cycle in cycles:
        problems.append(f"{folder}: an arrow runs back up inside {name}: "
                        f"{' -> '.join(cycle)} (a unit is a header and its .cpp)")

for p in problems:
    print("include_graph:", p)
sys.exit(1 if problems else 0)
