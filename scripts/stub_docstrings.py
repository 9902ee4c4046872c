#!/usr/bin/env python3
"""Write the docstrings of drivekin's type stubs from the compiled modules.

The ``.pyx`` docstrings are the single source. For every ``src/drivekin/**/*.pyi`` that
has a compiled module beside it (subpackages included: ``_core/wheels.pyi`` is the stub
of ``drivekin._core.wheels``), this script reads the module's runtime ``__doc__``
strings (without the signature line that Cython's ``embedsignature=True`` prepends, see
:func:`runtime_doc`) and writes them as the stub's docstrings: the module's, each
class's (private bases included) and each public method's, static/class method's,
property getter's and module-level function's that exists at runtime. Overloads keep the
docstring on the overload(s) that carry one (the first one when it is new); property
setters/deleters and dunders carry none; members and classes that do not exist at
runtime are left alone.

Only docstring nodes are replaced, inserted or removed (at their ``ast`` positions, with
the stub's own indentation); every other byte of a stub stays as it is, and a second run
changes nothing. A docstring keeps the stub's layout (a line break after the opening
quotes, closing quotes on a line of their own, or not); a new one gets the stubs'
convention: closing quotes on their own line for a multi-line module or class docstring,
on the last text line otherwise.

    python scripts/stub_docstrings.py                  # rewrite the stale stubs
    python scripts/stub_docstrings.py --check          # list the stale stubs, exit 1
    python scripts/stub_docstrings.py --check --diff   # ... and show what would change

It imports the drivekin whose directory holds the stubs (``src/drivekin`` beside this
script unless ``--package-dir`` says otherwise; that directory goes first on sys.path,
so no PYTHONPATH is needed), which therefore needs an in-place build (``python setup.py
build_ext --inplace``). Exit status: 0 up to date / rewritten, 1 stale (``--check``),
2 error. ``tests/api/test_stubs.py`` imports :func:`runtime_doc`
from here and runs ``--check``.
"""
from __future__ import annotations

import argparse
import ast
import difflib
import importlib
import importlib.machinery
import inspect
import re
import sys
import types
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DEFAULT_PACKAGE_DIR = REPO / "src" / "drivekin"


def public(name: str) -> bool:
    return not name.startswith("_")


# ---------------------------------------------------------------------------------------
# Runtime docstrings
#
# With embedsignature=True Cython prepends one line to the docstring of every def
# function, and of every class that defines __init__ itself (the line is taken from it):
#     methods:  "<__qualname__>(<parameters>)", e.g. "Translation2d.getDistance(self,
#               Translation2d other)" or "_ChassisVector.plus(self, _ChassisVector other)"
#     classes:  "<ClassName>(<__init__ parameters>)", e.g. "Pose2d(a=None, b=None, c=None)"
# optionally followed by " -> <return type>", then a blank line and the source docstring
# (or nothing when the source has no docstring). Classes that inherit __init__ (the
# mecanum/differential wheel values) get no line, and properties and module docstrings are
# left alone. Most class docstrings in the sources themselves start with a "Name(...)"
# line (SwerveDriveKinematics's is even identical to the embedded one), so a class line is
# removed only when the module was built with embedsignature and the class has its own
# __init__, and then exactly one line, which must look like a signature.

def _signature_line(name: str) -> re.Pattern[str]:
    # With binding=False a static method's __qualname__ is its bare name while Cython
    # embeds "Class.name(...)": a bare name may carry one class prefix.
    prefix = "" if "." in name else r"(?:\w+\.)?"
    return re.compile(rf"{prefix}{re.escape(name)}\(.*\)(?:\s*->\s*\S.*)?")


def _split_first_line(doc: str) -> tuple[str, str]:
    """Split off the embedded signature line and the blank line after it."""
    first, _, rest = doc.partition("\n")
    blank, _, rest = rest.partition("\n")
    if blank.strip():
        raise AssertionError(f"embedded signature not followed by a blank line: {doc!r}")
    return first, rest


def _module_functions_and_classes(mod: types.ModuleType) -> list[object]:
    return [obj for obj in vars(mod).values()
            if (isinstance(obj, type) or callable(obj))
            and getattr(obj, "__module__", None) == mod.__name__]


def module_embeds_signatures(mod: types.ModuleType) -> bool:
    """True if the module was compiled with embedsignature: the docstring of one of its
    functions or of a public method of one of its classes starts with its own qualified
    signature line."""
    candidates: list[object] = []
    for obj in _module_functions_and_classes(mod):
        if isinstance(obj, type):
            for klass in obj.__mro__[:-1]:                  # without object
                candidates += [v for k, v in vars(klass).items() if public(k)]
        else:
            candidates.append(obj)
    for raw in candidates:
        func = raw.__func__ if isinstance(raw, (staticmethod, classmethod)) else raw
        doc = getattr(func, "__doc__", None)
        qualname = getattr(func, "__qualname__", None)
        if callable(func) and doc and qualname and _signature_line(qualname).fullmatch(
                doc.partition("\n")[0]):
            return True
    return False


_CYTHON_ATTRIBUTE_DOC = re.compile(r"\w+: '[^']*'")    # cdef public/readonly: "dx: 'double'"


def runtime_doc(obj: object, *, kind: str, embeds: bool) -> str | None:
    """``obj.__doc__`` without Cython's embedded signature line, cleaned; None if empty.
    ``kind`` is "module", "class", "function" (method, static method, function) or
    "attribute" (property, cdef attribute)."""
    doc = obj.__doc__
    if kind == "class":
        if doc is not None and embeds and "__init__" in vars(obj):
            first, rest = _split_first_line(doc)
            assert _signature_line(obj.__name__).fullmatch(first), (
                f"{obj.__name__}: expected an embedded class signature, got {first!r}")
            doc = rest
    elif kind == "function":
        if doc is not None:
            first = doc.partition("\n")[0]
            if _signature_line(obj.__qualname__).fullmatch(first):
                doc = _split_first_line(doc)[1]
            else:
                assert not embeds, f"{obj.__qualname__}: embedded signature missing: {doc!r}"
    elif kind == "attribute":
        # Cython documents cdef public/readonly attributes with their C type only.
        if doc is not None and _CYTHON_ATTRIBUTE_DOC.fullmatch(doc.strip()):
            doc = None
    doc = inspect.cleandoc(doc) if doc else None
    return doc or None


# ---------------------------------------------------------------------------------------
# Discovery

def _extension_suffixes() -> list[str]:
    return sorted(importlib.machinery.EXTENSION_SUFFIXES, key=len, reverse=True)


def stub_modules(pkg_dir: Path) -> list[tuple[Path, str]]:
    """(stub path, dotted module name) of every ``*.pyi`` under ``pkg_dir`` (recursively)
    with a compiled module of the same name beside it."""
    found = []
    for stub in sorted(pkg_dir.rglob("*.pyi")):
        if any(stub.with_name(stub.stem + s).is_file() for s in _extension_suffixes()):
            parts = stub.relative_to(pkg_dir).with_suffix("").parts
            found.append((stub, ".".join((pkg_dir.name, *parts))))
    return found


# ---------------------------------------------------------------------------------------
# Expected docstrings of a stub

@dataclass
class Target:
    """The docstring that the body of ``scope`` (a Module, ClassDef or FunctionDef) must
    start with: ``doc`` (cleaned), or none if ``doc`` is None."""
    scope: ast.AST
    doc: str | None
    where: str = ""


def _target(scope: ast.AST, obj: object, kind: str, embeds: bool, where: str) -> Target:
    return Target(scope, runtime_doc(obj, kind=kind, embeds=embeds), where)


def _decorators(node: ast.FunctionDef | ast.AsyncFunctionDef) -> set[str]:
    names = set()
    for d in node.decorator_list:
        if isinstance(d, ast.Name):
            names.add(d.id)
        elif isinstance(d, ast.Attribute):
            names.add(d.attr)                  # "setter" for @x.setter, typing.overload
    return names


DESCRIPTORS = (property, types.GetSetDescriptorType, types.MemberDescriptorType)


def _robotpy_spellings(cls: type) -> dict[str, str]:
    from drivekin._core import pynames
    return pynames.spellings(cls)


def _function_targets(body: list[ast.stmt], owner: object, embeds: bool,
                      where: str) -> list[Target]:
    """Targets of the public functions defined in ``body`` (a class body when ``owner``
    is a class, the module body when it is the module)."""
    groups: dict[str, list[ast.FunctionDef | ast.AsyncFunctionDef]] = {}
    targets = []
    # robotpy 2027's spellings of properties (scripts/stub_aliases.py) share the Java
    # name's docstring, which the stub carries once.
    spellings = _robotpy_spellings(owner) if isinstance(owner, type) else {}
    for node in body:
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) or not public(
                node.name) or node.name in spellings:
            continue
        if {"setter", "deleter"} & _decorators(node):
            targets.append(Target(node, None, where=f"{where}{node.name} (setter)"))
        else:
            groups.setdefault(node.name, []).append(node)
    for name, nodes in groups.items():
        try:
            raw = inspect.getattr_static(owner, name)
        except AttributeError:
            continue                           # not at runtime: stubtest's business
        if isinstance(raw, DESCRIPTORS):
            obj, kind = raw, "attribute"
        else:
            obj, kind = getattr(owner, name), "function"
        first = _target(nodes[0], obj, kind, embeds, f"{where}{name}")
        documented = [n for n in nodes if _docstring_node(n) is not None] or nodes[:1]
        for node in nodes:
            doc = first.doc if node in documented else None
            targets.append(Target(node, doc, first.where))
    return targets


def _class_targets(node: ast.ClassDef, cls: type, embeds: bool) -> list[Target]:
    targets = [_target(node, cls, "class", embeds, f"class {node.name}")]
    targets += _function_targets(node.body, cls, embeds, f"{node.name}.")
    for item in node.body:
        if isinstance(item, ast.ClassDef) and isinstance(vars(cls).get(item.name), type):
            targets += _class_targets(item, vars(cls)[item.name], embeds)
    return targets


def stub_targets(tree: ast.Module, mod: types.ModuleType) -> list[Target]:
    embeds = module_embeds_signatures(mod)
    targets = [_target(tree, mod, "module", embeds, "module")]
    targets += _function_targets(tree.body, mod, embeds, "")
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and isinstance(vars(mod).get(node.name), type):
            targets += _class_targets(node, vars(mod)[node.name], embeds)
    return targets


# ---------------------------------------------------------------------------------------
# Rewriting (byte offsets: ast columns are UTF-8 byte offsets)

class StubError(Exception):
    pass


def _docstring_node(scope: ast.AST) -> ast.Expr | None:
    body = getattr(scope, "body", None)
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
            and isinstance(body[0].value.value, str):
        return body[0]
    return None


def _is_ellipsis(stmt: ast.stmt) -> bool:
    return (isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant)
            and stmt.value.value is Ellipsis)


def _stmt_first_line(stmt: ast.stmt) -> int:
    decorators = getattr(stmt, "decorator_list", [])
    return min([stmt.lineno] + [d.lineno for d in decorators])


def _layout(scope: ast.AST, doc: str, existing: ast.Expr | None) -> tuple[bool, bool]:
    """(line break after the opening quotes, closing quotes on a line of their own)."""
    if existing is not None:
        lines = existing.value.value.split("\n")
        return (len(lines) > 1 and not lines[0].strip(),
                len(lines) > 1 and not lines[-1].strip())
    return False, "\n" in doc and isinstance(scope, (ast.Module, ast.ClassDef))


def _literal(doc: str, indent: str, layout: tuple[bool, bool]) -> str:
    opening_break, closing_line = layout
    first, *rest = doc.split("\n")
    text = "\n".join([first] + [indent + line if line else "" for line in rest])
    if opening_break:
        text = "\n" + indent + text
    if closing_line and rest:      # (cleandoc keeps the indent of a one-line docstring's)
        text += "\n" + indent
    text = text.replace("\\", "\\\\")
    if '"""' in text or text.endswith('"'):
        text = text.replace('"', '\\"')
    literal = f'"""{text}"""'
    assert inspect.cleandoc(ast.literal_eval(literal)) == doc, literal
    return literal


class _Source:
    def __init__(self, data: bytes):
        self.data = data
        self.lines = data.splitlines(keepends=True)
        self.starts = [0]
        for line in self.lines:
            self.starts.append(self.starts[-1] + len(line))

    def offset(self, lineno: int, col: int) -> int:
        return self.starts[lineno - 1] + col

    def line(self, lineno: int) -> bytes:
        return self.lines[lineno - 1]

    def prefix(self, lineno: int, col: int) -> bytes:
        return self.line(lineno)[:col]

    def indent_of(self, lineno: int) -> str:
        line = self.line(lineno)
        return line[: len(line) - len(line.lstrip(b" \t"))].decode()


def _indent_unit(tree: ast.Module, src: _Source) -> str:
    for node in ast.walk(tree):
        if isinstance(node, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            if node.body[0].lineno > node.lineno:
                outer = src.indent_of(node.lineno)
                inner = src.indent_of(node.body[0].lineno)
                if inner.startswith(outer) and len(inner) > len(outer):
                    return inner[len(outer):]
    return "    "


def _edits(target: Target, src: _Source, unit: str) -> list[tuple[int, int, bytes]]:
    scope, where = target.scope, target.where
    body = scope.body
    existing = _docstring_node(scope)
    header_indent = "" if isinstance(scope, ast.Module) else src.indent_of(scope.lineno)
    body_indent = "" if isinstance(scope, ast.Module) else header_indent + unit

    def stmt_indent(stmt: ast.stmt) -> str | None:
        prefix = src.prefix(stmt.lineno, stmt.col_offset)
        return None if prefix.strip() else prefix.decode()

    layout = _layout(scope, target.doc or "", existing)

    def span(stmt: ast.stmt) -> tuple[int, int]:
        return (src.offset(stmt.lineno, stmt.col_offset),
                src.offset(stmt.end_lineno, stmt.end_col_offset))

    if existing is not None:
        start, end = span(existing)
        if target.doc is not None:
            indent = stmt_indent(existing)
            indent = body_indent if indent is None else indent
            return [(start, end, _literal(target.doc, indent, layout).encode())]
        if len(body) == 1:
            return [(start, end, b"...")]
        rest_of_line = src.line(existing.end_lineno)[existing.end_col_offset:]
        if stmt_indent(existing) is None or rest_of_line.strip():
            raise StubError(f"{where}: cannot remove a docstring that shares its line")
        return [(src.starts[existing.lineno - 1], src.starts[existing.end_lineno], b"")]

    if target.doc is None:
        return []
    if len(body) == 1 and _is_ellipsis(body[0]) and not isinstance(scope, ast.Module):
        start, end = span(body[0])
        indent = stmt_indent(body[0])
        if indent is not None:                 # "..." on a line of its own
            return [(start, end, _literal(target.doc, indent, layout).encode())]
        # "def f(self) -> int: ..." becomes "def f(self) -> int:\n<indent>\"\"\"doc\"\"\""
        line = src.line(body[0].lineno)
        head = line[: body[0].col_offset].rstrip(b" \t")
        if not head.endswith(b":") or line[body[0].end_col_offset:].strip():
            raise StubError(f"{where}: cannot insert a docstring into this one-line body")
        colon = src.offset(body[0].lineno, len(head))
        literal = _literal(target.doc, body_indent, layout)
        return [(colon, end, f"\n{body_indent}{literal}".encode())]
    if isinstance(scope, ast.Module):          # at the top, after a shebang/coding line
        lineno = 1
        while lineno <= len(src.lines) and lineno <= 2 and re.match(
                rb"#!|#.*coding[:=]", src.line(lineno)):
            lineno += 1
        at = src.starts[lineno - 1]
        return [(at, at, f"{_literal(target.doc, '', layout)}\n".encode())]
    first = body[0]
    lineno = _stmt_first_line(first)           # its first decorator's line, if any
    starts_line = (src.line(lineno).lstrip().startswith(b"@") if lineno < first.lineno
                   else stmt_indent(first) is not None)
    if not starts_line or (not isinstance(scope, ast.Module) and lineno == scope.lineno):
        raise StubError(f"{where}: cannot insert a docstring before a statement that does "
                        "not start its line")
    indent = src.indent_of(lineno)
    literal = _literal(target.doc, indent, layout)
    at = src.starts[lineno - 1]
    return [(at, at, f"{indent}{literal}\n".encode())]


def _without_docstrings(text: str) -> str:
    """ast.dump of the stub ``text`` with every docstring dropped and every body that is
    then empty or only ``...`` normalised: what a rewrite must leave unchanged."""
    tree = ast.parse(text)
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef,
                             ast.AsyncFunctionDef)):
            if _docstring_node(node) is not None:
                body = body[1:]
            if not body or (len(body) == 1 and _is_ellipsis(body[0])):
                body = [] if isinstance(node, ast.Module) else [
                    ast.Expr(ast.Constant(Ellipsis))]
            node.body = body
    return ast.dump(tree)


def rewrite(text: str, mod: types.ModuleType) -> str:
    """The stub ``text`` with every docstring written from ``mod`` (see the module
    docstring)."""
    tree = ast.parse(text)
    src = _Source(text.encode("utf-8"))
    unit = _indent_unit(tree, src)
    targets = stub_targets(tree, mod)
    edits = sorted(e for t in targets for e in _edits(t, src, unit))
    for (_, end, _), (start, _, _) in zip(edits, edits[1:]):
        if end > start:
            raise StubError(f"{mod.__name__}: overlapping docstring edits")
    data = src.data
    for start, end, new in reversed(edits):
        data = data[:start] + new + data[end:]
    result = data.decode("utf-8")
    # Check the result: the docstrings are as expected and nothing else changed.
    new_tree = ast.parse(result)
    new_targets = stub_targets(new_tree, mod)
    got = [ast.get_docstring(t.scope, clean=True) for t in new_targets]
    want = [t.doc for t in new_targets]
    if got != want:
        raise StubError(f"{mod.__name__}: rewritten docstrings do not match")
    if _without_docstrings(result) != _without_docstrings(text):
        raise StubError(f"{mod.__name__}: a rewrite changed more than docstrings")
    return result


# ---------------------------------------------------------------------------------------
# Command line

def _import_package(pkg_dir: Path) -> None:
    """Import the package in ``pkg_dir`` (its parent first on sys.path) and make sure it
    is that one, not another installed copy."""
    sys.path.insert(0, str(pkg_dir.parent))
    package = importlib.import_module(pkg_dir.name)
    found = Path(package.__file__).resolve().parent
    if found != pkg_dir.resolve():
        raise StubError(f"imported {pkg_dir.name} from {found}, not from {pkg_dir}; run "
                        f"with PYTHONPATH={pkg_dir.parent}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.partition("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="write nothing; list the stale stubs and exit 1 if any")
    parser.add_argument("--diff", action="store_true",
                        help="print a unified diff of every stale stub")
    parser.add_argument("--package-dir", type=Path, default=DEFAULT_PACKAGE_DIR,
                        help="the package whose stubs to write (default: %(default)s)")
    args = parser.parse_args(argv)
    pkg_dir = args.package_dir.resolve()
    try:
        _import_package(pkg_dir)
        stubs = stub_modules(pkg_dir)
        if not stubs:
            raise StubError(f"no stub with a compiled module under {pkg_dir} (is it built?)")
        stale = []
        for path, name in stubs:
            text = path.read_text(encoding="utf-8")
            new = rewrite(text, importlib.import_module(name))
            if new == text:
                continue
            stale.append(path)
            if args.diff:
                sys.stdout.writelines(difflib.unified_diff(
                    text.splitlines(keepends=True), new.splitlines(keepends=True),
                    str(path), f"{path} (from {name}.__doc__)"))
            if not args.check:
                path.write_bytes(new.encode("utf-8"))
    except (StubError, AssertionError) as exc:    # AssertionError: from runtime_doc
        print(f"stub_docstrings.py: error: {exc}", file=sys.stderr)
        return 2
    for path in stale:
        print(f"{'stale' if args.check else 'rewrote'}: {path}")
    if args.check and stale:
        print(f"{len(stale)} stub(s) with docstrings that differ from the compiled modules; "
              f"run: python scripts/stub_docstrings.py", file=sys.stderr)
        return 1
    if not stale:
        print(f"{len(stubs)} stubs up to date")
    return 0


if __name__ == "__main__":
    sys.exit(main())
