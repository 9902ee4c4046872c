"""docs/DESIGN.md's layout block lists every file of the library, and only files that exist.

The block is a tree indented by two spaces a level: a directory ends in ``/``; a file line
starts with its name, then optionally further suffixes of the same stem
(``swerve.pyx .pxd .pyi``), then two spaces and what it holds."""
import itertools
import pathlib
import re
import shutil
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]  # tests/api/ -> the repository root
DESIGN = ROOT / "docs" / "DESIGN.md"
PACKAGE = "src/drivekin/"


def _layout_block(text):
    section = text.split("\n## Layout\n", 1)[1].split("\n## ", 1)[0]
    return re.search(r"^```\n(.*?)^```", section, re.S | re.M).group(1)


def _listed(block):
    """The paths (relative to the repository root) the block's src/drivekin/ tree names."""
    lines = block.splitlines()
    assert lines[0] == PACKAGE, lines[0]
    paths, parents = set(), [PACKAGE.rstrip("/")]
    for line in lines[1:]:
        depth = (len(line) - len(line.lstrip(" "))) // 2
        if depth == 0:                               # the tree of src/drivekin/ has ended
            break
        first, *rest = re.split(r" {2,}", line.strip(), maxsplit=1)[0].split()
        names = [first] + [t for t in itertools.takewhile(lambda t: t.startswith("."), rest)]
        del parents[depth:]
        assert len(parents) == depth, f"indentation of {line!r}"
        if names[0].endswith("/"):
            parents.append(names[0].rstrip("/"))
            continue
        stem = first[:first.index(".", 1)] if "." in first[1:] else first
        for name in [first] + [stem + suffix for suffix in names[1:]]:
            paths.add("/".join(parents + [name]))
    return paths


def _library_files():
    if not (ROOT / ".git").exists() or shutil.which("git") is None:
        pytest.skip("not a git checkout: the library's files are the tracked ones")
    out = subprocess.run(["git", "ls-files", "--", PACKAGE], cwd=ROOT, check=True,
                         capture_output=True, text=True).stdout
    return set(out.split())


def test_layout_parser_reads_suffix_lists_and_nesting():
    block = ("src/drivekin/\n  a.pyx .pxd  holds a\n  _core/  private\n    b.h  b\n"
             "  c.py  c\ntests/  elsewhere\n")
    assert _listed(block) == {"src/drivekin/a.pyx", "src/drivekin/a.pxd",
                              "src/drivekin/_core/b.h", "src/drivekin/c.py"}


def test_every_library_file_is_in_the_layout():
    files = _library_files()
    assert files, "git ls-files listed nothing under src/drivekin/"
    listed = _listed(_layout_block(DESIGN.read_text(encoding="utf-8")))
    assert sorted(files - listed) == [], "add these to docs/DESIGN.md's layout block"
    assert sorted(listed - files) == [], "docs/DESIGN.md's layout block names files that are gone"
