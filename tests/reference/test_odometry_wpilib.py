"""WPILib 2027 odometry unit tests (DifferentialDriveOdometry, MecanumDriveOdometry,
SwerveDriveOdometry), restated for drivekin, plus the digest's odometry edge cases
(/work/shared/reference/wpilib-kinematics.md, sections 10 and 13).

Source of the ported cases: wpilibsuite/allwpilib main @ caf0fb2d,
wpimath/src/test/java/org/wpilib/math/kinematics/{DifferentialDriveOdometry,
MecanumDriveOdometry,SwerveDriveOdometry}Test.java (the C++ tests under
wpimath/src/test/native/cpp/kinematics/ hold the same deterministic cases). Tolerances are
WPILib's own (1e-9, 0.01, 0.1 and the accuracy-test bounds).

The accuracy tests (``test_accuracy_facing_*``) need a spline trajectory as ground truth.
drivekin has no trajectory generator, so the ground truth comes from robotpy-wpimath 2026's
``TrajectoryGenerator.generateTrajectory`` -- the generator these Java tests used until the
2027 trajectory rewrite (#8172), which renamed the calls but kept the waypoints, config,
seeds and bounds. The noise is Java's ``java.util.Random(seed).nextGaussian()``
re-implemented in ``wpilib_port.JavaRandom`` (same LCG and polar method; it can differ from
Java in the last bit because Java uses fdlibm's StrictMath.log). Those tests skip when
robotpy-wpimath is not installed.

Closed form used by the edge cases: one odometry step from pose (x, y, theta) with twist
(dx, dy, dtheta) moves by (dx*s - dy*c, dx*c + dy*s) rotated by theta, s = sin(dtheta)/dtheta,
c = (1 - cos(dtheta))/dtheta, and turns by dtheta; dtheta is always the wrapped gyro change.
"""
import math

import numpy as np
import pytest

from drivekin import (
    ChassisVelocities,
    DifferentialDriveOdometry,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveModulePosition,
    Translation2d,
)
from tests._support.wpilib_port import (BL, BR, DT, EPS, FL, FR, JavaRandom, assert_close,
                                        assert_pose, trajectory_generator)



def step(start, dx, dy, dtheta):
    """Closed-form pose after one odometry step (start = (x, y, theta))."""
    x0, y0, th0 = start
    if dtheta == 0.0:
        s, c = 1.0, 0.0
    else:
        s, c = math.sin(dtheta) / dtheta, (1.0 - math.cos(dtheta)) / dtheta
    lx, ly = dx * s - dy * c, dx * c + dy * s
    return (x0 + lx * math.cos(th0) - ly * math.sin(th0),
            y0 + lx * math.sin(th0) + ly * math.cos(th0),
            th0 + dtheta)


def deg(d):
    return Rotation2d.fromDegrees(d)


def zeros4():
    return [SwerveModulePosition() for _ in range(4)]


# =========================================================================================
# Ported: DifferentialDriveOdometryTest
# =========================================================================================
class TestDifferentialDriveOdometry:
    def test_odometry_with_encoder_distances(self):
        odometry = DifferentialDriveOdometry(Rotation2d.kZero, 0, 0)
        odometry.resetPosition(deg(45), 0, 0, Pose2d.kZero)
        pose = odometry.update(deg(135.0), 0.0, 5 * math.pi)
        assert_close(5.0, pose.getX())
        assert_close(5.0, pose.getY())
        assert_close(90.0, pose.getRotation().getDegrees())


# =========================================================================================
# Ported: MecanumDriveOdometryTest
# =========================================================================================
@pytest.fixture
def mecanum_kinematics():
    return MecanumDriveKinematics(FL, FR, BL, BR)


@pytest.fixture
def mecanum_odometry(mecanum_kinematics):
    return MecanumDriveOdometry(mecanum_kinematics, Rotation2d.kZero,
                                MecanumDriveWheelPositions())


class TestMecanumDriveOdometry:
    def test_multiple_consecutive_updates(self, mecanum_odometry):
        positions = MecanumDriveWheelPositions(3.536, 3.536, 3.536, 3.536)
        mecanum_odometry.resetPosition(Rotation2d.kZero, positions, Pose2d.kZero)
        mecanum_odometry.update(Rotation2d.kZero, positions)
        second = mecanum_odometry.update(Rotation2d.kZero, positions)
        assert_close(0.0, second.getX(), 0.01)
        assert_close(0.0, second.getY(), 0.01)
        assert_close(0.0, second.getRotation().getDegrees(), 0.01)

    def test_two_iterations(self, mecanum_odometry):
        positions = MecanumDriveWheelPositions(0.3536, 0.3536, 0.3536, 0.3536)
        mecanum_odometry.resetPosition(Rotation2d.kZero, MecanumDriveWheelPositions(),
                                       Pose2d.kZero)
        mecanum_odometry.update(Rotation2d.kZero, MecanumDriveWheelPositions())
        pose = mecanum_odometry.update(Rotation2d.kZero, positions)
        assert_close(0.3536, pose.getX(), 0.01)
        assert_close(0.0, pose.getY(), 0.01)
        assert_close(0.0, pose.getRotation().getDegrees(), 0.01)

    def test_90degree_turn(self, mecanum_odometry):
        # A 90 degree turn about the point between the front-left and rear-left wheels.
        positions = MecanumDriveWheelPositions(-13.328, 39.986, -13.329, 39.986)
        mecanum_odometry.resetPosition(Rotation2d.kZero, MecanumDriveWheelPositions(),
                                       Pose2d.kZero)
        mecanum_odometry.update(Rotation2d.kZero, MecanumDriveWheelPositions())
        pose = mecanum_odometry.update(Rotation2d.kCCW_Pi_2, positions)
        assert_close(8.4855, pose.getX(), 0.01)
        assert_close(8.4855, pose.getY(), 0.01)
        assert_close(90.0, pose.getRotation().getDegrees(), 0.01)

    def test_gyro_angle_reset(self, mecanum_odometry):
        gyro = Rotation2d.kCCW_Pi_2
        mecanum_odometry.resetPosition(gyro, MecanumDriveWheelPositions(),
                                       Pose2d(Translation2d.kZero, Rotation2d.kZero))
        positions = MecanumDriveWheelPositions(3.536, 3.536, 3.536, 3.536)
        mecanum_odometry.update(gyro, MecanumDriveWheelPositions())
        pose = mecanum_odometry.update(gyro, positions)
        assert_close(3.536, pose.getX(), 0.1)
        assert_close(0.0, pose.getY(), 0.1)
        assert_close(0.0, pose.getRotation().getRadians(), 0.1)

    def test_accuracy_facing_trajectory(self):
        mean_error, max_error, distance_ratio = mecanum_accuracy(
            lambda truth: ChassisVelocities(truth.velocity, 0, truth.velocity * truth.curvature),
            lambda truth, noise: Rotation2d(truth.pose.rotation().radians()).plus(noise))
        assert_close(0.0, mean_error, 0.35)  # "Incorrect mean error"
        assert_close(0.0, max_error, 0.35)  # "Incorrect max error"
        assert_close(1.0, distance_ratio, 0.05)  # distance travelled

    def test_accuracy_facing_x_axis(self):
        def velocities(truth):
            heading = truth.pose.rotation().radians()
            return ChassisVelocities(truth.velocity * math.cos(heading),
                                     truth.velocity * math.sin(heading), 0)

        mean_error, max_error, distance_ratio = mecanum_accuracy(
            velocities, lambda truth, noise: noise)
        assert_close(0.0, mean_error, 0.15)  # "Incorrect mean error"
        assert_close(0.0, max_error, 0.3)  # "Incorrect max error"
        assert_close(1.0, distance_ratio, 0.05)  # distance travelled


# =========================================================================================
# Ported: SwerveDriveOdometryTest
# =========================================================================================
@pytest.fixture
def swerve_odometry():
    kinematics = SwerveDriveKinematics(FL, FR, BL, BR)
    return SwerveDriveOdometry(kinematics, Rotation2d.kZero, zeros4())


class TestSwerveDriveOdometry:
    def test_two_iterations(self, swerve_odometry):
        deltas = [SwerveModulePosition(0.5, Rotation2d.kZero) for _ in range(4)]
        swerve_odometry.update(Rotation2d.kZero, zeros4())
        pose = swerve_odometry.update(Rotation2d.kZero, deltas)
        assert_close(5.0 / 10.0, pose.getX(), 0.01)
        assert_close(0.0, pose.getY(), 0.01)
        assert_close(0.0, pose.getRotation().getDegrees(), 0.01)

    def test_90degree_turn(self, swerve_odometry):
        # A 90 degree turn about the point between the front-left and rear-left wheels.
        deltas = [
            SwerveModulePosition(18.85, Rotation2d.kCCW_Pi_2),
            SwerveModulePosition(42.15, deg(26.565)),
            SwerveModulePosition(18.85, Rotation2d.kCW_Pi_2),
            SwerveModulePosition(42.15, deg(-26.565)),
        ]
        swerve_odometry.update(Rotation2d.kZero, zeros4())
        pose = swerve_odometry.update(Rotation2d.kCCW_Pi_2, deltas)
        assert_close(12.0, pose.getX(), 0.01)
        assert_close(12.0, pose.getY(), 0.01)
        assert_close(90.0, pose.getRotation().getDegrees(), 0.01)

    def test_gyro_angle_reset(self, swerve_odometry):
        gyro = Rotation2d.kCCW_Pi_2
        swerve_odometry.resetPosition(gyro, zeros4(),
                                      Pose2d(Translation2d.kZero, Rotation2d.kZero))
        swerve_odometry.update(gyro, zeros4())
        delta = SwerveModulePosition(1.0, Rotation2d.kZero)
        pose = swerve_odometry.update(gyro, [delta, delta, delta, delta])
        assert_close(1.0, pose.getX(), 0.1)
        assert_close(0.0, pose.getY(), 0.1)
        assert_close(0.0, pose.getRotation().getRadians(), 0.1)

    def test_reset_translation(self, swerve_odometry):
        positions = zeros4()
        gyro = deg(30.0)
        swerve_odometry.resetPosition(Rotation2d.kZero, positions,
                                      Pose2d(Translation2d.kZero, Rotation2d.kZero))
        initial = swerve_odometry.update(gyro, positions)
        assert_close(0.0, initial.getX(), 0.1)
        assert_close(0.0, initial.getY(), 0.1)
        assert_close(30.0, initial.getRotation().getDegrees(), 0.1)
        swerve_odometry.resetTranslation(Translation2d(0.5, 0))
        new = swerve_odometry.update(gyro, positions)
        assert_close(0.5, new.getX(), 0.1)
        assert_close(0.0, new.getY(), 0.1)
        assert_close(30.0, new.getRotation().getDegrees(), 0.1)

    def test_reset_rotation(self, swerve_odometry):
        positions = zeros4()
        gyro = deg(30.0)
        swerve_odometry.resetPosition(Rotation2d.kZero, positions,
                                      Pose2d(0.5, 0.0, Rotation2d.kZero))
        initial = swerve_odometry.update(gyro, positions)
        assert_close(0.5, initial.getX(), 0.1)
        assert_close(0.0, initial.getY(), 0.1)
        assert_close(30.0, initial.getRotation().getDegrees(), 0.1)
        swerve_odometry.resetRotation(Rotation2d.kCCW_90deg)
        new = swerve_odometry.update(gyro, positions)
        assert_close(0.5, new.getX(), 0.1)
        assert_close(0.0, new.getY(), 0.1)
        assert_close(90.0, new.getRotation().getDegrees(), 0.1)

    def test_accuracy_facing_trajectory(self):
        def step(truth, rand, kinematics, modules):
            module_velocities = kinematics.toSwerveModuleVelocities(
                ChassisVelocities(truth.velocity, 0.0, truth.velocity * truth.curvature))
            for mv in module_velocities:
                mv.angle = mv.angle.plus(Rotation2d(rand.next_gaussian() * 0.005))
                mv.velocity += rand.next_gaussian() * 0.1
            for m, mv in zip(modules, module_velocities):
                m.distance += mv.velocity * DT
                m.angle = mv.angle
            truth_rotation = Rotation2d(truth.pose.rotation().radians())
            return truth_rotation.plus(Rotation2d(rand.next_gaussian() * 0.05))

        final, mean_error, max_error = swerve_accuracy(step)
        assert_close(0.0, final.getX(), 1e-1)  # "Incorrect Final X"
        assert_close(0.0, final.getY(), 1e-1)  # "Incorrect Final Y"
        assert_close(math.pi / 4, final.getRotation().getRadians(), 10 * math.pi / 180)
        assert_close(0.0, mean_error, 0.05)  # "Incorrect mean error"
        assert_close(0.0, max_error, 0.125)  # "Incorrect max error"

    def test_accuracy_facing_x_axis(self):
        def step(truth, rand, kinematics, modules):
            travelled = truth.velocity * DT + 0.5 * truth.acceleration * DT * DT
            heading = Rotation2d(truth.pose.rotation().radians())
            for m in modules:
                m.distance += travelled
                m.angle = heading
            return Rotation2d(rand.next_gaussian() * 0.05)

        final, mean_error, max_error = swerve_accuracy(step)
        assert_close(0.0, final.getX(), 1e-1)  # "Incorrect Final X"
        assert_close(0.0, final.getY(), 1e-1)  # "Incorrect Final Y"
        assert_close(0.0, final.getRotation().getRadians(), 10 * math.pi / 180)
        assert_close(0.0, mean_error, 0.06)  # "Incorrect max error" (sic)
        assert_close(0.0, max_error, 0.125)  # "Incorrect max error"


# ---- accuracy-test support --------------------------------------------------------------
MECANUM_WAYPOINTS = [(0, 0, 0.0), (20, 20, 0.0), (10, 10, math.pi), (30, 30, 0.0),
                     (20, 20, math.pi), (10, 10, 0.0)]
SWERVE_WAYPOINTS = [(0, 0, math.radians(45)), (3, 0, -math.pi / 2), (0, 0, math.radians(135)),
                    (-3, 0, -math.pi / 2), (0, 0, math.radians(45))]


def drive_along(odometry, waypoints, seed, step):
    """The accuracy tests' loop. Follows the trajectory through ``waypoints`` (max 0.5 m/s,
    2 m/s²) in steps of DT; at each step ``step(truth, rand)`` (``rand`` = JavaRandom(seed))
    advances the simulated wheel positions and returns ``(gyro, positions)`` for
    ``odometry.update``. Returns (mean error, max error, odometry distance / trajectory
    distance), an error being the distance of the odometry pose from the true position."""
    trajectory = trajectory_generator()(waypoints, 0.5, 2.0)
    rand = JavaRandom(seed)
    t = 0.0
    max_error, error_sum = -math.inf, 0.0
    odometry_distance, trajectory_distance = 0.0, 0.0
    duration = trajectory.totalTime()
    while t <= duration:
        truth = trajectory.sample(t)
        trajectory_distance += truth.velocity * DT + 0.5 * truth.acceleration * DT * DT
        gyro, positions = step(truth, rand)
        last_pose = odometry.getPose()
        x_hat = odometry.update(gyro, positions)
        odometry_distance += last_pose.getTranslation().getDistance(x_hat.getTranslation())
        error = Translation2d(truth.pose.X(), truth.pose.Y()).getDistance(
            x_hat.getTranslation())
        max_error = max(max_error, error)
        error_sum += error
        t += DT
    return error_sum / (duration / DT), max_error, odometry_distance / trajectory_distance


def mecanum_accuracy(velocities, gyro):
    """MecanumDriveOdometryTest's accuracy run: wheels at (±1, ±1) m, wheel velocities of
    ``velocities(truth)`` plus N(0, 0.1) noise integrated into the wheel positions, gyro
    reading ``gyro(truth, noise)`` with noise = Rotation2d(N(0, 0.05)). Returns
    :func:`drive_along`'s numbers."""
    kinematics = MecanumDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                        Translation2d(-1, -1), Translation2d(-1, 1))
    positions = MecanumDriveWheelPositions()
    odometry = MecanumDriveOdometry(kinematics, Rotation2d.kZero, positions, Pose2d.kZero)

    def step(truth, rand):
        wheels = kinematics.toWheelVelocities(velocities(truth))
        wheels.frontLeft += rand.next_gaussian() * 0.1
        wheels.frontRight += rand.next_gaussian() * 0.1
        wheels.rearLeft += rand.next_gaussian() * 0.1
        wheels.rearRight += rand.next_gaussian() * 0.1
        positions.frontLeft += wheels.frontLeft * DT
        positions.frontRight += wheels.frontRight * DT
        positions.rearLeft += wheels.rearLeft * DT
        positions.rearRight += wheels.rearRight * DT
        return gyro(truth, Rotation2d(rand.next_gaussian() * 0.05)), positions

    return drive_along(odometry, MECANUM_WAYPOINTS, 5190, step)


def swerve_accuracy(step):
    """SwerveDriveOdometryTest's accuracy run: modules at (±1, ±1) m; ``step(truth, rand,
    kinematics, modules)`` moves the four SwerveModulePosition ``modules`` and returns the
    gyro reading. Returns (final pose, mean error, max error)."""
    kinematics = SwerveDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                       Translation2d(-1, -1), Translation2d(-1, 1))
    odometry = SwerveDriveOdometry(kinematics, Rotation2d.kZero, zeros4())
    modules = zeros4()
    mean_error, max_error, _ = drive_along(
        odometry, SWERVE_WAYPOINTS, 4915,
        lambda truth, rand: (step(truth, rand, kinematics, modules), modules))
    return odometry.getPose(), mean_error, max_error


def test_java_random_matches_jdk():
    # Values printed by OpenJDK 17: new Random(0).nextGaussian() twice, new Random(42) the
    # same, and nextDouble() of both seeds.
    r = JavaRandom(0)
    assert r.next_gaussian() == 0.8025330637390305
    assert r.next_gaussian() == -0.9015460884175122
    r = JavaRandom(42)
    assert_close(1.1419053154730547, r.next_gaussian(), 1e-15)  # StrictMath.log: ~1 ulp
    assert_close(0.9194079489827879, r.next_gaussian(), 1e-15)
    assert JavaRandom(42).next_double() == 0.7275636800328681
    assert JavaRandom(0).next_double() == 0.730967787376657


# =========================================================================================
# Edge cases from the digest (not in the WPILib tests)
# =========================================================================================
class _Drive:
    """Uniform driver for the three odometry classes. ``d`` is a forward distance driven
    by every wheel (so the wheel-derived twist is (d, 0, 0) for every drivetrain)."""

    def __init__(self, kind):
        self.kind = kind

    def make(self, gyro, d, pose=None):
        args = () if pose is None else (pose,)
        if self.kind == "differential":
            self.odo = DifferentialDriveOdometry(gyro, d, d, *args)
        elif self.kind == "mecanum":
            self.odo = MecanumDriveOdometry(MecanumDriveKinematics(FL, FR, BL, BR), gyro,
                                            MecanumDriveWheelPositions(d, d, d, d), *args)
        else:
            self.odo = SwerveDriveOdometry(SwerveDriveKinematics(FL, FR, BL, BR), gyro,
                                           [SwerveModulePosition(d) for _ in range(4)], *args)
        return self.odo

    def update(self, gyro, d):
        if self.kind == "differential":
            return self.odo.update(gyro, d, d)
        if self.kind == "mecanum":
            return self.odo.update(gyro, MecanumDriveWheelPositions(d, d, d, d))
        return self.odo.update(gyro, [SwerveModulePosition(d) for _ in range(4)])

    def reset_position(self, gyro, d, pose):
        if self.kind == "differential":
            return self.odo.resetPosition(gyro, d, d, pose)
        if self.kind == "mecanum":
            return self.odo.resetPosition(gyro, MecanumDriveWheelPositions(d, d, d, d), pose)
        return self.odo.resetPosition(gyro, [SwerveModulePosition(d) for _ in range(4)], pose)


@pytest.fixture(params=["differential", "mecanum", "swerve"])
def drive(request):
    return _Drive(request.param)


class TestOdometryRules:
    def test_default_initial_pose_is_origin(self, drive):
        odo = drive.make(deg(77), 3.0)
        assert_pose((0.0, 0.0, 0.0), odo.getPose())

    def test_heading_change_from_wrapped_gyro_difference(self, drive):
        # 170 deg -> -170 deg is +20 deg, not -340 deg: the translation of the arc shows it.
        drive.make(deg(170), 0.0)
        pose = drive.update(deg(-170), 1.0)
        assert_pose(step((0.0, 0.0, 0.0), 1.0, 0.0, math.radians(20)), pose)
        # ... and back again is -20 deg.
        pose = drive.update(deg(170), 2.0)
        expected = step(step((0.0, 0.0, 0.0), 1.0, 0.0, math.radians(20)),
                        1.0, 0.0, math.radians(-20))
        assert_pose(expected, pose)

    def test_gyro_need_not_match_pose_heading(self, drive):
        drive.make(deg(90), 0.0, Pose2d(1.0, 2.0, Rotation2d.kZero))
        pose = drive.update(deg(90), 1.0)
        assert_pose((2.0, 2.0, 0.0), pose)
        pose = drive.update(deg(120), 1.0)
        assert_pose((2.0, 2.0, math.radians(30)), pose)
        pose = drive.update(deg(120), 3.0)
        assert_pose(step((2.0, 2.0, math.radians(30)), 2.0, 0.0, 0.0), pose)

    def test_initial_pose_heading(self, drive):
        drive.make(Rotation2d.kZero, 0.0, Pose2d(0.0, 0.0, Rotation2d.kCCW_Pi_2))
        assert_pose((0.0, 1.0, math.pi / 2), drive.update(Rotation2d.kZero, 1.0))

    def test_update_returns_pose_and_get_pose_matches(self, drive):
        odo = drive.make(Rotation2d.kZero, 0.0)
        first = drive.update(deg(10), 1.0)
        assert first == odo.getPose()
        assert (first.getX(), first.getY()) == (odo.getPose().getX(), odo.getPose().getY())
        expected_first = step((0.0, 0.0, 0.0), 1.0, 0.0, math.radians(10))
        second = drive.update(deg(25), 2.5)
        # The pose returned earlier is a value, not a view of the odometry state.
        assert_pose(expected_first, first)
        assert_pose(step(expected_first, 1.5, 0.0, math.radians(15)), second)
        assert second == odo.getPose()

    def test_reset_pose_leaves_baselines_alone(self, drive):
        odo = drive.make(Rotation2d.kZero, 0.0)
        drive.update(deg(30), 5.0)
        assert odo.resetPose(Pose2d(1.0, 1.0, Rotation2d.kZero)) is None
        assert_pose((1.0, 1.0, 0.0), odo.getPose())
        # Deltas are still measured from gyro 30 deg and wheel distance 5.
        pose = drive.update(deg(40), 6.0)
        assert_pose(step((1.0, 1.0, 0.0), 1.0, 0.0, math.radians(10)), pose)

    def test_reset_translation_keeps_heading_and_baselines(self, drive):
        odo = drive.make(Rotation2d.kZero, 0.0)
        drive.update(deg(30), 5.0)
        odo.resetTranslation(Translation2d(-2.0, 3.0))
        assert_pose((-2.0, 3.0, math.radians(30)), odo.getPose())
        assert_pose((-2.0, 3.0, math.radians(30)), drive.update(deg(30), 5.0))
        assert_pose(step((-2.0, 3.0, math.radians(30)), 1.0, 0.0, 0.0),
                    drive.update(deg(30), 6.0))

    def test_reset_rotation_keeps_translation_and_baselines(self, drive):
        # The robotpy-wpimath 2026.2.2 scenario: its C++ ResetRotation composed the offset with
        # the wrong sign, so the next update reported 150 deg. WPILib 2027 (and Java always):
        # the heading stays 90 deg while the gyro does not move.
        odo = drive.make(Rotation2d.kZero, 0.0, Pose2d(0.5, 0.0, Rotation2d.kZero))
        pose = drive.update(deg(30), 0.0)
        assert_pose((0.5, 0.0, math.radians(30)), pose)
        odo.resetRotation(Rotation2d.kCCW_90deg)
        assert_pose((0.5, 0.0, math.pi / 2), odo.getPose())
        pose = drive.update(deg(30), 0.0)
        assert_close(90.0, pose.getRotation().getDegrees())
        assert_pose((0.5, 0.0, math.pi / 2), pose)
        # Further gyro motion is added to the reset heading: 30 -> 40 deg gives 100 deg.
        pose = drive.update(deg(40), 1.0)
        assert_pose(step((0.5, 0.0, math.pi / 2), 1.0, 0.0, math.radians(10)), pose)
        assert_close(100.0, pose.getRotation().getDegrees())

    def test_reset_position_sets_all_three(self, drive):
        odo = drive.make(Rotation2d.kZero, 0.0)
        drive.update(deg(5), 2.0)
        assert drive.reset_position(deg(50), 7.0, Pose2d(3.0, 4.0, deg(-90))) is None
        assert_pose((3.0, 4.0, -math.pi / 2), odo.getPose())
        assert_pose((3.0, 3.0, -math.pi / 2), drive.update(deg(50), 8.0))
        assert_pose((3.0, 3.0, math.radians(-80)), drive.update(deg(60), 8.0))

    def test_many_small_steps_trace_a_circle(self, drive):
        # Drive a full circle of radius 2 in 360 steps: d = 2 * 2pi / 360, dtheta = 1 deg.
        drive.make(Rotation2d.kZero, 0.0)
        n = 360
        pose = None
        for i in range(1, n + 1):
            pose = drive.update(deg(i), 2.0 * 2.0 * math.pi * i / n)
        # Each step is an exact arc, so the circle closes up to rounding.
        assert_pose((0.0, 0.0, 0.0), pose, 1e-9)


class TestDifferentialOdometryEdgeCases:
    def test_heading_comes_from_gyro_not_wheels(self):
        # The wheels say "turning" (left 0, right 1) but the gyro does not move: dtheta = 0.
        odo = DifferentialDriveOdometry(Rotation2d.kZero, 0.0, 0.0)
        assert_pose((0.5, 0.0, 0.0), odo.update(Rotation2d.kZero, 0.0, 1.0))

    def test_distance_baselines(self):
        odo = DifferentialDriveOdometry(Rotation2d.kZero, 10.0, -4.0)
        assert_pose((1.5, 0.0, 0.0), odo.update(Rotation2d.kZero, 11.0, -2.0))


class TestMecanumOdometryEdgeCases:
    def test_heading_comes_from_gyro_not_wheels(self, mecanum_kinematics):
        # Pure rotation signature (the wheels say omega = 1 rad) but the gyro does not move.
        odo = MecanumDriveOdometry(mecanum_kinematics, Rotation2d.kZero,
                                   MecanumDriveWheelPositions())
        pose = odo.update(Rotation2d.kZero, MecanumDriveWheelPositions(-24, 24, -24, 24))
        assert_pose((0.0, 0.0, 0.0), pose)

    def test_strafe(self, mecanum_kinematics):
        # vy = (-fl + fr + rl - rr) / 4 for the +-12 layout.
        odo = MecanumDriveOdometry(mecanum_kinematics, Rotation2d.kZero,
                                   MecanumDriveWheelPositions())
        pose = odo.update(Rotation2d.kZero, MecanumDriveWheelPositions(-2, 2, 2, -2))
        assert_pose((0.0, 2.0, 0.0), pose)

    def test_wheel_positions_are_copied(self, mecanum_kinematics):
        positions = MecanumDriveWheelPositions()
        odo = MecanumDriveOdometry(mecanum_kinematics, Rotation2d.kZero, positions)
        positions.frontLeft = positions.frontRight = positions.rearLeft = 1.0
        positions.rearRight = 1.0
        assert_pose((1.0, 0.0, 0.0), odo.update(Rotation2d.kZero, positions))
        for name in ("frontLeft", "frontRight", "rearLeft", "rearRight"):
            setattr(positions, name, getattr(positions, name) + 2.0)
        assert_pose((3.0, 0.0, 0.0), odo.update(Rotation2d.kZero, positions))
        # resetPosition copies too.
        odo.resetPosition(Rotation2d.kZero, positions, Pose2d.kZero)
        positions.frontLeft = positions.frontRight = positions.rearLeft = 4.0
        positions.rearRight = 4.0
        assert_pose((1.0, 0.0, 0.0), odo.update(Rotation2d.kZero, positions))


class TestSwerveOdometryEdgeCases:
    def test_uses_end_module_angle(self):
        # Distances change by 1 m while the modules turn from 0 to 90 deg: the delta is taken
        # at the end angle, so the robot moves left, not forward.
        kin = SwerveDriveKinematics(FL, FR, BL, BR)
        odo = SwerveDriveOdometry(kin, Rotation2d.kZero, zeros4())
        pose = odo.update(Rotation2d.kZero,
                          [SwerveModulePosition(1.0, Rotation2d.kCCW_Pi_2) for _ in range(4)])
        assert_pose((0.0, 1.0, 0.0), pose)

    def test_module_positions_are_copied(self):
        kin = SwerveDriveKinematics(FL, FR, BL, BR)
        modules = zeros4()
        odo = SwerveDriveOdometry(kin, Rotation2d.kZero, modules)
        for m in modules:
            m.distance = 1.0
        assert_pose((1.0, 0.0, 0.0), odo.update(Rotation2d.kZero, modules))
        for m in modules:
            m.distance += 0.5
        assert_pose((1.5, 0.0, 0.0), odo.update(Rotation2d.kZero, modules))

    @pytest.mark.parametrize("count", [3, 5])
    def test_wrong_module_count_rejected(self, count):
        kin = SwerveDriveKinematics(FL, FR, BL, BR)
        wrong = [SwerveModulePosition(1.0) for _ in range(count)]
        with pytest.raises(ValueError, match="4"):
            SwerveDriveOdometry(kin, Rotation2d.kZero, wrong)
        odo = SwerveDriveOdometry(kin, Rotation2d.kZero, zeros4())
        with pytest.raises(ValueError, match="4"):
            odo.update(Rotation2d.kZero, wrong)
        with pytest.raises(ValueError, match="4"):
            odo.resetPosition(Rotation2d.kZero, wrong, Pose2d(5.0, 5.0, Rotation2d.kZero))
        # The failed calls changed nothing: pose, gyro and wheel baselines intact.
        assert_pose((0.0, 0.0, 0.0), odo.getPose())
        pose = odo.update(deg(10), [SwerveModulePosition(1.0) for _ in range(4)])
        assert_pose(step((0.0, 0.0, 0.0), 1.0, 0.0, math.radians(10)), pose)

    def test_numpy_form_matches_objects(self):
        rng = np.random.default_rng(2027)
        kin_a = SwerveDriveKinematics(FL, FR, BL, BR)
        kin_b = SwerveDriveKinematics(FL, FR, BL, BR)
        start = np.column_stack([rng.uniform(-1, 1, 4), rng.uniform(-math.pi, math.pi, 4)])

        def objects(arr):
            return [SwerveModulePosition(d, Rotation2d(a)) for d, a in arr]

        initial = Pose2d(1.0, -2.0, deg(33))
        odo_obj = SwerveDriveOdometry(kin_a, deg(5), objects(start), initial)
        odo_arr = SwerveDriveOdometry(kin_b, deg(5), np.ascontiguousarray(start), initial)
        current = start.copy()
        gyro = 5.0
        for i in range(50):
            current[:, 0] += rng.uniform(-0.05, 0.1, 4)
            current[:, 1] = rng.uniform(-math.pi, math.pi, 4)
            gyro += rng.uniform(-7, 7)
            a = odo_obj.update(deg(gyro), objects(current))
            b = odo_arr.update(deg(gyro), current)
            assert_pose((a.getX(), a.getY(), a.getRotation().getRadians()), b)
            if i == 25:
                reset = Pose2d(-3.0, 0.5, deg(-120))
                odo_obj.resetPosition(deg(gyro), objects(current), reset)
                odo_arr.resetPosition(deg(gyro), current, reset)
        assert odo_obj.getPose() == odo_arr.getPose()

    def test_numpy_form_closed_form(self):
        kin = SwerveDriveKinematics(FL, FR, BL, BR)
        odo = SwerveDriveOdometry(kin, Rotation2d.kZero, np.zeros((4, 2)))
        arr = np.array([[1.0, math.pi / 2]] * 4)
        assert_pose((0.0, 1.0, 0.0), odo.update(Rotation2d.kZero, arr))

    @pytest.mark.parametrize("modules", [
        (Translation2d(1, 0), Translation2d(-1, 0)),
        (Translation2d(1, 1), Translation2d(1, -1), Translation2d(-1, 0)),
        (FL, FR, BL, BR, Translation2d(0, 20), Translation2d(0, -20)),
    ])
    def test_any_module_count(self, modules):
        n = len(modules)
        kin = SwerveDriveKinematics(*modules)
        odo = SwerveDriveOdometry(kin, Rotation2d.kZero, [SwerveModulePosition()] * n)
        pose = odo.update(deg(45), [SwerveModulePosition(2.0, Rotation2d.kZero)] * n)
        assert_pose(step((0.0, 0.0, 0.0), 2.0, 0.0, math.pi / 4), pose)
        with pytest.raises(ValueError):
            odo.update(deg(45), [SwerveModulePosition()] * (n + 1))
