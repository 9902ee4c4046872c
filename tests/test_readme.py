"""Every Python example in README.md and in the docs/*.md pages runs as written."""
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
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
