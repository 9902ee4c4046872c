"""Sphinx configuration of drivekin's documentation site (built in CI with warnings as
errors: ``python -m sphinx -W --keep-going -b html docs docs/_build/html``).

Sphinx rather than MkDocs: drivekin's docstrings are reStructuredText (``:meth:``,
``:class:`` and literal roles, written for the stubs and ``help()``), which Sphinx reads
natively, while the guides stay Markdown for GitHub through MyST. The API reference is
sphinx-autoapi reading the ``.pyi`` stubs (before the ``.py`` files), so the compiled
modules' signatures, with their types, come from the stubs, and their docstrings are the
compiled modules' own (scripts/stub_docstrings.py copies them; a test keeps them equal).
Nothing is imported, so the site builds without compiling drivekin.

Each member is documented once, under its Java name; robotpy 2027's spelling of it (the
alias block at the end of each stub class, written by scripts/stub_aliases.py) is a line
at the top of that entry, and the alias itself is not listed. robotpy's class names
(``SwerveDrive4Kinematics``, ...; the ``TYPE_CHECKING`` block of ``drivekin/__init__.py``)
are named in the entry of the class they build.
"""
from __future__ import annotations

import ast
import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

project = "drivekin"
release = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
version = release
copyright = "the drivekin authors"

extensions = ["myst_parser", "autoapi.extension"]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}   # autoapi writes .rst
root_doc = "index"
exclude_patterns = ["_build"]
# autoapi cannot follow imports into the private packages it is told to skip.
suppress_warnings = ["autoapi.python_import_resolution"]
myst_heading_anchors = 4          # GitHub's heading slugs, so #anchors work on both
html_theme = "furo"
html_title = f"drivekin {release}"

autoapi_type = "python"
autoapi_dirs = [str(ROOT / "src" / "drivekin")]
autoapi_file_patterns = ["*.pyi", "*.py"]
# Private packages and the programs (documented by their --help) are not API, except the
# private modules whose names a public module re-exports (drivekin.choreo's samples and
# report, the sampler its trajectory inherits from; drivekin.replay.listing): autoapi reads
# those so the names are documented under the public module, with no page of their own.
REEXPORTED = {"choreokernel.pyi", "choreocheck.py", "listing.py"}
autoapi_ignore = [str(p) for p in sorted((ROOT / "src" / "drivekin" / "_core").iterdir())
                  if p.name not in REEXPORTED] + ["*/app/*", "*/__main__.py"]
autoapi_options = ["members", "undoc-members", "inherited-members", "show-inheritance",
                   "show-module-summary", "special-members", "imported-members"]
autoapi_member_order = "groupwise"
autoapi_keep_files = True     # docs/api/ (ignored by git): to read what was generated
autoapi_root = "api"
autoapi_add_toctree_entry = False

# The guides link to the README and the changelog as a checkout shows them; on the site
# those are pages (the README is the home page). Files that are not pages are named, not
# linked (tests/integration/test_doc_links.py).
LINKS = [
    (re.compile(r"\]\(\.\./README\.md"), "](index.md"),
    (re.compile(r"\]\((?:\.\./)?CHANGELOG\.md"), "](changelog.md"),
]


def _site_links(app, docname, source, *included):
    for pattern, replacement in LINKS:
        source[0] = pattern.sub(replacement, source[0])


# -- robotpy 2027's spellings ------------------------------------------------------------
# Read from the stubs' text, as autoapi reads them: importing drivekin would need the
# compiled modules.
SRC = ROOT / "src"
STUB_MARKER = "# robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)"


def _words(name):
    return name.replace("_", "").lower()


def _java_of_property(alias, java_names, where):
    """The Java member a property alias (``def stall_torque``) stands for: the stub
    writes no reference to it, so match the spelling (stallTorque, R, getX)."""
    found = [j for j in java_names if _words(j) == _words(alias)] or \
        [j for j in java_names if j.startswith("get") and _words(j[3:]) == _words(alias)]
    if len(found) != 1:
        raise ValueError(f"{where}: robotpy property {alias!r} matches Java {found}")
    return found[0]


def _stub_spellings():
    """{full name of the stub class that defines the Java members: {Java name: robotpy
    2027 name}}, from each class's block after STUB_MARKER."""
    out = {}
    pkg = SRC / "drivekin"
    # A class written in Python has its block in its source, under ``if TYPE_CHECKING:``.
    sources = sorted(p for p in pkg.glob("*.py") if not p.with_suffix(".pyi").exists())
    for path in sorted(pkg.rglob("*.pyi")) + sources:
        text = path.read_text(encoding="utf-8")
        lines = text.splitlines()
        module = ".".join(path.relative_to(SRC).with_suffix("").parts)
        for node in ast.parse(text).body:
            if not isinstance(node, ast.ClassDef):
                continue
            marker = next((i + 1 for i in range(node.lineno, node.end_lineno)
                           if lines[i].strip() == STUB_MARKER), None)
            if marker is None:
                continue
            java_names = {m.name for m in node.body
                          if isinstance(m, ast.FunctionDef) and m.lineno < marker}
            spelled = {}
            block = [i for i in node.body if i.lineno >= marker]
            for item in [x for i in block for x in (i.body if isinstance(i, ast.If) else [i])]:
                if isinstance(item, ast.Assign):          # radians = getRadians
                    spelled[item.value.id] = item.targets[0].id
                elif "property" in {ast.unparse(d) for d in item.decorator_list}:
                    spelled[_java_of_property(item.name, java_names,
                                              f"{module}.{node.name}")] = item.name
            out[f"{module}.{node.name}"] = spelled
    return out


def _robotpy_class_names():
    """{drivekin class name: the sentence naming robotpy 2027's class names that build
    it}, from the declarations for type checkers in drivekin/__init__.py."""
    tree = ast.parse((SRC / "drivekin" / "__init__.py").read_text(encoding="utf-8"))
    block = next(n for n in tree.body if isinstance(n, ast.If)
                 and ast.unparse(n.test) == "TYPE_CHECKING")
    names, calls = {}, {}
    for item in block.body:
        if isinstance(item, ast.Assign):                  # SwerveDrive4Kinematics = ...
            names.setdefault(item.value.id, []).extend(t.id for t in item.targets)
        elif isinstance(item, ast.ClassDef):              # TimeInterpolatablePose2dBuffer
            base = ast.unparse(item.bases[0].value)
            names.setdefault(base, []).append(item.name)
            init = next(f for f in item.body if isinstance(f, ast.FunctionDef)).args
            params = [a.arg for a in init.args[1:]]
            defaults = [None] * (len(params) - len(init.defaults)) + init.defaults
            calls[base] = ", ".join(p if d is None else f"{p}={ast.unparse(d)}"
                                    for p, d in zip(params, defaults))
    return {cls: "robotpy 2027's names for this class: "
            + ", ".join(f"``{n}``" for n in found)
            + (f", each called as ``({calls[cls]})``." if cls in calls else ".")
            for cls, found in names.items()}


SPELLINGS = _stub_spellings()
CLASS_NAMES = _robotpy_class_names()


def _robotpy_spellings(app, what, name, obj, skip, options):
    """autoapi-skip-member: hide the robotpy aliases; name them in their Java member's
    entry (a line above its text) and robotpy's class names in the class's entry (after
    its first paragraph, which stays the summary in the module's table). The one
    autoapi event that sees every documented object, inherited members included, before
    it is written out; ``docstring`` is the text autoapi's templates render."""
    owner, _, member = name.rpartition(".")
    if what == "class":
        line = CLASS_NAMES.get(member)
        if line and line not in obj.docstring:
            first, sep, rest = obj.docstring.partition("\n\n")
            obj.docstring = f"{first}\n\n{line}{sep}{rest}"
        return None
    # An inherited member is documented from the class that defines it (_Frame2d).
    owner = obj.obj.get("inherited_from", {}).get("full_name", owner)
    spelled = SPELLINGS.get(owner, {})
    if member in spelled.values():
        return True
    py = spelled.get(member)
    if py is not None:
        line = f"robotpy 2027: ``{py}{'' if what == 'property' else '()'}``"
        if not obj.docstring.startswith(line):
            obj.docstring = f"{line}\n\n{obj.docstring}"
    return None


def _stubs_for_astroid():
    """autoapi finds a class's inherited members through astroid, which resolves a base
    imported from a compiled module to the extension (or nothing) and cannot read it:
    give it the stub of each re-exported compiled module (ChoreoTrajectory's sampling
    methods are ChoreoSampler's)."""
    import astroid

    for name in REEXPORTED:
        stub = ROOT / "src" / "drivekin" / "_core" / name
        if stub.suffix == ".pyi":
            module = f"drivekin._core.{stub.stem}"
            astroid.MANAGER.astroid_cache[module] = astroid.MANAGER.ast_from_file(
                str(stub), module, source=True)


def _private_and_reexported(app, what, name, obj, skip, options):
    """autoapi-skip-member: no page for a private module (only REEXPORTED ones are read);
    a name a module imports is documented where it is defined, unless that is private
    (drivekin.choreo's SwerveSample is documented there)."""
    if what == "module" and any(part.startswith("_") for part in name.split(".")):
        return True
    original = obj.obj.get("original_path")
    if original is not None and not any(p.startswith("_") for p in original.split(".")):
        return True
    return None


def setup(app):
    _stubs_for_astroid()         # here, not at import: the tests run this file without astroid
    app.connect("autoapi-skip-member", _private_and_reexported)
    app.connect("autoapi-skip-member", _robotpy_spellings)
    app.connect("source-read", _site_links)
    app.connect("include-read", lambda app, path, parent, content: _site_links(app, parent, content))
