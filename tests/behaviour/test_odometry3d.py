"""3-D odometry (drivekin.odometry3d) against closed forms: a ramp, the gyro-delta rule, the
2-D odometry on level ground, and refused calls.

Every 3-D odometry class of the catalog drives the same motions here: "forward d m" in its
own readings (all swerve modules at 0°, all mecanum or differential wheels, the forward dead
wheels), and "turn on the spot" only through the gyro, so the expected poses are closed forms
in the robot's frame, whatever the drivetrain.
"""
import math

import numpy as np
import pytest

from drivekin import (
    ChassisVelocities,
    DeadWheelKinematics,
    DeadWheelOdometry,
    DeadWheelOdometry3d,
    DifferentialDriveOdometry,
    DifferentialDriveOdometry3d,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveOdometry3d,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveDriveOdometry3d,
    SwerveModulePosition,
    Translation2d,
    TwoDeadWheelOdometry,
    TwoDeadWheelOdometry3d,
)
from drivekin._core import catalog
from drivekin.geometry3d import Pose3d, Rotation3d, Translation3d

R3 = Rotation3d
CORNERS = [Translation2d(0.3, 0.3), Translation2d(0.3, -0.3), Translation2d(-0.3, 0.3),
           Translation2d(-0.3, -0.3)]
DEAD = [Pose2d(0, 0.2, Rotation2d()), Pose2d(0, -0.2, Rotation2d()),
        Pose2d(0.1, 0, Rotation2d.kCCW_Pi_2)]


def forward(cls, d):
    """The update arguments (without the gyro) that mean "the robot has moved d m forward
    since the start" to the catalog's example of ``cls``."""
    if cls is SwerveDriveOdometry3d:
        return ([SwerveModulePosition(d, Rotation2d())] * 4,)
    if cls is MecanumDriveOdometry3d:
        return (MecanumDriveWheelPositions(d, d, d, d),)
    if cls is DeadWheelOdometry3d:
        # The catalog's layout has a wheel turned 0.1 rad: its readings, from its own
        # inverse kinematics.
        kin = catalog.BY_CLASS[DeadWheelKinematics].example()
        return (list(kin.toWheelVelocities(ChassisVelocities(d, 0.0, 0.0))),)
    return (d, d) if cls is DifferentialDriveOdometry3d else (d, 0.0)


def update(odo, gyro, d):
    args = forward(type(odo), d)
    dead = isinstance(odo, (DeadWheelOdometry3d, TwoDeadWheelOdometry3d))
    return odo.update(*args, gyro) if dead else odo.update(gyro, *args)


def reset(odo, gyro, d, pose):
    args = forward(type(odo), d)
    if isinstance(odo, (DeadWheelOdometry3d, TwoDeadWheelOdometry3d)):
        odo.resetPosition(*args, gyro, pose)
    else:
        odo.resetPosition(gyro, *args, pose)


ODOMETRY3D = [pytest.param(e.example, id=e.drivetrain) for e in catalog.entries("odometry3d")]


def quat(r):
    q = r.getQuaternion()
    return np.array([q.getW(), q.getX(), q.getY(), q.getZ()])


def rotate(q, v):
    """v rotated by the unit quaternion q = (w, x, y, z) (its rotation matrix)."""
    w, x, y, z = q
    m = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return m @ np.asarray(v, dtype=float)


def xyz(p):
    return np.array([p.getX(), p.getY(), p.getZ()])


def same_rotation(a, b, tol=1e-12):
    return abs(abs(quat(a) @ quat(b)) - 1.0) <= tol


@pytest.mark.parametrize("make", ODOMETRY3D)
@pytest.mark.parametrize("slope", [0.1, -0.25, 0.6])
def test_driving_up_a_pitched_ramp_produces_z(make, slope):
    # Level ground, then the gyro pitches nose-up by `slope` (a negative pitch, as WPILib's
    # pitch turns +x towards -z) with the wheels still, then 2 m forward: the robot climbs
    # 2·sin(slope) m along its own x axis.
    odo = make()
    reset(odo, R3(), 0.0, Pose3d())
    ramp = R3(0.0, -slope, 0.0)
    pose = update(odo, ramp, 0.0)
    assert np.array_equal(xyz(pose), [0.0, 0.0, 0.0]) and same_rotation(pose.getRotation(), ramp)
    pose = update(odo, ramp, 2.0)
    np.testing.assert_allclose(xyz(pose), [2 * math.cos(slope), 0.0, 2 * math.sin(slope)],
                               rtol=0, atol=1e-12)
    # Back on level ground and 1 m further: z stays where the ramp left it.
    pose = update(odo, R3(), 2.0)
    pose = update(odo, R3(), 3.0)
    np.testing.assert_allclose(xyz(pose), [2 * math.cos(slope) + 1, 0.0, 2 * math.sin(slope)],
                               rtol=0, atol=1e-12)


@pytest.mark.parametrize("make", ODOMETRY3D)
def test_only_gyro_changes_are_composed_onto_the_initial_rotation(make):
    # The catalog's example starts pitched and rolled (its start pose) with a level gyro,
    # and the gyro is tilted at the reset: the pose keeps the start rotation, and a later
    # gyro change Δ (in the gyro's own frame) turns it into start·Δ.
    odo = make()
    start = odo.getPose()
    gyro0 = R3(0.2, -0.1, 2.5)
    reset(odo, gyro0, 0.0, start)
    assert odo.getPose() == start
    delta = R3(0.05, 0.1, -0.3)
    # Rotation3d.rotateBy(o) is o·q: delta.rotateBy(gyro0) = gyro0·Δ, Δ in the gyro's frame
    # (its relativeTo(gyro0) is Δ).
    pose = update(odo, delta.rotateBy(gyro0), 0.0)
    expected = delta.rotateBy(start.getRotation())     # start·Δ
    assert same_rotation(pose.getRotation(), expected)
    if isinstance(odo, (DeadWheelOdometry3d, TwoDeadWheelOdometry3d)):
        return   # still dead wheels off the centre mean the robot moved (the arcs)
    assert np.allclose(xyz(pose), xyz(start), rtol=0, atol=1e-15)
    # 1 m forward now goes along the turned robot's x axis.
    pose = update(odo, delta.rotateBy(gyro0), 1.0)
    np.testing.assert_allclose(xyz(pose), xyz(start) + rotate(quat(expected), [1, 0, 0]),
                               rtol=0, atol=1e-12)


@pytest.mark.parametrize("make", ODOMETRY3D)
def test_resets_set_the_pose_and_keep_the_baselines(make):
    odo = make()
    reset(odo, R3(), 0.0, Pose3d())
    odo.resetRotation(R3(0, 0, math.pi / 2))
    odo.resetTranslation(Translation3d(1, 2, 3))
    pose = update(odo, R3(), 1.0)                       # heading 90°: forward is +y
    np.testing.assert_allclose(xyz(pose), [1, 3, 3], rtol=0, atol=1e-12)
    odo.resetPose(Pose3d(5, 5, 5, R3()))
    pose = update(odo, R3(), 3.0)                       # 2 m more, level
    np.testing.assert_allclose(xyz(pose), [7, 5, 5], rtol=0, atol=1e-12)


# ---- level ground: the 2-D odometry's poses ------------------------------------------------
# With the gyro turning about z only, every 3-D odometry is its 2-D counterpart lifted: same
# x, y and heading (to rounding: the 3-D step goes through quaternions), z = 0.

def _pairs():
    swerve = SwerveDriveKinematics(*CORNERS)
    mecanum = MecanumDriveKinematics(*CORNERS)
    dead = DeadWheelKinematics(DEAD)

    def modules(i):
        return [SwerveModulePosition(0.01 * i * (1 + 0.3 * j), Rotation2d(0.05 * i + j))
                for j in range(4)]

    def wheels(i):
        return [0.01 * i * (1 + 0.2 * j) for j in range(4)]

    return {
        "swerve": (lambda g, p: SwerveDriveOdometry(swerve, g, modules(0), p),
                   lambda g, p: SwerveDriveOdometry3d(swerve, g, modules(0), p),
                   lambda o, g, i: o.update(g, modules(i))),
        "mecanum": (lambda g, p: MecanumDriveOdometry(mecanum, g, MecanumDriveWheelPositions(), p),
                    lambda g, p: MecanumDriveOdometry3d(mecanum, g, MecanumDriveWheelPositions(),
                                                        p),
                    lambda o, g, i: o.update(g, MecanumDriveWheelPositions(*wheels(i)))),
        "differential": (lambda g, p: DifferentialDriveOdometry(g, 0.0, 0.0, p),
                         lambda g, p: DifferentialDriveOdometry3d(g, 0.0, 0.0, p),
                         lambda o, g, i: o.update(g, *wheels(i)[:2])),
        "deadwheel": (lambda g, p: DeadWheelOdometry(dead, [0.0] * 3, g, p),
                      lambda g, p: DeadWheelOdometry3d(dead, [0.0] * 3, g, p),
                      lambda o, g, i: o.update(wheels(i)[:3], g)),
        "twodeadwheel": (lambda g, p: TwoDeadWheelOdometry(0.2, -0.1, 0.0, 0.0, g, p),
                         lambda g, p: TwoDeadWheelOdometry3d(0.2, -0.1, 0.0, 0.0, g, p),
                         lambda o, g, i: o.update(*wheels(i)[:2], g)),
    }


@pytest.mark.parametrize("name", sorted(_pairs()))
def test_level_ground_gives_the_2d_odometry_poses(name):
    make2, make3, step = _pairs()[name]
    assert {e.drivetrain for e in catalog.entries("odometry3d")} == set(_pairs())
    start = Pose2d(1.0, -2.0, Rotation2d(0.7))
    o2 = make2(Rotation2d(0.3), start)
    o3 = make3(R3(Rotation2d(0.3)), Pose3d(start))
    for i in range(1, 120):
        yaw = 0.3 + 0.04 * i * math.sin(0.1 * i)
        p2 = step(o2, Rotation2d(yaw), i)
        p3 = step(o3, R3(Rotation2d(yaw)), i)
        assert abs(p3.getX() - p2.getX()) <= 1e-12 and abs(p3.getY() - p2.getY()) <= 1e-12
        assert p3.getZ() == 0.0
        r2, r3 = p2.getRotation(), p3.getRotation().toRotation2d()
        assert math.hypot(r3.getCos() - r2.getCos(), r3.getSin() - r2.getSin()) <= 1e-12


# ---- refused calls change nothing ----------------------------------------------------------

def _state(odo):
    p = odo.getPose()
    return (tuple(xyz(p)), tuple(quat(p.getRotation())))


@pytest.mark.parametrize("call, exc, needle", [
    (lambda o: o.update(R3(), [SwerveModulePosition()] * 3), ValueError, "expected 4"),
    (lambda o: o.update(R3(), [SwerveModulePosition()] * 5), ValueError, "expected 4"),
    (lambda o: o.resetPosition(R3(), [SwerveModulePosition()] * 3, Pose3d()), ValueError,
     "expected 4"),
    (lambda o: o.update(Rotation2d(), [SwerveModulePosition()] * 4), TypeError, "Rotation3d"),
    (lambda o: o.update(R3(), np.zeros((3, 2))), ValueError, "(4, 2)"),
    (lambda o: o.update(R3(), [1.0] * 4), TypeError, "SwerveModulePosition"),
    (lambda o: o.resetPose(Pose2d()), TypeError, "Pose3d"),
    (lambda o: o.resetTranslation(Translation2d()), TypeError, "Translation3d"),
    (lambda o: o.resetRotation(Rotation2d()), TypeError, "Rotation3d"),
    (lambda o: o.resetPosition(R3(), [SwerveModulePosition()] * 4, Pose2d()), TypeError,
     "Pose3d"),
])
def test_swerve_refused_calls_change_nothing(call, exc, needle):
    odo = SwerveDriveOdometry3d(SwerveDriveKinematics(*CORNERS), R3(),
                                [SwerveModulePosition()] * 4, Pose3d(1, 2, 3, R3(0.1, 0.2, 0.3)))
    update(odo, R3(0.0, 0.1, 0.2), 0.5)
    before = _state(odo)
    with pytest.raises(exc) as info:
        call(odo)
    assert needle in str(info.value)
    assert _state(odo) == before
    # ...and the baselines did not move either: the same readings again are a no-op.
    assert _state_after(odo, lambda o: update(o, R3(0.0, 0.1, 0.2), 0.5)) == before


def _state_after(odo, call):
    call(odo)
    return _state(odo)


@pytest.mark.parametrize("cls, args, exc, needle", [
    (MecanumDriveOdometry3d, (MecanumDriveKinematics(*CORNERS), R3(), [0.0] * 4), TypeError,
     "MecanumDriveWheelPositions"),
    (DifferentialDriveOdometry3d, (R3(), "1", 0.0), TypeError, "numbers"),
    (DifferentialDriveOdometry3d, (Rotation2d(), 0.0, 0.0), TypeError, "Rotation3d"),
    (DifferentialDriveOdometry3d, (R3(), 0.0, 0.0, Pose2d()), TypeError, "Pose3d"),
    (DeadWheelOdometry3d, (DeadWheelKinematics(DEAD), [0.0] * 2, R3()), ValueError, "3"),
    (DeadWheelOdometry3d, (DeadWheelKinematics(DEAD), [0.0] * 3, None), TypeError, "Rotation3d"),
    (TwoDeadWheelOdometry3d, (math.inf, 0.0, 0.0, 0.0, R3()), ValueError, "finite"),
    (SwerveDriveOdometry3d, (MecanumDriveKinematics(*CORNERS), R3(), []), TypeError,
     "SwerveDriveKinematics"),
])
def test_bad_constructor_arguments(cls, args, exc, needle):
    with pytest.raises(exc) as info:
        cls(*args)
    assert needle in str(info.value)


@pytest.mark.parametrize("make", ODOMETRY3D)
def test_init_once_and_not_before(make):
    odo = make()
    before = _state(odo)
    with pytest.raises(TypeError, match="already initialised"):
        odo.__init__(*_ctor_args(odo))
    assert _state(odo) == before
    blank = type(odo).__new__(type(odo))
    with pytest.raises(RuntimeError, match="has not completed"):
        blank.getPose()
    with pytest.raises(RuntimeError, match="has not completed"):
        update(blank, R3(), 0.0)


def _ctor_args(odo):
    cls = type(odo)
    if cls is SwerveDriveOdometry3d:
        return (SwerveDriveKinematics(*CORNERS), R3(), [SwerveModulePosition()] * 4)
    if cls is MecanumDriveOdometry3d:
        return (MecanumDriveKinematics(*CORNERS), R3(), MecanumDriveWheelPositions())
    if cls is DifferentialDriveOdometry3d:
        return (R3(), 0.0, 0.0)
    if cls is DeadWheelOdometry3d:
        return (DeadWheelKinematics(DEAD), [0.0] * 3, R3())
    return (0.1, 0.1, 0.0, 0.0, R3())


def test_two_dead_wheels_are_dead_wheel_odometry_and_report_chassis_velocities():
    # TwoDeadWheelOdometry3d(a, b, ...) is a DeadWheelOdometry3d on [Pose2d(0, a, 0°),
    # Pose2d(b, 0, 90°)] (the upstream layout), turning on the spot included.
    two = TwoDeadWheelOdometry3d(0.2, -0.1, 0.0, 0.0, R3())
    dead = DeadWheelOdometry3d(DeadWheelKinematics([Pose2d(0, 0.2, Rotation2d()),
                                                    Pose2d(-0.1, 0, Rotation2d.kCCW_Pi_2)]),
                               [0.0, 0.0], R3())
    for i in range(1, 50):
        g = R3(0.01 * i, -0.02 * i, 0.1 * i)
        a = two.update(0.02 * i - 0.2 * 0.1 * i, 0.01 * i + 0.1 * 0.1 * i, g)
        b = dead.update([0.02 * i - 0.2 * 0.1 * i, 0.01 * i + 0.1 * 0.1 * i], g)
        np.testing.assert_allclose(xyz(a), xyz(b), rtol=0, atol=1e-12)
        assert same_rotation(a.getRotation(), b.getRotation())
    v = two.toChassisVelocities(1.0, 2.0, 3.0)
    assert (v.vx, v.vy, v.omega) == (1.0 + 3.0 * 0.2, 2.0 + 3.0 * 0.1, 3.0)


# ---- the step's exp against mpmath --------------------------------------------------------

@pytest.mark.parametrize("angle", [0.0, 1e-12, 1e-9, 3e-8, 1e-7, 1e-6, 1e-5, 0.99e-3, 1.01e-3,
                                   0.1, 1.0, 3.0, math.pi - 1e-6])
def test_one_step_is_the_exact_twist_exp(angle):
    # One update from the origin with the gyro turned by `angle` about a skew axis while the
    # robot moves u = (dx, dy): the pose is Twist3d(dx, dy, 0, ρ).exp(), ρ the gyro change's
    # rotation vector, to 1e-15 of |u| at every angle (WPILib's closed form B = (1 − cos θ)/θ²
    # cancels near 1e-7 rad; the step never forms it). Two odometries: a differential drive
    # (dy = 0), and dead wheels at the centre, one rolling forward and one left, which read
    # (dx, dy) and sweep no arcs as the robot turns.
    mp = pytest.importorskip("mpmath")
    mp.mp.prec = 200
    axis = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    gyro = R3((axis * angle).tolist())
    w, x, y, z = (mp.mpf(float(c)) for c in quat(gyro))
    if w < 0:
        w, x, y, z = -w, -x, -y, -z
    vn = mp.sqrt(x * x + y * y + z * z)
    theta = 2 * mp.atan2(vn, w)
    r = [c * theta / vn for c in (x, y, z)] if vn else [mp.mpf(0)] * 3
    b = (1 - mp.cos(theta)) / theta ** 2 if theta else mp.mpf(1) / 2
    c = (theta - mp.sin(theta)) / theta ** 3 if theta else mp.mpf(1) / 6
    centre = DeadWheelKinematics([Pose2d(0, 0, Rotation2d()), Pose2d(0, 0, Rotation2d.kCCW_Pi_2)])
    for u, step in (((0.7, 0.0), lambda: DifferentialDriveOdometry3d(R3(), 0.0, 0.0)
                     .update(gyro, 0.7, 0.7)),
                    ((0.7, -0.4), lambda: DeadWheelOdometry3d(centre, [0.0, 0.0], R3())
                     .update([0.7, -0.4], gyro))):
        pose = step()
        uu = [mp.mpf(u[0]), mp.mpf(u[1]), mp.mpf(0)]
        c1 = _cross(r, uu)
        c2 = _cross(r, c1)
        exact = [uu[i] + b * c1[i] + c * c2[i] for i in range(3)]
        err = max(abs(float(exact[i]) - v) for i, v in enumerate(xyz(pose)))
        assert err <= 1e-15 * math.hypot(*u), (angle, u, err)
        assert same_rotation(pose.getRotation(), gyro, 1e-15)


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
