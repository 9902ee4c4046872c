"""WPILib's 3-D pose-estimator unit tests restated for drivekin, with WPILib's own numbers and
tolerances (allwpilib main caf0fb2d, wpimath/src/test/java/org/wpilib/math/estimator/:
SwerveDrivePoseEstimator3dTest.java, MecanumDrivePoseEstimator3dTest.java,
DifferentialDrivePoseEstimator3dTest.java), and the 3-D odometry tests
(wpimath/src/test/java/org/wpilib/math/kinematics/*DriveOdometry3dTest.java) that need no
trajectory.

The trajectory tests are the 2-D ones (``test_estimator_wpilib.py``) run through the 3-D
estimators: Java's 3-D tests lift every 2-D quantity with ``new Rotation3d(Rotation2d)`` and
``new Pose3d(Pose2d)`` and read the estimate back through ``toRotation2d``, which is what
:class:`Lifted` does around the same simulation, random draws and tolerances. The
deterministic tests run on the 2-D file's drivetrain kits, whose update calls take any gyro
type, with the 3-D estimators built as Java's tests build them; the two dead-wheel
estimators (drivekin's, following the 2-D ones) run them too.
"""
import math

import pytest

from drivekin import (
    DeadWheelPoseEstimator3d,
    DifferentialDriveKinematics,
    DifferentialDriveOdometry3d,
    DifferentialDrivePoseEstimator3d,
    MecanumDriveKinematics,
    MecanumDriveOdometry3d,
    MecanumDrivePoseEstimator3d,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry3d,
    SwerveDrivePoseEstimator3d,
    SwerveModulePosition,
    Translation2d,
    TwoDeadWheelPoseEstimator3d,
)
from drivekin.deadwheel import DeadWheelKinematics
from drivekin.geometry3d import Pose3d, Rotation3d, Translation3d
from tests._support.wpilib_port import EPS, WHEELS, assert_close
from tests.reference import test_estimator_wpilib as base

R3 = Rotation3d


class Lifted:
    """A 3-D estimator driven with the 2-D test's quantities, lifted as Java's 3-D tests
    lift them; the estimate is read back as its Pose2d (x, y, Rotation2d(yaw))."""

    def __init__(self, estimator):
        self.e = estimator

    def resetPosition(self, gyro, *args):
        *readings, pose = args
        self.e.resetPosition(R3(gyro), *readings, Pose3d(pose))

    def updateWithTime(self, t, gyro, *readings):
        return self.e.updateWithTime(t, R3(gyro), *readings).toPose2d()

    def addVisionMeasurement(self, pose, t):
        self.e.addVisionMeasurement(Pose3d(pose), t)

    def getEstimatedPosition(self):
        return self.e.getEstimatedPosition().toPose2d()


def make_swerve(vision):
    kinematics = base.swerve_kinematics()
    return base.Swerve(Lifted(SwerveDrivePoseEstimator3d(
        kinematics, R3(), base.zeros4(), Pose3d(), (0.1,) * 4, vision)), kinematics)


def make_mecanum():
    kinematics = MecanumDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                        Translation2d(-1, -1), Translation2d(-1, 1))
    return base.Mecanum(Lifted(MecanumDrivePoseEstimator3d(
        kinematics, R3(), MecanumDriveWheelPositions(), Pose3d(), (0.1,) * 4,
        (0.45, 0.45, 0.45, 0.1))), kinematics)


def make_differential():
    return base.Differential(Lifted(DifferentialDrivePoseEstimator3d(
        R3(), 0.0, 0.0, Pose3d(), (0.02, 0.02, 0.02, 0.01), (0.1,) * 4)),
        DifferentialDriveKinematics(1.0))


class TestFollowTrajectory:
    # testAccuracy[FacingTrajectory] and testBadInitialPose: java.util.Random(3538), vision
    # every 0.1 s delivered 0.25 s late (swerve's bad-pose test: 1.0 s late).
    def test_swerve_accuracy_facing_trajectory(self):
        traj = base.trajectory()
        base.follow_trajectory(make_swerve((0.5,) * 4), traj, base.ours(traj.initialPose()),
                               0.02, 0.1, 0.25, True)

    def test_swerve_bad_initial_pose(self):
        traj = base.trajectory()
        drive = make_swerve((0.9,) * 4)
        for pose in base.bad_initial_poses(traj):
            base.follow_trajectory(drive, traj, pose, 0.02, 0.1, 1.0, False)

    def test_mecanum_accuracy_facing_trajectory(self):
        traj = base.trajectory()
        base.follow_trajectory(make_mecanum(), traj, base.ours(traj.initialPose()),
                               0.02, 0.1, 0.25, True)

    def test_mecanum_bad_initial_pose(self):
        traj = base.trajectory()
        drive = make_mecanum()
        for pose in base.bad_initial_poses(traj):
            base.follow_trajectory(drive, traj, pose, 0.02, 0.1, 0.25, False)

    def test_differential_accuracy(self):
        traj = base.trajectory()
        base.follow_trajectory(make_differential(), traj, base.ours(traj.initialPose()),
                               0.02, 0.1, 0.25, True)

    def test_differential_bad_initial_pose(self):
        traj = base.trajectory()
        drive = make_differential()
        for pose in base.bad_initial_poses(traj):
            base.follow_trajectory(drive, traj, pose, 0.02, 0.1, 0.25, False)


# ---- the deterministic tests, one set per drivetrain ------------------------------------------
# The 2-D kits feed "every wheel has travelled d m, gyro g" in each drivetrain's terms; only
# the constructors differ.


class SwerveKit(base.SwerveKit):
    @classmethod
    def make(cls, pose, state, vision):
        return SwerveDrivePoseEstimator3d(cls.kinematics(), R3(), base.zeros4(), pose, state,
                                          vision)

    @staticmethod
    def make_simultaneous(pose):
        return SwerveDrivePoseEstimator3d(base.swerve_kinematics(), R3(), base.zeros4(), pose,
                                          (0.1,) * 4, (0.9,) * 4)


class MecanumKit(base.MecanumKit):
    @staticmethod
    def make(pose, state, vision):
        kinematics = MecanumDriveKinematics(Translation2d(1, 1), Translation2d(-1, 1),
                                            Translation2d(1, -1), Translation2d(-1, -1))
        return MecanumDrivePoseEstimator3d(kinematics, R3(), MecanumDriveWheelPositions(),
                                           pose, state, vision)

    @staticmethod
    def make_simultaneous(pose):
        kinematics = MecanumDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                            Translation2d(-1, -1), Translation2d(-1, 1))
        return MecanumDrivePoseEstimator3d(kinematics, R3(), MecanumDriveWheelPositions(),
                                           pose, (0.1,) * 4, (0.45, 0.45, 0.45, 0.1))


class DifferentialKit(base.DifferentialKit):
    @staticmethod
    def make(pose, state, vision):
        return DifferentialDrivePoseEstimator3d(R3(), 0.0, 0.0, pose, state, vision)

    @classmethod
    def make_simultaneous(cls, pose):
        return cls.make(pose, (0.02, 0.02, 0.02, 0.01), (0.1,) * 4)


class TwoDeadWheelKit(base.TwoDeadWheelKit):
    """Offsets 1 m, the forward wheel at d, the lateral one at 0 (the 2-D kit's)."""

    @staticmethod
    def make(pose, state, vision):
        return TwoDeadWheelPoseEstimator3d(1.0, 1.0, 0.0, 0.0, R3(), pose, state, vision)

    @staticmethod
    def make_simultaneous(pose):
        return TwoDeadWheelPoseEstimator3d(1.0, 1.0, 0.0, 0.0, R3(), pose)


class DeadWheelKit:
    """Two forward wheels at y = ±0.5 m and a lateral one: "every wheel d" moves the
    forward ones d and the lateral one 0, which is forward motion."""

    name = "deadwheel"
    LAYOUT = [Pose2d(0, 0.5, Rotation2d()), Pose2d(0, -0.5, Rotation2d()),
              Pose2d(0.2, 0, Rotation2d.kCCW_Pi_2)]

    @classmethod
    def make(cls, pose, state, vision):
        return DeadWheelPoseEstimator3d(DeadWheelKinematics(cls.LAYOUT), [0.0] * 3, R3(), pose,
                                        state, vision)

    @classmethod
    def make_simultaneous(cls, pose):
        return cls.make(pose, (0.1,) * 4, (0.9,) * 4)

    @staticmethod
    def update_with_time(e, t, gyro, d):
        return e.updateWithTime(t, [d, d, 0.0], gyro)

    @staticmethod
    def update(e, gyro, d):
        return e.update([d, d, 0.0], gyro)

    @staticmethod
    def reset_position(e, gyro, d, pose):
        e.resetPosition([d, d, 0.0], gyro, pose)


@pytest.fixture(params=[SwerveKit, MecanumKit, DifferentialKit, TwoDeadWheelKit, DeadWheelKit],
                ids=lambda k: k.name)
def kit(request):
    return request.param


def assert_estimate(e, x, y, z, roll, pitch, yaw):
    """Java's assertAll of getX/Y/Z and getRotation().getX/Y/Z within kEpsilon."""
    p = e.getEstimatedPosition()
    r = p.getRotation()
    for want, got in ((x, p.getX()), (y, p.getY()), (z, p.getZ()), (roll, r.getX()),
                      (pitch, r.getY()), (yaw, r.getZ())):
        assert_close(want, got, EPS)


def assert_sample(expected, actual):
    """Java's assertEquals(Optional.of(pose), estimator.sampleAt(t)): Pose3d.equals."""
    assert actual is not None
    assert actual == expected, f"{actual} != {expected}"


def test_simultaneous_vision_measurements(kit):
    # Every measurement stamped at the same time must count: were only one applied, 1000
    # rounds would converge onto it.
    e = kit.make_simultaneous(Pose3d(1, 2, 0, R3(0, 0, -math.pi / 2)))
    kit.update_with_time(e, 0.0, R3(), 0.0)
    measurements = [Pose2d(0, 0, Rotation2d.kZero), Pose2d(3, 1, Rotation2d.kCCW_Pi_2),
                    Pose2d(2, 4, Rotation2d.kPi)]
    for _ in range(1000):
        for m in measurements:
            e.addVisionMeasurement(Pose3d(m), 0.0)
    est = e.getEstimatedPosition()
    for m in measurements:
        dx = abs(m.getX() - est.getX())
        dy = abs(m.getY() - est.getY())
        dtheta = abs(m.getRotation().getDegrees() - est.getRotation().toRotation2d().getDegrees())
        assert dx > 0.08 or dy > 0.08 or dtheta > 0.08, (
            f"Estimator converged to one vision measurement: {est} -> {m}")


def test_discards_old_vision_measurements(kit):
    # testDiscardsOldVisionMeasurements (swerve, mecanum), testDiscardsStaleVisionMeasurements
    # (differential): a measurement made 3 s before the newest sample changes nothing.
    e = kit.make(Pose3d(), (0.1,) * 4, (0.9,) * 4)
    time = 0.0
    while time < 4:  # fill the buffer
        kit.update_with_time(e, time, R3(), 0.0)
        time += 0.02
    before = e.getEstimatedPosition()
    e.addVisionMeasurement(Pose3d(10, 10, 0, R3(0, 0, 0.1)), 1.0, (0.1,) * 4)
    after = e.getEstimatedPosition()
    assert (after.getX(), after.getY(), after.getZ()) == (before.getX(), before.getY(),
                                                          before.getZ())
    assert ((after.getRotation().getX(), after.getRotation().getY(), after.getRotation().getZ())
            == (before.getRotation().getX(), before.getRotation().getY(),
                before.getRotation().getZ()))


def test_sample_at(kit):
    e = kit.make(Pose3d(), (1,) * 4, (1,) * 4)
    assert e.sampleAt(1) is None  # empty before the first update

    time = 1.0
    while time <= 2 + 1e-9:  # Java's loop, with its tolerance for rounding of the sum
        kit.update_with_time(e, time, R3(), time)
        time += 0.02

    assert_sample(Pose3d(1.02, 0, 0, R3()), e.sampleAt(1.02))  # an added time
    assert_sample(Pose3d(1.01, 0, 0, R3()), e.sampleAt(1.01))  # interpolated
    assert_sample(Pose3d(1, 0, 0, R3()), e.sampleAt(0.5))  # before the oldest
    assert_sample(Pose3d(2, 0, 0, R3()), e.sampleAt(2.5))  # after the newest

    # A measurement after the newest sample changes none of the samples before it.
    e.addVisionMeasurement(Pose3d(2, 0, 0, R3(0, 0, 1)), 2.2)
    assert_sample(Pose3d(1.02, 0, 0, R3()), e.sampleAt(1.02))
    assert_sample(Pose3d(1.01, 0, 0, R3()), e.sampleAt(1.01))
    assert_sample(Pose3d(1, 0, 0, R3()), e.sampleAt(0.5))

    # One before the oldest sample, still within 1.5 s: y is halfway to 0.2 everywhere.
    e.addVisionMeasurement(Pose3d(1, 0.2, 0, R3()), 0.9)
    assert_sample(Pose3d(1.02, 0.1, 0, R3()), e.sampleAt(1.02))
    assert_sample(Pose3d(1.01, 0.1, 0, R3()), e.sampleAt(1.01))
    assert_sample(Pose3d(1, 0.1, 0, R3()), e.sampleAt(0.5))
    assert_sample(Pose3d(2, 0.1, 0, R3()), e.sampleAt(2.5))


def test_reset(kit):
    # Java's testReset stamps its vision measurements with MathSharedStore.getTimestamp(),
    # as update() does: a frozen clock keeps the two on the same time.
    from drivekin import MathSharedStore
    MathSharedStore.setTimestampSource(lambda: 5.0)
    try:
        e = kit.make(Pose3d(), (1,) * 4, (1,) * 4)

        kit.reset_position(e, R3(), 1.0, Pose3d(1, 0, 0, R3()))
        assert_estimate(e, 1, 0, 0, 0, 0, 0)

        kit.update(e, R3(), 2.0)  # orientation and wheel positions
        assert_estimate(e, 2, 0, 0, 0, 0, 0)

        e.addVisionMeasurement(Pose3d(3, 0, 0, R3()), MathSharedStore.getTimestamp())
        assert_estimate(e, 2.5, 0, 0, 0, 0, 0)  # a different translation

        e.resetRotation(R3(Rotation2d.kCCW_Pi_2))
        assert_estimate(e, 2.5, 0, 0, 0, 0, math.pi / 2)

        kit.update(e, R3(), 3.0)  # forward is now +y
        assert_estimate(e, 2.5, 1, 0, 0, 0, math.pi / 2)

        e.addVisionMeasurement(Pose3d(2.5, 1, 0, R3(Rotation2d.kPi)),
                               MathSharedStore.getTimestamp())
        assert_estimate(e, 2.5, 1, 0, 0, 0, math.pi * 3 / 4)  # a different rotation

        e.resetTranslation(Translation3d(-1, -1, -1))
        assert_estimate(e, -1, -1, -1, 0, 0, math.pi * 3 / 4)

        e.resetPose(Pose3d())
        assert_estimate(e, 0, 0, 0, 0, 0, 0)
    finally:
        MathSharedStore.setTimestampSource(None)


# ---- the odometry tests without a trajectory --------------------------------------------------

def swerve_odometry(pose=None):
    zero = SwerveModulePosition()
    return SwerveDriveOdometry3d(SwerveDriveKinematics(*WHEELS), R3(), [zero] * 4, pose)


def mecanum_odometry(pose=None):
    return MecanumDriveOdometry3d(MecanumDriveKinematics(*WHEELS), R3(),
                                  MecanumDriveWheelPositions(), pose)


def differential_odometry(pose=None):
    return DifferentialDriveOdometry3d(R3(), 0.0, 0.0, pose)


def assert_planar(pose, x, y, degrees, tol):
    assert_close(x, pose.getX(), tol)
    assert_close(y, pose.getY(), tol)
    assert_close(0.0, pose.getZ(), tol)
    assert_close(degrees, pose.getRotation().toRotation2d().getDegrees(), tol)


@pytest.mark.parametrize("make", [swerve_odometry, mecanum_odometry, differential_odometry])
def test_odometry_initialize(make):
    pose = make(Pose3d(1, 2, 0, R3(0, 0, math.radians(45)))).getPose()
    assert_planar(pose, 1.0, 2.0, 45.0, EPS)


def test_swerve_odometry_two_iterations_and_90_degree_turn():
    odo = swerve_odometry()
    zero = [SwerveModulePosition()] * 4
    odo.update(R3(), zero)
    pose = odo.update(R3(), [SwerveModulePosition(0.5, Rotation2d.kZero)] * 4)
    assert_planar(pose, 0.5, 0.0, 0.0, 0.01)

    # A 90° turn about the point between the left modules.
    odo = swerve_odometry()
    odo.update(R3(), zero)
    pose = odo.update(R3(0, 0, math.pi / 2), [
        SwerveModulePosition(18.85, Rotation2d.kCCW_Pi_2),
        SwerveModulePosition(42.15, Rotation2d.fromDegrees(26.565)),
        SwerveModulePosition(18.85, Rotation2d.kCW_Pi_2),
        SwerveModulePosition(42.15, Rotation2d.fromDegrees(-26.565))])
    assert_planar(pose, 12.0, 12.0, 90.0, 0.01)


def test_mecanum_odometry_iterations_and_90_degree_turn():
    odo = mecanum_odometry()
    w = MecanumDriveWheelPositions(3.536, 3.536, 3.536, 3.536)
    odo.resetPosition(R3(), w, Pose3d())
    odo.update(R3(), w)
    assert_planar(odo.update(R3(), w), 0.0, 0.0, 0.0, 0.01)  # testMultipleConsecutiveUpdates

    odo.resetPosition(R3(), MecanumDriveWheelPositions(), Pose3d())
    odo.update(R3(), MecanumDriveWheelPositions())
    pose = odo.update(R3(), MecanumDriveWheelPositions(0.3536, 0.3536, 0.3536, 0.3536))
    assert_planar(pose, 0.3536, 0.0, 0.0, 0.01)  # testTwoIterations

    odo.resetPosition(R3(), MecanumDriveWheelPositions(), Pose3d())
    odo.update(R3(), MecanumDriveWheelPositions())
    pose = odo.update(R3(0, 0, math.pi / 2),
                      MecanumDriveWheelPositions(-13.328, 39.986, -13.329, 39.986))
    assert_planar(pose, 8.4855, 8.4855, 90.0, 0.01)  # test90degreeTurn


@pytest.mark.parametrize("odometry, zero, forward, x", [
    (swerve_odometry, [SwerveModulePosition()] * 4,
     [SwerveModulePosition(1.0, Rotation2d.kZero)] * 4, 1.0),
    (mecanum_odometry, MecanumDriveWheelPositions(),
     MecanumDriveWheelPositions(3.536, 3.536, 3.536, 3.536), 3.536),
], ids=["swerve", "mecanum"])
def test_odometry_gyro_angle_reset(odometry, zero, forward, x):
    # The gyro reads 90° at the reset to a 0° field pose: forward stays +x.
    odo = odometry()
    gyro = R3(0, 0, math.pi / 2)
    odo.resetPosition(gyro, zero, Pose3d(Translation3d(), R3()))
    odo.update(gyro, zero)
    pose = odo.update(gyro, forward)
    assert_close(x, pose.getX(), 0.1)
    assert_close(0.0, pose.getY(), 0.1)
    assert_close(0.0, pose.getZ(), 0.1)
    assert_close(0.0, pose.getRotation().toRotation2d().getRadians(), 0.1)


def test_differential_odometry_with_encoder_distances():
    odo = differential_odometry()
    odo.resetPosition(R3(0, 0, math.radians(45)), 0, 0, Pose3d())
    pose = odo.update(R3(0, 0, math.radians(135)), 0.0, 5 * math.pi)
    assert_planar(pose, 5.0, 5.0, 90.0, EPS)


@pytest.mark.parametrize("odometry, zero", [
    (swerve_odometry, ([SwerveModulePosition()] * 4,)),
    (mecanum_odometry, (MecanumDriveWheelPositions(),)),
    (differential_odometry, (0.0, 0.0)),
], ids=["swerve", "mecanum", "differential"])
def test_odometry_gyro_offset(odometry, zero):
    # The gyro pitches 5° -> 10° while the pose faces 90°: the pose pitches 5° about its own
    # axis, and its Euler angles are (0, 5°, 90°).
    odo = odometry()
    odo.resetPosition(R3(0, math.radians(5), 0), *zero, Pose3d(Translation3d(),
                                                              R3(0, 0, math.radians(90))))
    pose = odo.update(R3(0, math.radians(10), 0), *zero)
    for want, got in ((0.0, pose.getX()), (0.0, pose.getY()), (0.0, pose.getZ()),
                      (0.0, pose.getRotation().getX()),
                      (math.radians(5), pose.getRotation().getY()),
                      (math.radians(90), pose.getRotation().getZ())):
        assert_close(want, got, EPS)
