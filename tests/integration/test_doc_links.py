"""README.md, docs/*.md and CHANGELOG.md (a page of the docs site) refer to nothing outside
the repository but the documentation site and upstream projects' pages.

A relative link must reach an existing file that is a page of the site (the README, the
changelog or a file under docs/): the site sends links to other files of the repository
to the source host (docs/conf.py). An absolute link must go to the documentation site or
to a host of ALLOWED. Paths of a development machine are refused even outside links."""
import pathlib
import re
from urllib.parse import urlsplit

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]  # tests/integration/ -> the root
DOCS = ROOT / "docs"
SITE = ("drivekin.github.io", "/drivekin/")
# Upstream projects' pages: (host, path prefix). The project's own source host is not
# upstream, so GitHub is allowed per organisation only.
ALLOWED = [
    ("docs.wpilib.org", "/"), ("github.com", "/wpilibsuite/"), ("robotpy.readthedocs.io", "/"),
    ("github.com", "/robotpy/"), ("pathplanner.dev", "/"), ("github.com", "/mjansen4857/"),
    ("choreo.autos", "/"), ("github.com", "/SleipnirGroup/"),
    ("docs.advantagekit.org", "/"), ("docs.advantagescope.org", "/"),
    ("github.com", "/Mechanical-Advantage/"), ("numpy.org", "/"),
    ("protobuf.dev", "/"), ("docs.python.org", "/"), ("www.sphinx-doc.org", "/"),
    ("v6.docs.ctr-electronics.com", "/"), ("rr.brott.dev", "/"), ("www.gobilda.com", "/"),
]
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)"   # [text](target)
                  r"|^\s*\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)"                  # [ref]: target
                  r"|<([a-z][a-z0-9+.-]*:[^>\s]+)>"                          # <scheme:...>
                  r"|(?:href|src)=\"([^\"]+)\"", re.M)                       # HTML
URL = re.compile(r"\b[a-z][a-z0-9+.-]*://[^\s)>\]`\"']+", re.I)
MACHINE = re.compile(r"shared/reference|\.\./\.\.|(?<![\w.~$])/(?:work|home|tmp|usr|root|opt|"
                     r"Users|mnt)/|~/|\b[A-Z]:\\(?=\w)")


def _pages():
    found = [ROOT / "README.md", ROOT / "CHANGELOG.md"] + sorted(DOCS.glob("*.md"))
    return [p for p in found if p.exists()]


PAGES = _pages()
IDS = [p.relative_to(ROOT).as_posix() for p in PAGES]


def _prose(text):
    """A page's text without its fenced code blocks (they hold code, not links)."""
    return re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)


def _slug(heading):
    """GitHub's (and the site's, myst_heading_anchors) anchor for a Markdown heading."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def _targets(text):
    """Every link target of a page: Markdown and HTML links in its prose, and any URL at
    all, code blocks included."""
    prose = _prose(text)
    found = [next(g for g in m.groups() if g) for m in LINK.finditer(prose)]
    return found + [u for u in URL.findall(text) if u not in found]


def _absolute_refusal(target):
    """Why an absolute target is refused, or None."""
    parts = urlsplit(target)
    if parts.scheme != "https":
        return "not https"
    host, path = parts.hostname or "", parts.path or "/"
    if (host, path[:len(SITE[1])]) == SITE or host == SITE[0] and path + "/" == SITE[1]:
        return None
    if any(host == h and path.startswith(prefix) for h, prefix in ALLOWED):
        return None
    return "neither the documentation site nor an upstream project on the allow-list"


def _relative_refusal(page, target):
    """Why a relative target is refused, or None."""
    path, _, anchor = target.partition("#")
    dest = (page.parent / path).resolve() if path else page
    if not dest.is_relative_to(ROOT):
        return "outside the repository"
    if not dest.exists():
        return "no such file"
    if dest not in (ROOT / "README.md", ROOT / "CHANGELOG.md") and not dest.is_relative_to(DOCS):
        return "not a page of the site, which would send it to the source host"
    if anchor:
        headings = re.findall(r"^#+ (.*)$", _prose(dest.read_text(encoding="utf-8")), re.M)
        if anchor not in {_slug(h) for h in headings}:
            return "no such heading"
    return None


def _link_refusals(page, text):
    refused = []
    for target in _targets(text):
        absolute = re.match(r"[a-z][a-z0-9+.-]*:", target, re.I)
        why = _absolute_refusal(target) if absolute else _relative_refusal(page, target)
        if why:
            refused.append(f"{target}: {why}")
    return refused


def _machine_refusals(text):
    return [f"{m.group(0)}: a path of a development machine" for m in MACHINE.finditer(text)]


def _refusals(page, text):
    return _link_refusals(page, text) + _machine_refusals(text)


@pytest.mark.parametrize("page", PAGES, ids=IDS)
def test_page_names_no_development_machine_path(page):
    assert _machine_refusals(page.read_text(encoding="utf-8")) == []


@pytest.mark.parametrize("page", PAGES, ids=IDS)
def test_page_links_only_to_the_repository_the_site_and_upstream(page):
    if not (ROOT / ".git").exists():
        pytest.skip("not a checkout: an sdist leaves out some linked files")
    assert _link_refusals(page, page.read_text(encoding="utf-8")) == []


def test_readme_links_to_the_guides():
    if not (ROOT / "README.md").exists():
        pytest.skip("README.md is not next to the tests (installed from an sdist?)")
    assert len(_targets((ROOT / "README.md").read_text(encoding="utf-8"))) >= 8


@pytest.mark.parametrize("text, refused", [
    ("[a](https://gist.github.com/someone/1234)", "gist.github.com"),
    ("[a](https://github.com/drivekin/drivekin/blob/main/x.py)", "github.com/drivekin"),
    ("see http://docs.wpilib.org/en/stable/", "not https"),
    ("<https://example.com/blog>", "example.com"),
    ('<a href="https://example.org/x">x</a>', "example.org"),
    ("[ref]: https://example.net/y", "example.net"),
    ("[a](../scripts/README.md)", "not a page of the site"),
    ("[a](missing.md)", "no such file"),
    ("[a](DESIGN.md#no-such-heading)", "no such heading"),
    ("[a](../../elsewhere.md)", "outside the repository"),
    ("digests in /work/shared/reference/", "development machine"),
    ("built in C:\\Users\\me\\drivekin", "development machine"),
    ("```sh\ncurl https://example.com/install.sh\n```", "example.com"),
])
def test_refusals_see_each_kind_of_outside_reference(text, refused):
    if not (DOCS / "DESIGN.md").exists():
        pytest.skip("docs/ is not next to the tests")
    found = _refusals(DOCS / "page.md", text)
    assert any(refused in r for r in found), found


@pytest.mark.parametrize("text", [
    "[site](https://drivekin.github.io/drivekin/api/drivekin/index.html)",
    "<https://drivekin.github.io/drivekin/>",
    "[WPILib](https://docs.wpilib.org/en/stable/docs/software/kinematics-and-odometry/)",
    "[PathPlannerLib](https://github.com/mjansen4857/pathplanner)",
    "[design](DESIGN.md#layout) and [the README](../README.md#examples)",
    "![plot](replay.png)",
])
def test_allowed_references_pass(text):
    if not (DOCS / "DESIGN.md").exists():
        pytest.skip("docs/ is not next to the tests")
    assert _refusals(DOCS / "page.md", text) == []
