"""The real Choreo trajectories beside the repository (../shared/choreo/trajs, SOURCES.md
there says where each comes from): the schema-3 files drivekin.choreo loads, and the older
ones it refuses."""
from __future__ import annotations

import pathlib

import pytest

TRAJS = pathlib.Path(__file__).resolve().parents[2] / ".." / "shared" / "choreo" / "trajs"


def _files(pattern: str) -> list[pathlib.Path]:
    return sorted(TRAJS.glob(pattern)) if TRAJS.is_dir() else []


# Top level, derived/ (a v2 differential file as v3) and synthetic/ (a differential that
# turns): every one schema 3. legacy/: versions 0-2 and "v2025.0.0".
CURRENT = _files("*.traj") + _files("derived/*.traj") + _files("synthetic/*.traj")
LEGACY = _files("legacy/*.traj")


def params(files: list[pathlib.Path]) -> list:
    """pytest parameters for files, one skip when the directory is absent."""
    if not files:
        return [pytest.param(None, marks=pytest.mark.skip(
            reason="../shared/choreo/trajs is not beside the repository"))]
    return [pytest.param(f, id=f.stem) for f in files]
