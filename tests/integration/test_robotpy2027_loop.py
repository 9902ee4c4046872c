"""A robot loop written exactly as a robotpy 2027 team writes it
(tests/_support/robotpy2027_robot.py: kinematics, desaturation, discretize, odometry, pose
estimators with vision), with only its import changed to drivekin, gives the same poses
as the same loop in WPILib's Java names (bit for bit: the names are the same functions)
and as the loop run on robotpy-wpimath 2026, an independent implementation (1e-9)."""
from __future__ import annotations

import math

import pytest

import drivekin as dk
from tests._support import robotpy2027_robot as robot

STEPS = 150
DT = robot.DT


def _java_swerve(steps):
    kinematics = dk.SwerveDriveKinematics(
        dk.Translation2d(0.3, 0.3), dk.Translation2d(0.3, -0.3),
        dk.Translation2d(-0.3, 0.3), dk.Translation2d(-0.3, -0.3))
    positions = [dk.SwerveModulePosition() for _ in range(4)]
    odometry = dk.SwerveDriveOdometry(kinematics, dk.Rotation2d(), positions, dk.Pose2d())
    estimator = dk.SwerveDrivePoseEstimator(kinematics, dk.Rotation2d(), positions,
                                            dk.Pose2d(), (0.1, 0.1, 0.1), (0.9, 0.9, 0.9))
    heading = dk.Rotation2d()
    for i in range(steps):
        t = i * DT
        field = dk.ChassisVelocities(3.0 * math.cos(t), 2.0 * math.sin(0.5 * t), 2.5)
        robot_relative = field.toRobotRelative(heading).discretize(DT)
        states = kinematics.toSwerveModuleVelocities(robot_relative)
        states = dk.SwerveDriveKinematics.desaturateWheelVelocities(
            states, robot.MAX_WHEEL_VELOCITY)
        states = [s.optimize(p.angle) for s, p in zip(states, positions)]
        positions = [dk.SwerveModulePosition(p.distance + s.velocity * DT, s.angle)
                     for s, p in zip(states, positions)]
        achieved = kinematics.toChassisVelocities(states)
        heading = heading.rotateBy(dk.Rotation2d(achieved.omega * DT))
        pose = odometry.update(heading, positions)
        estimator.updateWithTime(t, heading, positions)
        if i % 10 == 5:
            seen = dk.Pose2d(pose.getX() + 0.05, pose.getY() - 0.02, pose.getRotation())
            estimator.addVisionMeasurement(seen, t - 0.04, (0.5, 0.5, 0.5))
    return odometry.getPose(), estimator.getEstimatedPosition()


def _java_tank(steps):
    kinematics = dk.DifferentialDriveKinematics(0.6)
    estimator = dk.DifferentialDrivePoseEstimator(dk.Rotation2d(), 0.0, 0.0, dk.Pose2d())
    left = right = 0.0
    for i in range(steps):
        t = i * DT
        wheels = kinematics.toWheelVelocities(dk.ChassisVelocities(2.0, 0.0, math.sin(t)))
        wheels = wheels.desaturate(1.8)
        left += wheels.left * DT
        right += wheels.right * DT
        heading = dk.Rotation2d((right - left) / kinematics.trackwidth)
        estimator.updateWithTime(t, heading, left, right)
        if i % 10 == 5:
            seen = estimator.getEstimatedPosition().transformBy(
                dk.Pose2d(0.03, 0.0, dk.Rotation2d()).minus(dk.Pose2d()))
            estimator.addVisionMeasurement(seen, t - 0.02)
    return estimator.getEstimatedPosition(), (left, right)


def _robotpy2026_swerve(steps):
    g = pytest.importorskip("wpimath.geometry")
    k = pytest.importorskip("wpimath.kinematics")
    e = pytest.importorskip("wpimath.estimator")
    kinematics = k.SwerveDrive4Kinematics(
        g.Translation2d(0.3, 0.3), g.Translation2d(0.3, -0.3),
        g.Translation2d(-0.3, 0.3), g.Translation2d(-0.3, -0.3))
    positions = tuple(k.SwerveModulePosition() for _ in range(4))
    odometry = k.SwerveDrive4Odometry(kinematics, g.Rotation2d(), positions, g.Pose2d())
    estimator = e.SwerveDrive4PoseEstimator(kinematics, g.Rotation2d(), positions,
                                            g.Pose2d(), (0.1, 0.1, 0.1), (0.9, 0.9, 0.9))
    heading = g.Rotation2d()
    for i in range(steps):
        t = i * DT
        field = k.ChassisSpeeds(3.0 * math.cos(t), 2.0 * math.sin(0.5 * t), 2.5)
        robot_relative = k.ChassisSpeeds.discretize(
            k.ChassisSpeeds.fromFieldRelativeSpeeds(field, heading), DT)
        states = kinematics.toSwerveModuleStates(robot_relative)
        states = k.SwerveDrive4Kinematics.desaturateWheelSpeeds(states,
                                                                robot.MAX_WHEEL_VELOCITY)
        for s, p in zip(states, positions):
            s.optimize(p.angle)                         # 2026: in place
        positions = tuple(k.SwerveModulePosition(p.distance + s.speed * DT, s.angle)
                          for s, p in zip(states, positions))
        achieved = kinematics.toChassisSpeeds(states)
        heading = heading.rotateBy(g.Rotation2d(achieved.omega * DT))
        pose = odometry.update(heading, positions)
        estimator.updateWithTime(t, heading, positions)
        if i % 10 == 5:
            seen = g.Pose2d(pose.X() + 0.05, pose.Y() - 0.02, pose.rotation())
            estimator.addVisionMeasurement(seen, t - 0.04, (0.5, 0.5, 0.5))
    return odometry.getPose(), estimator.getEstimatedPosition()


def _bits(pose):
    return (pose.getX(), pose.getY(), pose.getRotation().getCos(),
            pose.getRotation().getSin())


def test_the_robotpy_2027_loop_equals_the_java_names_loop_bit_for_bit():
    got, want = robot.swerve(STEPS), _java_swerve(STEPS)
    assert [_bits(p) for p in got] == [_bits(p) for p in want]
    tank, java_tank = robot.tank(STEPS), _java_tank(STEPS)
    assert _bits(tank[0]) == _bits(java_tank[0]) and tank[1] == java_tank[1]
    # The loop moved, turned and took vision: the comparison is not of two origins.
    odometry, estimate = got
    assert math.hypot(odometry.x, odometry.y) > 0.5
    assert odometry.getTranslation().getDistance(estimate.getTranslation()) > 1e-4


def test_the_robotpy_2027_loop_agrees_with_robotpy_wpimath_2026():
    rp_odometry, rp_estimate = _robotpy2026_swerve(STEPS)
    odometry, estimate = robot.swerve(STEPS)
    for mine, theirs in ((odometry, rp_odometry), (estimate, rp_estimate)):
        assert mine.x == pytest.approx(theirs.X(), abs=1e-9)
        assert mine.y == pytest.approx(theirs.Y(), abs=1e-9)
        assert mine.rotation().cos() == pytest.approx(theirs.rotation().cos(), abs=1e-9)
        assert mine.rotation().sin() == pytest.approx(theirs.rotation().sin(), abs=1e-9)
