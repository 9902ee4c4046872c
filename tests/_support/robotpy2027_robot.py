"""A robot's drive code as a robotpy 2027 team writes it (the names of robotpy 2027's
documentation: snake_case methods and keywords, SwerveDrive4Kinematics, properties
``x``/``vx``/``velocity``), with one change: the import below. For robotpy 2027, whose
wpimath has every class at its top level (mostrobotpy 9caf4fe5), it reads

    from wpimath import (ChassisVelocities, DifferentialDriveKinematics, ...)

tests/integration/test_robotpy2027_loop.py runs it against the same loop in WPILib's Java
names and against robotpy-wpimath 2026.
"""
from __future__ import annotations

import math

from drivekin import (ChassisVelocities, DifferentialDriveKinematics,
                      DifferentialDrivePoseEstimator, Pose2d, Rotation2d, SwerveDrive4Kinematics, SwerveDrive4Odometry,
                      SwerveDrive4PoseEstimator, SwerveModulePosition, Translation2d)

DT = 0.02
MAX_WHEEL_VELOCITY = 4.5       # m/s


def swerve(steps: int) -> tuple[Pose2d, Pose2d]:
    kinematics = SwerveDrive4Kinematics(
        Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
        Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    positions = [SwerveModulePosition() for _ in range(4)]
    odometry = SwerveDrive4Odometry(kinematics, Rotation2d(), positions, Pose2d())
    estimator = SwerveDrive4PoseEstimator(
        kinematics, gyro_angle=Rotation2d(), module_positions=positions,
        initial_pose=Pose2d(), state_std_devs=(0.1, 0.1, 0.1),
        vision_measurement_std_devs=(0.9, 0.9, 0.9))
    heading = Rotation2d()
    for i in range(steps):
        t = i * DT
        field = ChassisVelocities(3.0 * math.cos(t), 2.0 * math.sin(0.5 * t), 2.5)
        robot = field.to_robot_relative(heading).discretize(DT)
        wanted = kinematics.to_swerve_module_velocities(robot)
        limited = SwerveDrive4Kinematics.desaturate_wheel_velocities(wanted,
                                                                     MAX_WHEEL_VELOCITY)
        states = [s.optimize(p.angle) for s, p in zip(limited, positions)]
        positions = [SwerveModulePosition(p.distance + s.velocity * DT, s.angle)
                     for s, p in zip(states, positions)]
        achieved = kinematics.to_chassis_velocities(states)
        heading = heading.rotate_by(Rotation2d(achieved.omega * DT))
        pose = odometry.update(heading, positions)
        estimator.update_with_time(t, heading, positions)
        if i % 10 == 5:
            seen = Pose2d(pose.x + 0.05, pose.y - 0.02, pose.rotation())
            estimator.add_vision_measurement(vision_robot_pose=seen, timestamp=t - 0.04,
                                             vision_measurement_std_devs=(0.5, 0.5, 0.5))
    return odometry.get_pose(), estimator.get_estimated_position()


def tank(steps: int) -> tuple[Pose2d, tuple[float, float]]:
    kinematics = DifferentialDriveKinematics(0.6)
    estimator = DifferentialDrivePoseEstimator(Rotation2d(), 0.0, 0.0, Pose2d())
    left = right = 0.0
    heading = Rotation2d()
    for i in range(steps):
        t = i * DT
        wheels = kinematics.to_wheel_velocities(ChassisVelocities(2.0, 0.0, math.sin(t)))
        wheels = wheels.desaturate(1.8)
        left += wheels.left * DT
        right += wheels.right * DT
        heading = Rotation2d((right - left) / kinematics.trackwidth)
        estimator.update_with_time(t, gyro_angle=heading, left_distance=left,
                                   right_distance=right)
        if i % 10 == 5:
            seen = estimator.get_estimated_position().transform_by(
                Pose2d(0.03, 0.0, Rotation2d()) - Pose2d())
            estimator.add_vision_measurement(seen, t - 0.02)
    return estimator.get_estimated_position(), (left, right)
