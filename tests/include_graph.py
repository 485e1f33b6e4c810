#!/usr/bin/env python3
"""The include graph against the tier table of docs/ARCHITECTURE.md, and the table against the
links of src/CMakeLists.txt. Exit 1, naming each offending include or link, when they disagree.

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

for p in problems:
    print("include_graph:", p)
sys.exit(1 if problems else 0)
