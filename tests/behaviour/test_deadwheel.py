"""Dead-wheel kinematics and odometry against the worked vectors of
/work/shared/reference/followers-and-estimators.md (§1.1–§1.3, the draft layouts of §2–§3
written as wheel poses, §6) and peers.md §1.7 (Road Runner's standard three-wheel layout),
plus construction-time validation. Exact vectors are held to WPILib's 1e-9; numbers the
digests print to six decimals are held to 5e-7.
"""
import math

import numpy as np
import pytest

from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    DeadWheelKinematics,
    DeadWheelOdometry,
    Pose2d,
    Rotation2d,
    Translation2d,
    TwoDeadWheelOdometry,
    Twist2d,
)
from tests._support.wpilib_port import EPS, assert_close, assert_pose

IN = 0.0254
SIX = 5e-7     # tolerance for values printed to six decimals


def fwd(y, x=0.0):
    """A wheel reading forward motion (rolling along 0°) at (x, y)."""
    return Pose2d(x, y, Rotation2d.kZero)


def left(x, y=0.0):
    """A wheel reading leftward motion (rolling along +90°) at (x, y)."""
    return Pose2d(x, y, Rotation2d.kCCW_Pi_2)


def double(a, b):
    """The draft's Double layout (xWheelYPos, yWheelXPos)."""
    return DeadWheelKinematics([fwd(a), left(b)])


def triple(y1, y2, x):
    """The draft's Triple layout (xWheel1YPos, xWheel2YPos, yWheelXPos)."""
    return DeadWheelKinematics([fwd(y1), fwd(y2), left(x)])


def assert_vec(expected, v, tol=EPS):
    got = {ChassisVelocities: lambda: (v.vx, v.vy, v.omega),
           ChassisAccelerations: lambda: (v.ax, v.ay, v.alpha),
           Twist2d: lambda: (v.dx, v.dy, v.dtheta)}.get(type(v), lambda: tuple(v))()
    assert len(got) == len(expected)
    for e, g in zip(expected, got):
        assert_close(e, g, tol)



# ---- §1.1 the general solve ------------------------------------------------------------

FOUR = [fwd(0.2), fwd(-0.2), left(0.1), left(-0.1)]


def test_least_squares_four_orthogonal_wheels():
    k = DeadWheelKinematics(FOUR)
    assert_vec((1.1, 0.2, 0.6), k.toTwist2d([1.0, 1.2, 0.3, 0.1]))
    assert_vec((1.1, 0.2, 0.5), k.toTwist2d([1.0, 1.2, 0.3, 0.1], gyro_delta=0.5))


def test_redundant_wheel_is_averaged_in_with_a_gyro():
    k = DeadWheelKinematics([fwd(0.3), left(0.2), fwd(-0.1)])
    assert_vec((1.11, 0.48, 0.1), k.toTwist2d([1.0, 0.5, 1.2], gyro_delta=0.1))


def test_exact_solve_is_not_the_drafts_mean():
    # §3.2 asymmetric counter-example: the draft's vx = (v1 + v2)/2 gives 0.9.
    k = triple(0.3, -0.1, 0.2)
    wheels = k.toWheelVelocities(ChassisVelocities(1.0, 0.0, 1.0))
    assert_vec((0.7, 1.1, 0.2), wheels)
    assert_vec((1.0, 0.0, 1.0), k.toChassisVelocities(wheels))
    assert_vec((1.0, 0.0, 1.0), k.toChassisVelocities(wheels, gyro_rate=1.0))


# ---- §1.2 observability --------------------------------------------------------------

@pytest.mark.parametrize("poses, needle", [
    ([fwd(0.1), fwd(-0.1), fwd(0.3)], "lateral (y) motion cannot be observed"),
    ([left(0.1), left(-0.2)], "forward (x) motion cannot be observed"),
    ([left(0.1), Pose2d(0.3, 0.2, Rotation2d.kCW_Pi_2)],  # backwards is still parallel
     "forward (x) motion cannot be observed"),
    ([Pose2d(0, 0, Rotation2d.fromDegrees(30)), Pose2d(1, 2, Rotation2d.fromDegrees(210))],
     "motion along 120° (robot frame) cannot be observed"),
])
def test_parallel_wheels_are_refused(poses, needle):
    with pytest.raises(ValueError, match="all wheels are parallel") as e:
        DeadWheelKinematics(poses)
    assert needle in str(e.value)


@pytest.mark.parametrize("poses, needle", [
    ([fwd(0.3), left(0.2)], "2 wheels cannot observe rotation"),
    # Two forward wheels on one line: the lines meet at (x_left, y1).
    ([fwd(0.3), fwd(0.3, x=0.5), left(0.2)], "passes through (0.2, 0.3) m"),
    # Three wheels rolling radially: every wheel's line passes through the centre.
    ([Pose2d(0.2, 0.0, Rotation2d.kZero), Pose2d(0.0, 0.2, Rotation2d.kCCW_Pi_2),
      Pose2d(-0.1, -0.1, Rotation2d.fromDegrees(45))], "passes through (0, 0) m"),
])
def test_layouts_that_need_a_gyro(poses, needle):
    k = DeadWheelKinematics(poses)
    assert k.requiresGyro()
    n = len(poses)
    with pytest.raises(ValueError, match="needs a gyro") as e:
        k.toTwist2d([0.0] * n)
    assert needle in str(e.value)
    with pytest.raises(ValueError, match="needs a gyro"):
        DeadWheelOdometry(k, [0.0] * n)
    # With the gyro the same layout works.
    assert k.toTwist2d([0.1] * n, gyro_delta=0.0).dtheta == 0.0
    DeadWheelOdometry(k, [0.0] * n, Rotation2d.kZero)


def test_observable_layout_does_not_need_a_gyro():
    assert not triple(0.3, -0.1, 0.2).requiresGyro()


@pytest.mark.parametrize("poses, exc, needle", [
    ([], ValueError, "at least 2 wheels, got 0"),
    ([fwd(0.1)], ValueError, "at least 2 wheels, got 1"),
    ([fwd(0.1), Translation2d(1, 2)], TypeError, "wheel 1 must be a drivekin Pose2d"),
    ([fwd(0.1), None], TypeError, "wheel 1 must be a drivekin Pose2d"),
    ([fwd(0.1), left(math.nan)], ValueError, "wheel 1 pose must be finite"),
    ([fwd(math.inf), left(0.1)], ValueError, "wheel 0 pose must be finite"),
    (5, TypeError, "sequence of Pose2d"),
])
def test_bad_layouts(poses, exc, needle):
    with pytest.raises(exc, match=".") as e:
        DeadWheelKinematics(poses)
    assert needle in str(e.value)


# ---- §1.3 Road Runner 1.0 -------------------------------------------------------------

def test_road_runner_standard_layout():
    # peers.md §1.7: deltas (0.50, 0.70, 0.10) in -> twist (0.600000, 0.152817, 0.014085).
    k = DeadWheelKinematics.fromRoadRunner(-7.1, 7.1, -3.75, 1.0)
    tw = k.toTwist2d([0.5 * IN, 0.7 * IN, 0.1 * IN])
    assert_close(0.6, tw.dx / IN, 1e-12)
    assert_close(0.1 + 3.75 / 71, tw.dy / IN, 1e-12)
    assert_close(1 / 71, tw.dtheta, 1e-15)
    assert_vec((0.6, 0.152817, 0.014085), Twist2d(tw.dx / IN, tw.dy / IN, tw.dtheta), SIX)
    # The exp-map step from the origin and from (10, 5, 90°), in inches.
    for start, expected in (((0, 0, 0), (0.598904, 0.157037, 0.014085)),
                            ((10, 5, math.pi / 2), (9.842963, 5.598904, 1.584881))):
        o = DeadWheelOdometry(k, [0.0, 0.0, 0.0],
                              initial_pose=Pose2d(start[0] * IN, start[1] * IN,
                                                 Rotation2d(start[2])))
        p = o.update([0.5 * IN, 0.7 * IN, 0.1 * IN])
        assert_close(expected[0], p.getX() / IN, SIX)
        assert_close(expected[1], p.getY() / IN, SIX)
        assert_close(expected[2], p.getRotation().getRadians(), SIX)


def test_road_runner_ticks_and_in_per_tick():
    # The same robot tuned with a real inPerTick: every number is divided by it.
    ipt = 0.001978956
    k = DeadWheelKinematics.fromRoadRunner(-7.1 / ipt, 7.1 / ipt, -3.75 / ipt, ipt)
    ticks = np.array([0.5, 0.7, 0.1]) / ipt
    tw = k.toTwist2d(ticks * ipt * IN)
    assert_close(0.6, tw.dx / IN, 1e-12)
    assert_close(0.1 + 3.75 / 71, tw.dy / IN, 1e-12)
    assert_close(1 / 71, tw.dtheta, 1e-14)


def test_road_runner_sign_trap():
    # A real tuner log (road-runner-quickstart#359): par0YTicks -962 is the LEFT wheel.
    k = DeadWheelKinematics.fromRoadRunner(-962, 912, -500, 0.002)
    par0, par1, perp = k.getWheelPoses()
    assert par0.getY() > 0 > par1.getY()
    assert_close(962 * 0.002 * IN, par0.getY(), 1e-15)
    assert_close(-500 * 0.002 * IN, perp.getX(), 1e-15)
    assert perp.getRotation().getDegrees() == pytest.approx(90.0)
    # A counter-clockwise spin moves a wheel on the left backwards, one on the right
    # forwards, and a perpendicular wheel behind the centre to the right.
    wheels = k.toWheelVelocities(ChassisVelocities(0.0, 0.0, 1.0))
    assert wheels[0] < 0 < wheels[1] and wheels[2] < 0


def test_road_runner_two_wheels_and_imu():
    k = DeadWheelKinematics.fromRoadRunnerTwoWheel(-7.1, -3.75, 1.0)
    assert k.requiresGyro()
    tw = k.toTwist2d([0.5 * IN, 0.1 * IN], gyro_delta=0.014)
    assert_close(0.5994, tw.dx / IN, 1e-12)
    assert_close(0.1525, tw.dy / IN, 1e-12)
    assert tw.dtheta == 0.014


@pytest.mark.parametrize("args, needle", [
    ((1.0, -1.0, 2.0, 0.0), "in_per_tick must be a positive finite"),
    ((1.0, -1.0, 2.0, -1e-3), "in_per_tick must be a positive finite"),
    ((1.0, -1.0, 2.0, math.nan), "in_per_tick must be a positive finite"),
    ((math.inf, -1.0, 2.0, 1e-3), "par0_y_ticks must be finite"),
    ((1.0, -1.0, math.nan, 1e-3), "perp_x_ticks must be finite"),
])
def test_road_runner_bad_parameters(args, needle):
    with pytest.raises(ValueError) as e:
        DeadWheelKinematics.fromRoadRunner(*args)
    assert needle in str(e.value)


# ---- §2 the Double layout (forward wheel + left wheel + gyro) ---------------------------

@pytest.mark.parametrize("wheels, omega, expected", [
    ((5, 0), 0, (5, 0, 0)), ((0, 5), 0, (0, 5, 0)), ((-5, 5), 5, (0, 0, 5)),
    ((1, -1), 5, (6, -6, 5)),
])
def test_double_layout_velocities(wheels, omega, expected):
    k = double(1.0, 1.0)
    assert_vec(expected, k.toChassisVelocities(wheels, gyro_rate=omega))
    back = k.toWheelVelocities(ChassisVelocities(*expected))
    assert_vec(wheels, back)


def test_double_layout_accelerations():
    k = double(0.25, -0.5)
    assert_vec((0.0, -4.0), k.toWheelAccelerations(ChassisAccelerations(1, -2, 4)))
    assert_vec((0.5, 0.0, -2.0), k.toChassisAccelerations([1, 1], angular_acceleration=-2))


def test_double_layout_wrapped_gyro_twist():
    k = double(0.2, 0.3)
    o = DeadWheelOdometry(k, [1.0, 1.0], Rotation2d.fromDegrees(170))
    dtheta = math.radians(20)
    expected = Twist2d(1 + 0.2 * dtheta, -0.5 - 0.3 * dtheta, dtheta).exp()
    p = o.update([2.0, 0.5], Rotation2d.fromDegrees(-170))
    assert_pose((expected.getX(), expected.getY(), dtheta), p)
    assert_vec((1 + 0.2 * dtheta, -0.5 - 0.3 * dtheta, dtheta),
               k.toTwist2d([1.0, -0.5], gyro_delta=dtheta))


def test_double_layout_odometry_vectors():
    k = double(1.0, 1.0)
    o = DeadWheelOdometry(k, [0.0, 0.0], Rotation2d.kZero)
    o.resetPosition([1.0, 1.0], Rotation2d.kZero, Pose2d.kZero)
    o.update([1.0, 1.0], Rotation2d.kZero)
    assert_pose((0, 0, 0), o.update([1.0, 1.0], Rotation2d.kZero))
    # A gyro offset does not rotate the motion.
    o.resetPosition([0.0, 0.0], Rotation2d.fromDegrees(90), Pose2d.kZero)
    o.update([0.0, 0.0], Rotation2d.fromDegrees(90))
    assert_pose((1, 0, 0), o.update([1.0, 0.0], Rotation2d.fromDegrees(90)))
    # Spin in place: the lever-arm terms cancel the wheel readings exactly.
    o.resetPosition([0.0, 0.0], Rotation2d.fromDegrees(30), Pose2d(1, 2, Rotation2d.kZero))
    assert_pose((1, 2, math.pi / 2),
                o.update([-math.pi / 2, math.pi / 2], Rotation2d.fromDegrees(120)))
    assert_pose((1, 3, math.pi / 2),
                o.update([-math.pi / 2 + 1, math.pi / 2], Rotation2d.fromDegrees(120)))


# ---- §3 the Triple layout --------------------------------------------------------------

@pytest.mark.parametrize("wheels, expected", [
    ((5, 5, 0), (5, 0, 0)), ((0, 0, 5), (0, 5, 0)), ((5, -5, -5), (0, 0, -5)),
    ((5, 1, -1), (3, 1, -2)),
])
def test_triple_symmetric_layout(wheels, expected):
    k = triple(1.0, -1.0, 1.0)
    assert_vec(expected, k.toChassisVelocities(wheels))
    assert_vec(wheels, k.toWheelVelocities(ChassisVelocities(*expected)))
    assert_vec(expected, k.toChassisAccelerations(wheels))


def test_triple_odometry_where_every_rule_agrees():
    k = triple(1.0, -1.0, 1.0)
    for gyro in (None, Rotation2d.kZero):
        o = DeadWheelOdometry(k, [1.0, 1.0, 1.0], gyro)
        assert_pose((0, 0, 0), o.update([1.0, 1.0, 1.0], gyro))
        o.resetPosition([0.0, 0.0, 0.0], gyro, Pose2d.kZero)
        assert_pose((0.1, 0, 0), o.update([0.1, 0.1, 0.0], gyro))
        o.resetPosition([0.0, 0.0, 0.0], gyro, Pose2d(1, 1, Rotation2d.kZero))
        assert_pose((3, 1, 0), o.update([2.0, 2.0, 0.0], gyro))
    g = Rotation2d.fromDegrees(90)
    o = DeadWheelOdometry(k, [0.0, 0.0, 0.0], g)
    o.update([1.0, 1.0, 0.0], g)
    assert_pose((1, 0, 0), o.getPose())


def test_triple_odometry_where_wheels_and_gyro_disagree():
    k = triple(1.0, -1.0, 1.0)
    spin = [-0.5, 0.5, 0.5]          # a 0.5 rad spin in place, as the wheels see it
    o = DeadWheelOdometry(k, [0.0, 0.0, 0.0])
    assert_pose((0, 0, 0.5), o.update(spin))
    # With a gyro that stays at 0 the wheels' disagreement averages out and the left
    # wheel's reading is lateral motion; then the gyro alone turns 0.5 rad.
    o = DeadWheelOdometry(k, [0.0, 0.0, 0.0], Rotation2d.kZero)
    assert_pose((0, 0.5, 0), o.update(spin, Rotation2d.kZero))
    assert_pose((0.122417, 0.020574, 0.5), o.update(spin, Rotation2d(0.5)), SIX)
    assert_pose((1 - math.cos(0.5), 0.5 - math.sin(0.5), 0.5), o.getPose())


# ---- §6 TwoDeadWheelOdometry -----------------------------------------------------------

def test_two_dead_wheel_resets():
    g10 = Rotation2d.fromDegrees(10)
    for o in (TwoDeadWheelOdometry(0.5, -0.25, 3.0, 4.0, g10),
              DeadWheelOdometry(double(0.5, -0.25), [3.0, 4.0], g10)):
        def upd(x, y, g):
            return o.update(x, y, g) if isinstance(o, TwoDeadWheelOdometry) else o.update([x, y], g)
        o.resetRotation(Rotation2d.fromDegrees(90))
        o.resetTranslation(Translation2d(1, 1))
        assert_pose((1, 2, math.pi / 2), upd(4.0, 4.0, g10))
        o.resetPose(Pose2d.kZero)
        expected = Twist2d(0.05, 0.05, 0.1).exp()
        p = upd(4.0, 4.025, Rotation2d(math.radians(10) + 0.1))
        assert_pose((expected.getX(), expected.getY(), 0.1), p, 1e-12)


def test_two_dead_wheel_initial_pose_and_defaults():
    start = Pose2d(1, 2, Rotation2d(0.3))
    assert TwoDeadWheelOdometry(0.1, 0.2, 0, 0, Rotation2d.kZero, start).getPose() == start
    assert TwoDeadWheelOdometry(0.1, 0.2, 0, 0, Rotation2d.kZero).getPose() == Pose2d.kZero
    assert DeadWheelOdometry(double(0.1, 0.2), [0, 0], Rotation2d.kZero).getPose() == Pose2d.kZero


@pytest.mark.parametrize("a, b", [(math.nan, 0.1), (0.1, math.inf)])
def test_two_dead_wheel_non_finite_offsets(a, b):
    with pytest.raises(ValueError, match="wheel offsets must be finite"):
        TwoDeadWheelOdometry(a, b, 0.0, 0.0, Rotation2d.kZero)


# ---- readings and the gyro contract -----------------------------------------------------

def test_readings_as_list_tuple_array_and_numpy_scalars():
    k = triple(0.3, -0.1, 0.2)
    values = [0.7, 1.1, 0.2]
    ref = k.toChassisVelocities(values)
    strided = np.zeros(6)
    strided[::2] = values
    for v in (tuple(values), np.array(values), strided[::2], [np.float64(x) for x in values]):
        got = k.toChassisVelocities(v)
        assert (got.vx, got.vy, got.omega) == (ref.vx, ref.vy, ref.omega)
    assert k.toChassisVelocities([1, 2, 3]) == k.toChassisVelocities([1.0, 2.0, 3.0])


@pytest.mark.parametrize("values, exc, needle", [
    ([1.0, 2.0], ValueError, "must hold 3 wheel values (one per wheel), got 2"),
    ([1.0, None, 2.0], TypeError, "wheel_velocities[1] must be a float, got NoneType"),
    ([1.0, "2", 2.0], TypeError, "wheel_velocities[1] must be a float, got str"),
    ([1.0, True, 2.0], TypeError, "wheel_velocities[1] must be a float, got bool"),
    ([1.0, 10 ** 400, 2.0], ValueError, "int too large for a float"),
    ((x for x in [1.0, 2.0, 3.0]), TypeError, "list or tuple of 3 floats or a 1-D float64"),
    (np.zeros(3, dtype=np.float32), TypeError, "dtype float64"),
    (np.zeros(3, dtype=object), TypeError, "dtype float64"),
    (np.zeros((3, 1)), ValueError, "shape (3,)"),
    (np.zeros(4), ValueError, "shape (3,)"),
])
def test_bad_readings(values, exc, needle):
    k = triple(0.3, -0.1, 0.2)
    with pytest.raises(exc) as e:
        k.toChassisVelocities(values)
    assert needle in str(e.value)


def test_gyro_use_is_fixed_at_construction():
    k = triple(0.3, -0.1, 0.2)
    with_gyro = DeadWheelOdometry(k, [0, 0, 0], Rotation2d.kZero)
    without = DeadWheelOdometry(k, [0, 0, 0])
    with pytest.raises(TypeError, match="uses a gyro, so gyro_angle must be a Rotation2d"):
        with_gyro.update([0.1, 0.1, 0.0])
    with pytest.raises(ValueError, match="constructed without a gyro"):
        without.update([0.1, 0.1, 0.0], Rotation2d.kZero)
    with pytest.raises(ValueError, match="constructed without a gyro"):
        without.resetPosition([0, 0, 0], Rotation2d.kZero, Pose2d.kZero)
    # Nothing moved.
    assert with_gyro.getPose() == Pose2d.kZero and without.getPose() == Pose2d.kZero
    assert_pose((0.1, 0, 0), without.update([0.1, 0.1, 0.0]))


def test_failed_update_changes_nothing():
    k = triple(0.3, -0.1, 0.2)
    o = DeadWheelOdometry(k, [0.0, 0.0, 0.0], Rotation2d.kZero)
    with pytest.raises(TypeError):
        o.update([0.5, 0.5, None], Rotation2d.kZero)
    # The baselines are untouched: the next good update sees the whole change.
    assert_pose((0.5, 0.0, 0.0), o.update([0.5, 0.5, 0.0], Rotation2d.kZero))


def test_into_forms_match_the_facade():
    k = triple(0.3, -0.1, 0.2)
    out = ChassisVelocities()
    k.toChassisVelocitiesInto([0.7, 1.1, 0.2], out, 1.0)
    ref = k.toChassisVelocities([0.7, 1.1, 0.2], 1.0)
    assert (out.vx, out.vy, out.omega) == (ref.vx, ref.vy, ref.omega)
    arr = np.full(3, np.nan)
    cv = ChassisVelocities(1.0, -0.5, 2.0)
    k.toWheelVelocitiesInto(cv, arr)
    assert tuple(arr) == k.toWheelVelocities(cv)
    with pytest.raises(ValueError, match="shape"):
        k.toWheelVelocitiesInto(cv, np.zeros(2))


def test_value_semantics():
    import copy
    import pickle
    k = triple(0.3, -0.1, 0.2)
    for dup in (copy.copy(k), copy.deepcopy(k), pickle.loads(pickle.dumps(k))):
        assert dup.getWheelPoses() == k.getWheelPoses()
        assert dup.toChassisVelocities([0.7, 1.1, 0.2]) == k.toChassisVelocities([0.7, 1.1, 0.2])
    assert repr(k).startswith("DeadWheelKinematics([Pose2d(0.0, 0.3, ")
    with pytest.raises(TypeError, match="already initialised"):
        k.__init__([fwd(1.0), left(1.0)])
    with pytest.raises(RuntimeError, match="has not completed"):
        DeadWheelKinematics.__new__(DeadWheelKinematics).toTwist2d([0.0, 0.0])
