#!/usr/bin/env python3
"""Write robotpy 2027's spellings of drivekin's members into the type stubs.

drivekin/_core/pynames.py gives every catalog class its robotpy 2027 names at import, as
the Java members themselves. For type checkers, each stub class that defines a Java member
(or, for a class written in Python, its source under ``if TYPE_CHECKING:``) gets, at
the end of its body, one line per robotpy name: ``radians = getRadians`` for a
method or static method (so the alias carries the Java member's signature and
overloads), and a ``@property`` with the getter's type for a property. The block starts
with a marker comment; a second run changes nothing.

    python scripts/stub_aliases.py            # rewrite the stubs whose block is stale
    python scripts/stub_aliases.py --check    # list them and exit 1

It imports the drivekin beside it (``src/drivekin``, which needs an in-place build) or the
one ``--package-dir`` names (an installed copy, whose stubs it then reads and writes).
``tests/api/test_stubs.py`` runs the check on the drivekin it tests.
"""
from __future__ import annotations

import argparse
import ast
import importlib
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
MARKER = "    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)"


def _stubs(pkg: Path) -> list[Path]:
    """The stubs, and the Python modules without one (their classes are read by type
    checkers from the source: the block goes under ``if TYPE_CHECKING:`` there)."""
    stubs = sorted(pkg.rglob("*.pyi"))
    return stubs + sorted(p for p in pkg.glob("*.py") if not p.with_suffix(".pyi").exists())


def _module(path: Path, pkg: Path) -> str:
    return ".".join(path.relative_to(pkg.parent).with_suffix("").parts)


def _wanted(module: str, cls_name: str, body: dict[str, ast.FunctionDef | None]
            ) -> dict[str, str]:
    """{robotpy name: Java name} that install() put into this stub class's runtime
    class (the one defining the Java members)."""
    from drivekin._core import pynames
    cls = getattr(importlib.import_module(module), cls_name, None)
    wanted = pynames.INSTALLED.get(cls, {}) if isinstance(cls, type) else {}
    missing = sorted(java for java in wanted.values() if java not in body)
    assert not missing, f"{module}.{cls_name}: the stub lacks {missing}"
    return dict(wanted)


def _block(wanted: dict[str, str], body: dict[str, ast.FunctionDef | None],
           source: bool) -> list[str]:
    lines = ["", MARKER]
    pad = "    "
    if source:                                   # a .py module: for type checkers only
        lines.append("    if TYPE_CHECKING:")
        pad = "        "
    for py, java in sorted(wanted.items()):
        getter = body[java]
        if getter is None:                       # a method, static method or overload set
            lines.append(f"{pad}{py} = {java}")
            continue
        returns = ast.unparse(getter.returns) if getter.returns else "Any"
        lines += [f"{pad}@property", f"{pad}def {py}(self) -> {returns}: ..."]
        setter = body.get(f"{java}.setter")
        if setter is not None:
            value = ast.unparse(setter.args.args[1].annotation or ast.Name("Any"))
            lines += [f"{pad}@{py}.setter",
                      f"{pad}def {py}(self, value: {value}) -> None: ..."]
    return lines


def _members(node: ast.ClassDef) -> dict[str, ast.FunctionDef | None]:
    """Java members of a stub class: name -> its property getter (None for methods)."""
    out: dict[str, ast.FunctionDef | None] = {}
    for item in node.body:
        if isinstance(item, ast.FunctionDef):
            decos = {ast.unparse(d) for d in item.decorator_list}
            if "property" in decos:
                out[item.name] = item
            elif f"{item.name}.setter" in decos:
                out[f"{item.name}.setter"] = item
            else:
                out.setdefault(item.name, None)
    return out


def rewrite(path: Path, pkg: Path) -> str:
    """The stub's text with every class's block up to date."""
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines()
    tree = ast.parse(text)
    module = _module(path, pkg)
    # Bottom-up, so earlier line numbers stay valid.
    for node in sorted((n for n in tree.body if isinstance(n, ast.ClassDef)),
                       key=lambda n: n.lineno, reverse=True):
        end = node.end_lineno or node.lineno
        body_lines = lines[node.lineno:end]
        if MARKER in body_lines:
            end = node.lineno + body_lines.index(MARKER) - 1     # with its blank line
            del lines[end:node.end_lineno]
        members = _members(node)
        wanted = _wanted(module, node.name, members)
        if wanted:
            lines[end:end] = _block(wanted, members, path.suffix == ".py")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="list stale stubs, exit 1")
    parser.add_argument("--package-dir", type=Path, default=SRC / "drivekin",
                        help="the drivekin whose stubs to write (default: %(default)s)")
    args = parser.parse_args(argv)
    pkg = args.package_dir.resolve()
    sys.path.insert(0, str(pkg.parent))
    found = Path(importlib.import_module("drivekin").__file__).resolve().parent
    if found != pkg:
        print(f"imported drivekin from {found}, not {pkg}", file=sys.stderr)
        return 2
    stale = []
    for path in _stubs(pkg):
        new = rewrite(path, pkg)
        if new != path.read_text(encoding="utf-8"):
            stale.append(path)
            if not args.check:
                path.write_text(new, encoding="utf-8")
    for path in stale:
        print(f"{'stale' if args.check else 'rewrote'}: {path}")
    return 1 if stale and args.check else 0


if __name__ == "__main__":
    sys.exit(main())
