"""Every Python example in README.md and in the docs/*.md pages runs as written, every
guide is indexed, and the README's test command is the one CI runs. (What the pages may
link to: test_doc_links.py.)"""
import ast
import pathlib
import re
import textwrap

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]  # tests/integration/ -> root
README = ROOT / "README.md"
DOCS = ROOT / "docs"
FENCE = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def _pages():
    pages = [README] if README.exists() else []
    return pages + (sorted(DOCS.glob("*.md")) if DOCS.is_dir() else [])


def _blocks(page):
    """(first line number, code) of every ```python block of a page."""
    text = page.read_text(encoding="utf-8")
    return [(text.count("\n", 0, m.start(1)), m.group(1)) for m in FENCE.finditer(text)]


PAGES = _pages()
CASES = [pytest.param(page, line, code, id=f"{page.relative_to(ROOT).as_posix()}-block{i}")
         for page in PAGES for i, (line, code) in enumerate(_blocks(page))]


def _needs_pages():
    if not README.exists():
        pytest.skip("README.md is not next to the tests (installed from an sdist?)")


def test_readme_has_examples():
    _needs_pages()
    assert len(_blocks(README)) >= 4


def test_docs_have_examples():
    _needs_pages()
    docs = [code for page in PAGES if page != README for _, code in _blocks(page)]
    assert len(docs) >= 9


def test_control_loop_example_is_checked():
    # test_example_runs calls `periodic`; make sure some page still defines it.
    _needs_pages()
    assert any(re.search(r"^def periodic\(", code, re.M) for _, _, code in
               (case.values for case in CASES))


@pytest.mark.parametrize("page, line, code", CASES)
def test_example_runs(page, line, code):
    namespace: dict = {}
    # Padded so that a traceback names the page's own line numbers.
    exec(compile("\n" * line + code, str(page), "exec"), namespace)
    if "periodic" in namespace:                      # the allocation-free loop example
        from drivekin import Rotation2d
        pose = namespace["periodic"](0.5, 0.2, 0.1, Rotation2d(0.3))
        assert type(pose).__name__ == "Pose2d"


def test_every_docs_page_is_indexed():
    _needs_pages()
    index = (DOCS / "README.md").read_text(encoding="utf-8")
    readme = README.read_text(encoding="utf-8")
    # The docs site's home page (the README) and changelog page only include other files.
    pages = {p.name for p in DOCS.glob("*.md")} - {"README.md", "index.md", "changelog.md"}
    assert pages
    assert [n for n in sorted(pages) if f"]({n})" not in index] == []
    assert [n for n in sorted(pages) if f"](docs/{n})" not in readme] == []


def test_every_docs_page_is_on_the_site():
    _needs_pages()
    site = (DOCS / "index.md").read_text(encoding="utf-8")
    listed = set(re.findall(r"^([\w-]+)$", site, re.M))
    pages = {p.stem for p in DOCS.glob("*.md")} - {"index"}
    assert sorted(pages - listed) == []


def test_readme_test_command_is_the_ci_command():
    ci = ROOT / ".ci" / "run"
    if not ci.exists():
        pytest.skip(".ci/run is not next to the tests (installed from an sdist?)")
    install, test = 'pip install ".[test]"', "python -m pytest"
    assert f"```sh\n{install} && {test}\n```" in README.read_text(encoding="utf-8")
    # CI runs the two halves as two steps of its step table, in this order (under
    # `set -e`, as `&&` would); reporting options come through PYTEST_ADDOPTS.
    lines = ci.read_text(encoding="utf-8").splitlines()
    assert f"python -m {install}" in lines and test in lines
    assert lines.index(f"python -m {install}") < lines.index(test)


# -- examples in docstrings (the API reference of the docs site shows them) ---------------

def _public_modules():
    import pkgutil
    import drivekin
    names = ["drivekin"] + [f"drivekin.{m.name}" for m in pkgutil.iter_modules(drivekin.__path__)
                            if not m.name.startswith("_") and m.name not in ("app",)]
    return sorted(names)


_LITERAL = re.compile(r"::\n\n((?:(?:[ ]{4}.*)?\n)+)")


def _docstring_examples():
    """(where, [code, ...]): each public docstring's literal blocks that are Python (they
    parse; a block of formulas does not), in order, and its doctests."""
    import importlib
    import inspect
    found = []
    for name in _public_modules():
        mod = importlib.import_module(name)
        objs = [(name, mod)]
        for attr, obj in vars(mod).items():
            if (attr.startswith("_") or inspect.ismodule(obj)
                    or getattr(obj, "__module__", name) != name):
                continue
            objs.append((f"{name}.{attr}", obj))
            if isinstance(obj, type):
                objs += [(f"{name}.{attr}.{m}", v) for m, v in vars(obj).items()
                         if not m.startswith("_")]
        for where, obj in objs:
            doc = inspect.getdoc(obj) or ""
            blocks = []
            for m in _LITERAL.finditer(doc + "\n"):
                code = textwrap.dedent(m.group(1))
                try:
                    ast.parse(code)
                except SyntaxError:
                    if ">>>" not in code:
                        continue
                blocks.append(code)
            if blocks:
                found.append((where, blocks))
    return found


DOCSTRING_EXAMPLES = _docstring_examples()


def test_docstrings_have_examples():
    assert len(DOCSTRING_EXAMPLES) >= 2, DOCSTRING_EXAMPLES


@pytest.mark.parametrize("where, blocks", DOCSTRING_EXAMPLES, ids=[w for w, _ in DOCSTRING_EXAMPLES])
def test_docstring_example_runs(where, blocks, tmp_path, monkeypatch, capsys):
    import doctest
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "__docstring_example__"}
    for code in blocks:
        if ">>>" in code:
            test = doctest.DocTestParser().get_doctest(code, namespace, where, None, 0)
            runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
            runner.run(test, out=lambda s: None)
            assert runner.failures == 0, f"{where}: {runner.failures} doctest failures"
        else:
            exec(compile(code, where, "exec"), namespace)
