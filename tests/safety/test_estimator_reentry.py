"""A module-position sequence whose Python protocol re-enters the pose estimator.

An earlier ``SwerveDrivePoseEstimator._at`` reserved one history slot, then let the
odometry read the positions (``PySequence_Fast`` on a non-list sequence runs its
``__getitem__``); a nested ``updateWithTime`` from there took that slot, and the outer
call then wrote one sample past the end of the C array: heap corruption, ``double free or
corruption`` on exit. ``_after_update`` now checks for room again. Run in a subprocess with
the debug allocator, which checks the block's trailing pad bytes when it is freed.
"""
from __future__ import annotations

import os
import subprocess
import sys


REPRO = """
from drivekin import (Pose2d, Rotation2d, SwerveDriveKinematics, SwerveDrivePoseEstimator,
                      SwerveModulePosition, Translation2d)

kin = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                            Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
pos = [SwerveModulePosition(0.0, Rotation2d()) for _ in range(4)]
est = SwerveDrivePoseEstimator(kin, Rotation2d(), pos, Pose2d())
for i in range(255):              # 255 samples within 1.5 s: none removed, one slot free
    est.updateWithTime(i * 0.0005, Rotation2d(), pos)

class Reentrant:
    fired = False
    def __len__(self):
        return 4
    def __getitem__(self, i):
        if i >= 4:
            raise IndexError
        if not Reentrant.fired:
            Reentrant.fired = True
            est.updateWithTime(0.2, Rotation2d(), pos)
        return pos[i]

try:
    est.updateWithTime(0.3, Rotation2d(), Reentrant())
except (TypeError, ValueError, RuntimeError):
    pass                          # refusing a re-entrant call is a correct outcome too
print(est.sampleAt(0.3).getX())
del est
print("survived")
"""


def test_reentrant_update_from_module_positions_stays_in_bounds():
    env = dict(os.environ, PYTHONMALLOC="debug")
    proc = subprocess.run([sys.executable, "-c", REPRO], capture_output=True, text=True,
                          timeout=120, env=env)
    assert proc.returncode == 0, f"exit {proc.returncode}\n{proc.stdout}\n{proc.stderr[-2000:]}"
    assert proc.stdout.splitlines()[-1] == "survived"
