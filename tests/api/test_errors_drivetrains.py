"""Bad input to the drivetrain classes (differential, mecanum, odometry, swerve odometry and
the allocation-free ``*Into`` methods) raises a clear ValueError or TypeError -- never a crash,
never a silent wrong answer -- and a failed call leaves the object usable and unchanged.

WPILib's IllegalArgumentException maps to ValueError (wrong module counts, bad trackwidth);
wrong argument types are TypeError.
"""
import math

import numpy as np
import pytest

from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    DifferentialDriveKinematics,
    DifferentialDriveOdometry,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelAccelerations,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Transform2d,
    Translation2d,
    Twist2d,
)
from tests._support.wpilib_port import BL, BR, FL, FR

ZERO = Rotation2d.kZero


def mecanum():
    return MecanumDriveKinematics(FL, FR, BL, BR)


def swerve():
    return SwerveDriveKinematics(FL, FR, BL, BR)


def swerve_odometry():
    return SwerveDriveOdometry(swerve(), ZERO, [SwerveModulePosition() for _ in range(4)])


def assert_pose(pose, x, y, degrees, tol=1e-9):
    assert abs(pose.getX() - x) <= tol
    assert abs(pose.getY() - y) <= tol
    assert abs(pose.getRotation().getDegrees() - degrees) <= tol


# =========================================================================================
# DifferentialDriveKinematics
# =========================================================================================
class TestDifferentialDriveKinematics:
    @pytest.mark.parametrize("trackwidth", [0.0, -0.0, -1.0, -1e-300, math.nan, math.inf,
                                            -math.inf])
    def test_bad_trackwidth_value(self, trackwidth):
        with pytest.raises(ValueError, match="trackwidth"):
            DifferentialDriveKinematics(trackwidth)

    @pytest.mark.parametrize("trackwidth", ["0.7", None, [0.7], Translation2d(0.7, 0)])
    def test_bad_trackwidth_type(self, trackwidth):
        with pytest.raises(TypeError, match="real number"):
            DifferentialDriveKinematics(trackwidth)

    def test_integer_trackwidth_is_fine(self):
        assert DifferentialDriveKinematics(2).trackwidth == 2.0

    @pytest.mark.parametrize("start, end", [
        (DifferentialDriveWheelPositions(1, 2), 3.0),
        (3.0, DifferentialDriveWheelPositions(1, 2)),
        (DifferentialDriveWheelPositions(1, 2), None),
    ])
    def test_to_twist2d_mixed_positions_and_distances(self, start, end):
        k = DifferentialDriveKinematics(0.5)
        with pytest.raises(TypeError, match="two DifferentialDriveWheelPositions or two distances"):
            k.toTwist2d(start, end)

    @pytest.mark.parametrize("start, end", [
        ("1", "2"),
        (None, None),
        (DifferentialDriveWheelVelocities(1, 2), DifferentialDriveWheelVelocities(1, 2)),
        (MecanumDriveWheelPositions(), MecanumDriveWheelPositions()),
    ])
    def test_to_twist2d_wrong_types(self, start, end):
        k = DifferentialDriveKinematics(0.5)
        with pytest.raises(TypeError, match="DifferentialDriveWheelPositions or two distances"):
            k.toTwist2d(start, end)

    def test_to_twist2d_missing_argument(self):
        with pytest.raises(TypeError):
            DifferentialDriveKinematics(0.5).toTwist2d(1.0)

    def test_wrong_value_classes(self):
        k = DifferentialDriveKinematics(0.5)
        with pytest.raises(TypeError, match="DifferentialDriveWheelVelocities"):
            k.toChassisVelocities(MecanumDriveWheelVelocities())
        with pytest.raises(TypeError, match="DifferentialDriveWheelVelocities"):
            k.toChassisVelocities(DifferentialDriveWheelAccelerations())
        with pytest.raises(TypeError, match="ChassisVelocities"):
            k.toWheelVelocities(ChassisAccelerations())
        with pytest.raises(TypeError, match="DifferentialDriveWheelAccelerations"):
            k.toChassisAccelerations(DifferentialDriveWheelVelocities())
        with pytest.raises(TypeError, match="ChassisAccelerations"):
            k.toWheelAccelerations(ChassisVelocities())
        with pytest.raises(TypeError):
            k.toWheelVelocities(None)


# =========================================================================================
# MecanumDriveKinematics
# =========================================================================================
class TestMecanumDriveKinematics:
    @pytest.mark.parametrize("bad", [(1.0, 1.0), None, Pose2d(), Rotation2d(), 12.0])
    @pytest.mark.parametrize("slot", range(4))
    def test_wheel_must_be_translation2d(self, bad, slot):
        wheels = [FL, FR, BL, BR]
        wheels[slot] = bad
        with pytest.raises(TypeError, match="Translation2d"):
            MecanumDriveKinematics(*wheels)

    def test_wrong_number_of_wheels(self):
        with pytest.raises(TypeError):
            MecanumDriveKinematics(FL, FR, BL)
        with pytest.raises(TypeError):
            MecanumDriveKinematics(FL, FR, BL, BR, BR)
        with pytest.raises(TypeError):
            MecanumDriveKinematics([FL, FR, BL, BR])

    @pytest.mark.parametrize("cor", [(12.0, 12.0), Pose2d(), "FL", 0.0])
    def test_center_of_rotation_must_be_translation2d(self, cor):
        k = mecanum()
        with pytest.raises(TypeError, match="center_of_rotation must be a Translation2d"):
            k.toWheelVelocities(ChassisVelocities(1, 2, 3), cor)
        with pytest.raises(TypeError, match="center_of_rotation must be a Translation2d"):
            k.toWheelAccelerations(ChassisAccelerations(1, 2, 3), cor)
        with pytest.raises(TypeError, match="center_of_rotation must be a Translation2d"):
            k.toWheelVelocitiesInto(ChassisVelocities(1, 2, 3), MecanumDriveWheelVelocities(),
                                    cor)
        # Still usable, and still at the origin CoR.
        w = k.toWheelVelocities(ChassisVelocities(2, 3, 1))
        assert (w.frontLeft, w.frontRight, w.rearLeft, w.rearRight) == (-25.0, 29.0, -19.0,
                                                                        23.0)

    def test_none_center_of_rotation(self):
        with pytest.raises(TypeError, match="center_of_rotation"):
            mecanum().toWheelVelocities(ChassisVelocities(), None)

    @pytest.mark.parametrize("end", [MecanumDriveWheelVelocities(), 3.0, "x",
                                     DifferentialDriveWheelPositions(1, 2)])
    def test_to_twist2d_end_type(self, end):
        with pytest.raises(TypeError, match="end must be a MecanumDriveWheelPositions"):
            mecanum().toTwist2d(MecanumDriveWheelPositions(), end)

    @pytest.mark.parametrize("start", [MecanumDriveWheelVelocities(), None, (1, 2, 3, 4)])
    def test_to_twist2d_start_type(self, start):
        with pytest.raises(TypeError, match="MecanumDriveWheelPositions"):
            mecanum().toTwist2d(start)

    def test_wrong_value_classes(self):
        k = mecanum()
        with pytest.raises(TypeError, match="MecanumDriveWheelVelocities"):
            k.toChassisVelocities(MecanumDriveWheelPositions())
        with pytest.raises(TypeError, match="MecanumDriveWheelVelocities"):
            k.toChassisVelocities(DifferentialDriveWheelVelocities())
        with pytest.raises(TypeError, match="MecanumDriveWheelAccelerations"):
            k.toChassisAccelerations(MecanumDriveWheelVelocities())
        with pytest.raises(TypeError, match="ChassisVelocities"):
            k.toWheelVelocities(ChassisAccelerations())
        with pytest.raises(TypeError, match="MecanumDriveWheelPositions"):
            k.interpolate(MecanumDriveWheelVelocities(), MecanumDriveWheelVelocities(), 0.5)
        with pytest.raises(TypeError, match="MecanumDriveWheelPositions"):
            k.copyInto(MecanumDriveWheelPositions(), MecanumDriveWheelVelocities())


# =========================================================================================
# Wheel value classes
# =========================================================================================
class TestWheelValues:
    @pytest.mark.parametrize("cls, other", [
        (MecanumDriveWheelVelocities, MecanumDriveWheelPositions()),
        (MecanumDriveWheelAccelerations, MecanumDriveWheelVelocities()),
        (DifferentialDriveWheelVelocities, DifferentialDriveWheelAccelerations()),
        (DifferentialDriveWheelAccelerations, MecanumDriveWheelAccelerations()),
    ])
    def test_arithmetic_needs_same_class(self, cls, other):
        a = cls()
        with pytest.raises(TypeError, match=f"expected a {cls.__name__}"):
            a.plus(other)
        with pytest.raises(TypeError, match=f"expected a {cls.__name__}"):
            a.minus(other)
        with pytest.raises(TypeError, match="unsupported operand"):
            a + other
        with pytest.raises(TypeError, match="unsupported operand"):
            a - other

    @pytest.mark.parametrize("cls", [MecanumDriveWheelVelocities, MecanumDriveWheelPositions,
                                     DifferentialDriveWheelVelocities,
                                     DifferentialDriveWheelAccelerations])
    def test_scalar_must_be_a_number(self, cls):
        a = cls(1.0, 2.0)
        with pytest.raises(TypeError, match="real number"):
            a.times("2")
        with pytest.raises(TypeError, match="real number"):
            a.div(None)
        with pytest.raises(TypeError):
            a * "2"
        with pytest.raises(TypeError):
            a / [2]
        with pytest.raises(TypeError, match="real number"):
            a.interpolate(cls(), "0.5")

    def test_interpolate_needs_same_class(self):
        with pytest.raises(TypeError, match="MecanumDriveWheelVelocities"):
            MecanumDriveWheelVelocities().interpolate(MecanumDriveWheelAccelerations(), 0.5)
        with pytest.raises(TypeError, match="DifferentialDriveWheelPositions"):
            DifferentialDriveWheelPositions(0, 0).interpolate(
                DifferentialDriveWheelVelocities(), 0.5)

    def test_constructor_arguments(self):
        with pytest.raises(TypeError, match="real number"):
            MecanumDriveWheelPositions("1", 2, 3, 4)
        with pytest.raises(TypeError):
            MecanumDriveWheelVelocities(1, 2, 3, 4, 5)
        with pytest.raises(TypeError):
            DifferentialDriveWheelPositions(1.0)
        with pytest.raises(TypeError, match="real number"):
            DifferentialDriveWheelVelocities(None, 1.0)

    def test_field_assignment_type(self):
        w = MecanumDriveWheelVelocities()
        with pytest.raises(TypeError, match="real number"):
            w.frontLeft = "fast"
        d = DifferentialDriveWheelPositions(0, 0)
        with pytest.raises(TypeError, match="real number"):
            d.left = None
        assert (w.frontLeft, d.left) == (0.0, 0.0)

    def test_desaturate_argument(self):
        with pytest.raises(TypeError, match="real number"):
            MecanumDriveWheelVelocities(1, 2, 3, 4).desaturate("3")
        with pytest.raises(TypeError, match="real number"):
            DifferentialDriveWheelVelocities(1, 2).desaturateInPlace(None)


# =========================================================================================
# *Into methods with the wrong ``out``
# =========================================================================================
class TestIntoMethods:
    @pytest.mark.parametrize("out", [DifferentialDriveWheelVelocities(),
                                     MecanumDriveWheelPositions(),
                                     MecanumDriveWheelAccelerations(), None, [0.0] * 4])
    def test_mecanum_to_wheel_velocities_into(self, out):
        with pytest.raises(TypeError, match="out"):
            mecanum().toWheelVelocitiesInto(ChassisVelocities(1, 0, 0), out)

    @pytest.mark.parametrize("out", [ChassisAccelerations(), Twist2d(), None, [0.0] * 3])
    def test_mecanum_to_chassis_velocities_into(self, out):
        with pytest.raises(TypeError, match="out"):
            mecanum().toChassisVelocitiesInto(MecanumDriveWheelVelocities(), out)

    @pytest.mark.parametrize("out", [MecanumDriveWheelVelocities(),
                                     DifferentialDriveWheelPositions(0, 0),
                                     DifferentialDriveWheelAccelerations(), None])
    def test_differential_to_wheel_velocities_into(self, out):
        with pytest.raises(TypeError, match="out"):
            DifferentialDriveKinematics(0.5).toWheelVelocitiesInto(ChassisVelocities(), out)

    @pytest.mark.parametrize("out", [ChassisAccelerations(), Pose2d(), None])
    def test_differential_to_chassis_velocities_into(self, out):
        with pytest.raises(TypeError, match="out"):
            DifferentialDriveKinematics(0.5).toChassisVelocitiesInto(
                DifferentialDriveWheelVelocities(), out)

    def test_swerve_module_velocities_into_objects(self):
        k = swerve()
        cv = ChassisVelocities(1, 0, 0)
        with pytest.raises(TypeError, match=r"out\[0\] must be a SwerveModuleVelocity"):
            k.toSwerveModuleVelocitiesInto(cv, [SwerveModulePosition() for _ in range(4)])
        with pytest.raises(ValueError, match="out must hold 4 SwerveModuleVelocity"):
            k.toSwerveModuleVelocitiesInto(cv, [SwerveModuleVelocity() for _ in range(3)])
        with pytest.raises(TypeError, match="out must be a sequence"):
            k.toSwerveModuleVelocitiesInto(cv, None)
        # A type error part-way through must not half-write the list.
        out = [SwerveModuleVelocity(7.0) for _ in range(3)] + [SwerveModulePosition()]
        with pytest.raises(TypeError, match=r"out\[3\]"):
            k.toSwerveModuleVelocitiesInto(cv, out)
        assert [m.velocity for m in out[:3]] == [7.0, 7.0, 7.0]

    @pytest.mark.parametrize("arr, exc, msg", [
        (np.zeros((3, 2)), ValueError, r"shape \(4, 2\)"),
        (np.zeros((4, 3)), ValueError, r"shape \(4, 2\)"),
        (np.zeros(8), ValueError, r"shape \(4, 2\)"),
        (np.zeros((4, 2), dtype=np.float32), TypeError, "float64"),
        (np.zeros((4, 2), dtype=np.int64), TypeError, "float64"),
        (np.zeros((4, 2), dtype=">f8"), TypeError, "float64"),
        (np.zeros((2, 4)).T, ValueError, "C-contiguous"),
        (np.zeros((4, 4))[:, ::2], ValueError, "C-contiguous"),
    ])
    def test_swerve_module_velocities_into_array(self, arr, exc, msg):
        with pytest.raises(exc, match=msg):
            swerve().toSwerveModuleVelocitiesInto(ChassisVelocities(1, 0, 0), arr)

    def test_swerve_module_velocities_into_read_only_array(self):
        arr = np.zeros((4, 2))
        arr.flags.writeable = False
        with pytest.raises(ValueError, match="writeable"):
            swerve().toSwerveModuleVelocitiesInto(ChassisVelocities(1, 0, 0), arr)

    def test_swerve_chassis_and_twist_into(self):
        k = swerve()
        with pytest.raises(TypeError, match="out"):
            k.toChassisVelocitiesInto([SwerveModuleVelocity() for _ in range(4)],
                                      ChassisAccelerations())
        with pytest.raises(TypeError, match="out"):
            k.toTwist2dInto([SwerveModulePosition() for _ in range(4)], Pose2d())
        with pytest.raises(TypeError, match="out"):
            k.toTwist2dInto([SwerveModulePosition() for _ in range(4)], None)


# =========================================================================================
# DifferentialDriveOdometry
# =========================================================================================
class TestDifferentialDriveOdometry:
    @pytest.mark.parametrize("gyro", [None, 0.0, Translation2d(), "0"])
    def test_gyro_must_be_rotation2d(self, gyro):
        with pytest.raises(TypeError, match="gyro_angle"):
            DifferentialDriveOdometry(gyro, 0.0, 0.0)
        odo = DifferentialDriveOdometry(ZERO, 0.0, 0.0)
        with pytest.raises(TypeError, match="gyro_angle"):
            odo.update(gyro, 1.0, 1.0)
        with pytest.raises(TypeError, match="gyro_angle"):
            odo.resetPosition(gyro, 0.0, 0.0, Pose2d())

    @pytest.mark.parametrize("left, right", [("1", 0.0), (0.0, None), ([1.0], 2.0)])
    def test_distances_must_be_numbers(self, left, right):
        with pytest.raises(TypeError, match="real number"):
            DifferentialDriveOdometry(ZERO, left, right)
        odo = DifferentialDriveOdometry(ZERO, 0.0, 0.0)
        with pytest.raises(TypeError, match="real number"):
            odo.update(ZERO, left, right)
        with pytest.raises(TypeError, match="real number"):
            odo.resetPosition(ZERO, left, right, Pose2d())
        # Nothing was half-applied.
        assert_pose(odo.update(ZERO, 1.0, 1.0), 1.0, 0.0, 0.0)

    def test_positions_object_is_not_accepted_for_distances(self):
        odo = DifferentialDriveOdometry(ZERO, 0.0, 0.0)
        with pytest.raises(TypeError):
            odo.update(ZERO, DifferentialDriveWheelPositions(1.0, 1.0))

    @pytest.mark.parametrize("pose", [(1.0, 2.0), Translation2d(), Rotation2d(), "origin"])
    def test_initial_pose_type(self, pose):
        with pytest.raises(TypeError, match="initial_pose must be a Pose2d"):
            DifferentialDriveOdometry(ZERO, 0.0, 0.0, pose)

    def test_reset_argument_types(self):
        odo = DifferentialDriveOdometry(ZERO, 0.0, 0.0)
        with pytest.raises(TypeError, match="pose"):
            odo.resetPosition(ZERO, 0.0, 0.0, None)
        with pytest.raises(TypeError, match="pose"):
            odo.resetPose(None)
        with pytest.raises(TypeError, match="pose"):
            odo.resetPose(Translation2d(1, 2))
        with pytest.raises(TypeError, match="translation"):
            odo.resetTranslation(Pose2d())
        with pytest.raises(TypeError, match="translation"):
            odo.resetTranslation((1.0, 2.0))
        with pytest.raises(TypeError, match="rotation"):
            odo.resetRotation(1.0)
        with pytest.raises(TypeError, match="rotation"):
            odo.resetRotation(None)
        assert_pose(odo.getPose(), 0.0, 0.0, 0.0)


# =========================================================================================
# MecanumDriveOdometry
# =========================================================================================
class TestMecanumDriveOdometry:
    def test_kinematics_type(self):
        for bad in (None, DifferentialDriveKinematics(0.5), swerve()):
            with pytest.raises(TypeError, match="kinematics"):
                MecanumDriveOdometry(bad, ZERO, MecanumDriveWheelPositions())

    def test_gyro_type(self):
        with pytest.raises(TypeError, match="gyro_angle"):
            MecanumDriveOdometry(mecanum(), None, MecanumDriveWheelPositions())
        odo = MecanumDriveOdometry(mecanum(), ZERO, MecanumDriveWheelPositions())
        with pytest.raises(TypeError, match="gyro_angle"):
            odo.update(0.0, MecanumDriveWheelPositions())

    @pytest.mark.parametrize("positions", [None, MecanumDriveWheelVelocities(),
                                           (1.0, 1.0, 1.0, 1.0), [1.0] * 4,
                                           DifferentialDriveWheelPositions(1, 1)])
    def test_wheel_positions_type(self, positions):
        with pytest.raises(TypeError, match="wheel_positions"):
            MecanumDriveOdometry(mecanum(), ZERO, positions)
        odo = MecanumDriveOdometry(mecanum(), ZERO, MecanumDriveWheelPositions())
        with pytest.raises(TypeError, match="wheel_positions"):
            odo.update(ZERO, positions)
        with pytest.raises(TypeError, match="wheel_positions"):
            odo.resetPosition(ZERO, positions, Pose2d())
        assert_pose(odo.update(ZERO, MecanumDriveWheelPositions(1, 1, 1, 1)), 1.0, 0.0, 0.0)

    def test_initial_pose_type(self):
        with pytest.raises(TypeError, match="initial_pose must be a Pose2d"):
            MecanumDriveOdometry(mecanum(), ZERO, MecanumDriveWheelPositions(),
                                 Transform2d())


# =========================================================================================
# SwerveDriveOdometry
# =========================================================================================
class TestSwerveDriveOdometry:
    def test_kinematics_type(self):
        for bad in (None, mecanum(), DifferentialDriveKinematics(0.5)):
            with pytest.raises(TypeError, match="kinematics"):
                SwerveDriveOdometry(bad, ZERO, [SwerveModulePosition() for _ in range(4)])

    def test_gyro_type(self):
        with pytest.raises(TypeError, match="gyro_angle"):
            SwerveDriveOdometry(swerve(), None, [SwerveModulePosition() for _ in range(4)])
        odo = swerve_odometry()
        with pytest.raises(TypeError, match="gyro_angle"):
            odo.update(None, [SwerveModulePosition() for _ in range(4)])
        with pytest.raises(TypeError, match="gyro_angle"):
            odo.resetPosition(90.0, [SwerveModulePosition() for _ in range(4)], Pose2d())

    @pytest.mark.parametrize("count", [0, 1, 3, 5, 8])
    def test_wrong_module_count(self, count):
        wrong = [SwerveModulePosition() for _ in range(count)]
        with pytest.raises(ValueError, match=f"expected 4 SwerveModulePosition objects.*got {count}"):
            SwerveDriveOdometry(swerve(), ZERO, wrong)
        odo = swerve_odometry()
        with pytest.raises(ValueError, match=f"expected 4 .*got {count}"):
            odo.update(ZERO, wrong)
        with pytest.raises(ValueError, match=f"expected 4 .*got {count}"):
            odo.resetPosition(ZERO, wrong, Pose2d(1, 1, ZERO))
        assert_pose(odo.getPose(), 0.0, 0.0, 0.0)

    @pytest.mark.parametrize("modules, msg", [
        (None, "module_positions must be a sequence"),
        (5, "module_positions must be a sequence"),
        ([SwerveModulePosition()] * 3 + [SwerveModuleVelocity()],
         r"module_positions\[3\] must be a SwerveModulePosition"),
        ([SwerveModulePosition()] * 3 + [None], r"module_positions\[3\]"),
        ([[0.0, 0.0]] * 4, r"module_positions\[0\] must be a SwerveModulePosition"),
        ([(1.0, ZERO)] * 4, r"module_positions\[0\]"),
    ])
    def test_module_position_types(self, modules, msg):
        with pytest.raises(TypeError, match=msg):
            SwerveDriveOdometry(swerve(), ZERO, modules)
        # update and resetPosition call the same argument wheel_positions (robotpy 2027).
        msg = msg.replace("module_positions", "wheel_positions")
        odo = swerve_odometry()
        with pytest.raises(TypeError, match=msg):
            odo.update(ZERO, modules)
        with pytest.raises(TypeError, match=msg):
            odo.resetPosition(ZERO, modules, Pose2d())

    @pytest.mark.parametrize("arr, exc, msg", [
        (np.zeros((3, 2)), ValueError, r"shape \(4, 2\), got \(3, 2\)"),
        (np.zeros((5, 2)), ValueError, r"shape \(4, 2\)"),
        (np.zeros((4, 3)), ValueError, r"shape \(4, 2\)"),
        (np.zeros((4, 1)), ValueError, r"shape \(4, 2\)"),
        (np.zeros(8), ValueError, r"shape \(4, 2\), got \(8,\)"),
        (np.zeros((4, 2, 1)), ValueError, r"shape \(4, 2\)"),
        (np.zeros((0, 2)), ValueError, r"shape \(4, 2\)"),
        (np.zeros((4, 2), dtype=np.float32), TypeError, "dtype float64.*float32"),
        (np.zeros((4, 2), dtype=np.int64), TypeError, "dtype float64.*int64"),
        (np.zeros((4, 2), dtype=np.complex128), TypeError, "dtype float64"),
        (np.zeros((4, 2), dtype=object), TypeError, "dtype float64"),
        (np.zeros((4, 2), dtype=">f8"), TypeError, "native byte order"),
        (np.zeros((2, 4)).T, ValueError, "C-contiguous"),
        (np.zeros((4, 4))[:, ::2], ValueError, "C-contiguous"),
        (np.zeros((8, 2))[::2], ValueError, "C-contiguous"),
    ])
    def test_bad_arrays(self, arr, exc, msg):
        with pytest.raises(exc, match=msg):
            SwerveDriveOdometry(swerve(), ZERO, arr)
        odo = swerve_odometry()
        with pytest.raises(exc, match=msg):
            odo.update(ZERO, arr)
        with pytest.raises(exc, match=msg):
            odo.resetPosition(ZERO, arr, Pose2d(3, 3, ZERO))
        # The failed calls changed nothing.
        assert_pose(odo.getPose(), 0.0, 0.0, 0.0)
        good = np.array([[1.0, 0.0]] * 4)
        assert_pose(odo.update(ZERO, good), 1.0, 0.0, 0.0)

    def test_read_only_array_is_accepted_for_input(self):
        arr = np.array([[2.0, 0.0]] * 4)
        arr.flags.writeable = False
        odo = swerve_odometry()
        assert_pose(odo.update(ZERO, arr), 2.0, 0.0, 0.0)

    def test_initial_pose_type(self):
        with pytest.raises(TypeError, match="initial_pose must be a Pose2d"):
            SwerveDriveOdometry(swerve(), ZERO, [SwerveModulePosition() for _ in range(4)],
                                Translation2d())

    def test_failed_update_leaves_state_intact(self):
        odo = swerve_odometry()
        odo.update(Rotation2d.fromDegrees(10), [SwerveModulePosition(1.0) for _ in range(4)])
        before = odo.getPose()
        bad = [SwerveModulePosition(50.0) for _ in range(3)] + ["not a module"]
        with pytest.raises(TypeError):
            odo.update(Rotation2d.fromDegrees(80), bad)
        assert odo.getPose() == before
        # Baselines are still gyro 10 deg and 1 m: no motion, no turn.
        after = odo.update(Rotation2d.fromDegrees(10), [SwerveModulePosition(1.0)] * 4)
        assert after == before
