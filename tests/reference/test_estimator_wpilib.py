"""WPILib's pose-estimator unit tests restated for drivekin, with WPILib's own numbers and
tolerances (allwpilib main, wpimath/src/test/java/org/wpilib/math/estimator/:
SwerveDrivePoseEstimatorTest.java and DifferentialDrivePoseEstimatorTest.java at
59687938, MecanumDrivePoseEstimatorTest.java at d8144b8a, TwoDeadWheelPoseEstimatorTest.java
at eaf4f0c3).

Differences of form, not of numbers:
- 2027's ``SplineSample.velocity`` is a robot-relative ChassisSpeeds; robotpy 2026's
  trajectory state (the generator used here, ``wpilib_port.trajectory_generator``) carries
  speed and curvature, so the chassis velocity is (v, 0, v·curvature), as the older
  Mecanum test writes it.
- 2027's DifferentialDrivePoseEstimator takes no kinematics; the test's kinematics
  (trackwidth 1 m) only turns the chassis velocity into wheel speeds.
- Upstream's TwoDeadWheelPoseEstimator (after PR #9155) takes a TwoDeadWheelPositions and the
  gyro first; drivekin keeps PR #9155's signature (xWheelYPos, yWheelXPos, xWheelPos,
  yWheelPos, gyroAngle, initialPose, …), so the calls are reordered, the readings unchanged.
- Java's Optional<Pose2d> equality is Pose2d.equals (1e-9 on translation and rotation).
"""
import math

import pytest

from drivekin import (
    ChassisVelocities,
    DifferentialDriveKinematics,
    DifferentialDrivePoseEstimator,
    MecanumDriveKinematics,
    MecanumDrivePoseEstimator,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDrivePoseEstimator,
    SwerveModulePosition,
    Transform2d,
    Translation2d,
    TwoDeadWheelPoseEstimator,
)
from tests._support.wpilib_port import EPS, JavaRandom, assert_close, trajectory_generator

R = Rotation2d

# The trajectory every follow test drives: max 2 m/s, 2 m/s².
WAYPOINTS = [(0, 0, math.radians(45)), (3, 0, -math.pi / 2), (0, 0, math.radians(135)),
             (-3, 0, -math.pi / 2), (0, 0, math.radians(45))]
ENDING_POSE = Pose2d(0, 0, Rotation2d.fromDegrees(45))


def ours(p):
    """A robotpy Pose2d as a drivekin Pose2d."""
    return Pose2d(p.X(), p.Y(), R(p.rotation().radians()))


def assert_pose_equals(expected, actual):
    """Java's assertEquals(Optional.of(pose), estimator.sampleAt(t))."""
    assert actual is not None
    assert_close(expected.getX(), actual.getX())
    assert_close(expected.getY(), actual.getY())
    assert_close(0.0, actual.getRotation().minus(expected.getRotation()).getRadians())


def assert_estimate(estimator, x, y, theta):
    pose = estimator.getEstimatedPosition()
    assert_close(x, pose.getX(), EPS)
    assert_close(y, pose.getY(), EPS)
    assert_close(theta, pose.getRotation().getRadians(), EPS)


# ---- the drivetrains behind one interface --------------------------------------------------
# Each adapter owns its simulated wheel readings; ``advance(velocities, rand, dt)`` moves them
# along the chassis velocity (drawing the test's wheel noise, if any, from ``rand`` in Java's
# order) and ``update(t, gyro)`` / ``reset(gyro, pose)`` feed them to the estimator.


def swerve_kinematics():
    return SwerveDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                 Translation2d(-1, -1), Translation2d(-1, 1))


def zeros4():
    return [SwerveModulePosition() for _ in range(4)]


class Swerve:
    def __init__(self, estimator, kinematics):
        self.estimator, self.kinematics = estimator, kinematics
        self.positions = zeros4()

    def reset(self, gyro, pose):
        self.positions = zeros4()
        self.estimator.resetPosition(gyro, self.positions, pose)

    def advance(self, velocities, rand, dt):
        states = self.kinematics.toSwerveModuleVelocities(velocities)
        for p, s in zip(self.positions, states):
            # Java: distance += speed * (1 - N·0.05) * dt, then angle = angle + N·0.005.
            p.distance += s.velocity * (1 - rand.next_gaussian() * 0.05) * dt
            p.angle = s.angle.plus(R(rand.next_gaussian() * 0.005))

    def update(self, t, gyro):
        return self.estimator.updateWithTime(t, gyro, self.positions)


class Mecanum:
    def __init__(self, estimator, kinematics):
        self.estimator, self.kinematics = estimator, kinematics
        self.positions = MecanumDriveWheelPositions()

    def reset(self, gyro, pose):
        self.positions = MecanumDriveWheelPositions()
        self.estimator.resetPosition(gyro, self.positions, pose)

    def advance(self, velocities, rand, dt):
        w = self.kinematics.toWheelVelocities(velocities)
        self.positions.frontLeft += w.frontLeft * dt
        self.positions.frontRight += w.frontRight * dt
        self.positions.rearLeft += w.rearLeft * dt
        self.positions.rearRight += w.rearRight * dt

    def update(self, t, gyro):
        return self.estimator.updateWithTime(t, gyro, self.positions)


class Differential:
    def __init__(self, estimator, kinematics):
        self.estimator, self.kinematics = estimator, kinematics
        self.left = self.right = 0.0

    def reset(self, gyro, pose):
        self.left = self.right = 0.0
        self.estimator.resetPosition(gyro, self.left, self.right, pose)

    def advance(self, velocities, rand, dt):
        w = self.kinematics.toWheelVelocities(velocities)
        self.left += w.left * dt
        self.right += w.right * dt

    def update(self, t, gyro):
        return self.estimator.updateWithTime(t, gyro, self.left, self.right)


def follow_trajectory(drive, trajectory, starting_pose, dt, vision_update_rate,
                      vision_update_delay, check_error):
    """testFollowTrajectory: vision measurements of the true pose plus noise
    (N·0.1, N·0.1, N·0.05 rad in the robot frame) taken every ``vision_update_rate`` s and
    delivered ``vision_update_delay`` s late, wheels driven along the true chassis velocity,
    gyro = true heading + N·0.05 − the trajectory's initial heading. java.util.Random(3538)."""
    drive.reset(Rotation2d.kZero, starting_pose)
    rand = JavaRandom(3538)
    start_rotation = ours(trajectory.initialPose()).getRotation()
    queue = {}  # Java's TreeMap<Double, Pose2d>: keys are inserted in increasing order
    t = 0.0
    max_error, error_sum = -math.inf, 0.0
    duration = trajectory.totalTime()
    while t <= duration:
        truth = trajectory.sample(t)
        true_pose = ours(truth.pose)
        if not queue or max(queue) + vision_update_rate < t:
            queue[t] = true_pose.plus(Transform2d(
                Translation2d(rand.next_gaussian() * 0.1, rand.next_gaussian() * 0.1),
                R(rand.next_gaussian() * 0.05)))
        if queue and min(queue) + vision_update_delay < t:
            key = min(queue)
            drive.estimator.addVisionMeasurement(queue.pop(key), key)

        drive.advance(ChassisVelocities(truth.velocity, 0.0, truth.velocity * truth.curvature),
                      rand, dt)
        gyro = true_pose.getRotation().plus(R(rand.next_gaussian() * 0.05)).minus(
            start_rotation)
        x_hat = drive.update(t, gyro)

        error = true_pose.getTranslation().getDistance(x_hat.getTranslation())
        max_error = max(max_error, error)
        error_sum += error
        t += dt

    final = drive.estimator.getEstimatedPosition()
    assert_close(ENDING_POSE.getX(), final.getX(), 0.08)  # "Incorrect Final X"
    assert_close(ENDING_POSE.getY(), final.getY(), 0.08)  # "Incorrect Final Y"
    assert_close(ENDING_POSE.getRotation().getRadians(), final.getRotation().getRadians(),
                 0.15)  # "Incorrect Final Theta"
    if check_error:
        assert_close(0.0, error_sum / (duration / dt), 0.07)  # "Incorrect mean error"
        assert_close(0.0, max_error, 0.2)  # "Incorrect max error"


def trajectory():
    return trajectory_generator()(WAYPOINTS, 2.0, 2.0)


def bad_initial_poses(trajectory):
    """The 64 starting poses of testBadInitialPose: the true start moved 1 m in each of 8
    directions and turned by each of 8 headings (multiples of 45°)."""
    start = ours(trajectory.initialPose())
    for direction in range(0, 360, 45):
        for heading in range(0, 360, 45):
            d = Rotation2d.fromDegrees(direction)
            yield start.plus(Transform2d(Translation2d(d.getCos(), d.getSin()),
                                         Rotation2d.fromDegrees(heading)))


def make_swerve(vision):
    kinematics = swerve_kinematics()
    return Swerve(SwerveDrivePoseEstimator(kinematics, Rotation2d.kZero, zeros4(), Pose2d.kZero,
                                           (0.1, 0.1, 0.1), vision), kinematics)


def make_mecanum():
    kinematics = MecanumDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                        Translation2d(-1, -1), Translation2d(-1, 1))
    return Mecanum(MecanumDrivePoseEstimator(kinematics, Rotation2d.kZero,
                                             MecanumDriveWheelPositions(), Pose2d.kZero,
                                             (0.1, 0.1, 0.1), (0.45, 0.45, 0.1)), kinematics)


def make_differential():
    return Differential(DifferentialDrivePoseEstimator(Rotation2d.kZero, 0.0, 0.0, Pose2d.kZero,
                                                       (0.02, 0.02, 0.01), (0.1, 0.1, 0.1)),
                        DifferentialDriveKinematics(1.0))


# ---- the trajectory-following tests -----------------------------------------------------------


class TestFollowTrajectory:
    def test_swerve_accuracy_facing_trajectory(self):
        traj = trajectory()
        follow_trajectory(make_swerve((0.5, 0.5, 0.5)), traj, ours(traj.initialPose()),
                          0.02, 0.1, 0.25, True)

    def test_swerve_bad_initial_pose(self):
        traj = trajectory()
        drive = make_swerve((0.9, 0.9, 0.9))
        for pose in bad_initial_poses(traj):
            follow_trajectory(drive, traj, pose, 0.02, 0.1, 1.0, False)

    def test_mecanum_accuracy_facing_trajectory(self):
        traj = trajectory()
        follow_trajectory(make_mecanum(), traj, ours(traj.initialPose()), 0.02, 0.1, 0.25, True)

    def test_mecanum_bad_initial_pose(self):
        traj = trajectory()
        drive = make_mecanum()
        for pose in bad_initial_poses(traj):
            follow_trajectory(drive, traj, pose, 0.02, 0.1, 0.25, False)

    def test_differential_accuracy(self):
        traj = trajectory()
        follow_trajectory(make_differential(), traj, ours(traj.initialPose()),
                          0.02, 0.1, 0.25, True)

    def test_differential_bad_initial_pose(self):
        traj = trajectory()
        drive = make_differential()
        for pose in bad_initial_poses(traj):
            follow_trajectory(drive, traj, pose, 0.02, 0.1, 0.25, False)


# ---- the deterministic tests, one set per drivetrain ------------------------------------------
# Each ``Kit`` builds the test's estimator and feeds it "every wheel has travelled d m, gyro g"
# in its drivetrain's terms (pure forward motion in the robot frame).


class SwerveKit:
    name = "swerve"

    @staticmethod
    def kinematics():
        # testDiscardsOldVisionMeasurements/testSampleAt/testReset list the modules in this
        # order (FL, BL, FR, BR); with every module alike it does not change the numbers.
        return SwerveDriveKinematics(Translation2d(1, 1), Translation2d(-1, 1),
                                     Translation2d(1, -1), Translation2d(-1, -1))

    @classmethod
    def make(cls, pose, state, vision):
        return SwerveDrivePoseEstimator(cls.kinematics(), Rotation2d.kZero, zeros4(), pose,
                                        state, vision)

    @staticmethod
    def make_simultaneous(pose):
        return SwerveDrivePoseEstimator(swerve_kinematics(), Rotation2d.kZero, zeros4(), pose,
                                        (0.1, 0.1, 0.1), (0.9, 0.9, 0.9))

    @staticmethod
    def wheels(d):
        return [SwerveModulePosition(d, Rotation2d.kZero) for _ in range(4)]

    @classmethod
    def update_with_time(cls, e, t, gyro, d):
        return e.updateWithTime(t, gyro, cls.wheels(d))

    @classmethod
    def update(cls, e, gyro, d):
        return e.update(gyro, cls.wheels(d))

    @classmethod
    def reset_position(cls, e, gyro, d, pose):
        e.resetPosition(gyro, cls.wheels(d), pose)



class MecanumKit:
    name = "mecanum"

    @staticmethod
    def make(pose, state, vision):
        kinematics = MecanumDriveKinematics(Translation2d(1, 1), Translation2d(-1, 1),
                                            Translation2d(1, -1), Translation2d(-1, -1))
        return MecanumDrivePoseEstimator(kinematics, Rotation2d.kZero,
                                         MecanumDriveWheelPositions(), pose, state, vision)

    @staticmethod
    def make_simultaneous(pose):
        kinematics = MecanumDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                            Translation2d(-1, -1), Translation2d(-1, 1))
        return MecanumDrivePoseEstimator(kinematics, Rotation2d.kZero,
                                         MecanumDriveWheelPositions(), pose,
                                         (0.1, 0.1, 0.1), (0.45, 0.45, 0.1))

    @staticmethod
    def update_with_time(e, t, gyro, d):
        return e.updateWithTime(t, gyro, MecanumDriveWheelPositions(d, d, d, d))

    @staticmethod
    def update(e, gyro, d):
        return e.update(gyro, MecanumDriveWheelPositions(d, d, d, d))

    @staticmethod
    def reset_position(e, gyro, d, pose):
        e.resetPosition(gyro, MecanumDriveWheelPositions(d, d, d, d), pose)



class DifferentialKit:
    name = "differential"

    @staticmethod
    def make(pose, state, vision):
        return DifferentialDrivePoseEstimator(Rotation2d.kZero, 0.0, 0.0, pose, state, vision)

    @classmethod
    def make_simultaneous(cls, pose):
        return cls.make(pose, (0.02, 0.02, 0.01), (0.1, 0.1, 0.1))

    @staticmethod
    def update_with_time(e, t, gyro, d):
        return e.updateWithTime(t, gyro, d, d)

    @staticmethod
    def update(e, gyro, d):
        return e.update(gyro, d, d)

    @staticmethod
    def reset_position(e, gyro, d, pose):
        e.resetPosition(gyro, d, d, pose)



class TwoDeadWheelKit:
    """xWheelYPos = yWheelXPos = 1 m; "every wheel d" is the forward wheel at d, the lateral
    wheel at 0 (upstream's TwoDeadWheelPositions(d, 0))."""

    name = "twodeadwheel"

    @staticmethod
    def make(pose, state, vision):
        return TwoDeadWheelPoseEstimator(1.0, 1.0, 0.0, 0.0, Rotation2d.kZero, pose,
                                         state, vision)

    @staticmethod
    def make_simultaneous(pose):
        # Upstream's test uses the default std devs and the origin.
        return TwoDeadWheelPoseEstimator(1.0, 1.0, 0.0, 0.0, Rotation2d.kZero, Pose2d.kZero)

    @staticmethod
    def update_with_time(e, t, gyro, d):
        return e.updateWithTime(t, d, 0.0, gyro)

    @staticmethod
    def update(e, gyro, d):
        return e.update(d, 0.0, gyro)

    @staticmethod
    def reset_position(e, gyro, d, pose):
        e.resetPosition(d, 0.0, gyro, pose)


@pytest.fixture(params=[SwerveKit, MecanumKit, DifferentialKit, TwoDeadWheelKit],
                ids=lambda k: k.name)
def kit(request):
    return request.param


def test_simultaneous_vision_measurements(kit):
    # All measurements stamped at the same time must each count: were only one applied,
    # 1000 rounds would converge onto it.
    e = kit.make_simultaneous(Pose2d(1, 2, Rotation2d.kCW_Pi_2))
    kit.update_with_time(e, 0.0, Rotation2d.kZero, 0.0)
    measurements = [Pose2d(0, 0, Rotation2d.kZero), Pose2d(3, 1, Rotation2d.kCCW_Pi_2),
                    Pose2d(2, 4, Rotation2d.kPi)]
    for _ in range(1000):
        for m in measurements:
            e.addVisionMeasurement(m, 0.0)
    est = e.getEstimatedPosition()
    for m in measurements:
        dx = abs(m.getX() - est.getX())
        dy = abs(m.getY() - est.getY())
        dtheta = abs(m.getRotation().getDegrees() - est.getRotation().getDegrees())
        assert dx > 0.08 or dy > 0.08 or dtheta > 0.08, (
            f"Estimator converged to one vision measurement: {est} -> {m}")


def test_discards_old_vision_measurements(kit):
    e = kit.make(Pose2d.kZero, (0.1, 0.1, 0.1), (0.9, 0.9, 0.9))
    time = 0.0
    while time < 4:  # fill the buffer
        kit.update_with_time(e, time, Rotation2d.kZero, 0.0)
        time += 0.02
    odometry_pose = e.getEstimatedPosition()
    # A measurement made 3 s ago: ignored, the estimate exactly unchanged.
    e.addVisionMeasurement(Pose2d(Translation2d(10, 10), R(0.1)), 1.0, (0.1, 0.1, 0.1))
    est = e.getEstimatedPosition()
    assert est.getX() == odometry_pose.getX()  # "Incorrect Final X"
    assert est.getY() == odometry_pose.getY()  # "Incorrect Final Y"
    assert est.getRotation().getRadians() == odometry_pose.getRotation().getRadians()


def test_sample_at(kit):
    e = kit.make(Pose2d.kZero, (1, 1, 1), (1, 1, 1))
    assert e.sampleAt(1) is None  # empty before the first update

    time = 1.0
    while time <= 2 + 1e-9:  # Java's loop, with its tolerance for rounding of the sum
        kit.update_with_time(e, time, Rotation2d.kZero, time)
        time += 0.02

    assert_pose_equals(Pose2d(1.02, 0, Rotation2d.kZero), e.sampleAt(1.02))  # an added time
    assert_pose_equals(Pose2d(1.01, 0, Rotation2d.kZero), e.sampleAt(1.01))  # interpolated
    assert_pose_equals(Pose2d(1, 0, Rotation2d.kZero), e.sampleAt(0.5))  # before the oldest
    assert_pose_equals(Pose2d(2, 0, Rotation2d.kZero), e.sampleAt(2.5))  # after the newest

    # A measurement after the newest sample changes none of the samples before it.
    e.addVisionMeasurement(Pose2d(2, 0, R(1)), 2.2)
    assert_pose_equals(Pose2d(1.02, 0, Rotation2d.kZero), e.sampleAt(1.02))
    assert_pose_equals(Pose2d(1.01, 0, Rotation2d.kZero), e.sampleAt(1.01))
    assert_pose_equals(Pose2d(1, 0, Rotation2d.kZero), e.sampleAt(0.5))

    # One before the oldest sample, still within 1.5 s: y is halfway to 0.2 everywhere.
    e.addVisionMeasurement(Pose2d(1, 0.2, Rotation2d.kZero), 0.9)
    assert_pose_equals(Pose2d(1.02, 0.1, Rotation2d.kZero), e.sampleAt(1.02))
    assert_pose_equals(Pose2d(1.01, 0.1, Rotation2d.kZero), e.sampleAt(1.01))
    assert_pose_equals(Pose2d(1, 0.1, Rotation2d.kZero), e.sampleAt(0.5))
    assert_pose_equals(Pose2d(2, 0.1, Rotation2d.kZero), e.sampleAt(2.5))


def test_reset(kit):
    e = kit.make(Pose2d.kZero, (1, 1, 1), (1, 1, 1))

    kit.reset_position(e, Rotation2d.kZero, 1.0, Pose2d(1, 0, Rotation2d.kZero))
    assert_estimate(e, 1, 0, 0)

    kit.update(e, Rotation2d.kZero, 2.0)  # orientation and wheel positions
    assert_estimate(e, 2, 0, 0)

    e.resetRotation(Rotation2d.kCCW_Pi_2)
    assert_estimate(e, 2, 0, math.pi / 2)

    kit.update(e, Rotation2d.kZero, 3.0)  # forward is now +y
    assert_estimate(e, 2, 1, math.pi / 2)

    e.resetTranslation(Translation2d(-1, -1))
    assert_estimate(e, -1, -1, math.pi / 2)

    e.resetPose(Pose2d.kZero)
    assert_estimate(e, 0, 0, 0)
