"""Choreo trajectory sampling on C doubles: choreolib Python 2026.0.3's ``sample_at``.

A sample row is the trajectory's columns (drivekin.choreo): swerve ``t x y heading vx vy
omega ax ay alpha fx0..3 fy0..3``, differential ``t x y heading vl vr omega al ar alpha
fl fr``. choreolib's rules: before the first sample or with one sample, the first; after
the last, the last (stored values); otherwise the first sample k at or after t, and unless
k = 0 or the two samples are less than 1 µs apart, the state integrated from sample k − 1
(so a time exactly on a sample is integrated, not read). Swerve integrates constant
accelerations; differential runs wpimath's adaptive Dormand–Prince (RKDP, max error 1e-6)
step for step, its quirks included; forces are linear between the two samples. The red
alliance's flip is 2026's rotation about the field centre.

ChoreoSampler is the base class of drivekin.choreo.ChoreoTrajectory: it owns a C-contiguous
read-only copy of the samples, and every method reads only that copy.
"""
# Hand-written stub for the private compiled module drivekin._core.choreokernel
# (_core/choreokernel.pyx). The docstrings are written from the compiled module's
# ``__doc__`` (the .pyx docstrings) by scripts/stub_docstrings.py: edit them in the .pyx,
# rebuild and rerun the script. ChoreoSampler is the runtime base class of
# drivekin.choreo.ChoreoTrajectory; the sample classes are what its methods return.

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike
from typing import final

from typing_extensions import disjoint_base

from drivekin.chassis import ChassisVelocities
from drivekin.geometry import Pose2d

FIELD_SIZE: tuple[float, float]

@disjoint_base
class _ChoreoSample:
    """A trajectory's state at one time (choreolib's sample fields)."""
    @property
    def t(self) -> float:
        """Time, s."""
    @property
    def x(self) -> float:
        """Field x, m (blue origin)."""
    @property
    def y(self) -> float:
        """Field y, m."""
    @property
    def heading(self) -> float:
        """Heading, rad (not wrapped)."""
    @property
    def omega(self) -> float:
        """Angular velocity, rad/s."""
    @property
    def alpha(self) -> float:
        """Angular acceleration, rad/s²."""
    def getPose(self) -> Pose2d:
        """The pose (x, y, heading) as a drivekin Pose2d."""

@final
class SwerveSample(_ChoreoSample):
    """SwerveSample: a swerve trajectory's state (choreolib's SwerveSample, ``t`` for its
    timestamp): pose, field-frame velocities and accelerations, module forces (N, field
    frame) in Choreo's order FL, BL, BR, FR.
    """
    def __init__(self, *args: object, **kwargs: object) -> None: ...
    @property
    def vx(self) -> float:
        """Field-frame x velocity, m/s."""
    @property
    def vy(self) -> float:
        """Field-frame y velocity, m/s."""
    @property
    def ax(self) -> float:
        """Field-frame x acceleration, m/s²."""
    @property
    def ay(self) -> float:
        """Field-frame y acceleration, m/s²."""
    @property
    def fx(self) -> tuple[float, float, float, float]:
        """Module forces along field x, N, (FL, BL, BR, FR)."""
    @property
    def fy(self) -> tuple[float, float, float, float]:
        """Module forces along field y, N, (FL, BL, BR, FR)."""
    def getChassisVelocities(self) -> ChassisVelocities:
        """Field-relative (vx, vy, omega) as a ChassisVelocities, as choreolib's
        get_chassis_speeds."""

@final
class DifferentialSample(_ChoreoSample):
    """DifferentialSample: a differential trajectory's state (choreolib's
    DifferentialSample, ``t`` for its timestamp): pose, wheel velocities and
    accelerations, wheel forces (N) left and right.
    """
    def __init__(self, *args: object, **kwargs: object) -> None: ...
    @property
    def vl(self) -> float:
        """Left wheel velocity, m/s."""
    @property
    def vr(self) -> float:
        """Right wheel velocity, m/s."""
    @property
    def al(self) -> float:
        """Left wheel acceleration, m/s²."""
    @property
    def ar(self) -> float:
        """Right wheel acceleration, m/s²."""
    @property
    def fl(self) -> float:
        """Left wheel force, N."""
    @property
    def fr(self) -> float:
        """Right wheel force, N."""
    def getChassisVelocities(self) -> ChassisVelocities:
        """((vl + vr) / 2, 0, omega) as a ChassisVelocities, as choreolib's
        get_chassis_speeds (choreolib calls it field-relative; its vx is along the
        robot's heading, so it is the robot-relative velocity)."""

@disjoint_base
class ChoreoSampler:
    """The sampling half of ChoreoTrajectory: a C-contiguous read-only copy of the samples
    (bound once by _bind) and the methods that read it.
    """
    def _bind(self, samples: ArrayLike, swerve: bool) -> np.ndarray: ...
    def newSample(self) -> SwerveSample | DifferentialSample:
        """A sample object of this trajectory's kind (its first sample), for
        :meth:`sampleInto`."""
    def sampleAt(self, t: float, mirrorForRedAlliance: bool = False
                 ) -> SwerveSample | DifferentialSample:
        """sampleAt(t, mirrorForRedAlliance=False)

        The state at time ``t`` (s) by choreolib's ``sample_at`` rules (see the module),
        as a SwerveSample or DifferentialSample; flipped for the red alliance (2026:
        rotated about the field centre) if asked. ``t`` must not be NaN (ValueError)."""
    def sampleInto(self, t: float, out: SwerveSample | DifferentialSample,
                   mirrorForRedAlliance: bool = False) -> SwerveSample | DifferentialSample:
        """sampleInto(t, out, mirrorForRedAlliance=False)

        :meth:`sampleAt` written into ``out`` (a sample of this trajectory's kind, from
        :meth:`newSample`) without allocating; returns ``out``. On an error ``out`` is
        unchanged."""
    def sampleAtMany(self, times: Sequence[float] | np.ndarray,
                     mirrorForRedAlliance: bool = False) -> np.ndarray:
        """sampleAtMany(times, mirrorForRedAlliance=False)

        :meth:`sampleAt` at every time of the 1-D ``times`` (s, none NaN): float64 rows
        (len(times), len(columns)) in ``columns`` order, computed without the GIL."""
