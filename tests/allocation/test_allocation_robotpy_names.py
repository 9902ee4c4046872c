"""The allocation-free paths stay allocation-free through robotpy 2027's names (the same
functions, drivekin._core.pynames): a robot loop body spelled the robotpy 2027 way, and
each ``...Into``/``...InPlace`` operation under its snake_case name."""
from __future__ import annotations

import numpy as np

from drivekin import (
    ChassisVelocities,
    DifferentialDriveKinematics,
    DifferentialDriveWheelVelocities,
    MecanumDriveKinematics,
    MecanumDriveWheelVelocities,
    Pose2d,
    Rotation2d,
    SwerveDrive4Kinematics,
    SwerveDrive4Odometry,
    SwerveDrive4PoseEstimator,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Translation2d,
    Twist2d,
)
from tests._support.alloc import assert_allocation_free

CORNERS = [Translation2d(0.3, 0.3), Translation2d(0.3, -0.3), Translation2d(-0.3, 0.3),
           Translation2d(-0.3, -0.3)]


class _Box:
    __slots__ = ("pose", "t")


def test_swerve_into_and_in_place_under_robotpy_names():
    kin = SwerveDrive4Kinematics(*CORNERS)
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    out = [SwerveModuleVelocity() for _ in range(4)]
    chassis = ChassisVelocities()
    tw = Twist2d()
    deltas = [SwerveModulePosition(0.01, Rotation2d(0.1 * i)) for i in range(4)]
    arr = np.array([[5.0, 0.1], [-6.0, 0.2], [4.0, 0.3], [7.0, 0.4]])
    desaturate = SwerveDrive4Kinematics.desaturate_wheel_velocities_in_place
    assert_allocation_free(lambda: kin.to_swerve_module_velocities_into(cv, out))
    assert_allocation_free(lambda: kin.to_chassis_velocities_into(out, chassis))
    assert_allocation_free(lambda: kin.to_twist2d_into(deltas, tw))
    assert_allocation_free(lambda: desaturate(arr, 5.5))
    assert_allocation_free(lambda: desaturate(out, cv, 5.5, 5.5, 3.5))
    assert_allocation_free(lambda: kin.desaturated_discretize_into(cv, 0.02, 4.0, chassis))


def test_chassis_and_wheels_under_robotpy_names():
    cv = ChassisVelocities(1.0, 2.0, 0.5)
    out = ChassisVelocities()
    r = Rotation2d(0.7)
    assert_allocation_free(lambda: cv.discretize_into(0.02, out))
    assert_allocation_free(lambda: cv.to_robot_relative_into(r, out))
    assert_allocation_free(lambda: cv.to_field_relative_into(r, out))
    mecanum = MecanumDriveKinematics(*CORNERS)
    wheels = MecanumDriveWheelVelocities()
    assert_allocation_free(lambda: mecanum.to_wheel_velocities_into(cv, wheels))
    assert_allocation_free(lambda: wheels.desaturate_in_place(1.0))
    tank = DifferentialDriveKinematics(0.6)
    sides = DifferentialDriveWheelVelocities()
    assert_allocation_free(lambda: tank.to_wheel_velocities_into(cv, sides))


def test_a_robotpy_2027_loop_body_allocates_nothing():
    kin = SwerveDrive4Kinematics(*CORNERS)
    positions = [SwerveModulePosition(0.0, Rotation2d(0.1 * i)) for i in range(4)]
    odometry = SwerveDrive4Odometry(kin, Rotation2d(), positions, Pose2d())
    estimator = SwerveDrive4PoseEstimator(kin, Rotation2d(), positions, Pose2d(),
                                          (0.1, 0.1, 0.1), (0.9, 0.9, 0.9))
    gyro = Rotation2d(0.01)
    box = _Box()
    box.t = 0.0

    def step():
        box.t += 0.02
        box.pose = odometry.update(gyro, positions)
        box.pose = estimator.update_with_time(box.t, gyro, positions)
        box.pose = odometry.get_pose()

    assert_allocation_free(step)
