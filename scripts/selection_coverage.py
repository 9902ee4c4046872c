"""Compare the compiled modules' line coverage of the whole test suite and of the
memory-safety selection, from per-folder coverage data written by
scripts/selection_coverage.sh (which says how). Exits 1 if the selection is more than one
percentage point below the whole suite.

Statements are what Cython's coverage plugin counts: the lines of each ``.pyx`` for which
Cython wrote code into its module's C file. The inline kernels of the ``.pxd`` files are
compiled into every module that uses them and have no report of their own in the plugin;
their lines reached by the whole suite but not by the selection are listed too.

    usage: python scripts/selection_coverage.py SCRATCH_TREE
"""
from __future__ import annotations

import ast
import glob
import os
import sys

from Cython.Coverage import Plugin
from coverage.data import CoverageData


def selection_kinds(tree: str) -> tuple[str, ...]:
    """MEMORY_SAFETY_KINDS from the tree's tests/conftest.py, read without importing it."""
    module = ast.parse(open(os.path.join(tree, "tests", "conftest.py")).read())
    for node in module.body:
        if (isinstance(node, ast.Assign) and len(node.targets) == 1
                and getattr(node.targets[0], "id", None) == "MEMORY_SAFETY_KINDS"):
            return tuple(ast.literal_eval(node.value))
    raise SystemExit("tests/conftest.py defines no MEMORY_SAFETY_KINDS")


def main(tree: str) -> int:
    src = os.path.join(tree, "src")
    statements: dict[str, set[int]] = {}
    plugin = Plugin()
    for c_file in glob.glob(os.path.join(src, "drivekin", "**", "*.c"), recursive=True):
        for name, code in plugin._parse_cfile_lines(c_file).items():
            if name.startswith("drivekin/"):
                statements.setdefault(os.path.join(src, name), set()).update(code)

    reached: dict[str, dict[str, set[int]]] = {}   # folder -> file -> lines
    for path in glob.glob(os.path.join(tree, "coverage", "*")):
        folder = os.path.basename(path).split(".")[0]
        if path.endswith(".log"):
            continue
        data = CoverageData(basename=path)
        data.read()
        lines = reached.setdefault(folder, {})
        for name in data.measured_files():
            if name in statements:
                lines.setdefault(name, set()).update(data.lines(name) or ())
    kinds = selection_kinds(tree)
    missing = [k for k in kinds if k not in reached]
    if missing:
        raise SystemExit(f"no coverage data for the selection's folders {missing}")

    def union(folders) -> dict[str, set[int]]:
        out: dict[str, set[int]] = {}
        for f in folders:
            for name, lines in reached[f].items():
                out.setdefault(name, set()).update(lines)
        return out

    whole, selection = union(reached), union(kinds)
    pyx = {n: s for n, s in statements.items() if n.endswith(".pyx")}
    total = sum(len(s) for s in pyx.values())

    def percent(cover: dict[str, set[int]]) -> float:
        return 100.0 * sum(len(cover.get(n, set()) & s) for n, s in pyx.items()) / total

    print(f"{len(pyx)} compiled modules, {total} statements (Cython's coverage plugin)")
    for folder in sorted(reached):
        print(f"  tests/{folder:<12} {percent(reached[folder]):6.2f} %")
    a, b = percent(whole), percent(selection)
    print(f"whole suite         {a:6.2f} %")
    print(f"selection           {b:6.2f} %  ({' + '.join(kinds)})")
    print("reached by the whole suite, not by the selection:")
    for name in sorted(statements):
        gap = sorted((whole.get(name, set()) - selection.get(name, set())) & statements[name])
        if gap:
            print(f"  {os.path.relpath(name, src)}: {len(gap)} lines {gap}")
    if a - b > 1.0:
        print(f"the selection is {a - b:.2f} percentage points below the whole suite (limit 1)")
        return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    sys.exit(main(sys.argv[1]))
