"""Sphinx configuration of drivekin's documentation site (built in CI with warnings as
errors: ``python -m sphinx -W --keep-going -b html docs docs/_build/html``).

Sphinx rather than MkDocs: drivekin's docstrings are reStructuredText (``:meth:``,
``:class:`` and literal roles, written for the stubs and ``help()``), which Sphinx reads
natively, while the guides stay Markdown for GitHub through MyST. The API reference is
sphinx-autoapi reading the ``.pyi`` stubs (before the ``.py`` files), so the compiled
modules' signatures, with their types, come from the stubs, and their docstrings are the
compiled modules' own (scripts/stub_docstrings.py copies them; a test keeps them equal).
Nothing is imported, so the site builds without compiling drivekin.
"""
from __future__ import annotations

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
# Private packages and the programs (documented by their --help) are not API.
autoapi_ignore = ["*/_core/*", "*/app/*", "*/__main__.py"]
autoapi_options = ["members", "undoc-members", "inherited-members", "show-inheritance",
                   "show-module-summary", "special-members"]
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


def setup(app):
    app.connect("source-read", _site_links)
    app.connect("include-read", lambda app, path, parent, content: _site_links(app, parent, content))
