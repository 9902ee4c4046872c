"""Whole recordings at once: numpy stacks through the same kernels as the per-call API.

Shapes follow one convention ("single or stacked", as in scipy.spatial.transform): an
argument that is one value per call in the per-call API is either that value's array
(shape ``S``) or a stack of N of them (shape ``(N,) + S``), and results have the matching
form. The value arrays are

==============================  ==========  =============================================
value                           shape S     columns
==============================  ==========  =============================================
chassis vector / pose           (3,)        ``[vx m/s, vy m/s, omega rad/s]``,
                                            ``[x m, y m, θ rad]``, ``[dx m, dy m, dθ rad]``
3-D pose / transform            (7,)        ``[x m, y m, z m, qw, qx, qy, qz]``
3-D twist                       (6,)        ``[dx m, dy m, dz m, rx rad, ry rad, rz rad]``
3-D gyro reading                (4,)        ``[w, x, y, z]`` (a Rotation3d's quaternion)
swerve modules (M modules)      (M, 2)      ``[velocity m/s or distance m, angle rad]``
wheels (mecanum, diff, dead)    (W,)        one value per wheel, the per-call order
angle / time step               ()          rad / s (a float, or an (N,) stack)
==============================  ==========  =============================================

A 3-D row is read as the per-call constructors read it: ``[x, y, z, qw, qx, qy, qz]`` is
``Pose3d(Translation3d(x, y, z), Rotation3d(Quaternion(qw, qx, qy, qz)))`` (the
quaternion normalised as that constructor and WPILib's struct unpacking do; a zero one is
the identity), a gyro row ``Rotation3d(Quaternion(w, x, y, z))``. Results hold the
getters' values (``getX()``, ..., ``getRotation().getQuaternion()``), so a result read
back as a row is normalised again, which may move a component by an ulp.

Every array must be a float64, native-endian, C-contiguous numpy array (the rule of the
per-call buffers; ``np.ascontiguousarray(x, dtype=np.float64)`` makes one). ``out=``, when
given, must have exactly the result's shape, be writeable and not overlap an input; it
is filled and returned. Angles in results are ``Rotation2d.getRadians()`` values, wrapped to
(−π, π].

Results are bit-identical to the per-call methods called in a loop, including their
state: swerve inverse kinematics reads and leaves the heading memory as N calls would,
and :func:`replay` leaves the odometry at the last sample. The loops run without the GIL;
do not use the same kinematics or odometry object from another thread meanwhile (memory
stays safe, but the interleaving is unspecified).

Every sine, cosine and atan2 comes from drivekin's own functions (``_core/dkmath.h``,
at most 1 ulp from the exact value), here vectorised by the compiler: ``SIMD`` names the
instruction set in use, the best the CPU has, chosen at import: ``"AVX-512"`` or
``"AVX2"`` (x86_64 CPUs that have them), ``"SSE2"`` (other x86_64), ``"NEON"``
(aarch64). The vector and scalar forms perform the same operations in the same order, so
results are the same bits whichever is in use, on every supported platform
(docs/DESIGN.md, "One trig"). The 3-D forms run the per-call kernels sample by sample,
with the scalar forms (a 3-D replay's module angles excepted).
"""
import numpy as np
import numpy.typing as npt

from drivekin.deadwheel import DeadWheelKinematics
from drivekin.differential import DifferentialDriveKinematics
from drivekin.geometry import Translation2d
from drivekin.mecanum import MecanumDriveKinematics
from drivekin.odometry import (
    DeadWheelOdometry,
    DifferentialDriveOdometry,
    MecanumDriveOdometry,
    SwerveDriveOdometry,
    TwoDeadWheelOdometry,
)
from drivekin.odometry3d import (
    DeadWheelOdometry3d,
    DifferentialDriveOdometry3d,
    MecanumDriveOdometry3d,
    SwerveDriveOdometry3d,
    TwoDeadWheelOdometry3d,
)
from drivekin.swerve import SwerveDriveKinematics
from drivekin.setpoint import PathConstraints, SwerveSetpoint, SwerveSetpointGenerator

_Array = npt.NDArray[np.float64]

SIMD: str
"""The instruction set the array sin/cos/atan2 run on: ``"AVX-512"``, ``"AVX2"``,
``"SSE2"``, ``"NEON"`` or ``"scalar"``. Results are the same bits on each."""

__all__ = ["desaturate", "desaturateWheelVelocities", "desaturatedDiscretize", "discretize", "exp", "generateSetpoints", "log", "relativeTo", "replay", "toChassisAccelerations", "toChassisVelocities", "toFieldRelative", "toRobotRelative", "toSwerveModuleAccelerations", "toSwerveModuleVelocities", "toWheelAccelerations", "toWheelVelocities", "transformBy"]


def toSwerveModuleVelocities(
    kinematics: SwerveDriveKinematics,
    chassisVelocities: _Array,
    centerOfRotation: Translation2d | None = None,
    out: _Array | None = None,
) -> _Array:
    """Module velocities ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]`` for chassis velocities
    ``(3,)`` / ``(N, 3)`` (robot-relative), about ``centerOfRotation`` (a Translation2d,
    m; default the robot centre). The heading memory is used and left as N
    :meth:`SwerveDriveKinematics.toSwerveModuleVelocities` calls would leave it."""

def toSwerveModuleAccelerations(
    kinematics: SwerveDriveKinematics,
    chassisAccelerations: _Array,
    angularVelocity: _Array | float = 0.0,
    centerOfRotation: Translation2d | None = None,
    out: _Array | None = None,
) -> _Array:
    """Module accelerations ``(M, 2)`` / ``(N, M, 2)`` ``[m/s², rad]`` for chassis
    accelerations ``(3,)`` / ``(N, 3)`` ``[ax, ay, alpha]`` while turning at
    ``angularVelocity`` (rad/s; a float or ``(N,)``), as
    :meth:`SwerveDriveKinematics.toSwerveModuleAccelerations`."""

def toWheelVelocities(
    kinematics: SwerveDriveKinematics | MecanumDriveKinematics | DifferentialDriveKinematics | DeadWheelKinematics,
    chassisVelocities: _Array,
    centerOfRotation: Translation2d | None = None,
    out: _Array | None = None,
) -> _Array:
    """Wheel velocities for chassis velocities ``(3,)`` / ``(N, 3)``: mecanum ``(4,)`` /
    ``(N, 4)`` (about ``centerOfRotation``), differential ``(N, 2)`` ``[left, right]``,
    dead-wheel ``(N, W)`` (surface velocities), all m/s; a SwerveDriveKinematics gives
    :func:`toSwerveModuleVelocities`."""

def toWheelAccelerations(
    kinematics: SwerveDriveKinematics | MecanumDriveKinematics | DifferentialDriveKinematics | DeadWheelKinematics,
    chassisAccelerations: _Array,
    centerOfRotation: Translation2d | None = None,
    out: _Array | None = None,
) -> _Array:
    """Wheel accelerations (m/s²) for chassis accelerations ``(3,)`` / ``(N, 3)``, shaped
    as :func:`toWheelVelocities`; a SwerveDriveKinematics gives
    :func:`toSwerveModuleAccelerations` with zero angular velocity."""

def toChassisVelocities(
    kinematics: SwerveDriveKinematics | MecanumDriveKinematics | DifferentialDriveKinematics | DeadWheelKinematics,
    wheelVelocities: _Array,
    gyroRates: _Array | float | None = None,
    out: _Array | None = None,
) -> _Array:
    """Chassis velocities ``(3,)`` / ``(N, 3)`` ``[vx, vy, omega]`` from swerve module
    velocities ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]``, or wheel velocities ``(W,)`` /
    ``(N, W)`` of a mecanum, differential or dead-wheel drive. ``gyroRates`` (rad/s, a
    float or ``(N,)``) is the dead-wheel form's optional gyro."""

def toChassisAccelerations(
    kinematics: SwerveDriveKinematics | MecanumDriveKinematics | DifferentialDriveKinematics | DeadWheelKinematics,
    wheelAccelerations: _Array,
    angularAccelerations: _Array | float | None = None,
    out: _Array | None = None,
) -> _Array:
    """Chassis accelerations ``(3,)`` / ``(N, 3)`` ``[ax, ay, alpha]`` from swerve module
    accelerations ``(M, 2)`` / ``(N, M, 2)`` ``[m/s², rad]`` or wheel accelerations;
    ``angularAccelerations`` (rad/s², a float or ``(N,)``) fixes alpha for dead wheels."""

def desaturateWheelVelocities(
    moduleVelocities: _Array,
    attainableMaxSpeed: _Array | float,
    attainableMaxModuleSpeed: float | None = None,
    attainableMaxTranslationalSpeed: float | None = None,
    attainableMaxRotationalVelocity: float | None = None,
    out: _Array | None = None,
) -> _Array:
    """:meth:`SwerveDriveKinematics.desaturateWheelVelocities` for module velocities
    ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]``, each sample scaled on its own. Either one
    limit ``attainableMaxSpeed`` (m/s), or the desired chassis velocities (``(3,)`` /
    ``(N, 3)``) in its place followed by the three limits (m/s, m/s, rad/s). Angles pass
    through unchanged (as in the per-call (M, 2) array form); ``out=moduleVelocities``
    desaturates in place."""

def desaturate(
    wheelVelocities: _Array,
    attainableMaxSpeed: float,
    out: _Array | None = None,
) -> _Array:
    """:meth:`MecanumDriveWheelVelocities.desaturate` (W = 4) and the differential one
    (W = 2) for wheel velocities ``(W,)`` / ``(N, W)`` (m/s), each sample scaled on its own;
    ``out=wheelVelocities`` desaturates in place."""

def discretize(
    chassisVelocities: _Array,
    dt: _Array | float,
    out: _Array | None = None,
) -> _Array:
    """:meth:`ChassisVelocities.discretize` for ``(3,)`` / ``(N, 3)`` velocities; ``dt`` (s)
    is a float or an ``(N,)`` stack."""

def desaturatedDiscretize(
    kinematics: SwerveDriveKinematics,
    chassisVelocities: _Array,
    dt: _Array | float,
    attainableMaxModuleVelocity: float,
    out: _Array | None = None,
) -> _Array:
    """:meth:`SwerveDriveKinematics.desaturatedDiscretize` for ``(3,)`` / ``(N, 3)``
    velocities; ``dt`` (s) is a float or an ``(N,)`` stack. Every sample is checked
    before any is written."""

def generateSetpoints(
    generator: SwerveSetpointGenerator,
    prevSetpoint: SwerveSetpoint,
    desiredVelocities: _Array,
    dt: _Array | float,
    inputVoltage: _Array | float = ...,
    constraints: PathConstraints | None = None,
) -> tuple[_Array, _Array, _Array]:
    """:meth:`SwerveSetpointGenerator.generateSetpoint` over a log of commands: from
    ``prevSetpoint``, each row of ``desiredVelocities`` (``(T, 3)`` float64, robot-relative
    vx, vy, ω) is fed the previous row's setpoint. ``dt`` (s) and ``inputVoltage`` (V, NaN
    for 12 V) are floats or ``(T,)`` stacks; ``constraints`` applies to every row.

    Returns ``(velocities, modules, feedforwards)``: ``(T, 3)`` chassis velocities,
    ``(T, N, 2)`` module ``[velocity m/s, angle rad]`` and ``(T, 5, N)`` feedforwards in
    :class:`DriveFeedforwards`' order. The same numbers as T calls, the generator's
    heading memory included (it is left as the last call leaves it). Every input is copied
    before any is checked (a constraints object's getters may run code), every row is
    checked before any is computed, and a refused call leaves the generator as it was;
    the GIL is held (the generator's scratch is shared)."""

def toRobotRelative(
    chassisVectors: _Array,
    robotAngles: _Array | float,
    out: _Array | None = None,
) -> _Array:
    """:meth:`ChassisVelocities.toRobotRelative` (and the ChassisAccelerations one) for
    ``(3,)`` / ``(N, 3)`` field-relative vectors and robot headings ``robotAngles`` (rad;
    a float or ``(N,)``)."""

def toFieldRelative(
    chassisVectors: _Array,
    robotAngles: _Array | float,
    out: _Array | None = None,
) -> _Array:
    """:meth:`ChassisVelocities.toFieldRelative` for ``(3,)`` / ``(N, 3)`` robot-relative
    vectors and robot headings ``robotAngles`` (rad; a float or ``(N,)``)."""

def transformBy(
    poses: _Array,
    transforms: _Array,
    out: _Array | None = None,
) -> _Array:
    """:meth:`Pose2d.transformBy` for ``(3,)`` / ``(N, 3)`` poses and transforms
    ``[x m, y m, θ rad]``, or :meth:`Pose3d.transformBy` for ``(7,)`` / ``(N, 7)`` ones
    ``[x m, y m, z m, qw, qx, qy, qz]``: each pose moved by its transform. Either argument
    may be a single value, which goes with every sample of the other."""

def relativeTo(
    poses: _Array,
    others: _Array,
    out: _Array | None = None,
) -> _Array:
    """:meth:`Pose2d.relativeTo` for ``(3,)`` / ``(N, 3)`` poses ``[x m, y m, θ rad]``, or
    :meth:`Pose3d.relativeTo` for ``(7,)`` / ``(N, 7)`` ones: each pose seen from the
    frame of its ``others`` pose. Either argument may be a single value, which goes with
    every sample of the other."""

def exp(
    twists: _Array,
    out: _Array | None = None,
) -> _Array:
    """:meth:`Twist2d.exp` for ``(3,)`` / ``(N, 3)`` twists ``[dx m, dy m, dθ rad]``: the
    transforms ``[x m, y m, θ rad]``; :meth:`Twist3d.exp` for ``(6,)`` / ``(N, 6)`` twists
    ``[dx m, dy m, dz m, rx rad, ry rad, rz rad]``: the transforms ``(7,)`` / ``(N, 7)``."""

def log(
    transforms: _Array,
    out: _Array | None = None,
) -> _Array:
    """:meth:`Transform2d.log` for ``(3,)`` / ``(N, 3)`` transforms ``[x m, y m, θ rad]``:
    the twists ``[dx m, dy m, dθ rad]``; :meth:`Transform3d.log` for ``(7,)`` / ``(N, 7)``
    transforms: the twists ``(6,)`` / ``(N, 6)``."""

def replay(
    odometry: SwerveDriveOdometry | MecanumDriveOdometry | DifferentialDriveOdometry | TwoDeadWheelOdometry | DeadWheelOdometry | SwerveDriveOdometry3d | MecanumDriveOdometry3d | DifferentialDriveOdometry3d | TwoDeadWheelOdometry3d | DeadWheelOdometry3d,
    gyroAngles: _Array | None,
    positions: _Array,
    out: _Array | None = None,
) -> _Array:
    """Run ``odometry.update`` for N samples; return the poses after each.

    The poses are ``(N, 3)`` ``[x m, y m, θ rad]``, or for a 3-D odometry ``(N, 7)``
    ``[x m, y m, z m, qw, qx, qy, qz]``; the odometry is left at the last one.

    ``gyroAngles`` is ``(N,)`` (rad; None for a DeadWheelOdometry built without a gyro),
    or for a 3-D odometry ``(N, 4)`` quaternions ``[w, x, y, z]`` (each read as
    ``Rotation3d(Quaternion(w, x, y, z))``); ``positions`` is what ``update`` reads,
    stacked: Swerve ``(N, M, 2)`` ``[distance m, angle rad]``; Mecanum ``(N, 4)``;
    Differential ``(N, 2)`` ``[left, right]``; TwoDeadWheel ``(N, 2)`` ``[xWheelPos,
    yWheelPos]``; DeadWheel ``(N, W)`` (m throughout), for the 2-D and 3-D classes
    alike."""
