"""What ``robotpy sync`` downloads for a SystemCore from a wheelhouse built by
scripts/wheels.sh (issue 16): run only when ``DRIVEKIN_WHEELHOUSE`` names that directory
(scripts/wheel_tests.sh and CI set it); skipped otherwise.

The command is the one robotpy-installer 2027 runs for the robot (``pip download
--only-binary :all: --python-version 314 --implementation cp --abi cp314`` with the
platforms ``linux_systemcore``, ``manylinux_2_38_aarch64`` down to
``manylinux_2_17_aarch64``, then ``linux_aarch64``), with ``--find-links`` at the
wheelhouse as ``robotpy sync --find-links`` adds it. Dependencies come from the package
index, as on a team's laptop (WPILib's own index, which robotpy adds as an extra index,
holds none of drivekin's).
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

WHEELHOUSE = os.environ.get("DRIVEKIN_WHEELHOUSE")
pytestmark = pytest.mark.skipif(
    not WHEELHOUSE, reason="set DRIVEKIN_WHEELHOUSE to the directory scripts/wheels.sh wrote")

PLATFORMS = (["linux_systemcore"] + [f"manylinux_2_{n}_aarch64" for n in range(38, 16, -1)]
             + ["linux_aarch64"])


def robotpy_sync_download(dest: Path) -> list[str]:
    cmd = [sys.executable, "-m", "pip", "download", "--only-binary", ":all:",
           "--python-version", "314", "--implementation", "cp", "--abi", "cp314"]
    for platform in PLATFORMS:
        cmd += ["--platform", platform]
    cmd += ["--find-links", WHEELHOUSE, "--dest", str(dest), "drivekin"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    return sorted(p.name for p in dest.iterdir())


def test_robotpy_sync_picks_the_aarch64_wheel(tmp_path):
    built = {p.name for p in Path(WHEELHOUSE).glob("drivekin-*-cp314-cp314-*aarch64.whl")}
    assert len(built) == 1, f"one cp314 aarch64 wheel expected in {WHEELHOUSE}: {built}"
    got = robotpy_sync_download(tmp_path)
    ours = [n for n in got if n.startswith("drivekin-")]
    assert ours == sorted(built), got
    # numpy, drivekin's one dependency, resolves for the robot too.
    assert any(n.startswith("numpy-") and "cp314" in n and "aarch64" in n for n in got), got
