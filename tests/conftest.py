"""Shared pytest configuration for the drivekin test suite.

* Hypothesis profiles: ``dev`` (the default, which the README's test command and CI run:
  derandomized, so a landing never depends on the luck of the draw) and ``explore``
  (random seeds, five times the examples: run it while developing to find new
  counter-examples, then pin each one with ``@example``). Pick one with the environment
  variable ``HYPOTHESIS_PROFILE``.
* ``DRIVEKIN_TEST_INSTALLED=1`` (scripts/wheel_tests.sh): the tests must run against an
  installed drivekin, not the source tree; the session fails at once otherwise.
* ``DRIVEKIN_EMULATED=1`` (scripts/wheel_tests.sh, under qemu-user): wall-clock budgets
  meant for real hardware are not checked (tests/safety/test_wpilog_hostile.py).
* The shared helper modules live in the package ``tests._support`` (``strategies``,
  ``alloc``, ``wpilib_port``, ``wpilog_logs``, ``wpilog_bytes``, ``real_logs``) and are imported from it by full name;
  ``tests`` is a package, so nothing edits ``sys.path`` (see ``tests/README.md``).
* ``--memory-safety`` (scripts/asan.sh and scripts/debug_tests.sh run it): only the kinds of
  test in :data:`MEMORY_SAFETY_KINDS` (tests/README.md, "The memory-safety selection").
* The robotpy-wpimath oracle is optional: ``wpimath_kin`` / ``wpimath_geo`` fixtures and
  :func:`require_wpimath` skip cleanly when it is not installed.
"""
from __future__ import annotations

import os
import types

import pytest
from hypothesis import HealthCheck, settings

# Layout strategies reject ill-conditioned module sets, and a few tests build many
# objects per example; neither should trip hypothesis' speed heuristics.
_COMMON_SUPPRESS = [HealthCheck.too_slow, HealthCheck.filter_too_much]

settings.register_profile(
    "dev",
    max_examples=100,
    derandomize=True,
    deadline=None,
    suppress_health_check=_COMMON_SUPPRESS,
)
settings.register_profile(
    "explore",
    max_examples=500,
    deadline=None,
    suppress_health_check=_COMMON_SUPPRESS,
    print_blob=True,
    database=None,
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "dev"))


#: The folders (kinds of test) that the memory-safety builds run. Chosen by coverage: under
#: this selection the compiled modules' line coverage is within 1 percentage point of the
#: whole suite's (tests/README.md gives both figures and how to measure them again). A kind,
#: not a list of files: a new class's tests join the selection by the folder they are in,
#: and the adversarial registry attacks every public callable the catalog lists.
MEMORY_SAFETY_KINDS = ("safety", "behaviour", "reference", "api")


def pytest_addoption(parser):
    parser.addoption("--memory-safety", action="store_true",
                     help="run only the memory-safety selection: the test folders "
                          + ", ".join(MEMORY_SAFETY_KINDS) + " (tests/README.md)")


def pytest_ignore_collect(collection_path, config):
    if not config.getoption("--memory-safety"):
        return None
    tests = os.path.dirname(os.path.abspath(__file__))
    rel = os.path.relpath(str(collection_path), tests).split(os.sep)
    if rel[0] in (".", "..") or len(rel) == 1:
        return None             # tests/ itself, its conftest and __init__, or outside it
    return True if rel[0] not in MEMORY_SAFETY_KINDS else None


def pytest_sessionstart(session):
    if os.environ.get("DRIVEKIN_TEST_INSTALLED") == "1":
        import drivekin
        where = os.path.dirname(drivekin.__file__)
        if os.path.basename(os.path.dirname(where)) not in ("site-packages", "dist-packages"):
            pytest.exit(f"DRIVEKIN_TEST_INSTALLED=1 but drivekin comes from {where}", 2)


def require_wpimath() -> types.SimpleNamespace:
    """Import robotpy-wpimath (the 2026 oracle) or skip the calling test/module.

    Returns a namespace with ``geometry`` and ``kinematics`` sub-modules.
    """
    pytest.importorskip("wpimath")
    geometry = pytest.importorskip("wpimath.geometry")
    kinematics = pytest.importorskip("wpimath.kinematics")
    return types.SimpleNamespace(geometry=geometry, kinematics=kinematics)


@pytest.fixture(scope="session")
def wpimath_kin():
    """``wpimath.kinematics`` (robotpy 2026 names); skips when robotpy is absent."""
    return require_wpimath().kinematics


@pytest.fixture(scope="session")
def wpimath_geo():
    """``wpimath.geometry`` (robotpy 2026 names); skips when robotpy is absent."""
    return require_wpimath().geometry
