"""WPILib's TwoDeadWheelOdometry unit tests (allwpilib PR #9155, head fdfb98c2,
wpimath/src/test/java/org/wpilib/math/kinematics/TwoDeadWheelOdometryTest.java), restated
for drivekin with WPILib's own tolerances, and run on both TwoDeadWheelOdometry and the
equivalent DeadWheelOdometry (forward wheel at (0, xWheelYPos) rolling along 0°, left
wheel at (yWheelXPos, 0) rolling along 90°, with a gyro).

The accuracy tests use the spline trajectory and java.util.Random noise of
test_odometry_wpilib.py (``wpilib_port.trajectory_generator``, robotpy-wpimath's generator;
they skip without it, and ``wpilib_port.JavaRandom``).
"""
import math

import pytest

from drivekin import (
    DeadWheelKinematics,
    DeadWheelOdometry,
    Pose2d,
    Rotation2d,
    Translation2d,
    TwoDeadWheelOdometry,
)
from tests._support.wpilib_port import DT, JavaRandom, assert_close, trajectory_generator

X_WHEEL_Y_POS = 1.0
Y_WHEEL_X_POS = 1.0


class General:
    """DeadWheelOdometry behind TwoDeadWheelOdometry's call signatures."""

    def __init__(self, a, b, x, y, gyro, pose=None):
        kin = DeadWheelKinematics([Pose2d(0.0, a, Rotation2d()),
                                   Pose2d(b, 0.0, Rotation2d.kCCW_Pi_2)])
        self.o = DeadWheelOdometry(kin, [x, y], gyro, pose)

    def resetPosition(self, x, y, gyro, pose):
        self.o.resetPosition([x, y], gyro, pose)

    def update(self, x, y, gyro):
        return self.o.update([x, y], gyro)

    def getPose(self):
        return self.o.getPose()


@pytest.fixture(params=["TwoDeadWheelOdometry", "DeadWheelOdometry"])
def make(request):
    return TwoDeadWheelOdometry if request.param == "TwoDeadWheelOdometry" else General


@pytest.fixture
def odometry(make):
    return make(X_WHEEL_Y_POS, Y_WHEEL_X_POS, 0.0, 0.0, Rotation2d.kZero)


def test_multiple_consecutive_updates(odometry):
    odometry.resetPosition(1, 1, Rotation2d.kZero, Pose2d.kZero)
    odometry.update(1, 1, Rotation2d.kZero)
    pose = odometry.update(1, 1, Rotation2d.kZero)
    assert_close(0.0, pose.getX(), 0.01)
    assert_close(0.0, pose.getY(), 0.01)
    assert_close(0.0, pose.getRotation().getDegrees(), 0.01)


def test_two_iterations(odometry):
    odometry.resetPosition(0.0, 0.0, Rotation2d.kZero, Pose2d.kZero)
    odometry.update(0.0, 0.0, Rotation2d.kZero)
    pose = odometry.update(0.1, 0.0, Rotation2d.kZero)
    assert_close(0.1, pose.getX(), 0.01)
    assert_close(0.0, pose.getY(), 0.01)
    assert_close(0.0, pose.getRotation().getDegrees(), 0.01)


def test_gyro_angle_reset(odometry):
    gyro = Rotation2d.kCCW_Pi_2
    odometry.resetPosition(0.0, 0.0, gyro, Pose2d(Translation2d.kZero, Rotation2d.kZero))
    odometry.update(1.0, 0.0, gyro)
    pose = odometry.update(1.0, 0.0, gyro)
    assert_close(1.0, pose.getX(), 0.1)
    assert_close(0.0, pose.getY(), 0.1)
    assert_close(0.0, pose.getRotation().getRadians(), 0.1)


@pytest.mark.parametrize("wheels, expected", [
    ((5, 0, 0), (5, 0, 0)),        # straight forwards
    ((0, 5, 0), (0, 5, 0)),        # straight left
    ((-5, 5, 5), (0, 0, 5)),       # spin in place
    ((1, -1, 5), (6, -6, 5)),      # mixed motion
])
def test_forward_kinematics(wheels, expected):
    odometry = TwoDeadWheelOdometry(X_WHEEL_Y_POS, Y_WHEEL_X_POS, 0.0, 0.0, Rotation2d.kZero)
    general = DeadWheelKinematics([Pose2d(0.0, X_WHEEL_Y_POS, Rotation2d()),
                                   Pose2d(Y_WHEEL_X_POS, 0.0, Rotation2d.kCCW_Pi_2)])
    for v in (odometry.toChassisVelocities(*wheels),
              general.toChassisVelocities(wheels[:2], gyro_rate=wheels[2])):
        assert_close(expected[0], v.vx, 0.1)
        assert_close(expected[1], v.vy, 0.1)
        assert_close(expected[2], v.omega, 0.1)


WAYPOINTS = [(0, 0, 0.0), (20, 20, math.radians(45)), (10, 10, math.radians(-90)),
             (30, 30, math.radians(135)), (20, 20, math.radians(-90)), (10, 10, 0.0)]


def accuracy(make, facing_trajectory):
    """The accuracy loop: wheel velocities from the inverse kinematics rows
    [1, 0, −xWheelYPos; 0, 1, yWheelXPos] applied to the true motion (robot frame when the
    robot faces along the path, field frame when it keeps facing +x), plus N(0, 0.05)
    noise; gyro = truth (or 0) plus N(0, 0.001) rad. Returns mean error, max error and the
    odometry / trajectory distance ratio."""
    trajectory = trajectory_generator()(WAYPOINTS, 0.5, 2.0)
    start = trajectory.sample(0.0).pose
    x_pos = y_pos = 0.0
    if facing_trajectory:
        odometry = make(X_WHEEL_Y_POS, Y_WHEEL_X_POS, x_pos, y_pos,
                        Rotation2d(start.rotation().radians()),
                        Pose2d(start.X(), start.Y(), Rotation2d(start.rotation().radians())))
    else:
        odometry = make(X_WHEEL_Y_POS, Y_WHEEL_X_POS, x_pos, y_pos, Rotation2d.kZero,
                        Pose2d.kZero)
    rand = JavaRandom(5190)
    t = 0.0
    max_error, error_sum, odometry_distance, trajectory_distance = -math.inf, 0.0, 0.0, 0.0
    duration = trajectory.totalTime()
    while t <= duration:
        truth = trajectory.sample(t)
        trajectory_distance += truth.velocity * DT + 0.5 * truth.acceleration * DT * DT
        heading = truth.pose.rotation().radians()
        if facing_trajectory:
            vx, vy, omega = truth.velocity, 0.0, truth.velocity * truth.curvature
        else:
            vx, vy, omega = truth.velocity * math.cos(heading), truth.velocity * math.sin(heading), 0.0
        x_vel = vx - X_WHEEL_Y_POS * omega + rand.next_gaussian() * 0.05
        y_vel = vy + Y_WHEEL_X_POS * omega + rand.next_gaussian() * 0.05
        x_pos += x_vel * DT
        y_pos += y_vel * DT
        last = odometry.getPose()
        if facing_trajectory:
            gyro = Rotation2d(heading).plus(Rotation2d(rand.next_gaussian() * 0.001))
        else:
            gyro = Rotation2d(rand.next_gaussian() * 0.001)
        x_hat = odometry.update(x_pos, y_pos, gyro)
        odometry_distance += last.getTranslation().getDistance(x_hat.getTranslation())
        error = Translation2d(truth.pose.X(), truth.pose.Y()).getDistance(x_hat.getTranslation())
        max_error = max(max_error, error)
        error_sum += error
        t += DT
    return error_sum / (duration / DT), max_error, odometry_distance / trajectory_distance


def test_accuracy_facing_trajectory(make):
    mean_error, max_error, ratio = accuracy(make, True)
    assert_close(0.0, mean_error, 0.35)   # "Incorrect mean error"
    assert_close(0.0, max_error, 0.35)    # "Incorrect max error"
    assert_close(1.0, ratio, 0.05)        # "Incorrect distance travelled"


def test_accuracy_facing_x_axis(make):
    mean_error, max_error, ratio = accuracy(make, False)
    assert_close(0.0, mean_error, 0.15)
    assert_close(0.0, max_error, 0.3)
    assert_close(1.0, ratio, 0.05)
