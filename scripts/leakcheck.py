#!/usr/bin/env python3
"""Leak check: run every hot operation and every error path of drivekin many times and
fail if memory stays allocated afterwards.

For each row of OPERATIONS and ERRORS: warm up (fills freelists and caches), then
compare two probes before and after a loop of calls, with garbage collected at both ends:

* ``sys.getallocatedblocks()`` over ``--count`` calls (default 10**6): live pymalloc
  blocks, i.e. Python objects and small PyMem buffers. Cheap and exact, but blind to
  blocks over 512 bytes (and always 0 under PYTHONMALLOC=malloc, e.g. in the ASan run).
* tracemalloc's traced size over a tenth as many calls (tracemalloc slows allocation
  3-10x): every Python allocator domain at any size (drivekin's PyMem buffers, numpy
  array data), so a leaked large buffer shows too.

Growth beyond a fixed slack (which does not scale with the count) fails the row: a leak
of one block per 1000 calls is 1000 blocks at the default count. Error rows must raise
the listed exception; any other outcome fails the row too. A row may divide the count
by a third element (constructors solving a pseudo-inverse take ~0.5 ms a call).

Adding an operation is one line in OPERATIONS or ERRORS. Every class of the catalog
(``drivekin._core.catalog``) also gets rows of its own, from its entry: building its
``example``, and copying it (values and kinematics), so a new class is leak-checked by
its catalog entry alone. The shared fixtures' swerve, mecanum and differential
kinematics are the catalog's examples too. Exit status: 0 if every row passed, 1
otherwise (the failing rows are named), 2 for bad arguments.

    python scripts/leakcheck.py                  # 10**6 calls per row, about 3 minutes
    python scripts/leakcheck.py --count 20000 -k swerve
"""
from __future__ import annotations

import argparse
import copy
import gc
import itertools
import sys
import time
import tracemalloc

import numpy as np

from drivekin import (
    ChassisAccelerations, ChassisVelocities, DeadWheelKinematics, DeadWheelOdometry,
    DifferentialDriveKinematics, DifferentialDriveOdometry, DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities, MecanumDriveOdometry,
    MecanumDriveWheelPositions, MecanumDriveWheelVelocities, Pose2d, Rotation2d,
    SwerveDriveKinematics, SwerveDriveOdometry, SwerveModuleAcceleration,
    SwerveModulePosition, SwerveModuleVelocity, Transform2d, Translation2d, Twist2d,
    TwoDeadWheelOdometry, wpistruct,
)
from drivekin import (DifferentialDriveOdometry3d, Pose3d, Rotation3d, SwerveDriveOdometry3d,
                      SwerveDrivePoseEstimator3d, Translation3d)
from drivekin._core import catalog
from drivekin.geometry import _rotation_from_cos_sin as rotation_from_cos_sin

SLACK_BLOCKS = 64          # one-off effects: a method cache entry, a resized dict, ...
SLACK_BYTES = 64 * 1024
WARMUP = 1000



def example(kind, drivetrain):
    """A new instance of the catalog's ``kind`` class of ``drivetrain`` (its example)."""
    (entry,) = catalog.entries(kind, drivetrain=drivetrain)
    return entry.example()


# --- fixtures shared by the rows -------------------------------------------------------
swerve = example("kinematics", "swerve")        # 4 modules at (±0.3, ±0.3) m
mecanum = example("kinematics", "mecanum")      # wheels at the same points
diff = example("kinematics", "differential")    # trackwidth 0.6 m
CORNERS = list(swerve.getModules())
cv = ChassisVelocities(1.0, 0.5, 0.8)
ca = ChassisAccelerations(0.5, 0.2, 0.3)
angle = Rotation2d(0.3)
cor = Translation2d(0.1, 0.0)
pose = Pose2d(1.0, 2.0, Rotation2d(0.5))
twist = Twist2d(0.1, 0.02, 0.05)
states = [SwerveModuleVelocity(4.0 + i, Rotation2d(0.1 * i)) for i in range(4)]
states_arr = np.array([[4.0 + i, 0.1 * i] for i in range(4)])
positions = [SwerveModulePosition(0.1 * i, Rotation2d(0.1 * i)) for i in range(4)]
positions_arr = np.array([[0.1 * i, 0.1 * i] for i in range(4)])
accels = [SwerveModuleAcceleration(1.0, Rotation2d(0.1 * i)) for i in range(4)]
out_states = [SwerveModuleVelocity() for _ in range(4)]
out_arr = np.zeros((4, 2))
out_cv, out_twist = ChassisVelocities(), Twist2d()
mwv = MecanumDriveWheelVelocities(5.0, 4.0, 3.0, 2.0)
mwp = MecanumDriveWheelPositions(0.1, 0.2, 0.3, 0.4)
out_mwv = MecanumDriveWheelVelocities()
dwv = DifferentialDriveWheelVelocities(5.0, 4.0)
out_dwv = DifferentialDriveWheelVelocities()
swerve_odo = SwerveDriveOdometry(swerve, Rotation2d(), positions)
mecanum_odo = MecanumDriveOdometry(mecanum, Rotation2d(), mwp)
diff_odo = DifferentialDriveOdometry(Rotation2d(), 0.0, 0.0)
packed_pose = wpistruct.pack(pose)
packed_swerve = wpistruct.pack(swerve)
packed_poses = wpistruct.packArray([pose] * 3)
buf = bytearray(64)
distinct = itertools.count()
# More modules than the desaturation's stack buffer holds: its heap path.
many_states = [SwerveModuleVelocity(4.0 + i, Rotation2d(0.01 * i)) for i in range(40)]
many_bad = many_states[:39] + [None]

# Dead wheels: three that observe rotation, and two that need the gyro.
DW_POSES = [Pose2d(0.0, 0.18, Rotation2d(0.0)), Pose2d(0.02, -0.16, Rotation2d(0.0)),
            Pose2d(-0.1, 0.01, Rotation2d.fromDegrees(90.0))]
deadwheel = DeadWheelKinematics(DW_POSES)
deadwheel2 = DeadWheelKinematics.fromRoadRunnerTwoWheel(-2000.0, -1500.0, 0.002)
dw_list = [0.1, -0.2, 0.3]
dw_arr = np.array(dw_list)
dw_strided = np.repeat(dw_arr, 2)[::2]
out_dw = np.zeros(3)
dw_odo = DeadWheelOdometry(deadwheel, dw_list)
dw_gyro_odo = DeadWheelOdometry(deadwheel, dw_list, angle)
two_dw_odo = TwoDeadWheelOdometry(0.1, -0.15, 0.0, 0.0, angle)


class BadFloat:
    def __float__(self):
        raise ArithmeticError("from __float__")


def new_state_copies():      # fresh, mutable inputs for the in-place desaturation
    for s, v in zip(states, (4.0, 5.0, 6.0, 7.0)):
        s.velocity = v
    return states


# (name, callable[, count divisor]): each callable is called with no arguments.
OPERATIONS = [
    ("Rotation2d(x)", lambda: Rotation2d(0.7)),
    ("Pose2d(x, y, rot)", lambda: Pose2d(1.0, 2.0, angle)),
    ("pose.exp(twist)", lambda: pose.exp(twist)),
    ("twist.exp()", lambda: twist.exp()),
    ("pose.plus(transform)", lambda: pose.plus(Transform2d(1.0, 0.0, angle))),
    ("pose.log(end)", lambda: pose.log(Pose2d(2.0, 1.0, angle))),
    ("cv.discretize", lambda: cv.discretize(0.02)),
    ("cv.discretizeInto", lambda: cv.discretizeInto(0.02, out_cv)),
    ("cv.toRobotRelative", lambda: cv.toRobotRelative(angle)),
    ("cv.toFieldRelative", lambda: cv.toFieldRelative(angle)),
    ("cv.toRobotRelativeInto", lambda: cv.toRobotRelativeInto(angle, out_cv)),
    ("cv.toFieldRelativeInto", lambda: cv.toFieldRelativeInto(angle, out_cv)),
    ("swerve IK", lambda: swerve.toSwerveModuleVelocities(cv)),
    ("swerve IK about a CoR", lambda: swerve.toSwerveModuleVelocities(cv, cor)),
    ("swerve IK Into list", lambda: swerve.toSwerveModuleVelocitiesInto(cv, out_states)),
    ("swerve IK Into ndarray", lambda: swerve.toSwerveModuleVelocitiesInto(cv, out_arr)),
    ("swerve FK list", lambda: swerve.toChassisVelocities(states)),
    ("swerve FK ndarray", lambda: swerve.toChassisVelocities(states_arr)),
    ("swerve FK Into list", lambda: swerve.toChassisVelocitiesInto(states, out_cv)),
    ("swerve FK Into ndarray", lambda: swerve.toChassisVelocitiesInto(states_arr, out_cv)),
    ("swerve toTwist2d deltas", lambda: swerve.toTwist2d(positions)),
    ("swerve toTwist2d start end", lambda: swerve.toTwist2d(positions, positions)),
    ("swerve toTwist2dInto list", lambda: swerve.toTwist2dInto(positions, out_twist)),
    ("swerve toTwist2dInto ndarray", lambda: swerve.toTwist2dInto(positions_arr, out_twist)),
    ("swerve accelerations", lambda: swerve.toSwerveModuleAccelerations(ca, 1.0)),
    ("swerve toChassisAccelerations", lambda: swerve.toChassisAccelerations(accels)),
    ("swerve interpolate", lambda: swerve.interpolate(positions, positions, 0.5)),
    ("swerve resetHeadings", lambda: swerve.resetHeadings([angle] * 4)),
    ("desaturate", lambda: SwerveDriveKinematics.desaturateWheelVelocities(states, 4.5)),
    ("desaturate 5-arg", lambda: SwerveDriveKinematics.desaturateWheelVelocities(
        states, cv, 4.5, 4.0, 6.0)),
    ("desaturateInPlace list", lambda: SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(
        new_state_copies(), 4.5)),
    ("desaturateInPlace ndarray", lambda: SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(
        states_arr, 4.5)),
    ("desaturateInPlace 5-arg", lambda: SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(
        new_state_copies(), cv, 4.5, 4.0, 6.0)),
    ("SwerveDriveKinematics()", lambda: SwerveDriveKinematics(*CORNERS), 100),
    ("mecanum IK", lambda: mecanum.toWheelVelocities(cv)),
    ("mecanum IK Into", lambda: mecanum.toWheelVelocitiesInto(cv, out_mwv)),
    ("mecanum FK", lambda: mecanum.toChassisVelocities(mwv)),
    ("mecanum FK Into", lambda: mecanum.toChassisVelocitiesInto(mwv, out_cv)),
    ("mecanum toTwist2d", lambda: mecanum.toTwist2d(mwp, mwp)),
    ("mecanum desaturate", lambda: mwv.desaturate(4.5)),
    ("mecanum desaturateInPlace", lambda: out_mwv.desaturateInPlace(4.5)),
    ("differential IK", lambda: diff.toWheelVelocities(cv)),
    ("differential IK Into", lambda: diff.toWheelVelocitiesInto(cv, out_dwv)),
    ("differential FK", lambda: diff.toChassisVelocities(dwv)),
    ("differential FK Into", lambda: diff.toChassisVelocitiesInto(dwv, out_cv)),
    ("differential toTwist2d", lambda: diff.toTwist2d(0.1, 0.2)),
    ("differential desaturate", lambda: dwv.desaturate(4.5)),
    ("differential desaturateInPlace", lambda: out_dwv.desaturateInPlace(4.5)),
    ("swerve odometry update list", lambda: swerve_odo.update(angle, positions)),
    ("swerve odometry update ndarray", lambda: swerve_odo.update(angle, positions_arr)),
    ("swerve odometry resetPosition", lambda: swerve_odo.resetPosition(angle, positions, pose)),
    ("SwerveDriveOdometry()", lambda: SwerveDriveOdometry(swerve, angle, positions)),
    ("mecanum odometry update", lambda: mecanum_odo.update(angle, mwp)),
    ("differential odometry update", lambda: diff_odo.update(angle, 0.1, 0.2)),
    ("wpistruct.pack Pose2d", lambda: wpistruct.pack(pose)),
    ("wpistruct.pack swerve", lambda: wpistruct.pack(swerve)),
    ("wpistruct.packInto", lambda: wpistruct.packInto(pose, buf, 8)),
    ("wpistruct.packArray", lambda: wpistruct.packArray([pose, pose, pose])),
    ("wpistruct.unpack Pose2d", lambda: wpistruct.unpack(Pose2d, packed_pose)),
    ("wpistruct.unpack swerve", lambda: wpistruct.unpack(SwerveDriveKinematics, packed_swerve),
     100),
    ("wpistruct.unpackArray", lambda: wpistruct.unpackArray(Pose2d, packed_poses)),
    # Issue 6 defect 13: a cache keyed by module count must stay bounded.
    ("wpistruct.getSize(numModules=many n)", lambda: wpistruct.getSize(
        SwerveDriveKinematics, numModules=2 + next(distinct) % 100_000)),
    ("str(pose)", lambda: str(pose)),
    ("desaturate 40 modules", lambda: SwerveDriveKinematics.desaturateWheelVelocities(
        many_states, 4.5)),
    ("swerve copy", lambda: swerve.copy(positions)),
    ("copy.copy(swerve)", lambda: copy.copy(swerve), 10),
    ("swerve __setstate__", lambda: swerve.__setstate__((angle,) * 4)),
    ("Pose2d(keywords)", lambda: Pose2d(translation=cor, rotation=angle)),
    ("pose.nearest", lambda: pose.nearest([pose, pose])),
    ("deadwheel FK list", lambda: deadwheel.toChassisVelocities(dw_list)),
    ("deadwheel FK ndarray", lambda: deadwheel.toChassisVelocities(dw_arr)),
    ("deadwheel FK strided ndarray", lambda: deadwheel.toChassisVelocities(dw_strided)),
    ("deadwheel FK gyro", lambda: deadwheel.toChassisVelocities(dw_list, 0.3)),
    ("deadwheel FK 2 wheels gyro", lambda: deadwheel2.toChassisVelocities((0.1, 0.2), 0.3)),
    ("deadwheel FK Into", lambda: deadwheel.toChassisVelocitiesInto(dw_list, out_cv)),
    ("deadwheel FK Into gyro ndarray", lambda: deadwheel.toChassisVelocitiesInto(
        dw_arr, out_cv, 0.3)),
    ("deadwheel IK", lambda: deadwheel.toWheelVelocities(cv)),
    ("deadwheel IK Into", lambda: deadwheel.toWheelVelocitiesInto(cv, out_dw)),
    ("deadwheel toTwist2d", lambda: deadwheel.toTwist2d(dw_list)),
    ("deadwheel toTwist2d gyro ndarray", lambda: deadwheel.toTwist2d(dw_arr, 0.02)),
    ("deadwheel toChassisAccelerations", lambda: deadwheel.toChassisAccelerations(dw_list)),
    ("deadwheel toWheelAccelerations", lambda: deadwheel.toWheelAccelerations(ca)),
    ("deadwheel getWheelPoses", lambda: deadwheel.getWheelPoses()),
    ("DeadWheelKinematics()", lambda: DeadWheelKinematics(DW_POSES), 100),
    ("DeadWheelKinematics.fromRoadRunner", lambda: DeadWheelKinematics.fromRoadRunner(
        -962.0, 912.0, -500.0, 0.002), 100),
    ("DeadWheelKinematics.fromRoadRunnerTwoWheel", lambda: DeadWheelKinematics
        .fromRoadRunnerTwoWheel(-962.0, -500.0, 0.002), 100),
    ("copy.copy(deadwheel)", lambda: copy.copy(deadwheel), 100),
    ("deadwheel odometry update list", lambda: dw_odo.update(dw_list)),
    ("deadwheel odometry update ndarray", lambda: dw_odo.update(dw_arr)),
    ("deadwheel odometry update gyro", lambda: dw_gyro_odo.update(dw_strided, angle)),
    ("deadwheel odometry resetPosition", lambda: dw_gyro_odo.resetPosition(
        dw_arr, angle, pose)),
    ("DeadWheelOdometry()", lambda: DeadWheelOdometry(deadwheel, dw_list, angle, pose)),
    ("two-dead-wheel odometry update", lambda: two_dw_odo.update(0.1, 0.2, angle)),
    ("two-dead-wheel odometry resetPosition", lambda: two_dw_odo.resetPosition(
        0.1, 0.2, angle, pose)),
    ("two-dead-wheel toChassisVelocities", lambda: two_dw_odo.toChassisVelocities(
        1.0, 0.5, 0.3)),
    ("TwoDeadWheelOdometry()", lambda: TwoDeadWheelOdometry(0.1, -0.15, 0.0, 0.0, angle, pose)),
]

# (name, callable, exception the call must raise)
ERRORS = [
    ("Rotation2d(str)", lambda: Rotation2d("x"), TypeError),
    ("Rotation2d(raising __float__)", lambda: Rotation2d(BadFloat()), ArithmeticError),
    ("Pose2d(x, y) missing rotation", lambda: Pose2d(1.0, 2.0), TypeError),
    ("pose.exp(None)", lambda: pose.exp(None), TypeError),
    ("cv.discretize(str)", lambda: cv.discretize("x"), TypeError),
    ("cv.toRobotRelativeInto(wrong out)", lambda: cv.toRobotRelativeInto(angle, pose), TypeError),
    ("swerve IK(None)", lambda: swerve.toSwerveModuleVelocities(None), TypeError),
    ("swerve IK Into short list", lambda: swerve.toSwerveModuleVelocitiesInto(
        cv, out_states[:3]), ValueError),
    ("swerve IK Into None element", lambda: swerve.toSwerveModuleVelocitiesInto(
        cv, out_states[:3] + [None]), TypeError),
    ("swerve IK Into float32", lambda: swerve.toSwerveModuleVelocitiesInto(
        cv, np.zeros((4, 2), np.float32)), TypeError),
    ("swerve IK Into wrong shape", lambda: swerve.toSwerveModuleVelocitiesInto(
        cv, np.zeros((3, 2))), ValueError),
    ("swerve FK None element", lambda: swerve.toChassisVelocities(states[:3] + [None]), TypeError),
    ("swerve FK wrong length", lambda: swerve.toChassisVelocities(states[:3]), ValueError),
    ("swerve FK int64 array", lambda: swerve.toChassisVelocities(
        np.zeros((4, 2), np.int64)), TypeError),
    ("swerve toTwist2dInto wrong element", lambda: swerve.toTwist2dInto(
        states, out_twist), TypeError),
    ("desaturate None element", lambda: SwerveDriveKinematics.desaturateWheelVelocities(
        states[:3] + [None], 4.5), TypeError),
    ("desaturate bad max", lambda: SwerveDriveKinematics.desaturateWheelVelocities(
        states, "x"), TypeError),
    ("desaturateInPlace float32", lambda: SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(
        np.zeros((4, 2), np.float32), 4.5), TypeError),
    ("SwerveDriveKinematics(one module)", lambda: SwerveDriveKinematics(CORNERS[0]), ValueError),
    ("mecanum IK Into wrong out", lambda: mecanum.toWheelVelocitiesInto(cv, out_dwv), TypeError),
    ("mecanum FK(None)", lambda: mecanum.toChassisVelocities(None), TypeError),
    ("differential toTwist2d(str, str)", lambda: diff.toTwist2d("a", "b"), TypeError),
    ("DifferentialDriveKinematics(-1)", lambda: DifferentialDriveKinematics(-1.0), ValueError),
    ("swerve odometry update short", lambda: swerve_odo.update(angle, positions[:3]), ValueError),
    ("swerve odometry update None gyro", lambda: swerve_odo.update(None, positions), TypeError),
    ("swerve odometry update float32", lambda: swerve_odo.update(
        angle, positions_arr.astype(np.float32)), TypeError),
    ("mecanum odometry update(None)", lambda: mecanum_odo.update(angle, None), TypeError),
    ("wpistruct.pack(object)", lambda: wpistruct.pack(object()), TypeError),
    ("wpistruct.packInto short buffer", lambda: wpistruct.packInto(pose, bytearray(8)), ValueError),
    ("wpistruct.packInto read-only", lambda: wpistruct.packInto(pose, bytes(24)), TypeError),
    ("wpistruct.unpack short data", lambda: wpistruct.unpack(Pose2d, b"\0" * 8), ValueError),
    ("wpistruct.unpack(str)", lambda: wpistruct.unpack(Pose2d, "abc"), TypeError),
    ("desaturate 40 modules, None element", lambda: SwerveDriveKinematics
        .desaturateWheelVelocities(many_bad, 4.5), TypeError),
    ("swerve interpolate None element", lambda: swerve.interpolate(
        positions, positions[:3] + [None], 0.5), TypeError),
    ("swerve __setstate__ short", lambda: swerve.__setstate__((angle,) * 3), ValueError),
    ("swerve re-init", lambda: swerve.__init__(*CORNERS), TypeError),
    ("uninitialised kinematics", lambda: SwerveDriveKinematics.__new__(
        SwerveDriveKinematics).toWheelVelocities(cv), RuntimeError),
    ("Rotation2d re-init", lambda: angle.__init__(1.0), TypeError),
    ("Translation2d(vector, extra)", lambda: Translation2d(np.zeros(2), 1.0), TypeError),
    ("pose.nearest None element", lambda: pose.nearest([pose, None]), TypeError),
    ("unpickle non-unit rotation", lambda: rotation_from_cos_sin(2.0, 0.0), ValueError),
    ("memoryview for an array", lambda: swerve.toChassisVelocities(
        memoryview(states_arr)), TypeError),
    ("deadwheel FK short list", lambda: deadwheel.toChassisVelocities(dw_list[:2]), ValueError),
    ("deadwheel FK None element", lambda: deadwheel.toChassisVelocities(
        [0.1, None, 0.3]), TypeError),
    ("deadwheel FK huge int", lambda: deadwheel.toChassisVelocities(
        [0.1, 10 ** 400, 0.3]), ValueError),
    ("deadwheel FK float32", lambda: deadwheel.toChassisVelocities(
        dw_arr.astype(np.float32)), TypeError),
    ("deadwheel FK generator", lambda: deadwheel.toChassisVelocities(
        x for x in dw_list), TypeError),
    ("deadwheel FK str gyro", lambda: deadwheel.toChassisVelocities(dw_list, "x"), TypeError),
    ("deadwheel FK gyro raising __float__", lambda: deadwheel.toChassisVelocities(
        dw_list, BadFloat()), ArithmeticError),
    ("deadwheel FK needs a gyro", lambda: deadwheel2.toChassisVelocities(
        [0.1, 0.2]), ValueError),
    ("deadwheel IK Into wrong shape", lambda: deadwheel.toWheelVelocitiesInto(
        cv, np.zeros(2)), ValueError),
    ("deadwheel IK Into float32", lambda: deadwheel.toWheelVelocitiesInto(
        cv, np.zeros(3, np.float32)), TypeError),
    ("DeadWheelKinematics(parallel)", lambda: DeadWheelKinematics(
        DW_POSES[:2] + [Pose2d(0.3, 0.0, Rotation2d.fromDegrees(180.0))]), ValueError),
    ("DeadWheelKinematics(nan pose)", lambda: DeadWheelKinematics(
        DW_POSES[:2] + [Pose2d(float("nan"), 0.0, angle)]), ValueError),
    ("DeadWheelKinematics(None element)", lambda: DeadWheelKinematics(
        DW_POSES[:2] + [None]), TypeError),
    ("fromRoadRunner(in_per_tick 0)", lambda: DeadWheelKinematics.fromRoadRunner(
        -962.0, 912.0, -500.0, 0.0), ValueError),
    ("deadwheel re-init", lambda: deadwheel.__init__(DW_POSES), TypeError),
    ("uninitialised deadwheel", lambda: DeadWheelKinematics.__new__(
        DeadWheelKinematics).toChassisVelocities(dw_list), RuntimeError),
    ("deadwheel odometry update unexpected gyro", lambda: dw_odo.update(dw_list, angle),
     ValueError),
    ("deadwheel odometry update missing gyro", lambda: dw_gyro_odo.update(dw_list), TypeError),
    ("deadwheel odometry update None element", lambda: dw_odo.update([0.1, 0.2, None]),
     TypeError),
    ("deadwheel odometry resetPosition float32", lambda: dw_gyro_odo.resetPosition(
        dw_arr.astype(np.float32), angle, pose), TypeError),
    ("DeadWheelOdometry(needs a gyro)", lambda: DeadWheelOdometry(deadwheel2, [0.0, 0.0]),
     ValueError),
    ("DeadWheelOdometry(bad wheels)", lambda: DeadWheelOdometry(
        deadwheel, [0.0, None, 0.0], angle), TypeError),
    ("DeadWheelOdometry re-init", lambda: dw_odo.__init__(deadwheel, dw_list), TypeError),
    ("TwoDeadWheelOdometry(nan offset)", lambda: TwoDeadWheelOdometry(
        float("nan"), 0.0, 0.0, 0.0, angle), ValueError),
]

# --- differential swerve (drivekin.diffswerve) -----------------------------------------
from drivekin import (  # noqa: E402
    DifferentialSwerveModuleKinematics, DifferentialSwerveModuleVelocities,
    DifferentialSwerveMotorVelocities,
)

dsk = DifferentialSwerveModuleKinematics(3.0, 5.0, 0.05, motor2_inverted=True)
dsk.resetModulePosition(angle, 12.0, -7.0)
ds_motors, ds_module, ds_pos = (DifferentialSwerveMotorVelocities(),
                                DifferentialSwerveModuleVelocities(), SwerveModulePosition())
ds_rates, ds_rates_arr = [1.0, -2.0, 4.0, 0.5], np.array([1.0, -2.0, 4.0, 0.5])
many_rates = [0.01 * i for i in range(40)]


def ds_saturated():            # fresh over-the-limit motors for the in-place desaturation
    ds_motors.motor1, ds_motors.motor2 = 280.0, 220.0
    return ds_motors


OPERATIONS += [
    ("diffswerve toMotorVelocities", lambda: dsk.toMotorVelocities(1.5, -2.0)),
    ("diffswerve toMotorVelocitiesInto", lambda: dsk.toMotorVelocitiesInto(1.5, -2.0, ds_motors)),
    ("diffswerve toModuleVelocities", lambda: dsk.toModuleVelocities(120.0, -80.0)),
    ("diffswerve toModuleVelocitiesInto", lambda: dsk.toModuleVelocitiesInto(
        120.0, -80.0, ds_module)),
    ("diffswerve toModulePosition", lambda: dsk.toModulePosition(30.0, -25.0)),
    ("diffswerve toModulePositionInto", lambda: dsk.toModulePositionInto(30.0, -25.0, ds_pos)),
    ("diffswerve resetModulePosition", lambda: dsk.resetModulePosition(angle, 12.0, -7.0)),
    ("diffswerve desaturateMotorVelocities", lambda: dsk.desaturateMotorVelocities(
        ds_saturated(), 200.0)),
    ("diffswerve desaturateMotorVelocitiesInPlace", lambda: dsk.desaturateMotorVelocitiesInPlace(
        ds_saturated(), 200.0)),
    ("diffswerve desaturateMotorVelocitiesInPlace proportional",
     lambda: dsk.desaturateMotorVelocitiesInPlace(ds_saturated(), 200.0, proportional=True)),
    ("diffswerve desaturateModuleVelocitiesInPlace list", lambda: dsk
        .desaturateModuleVelocitiesInPlace(new_state_copies(), ds_rates, 400.0)),
    ("diffswerve desaturateModuleVelocitiesInPlace ndarray", lambda: dsk
        .desaturateModuleVelocitiesInPlace(states_arr, ds_rates_arr, 400.0)),
    ("diffswerve desaturateModuleVelocitiesInPlace 40 modules", lambda: dsk
        .desaturateModuleVelocitiesInPlace(many_states, many_rates, 1e6)),
    ("DifferentialSwerveModuleKinematics()", lambda: DifferentialSwerveModuleKinematics(
        3.0, 5.0, 0.05, motor2_inverted=True)),
    ("copy.copy(diffswerve kinematics)", lambda: copy.copy(dsk)),
]

ERRORS += [
    ("DifferentialSwerveModuleKinematics(zero ratio)", lambda: DifferentialSwerveModuleKinematics(
        0.0, 5.0, 0.05), ValueError),
    ("DifferentialSwerveModuleKinematics(inf radius)", lambda: DifferentialSwerveModuleKinematics(
        3.0, 5.0, float("inf")), ValueError),
    ("diffswerve toMotorVelocitiesInto wrong out", lambda: dsk.toMotorVelocitiesInto(
        1.0, 2.0, ds_module), TypeError),
    ("diffswerve resetModulePosition NaN", lambda: dsk.resetModulePosition(
        angle, float("nan"), 0.0), ValueError),
    ("diffswerve desaturate negative limit", lambda: dsk.desaturateMotorVelocities(
        ds_motors, -1.0), ValueError),
    ("diffswerve desaturate proportional=1", lambda: dsk.desaturateMotorVelocities(
        ds_motors, 1.0, proportional=1), TypeError),
    ("diffswerve drive level short rates", lambda: dsk.desaturateModuleVelocitiesInPlace(
        states, ds_rates[:3], 400.0), ValueError),
    ("diffswerve drive level None rate", lambda: dsk.desaturateModuleVelocitiesInPlace(
        states, [1.0, None, 1.0, 1.0], 400.0), TypeError),
    ("diffswerve drive level None module", lambda: dsk.desaturateModuleVelocitiesInPlace(
        states[:3] + [None], ds_rates, 400.0), TypeError),
    ("diffswerve drive level float32 rates", lambda: dsk.desaturateModuleVelocitiesInPlace(
        states_arr, ds_rates_arr.astype(np.float32), 400.0), TypeError),
    ("diffswerve drive level 40 modules, 39 rates", lambda: dsk
        .desaturateModuleVelocitiesInPlace(many_states, many_rates[:39], 1e6), ValueError),
    ("diffswerve drive level 40 modules, bad rate", lambda: dsk
        .desaturateModuleVelocitiesInPlace(many_states, many_rates[:39] + ["x"], 1e6),
     TypeError),
    ("diffswerve __setstate__ NaN", lambda: dsk.__setstate__((angle, float("nan"), 0.0)),
     ValueError),
    ("uninitialised diffswerve kinematics", lambda: DifferentialSwerveModuleKinematics.__new__(
        DifferentialSwerveModuleKinematics).toModulePosition(0.0, 0.0), RuntimeError),
]

# --- the setpoint generator (drivekin.setpoint) ----------------------------------------
import drivekin.batch as _batch  # noqa: E402
from drivekin import (  # noqa: E402
    ChassisVelocities, DriveFeedforwards, PathConstraints, SwerveSetpoint,
    SwerveSetpointGenerator,
)

sp_gen = SwerveSetpointGenerator(catalog.BY_CLASS[SwerveSetpointGenerator].example().config,
                                 10.0)
sp_prev = catalog.BY_CLASS[SwerveSetpoint].example()
sp_out = catalog.BY_CLASS[SwerveSetpoint].example()
sp_cmd = ChassisVelocities(3.0, 1.0, 2.0)
sp_limits = PathConstraints(2.0, 3.0, 4.0, 5.0)
sp_rows = np.tile([3.0, 1.0, 2.0], (8, 1))
OPERATIONS += [
    ("generateSetpoint", lambda: sp_gen.generateSetpoint(sp_prev, sp_cmd, 0.02, 11.0, sp_limits)),
    ("generateSetpointInto", lambda: sp_gen.generateSetpointInto(sp_prev, sp_cmd, 0.02, sp_out)),
    ("batch.generateSetpoints", lambda: _batch.generateSetpoints(sp_gen, sp_prev, sp_rows, 0.02),
     10),
]
ERRORS += [
    ("generateSetpoint dt=0", lambda: sp_gen.generateSetpoint(sp_prev, sp_cmd, 0.0), ValueError),
    ("generateSetpointInto 3-module out", lambda: sp_gen.generateSetpointInto(
        sp_prev, sp_cmd, 0.02, SwerveSetpoint(sp_cmd, sp_prev.moduleVelocities[:3],
                                              DriveFeedforwards.zeros(3))), ValueError),
    ("DriveFeedforwards bad last row", lambda: DriveFeedforwards(
        [1.0, 2.0], [1.0, 2.0], [1.0, 2.0], [1.0, 2.0], [1.0, "x"]), TypeError),
    ("batch.generateSetpoints NaN row", lambda: _batch.generateSetpoints(
        sp_gen, sp_prev, np.full((4, 3), np.nan), 0.02), ValueError),
]

# --- 3-D odometry and pose estimators ---------------------------------------------------
gyro3 = Rotation3d(0.1, -0.2, 0.3)
pose3 = Pose3d(1.0, 2.0, 0.1, Rotation3d(0.05, 0.0, 0.4))
swerve_odo3 = SwerveDriveOdometry3d(swerve, Rotation3d(), positions)
swerve_est3 = SwerveDrivePoseEstimator3d(swerve, Rotation3d(), positions, Pose3d())
est3_clock = itertools.count(0.0, 0.02).__next__


def est3_step_and_vision():
    # The history slides and the records stay bounded: one update, one measurement 50 ms
    # old, on the same clock.
    t = est3_clock()
    swerve_est3.updateWithTime(t, gyro3, positions)
    swerve_est3.addVisionMeasurement(pose3, t - 0.05, (0.5, 0.5, 0.5, 0.5))


OPERATIONS += [
    ("swerve odometry3d update list", lambda: swerve_odo3.update(gyro3, positions)),
    ("swerve odometry3d update ndarray", lambda: swerve_odo3.update(gyro3, positions_arr)),
    ("swerve odometry3d resetPosition", lambda: swerve_odo3.resetPosition(
        gyro3, positions, pose3)),
    ("swerve odometry3d resetRotation", lambda: swerve_odo3.resetRotation(gyro3)),
    ("swerve estimator3d updateWithTime + addVisionMeasurement", est3_step_and_vision),
    ("swerve estimator3d sampleAt", lambda: swerve_est3.sampleAt(0.5)),
    ("swerve estimator3d resetTranslation", lambda: swerve_est3.resetTranslation(
        Translation3d(1.0, 2.0, 3.0))),
]
ERRORS += [
    ("swerve odometry3d update short", lambda: swerve_odo3.update(gyro3, positions[:3]),
     ValueError),
    ("swerve odometry3d update 2-D gyro", lambda: swerve_odo3.update(angle, positions),
     TypeError),
    ("swerve estimator3d 3 std devs", lambda: swerve_est3.setVisionMeasurementStdDevs(
        (0.5, 0.5, 0.5)), ValueError),
    ("swerve estimator3d 2-D vision pose", lambda: swerve_est3.addVisionMeasurement(
        pose, 0.0), TypeError),
]

# --- drivekin.batch's compositions and 3-D forms --------------------------------------
b3_frames = np.tile([1.0, 2.0, 0.5, 0.9, 0.1, -0.2, 0.3], (8, 1))
b3_twists = np.tile([0.1, 0.2, 0.0, 0.01, 0.02, 0.3], (8, 1))
b3_gyro = np.tile([1.0, 0.0, 0.0, 0.0], (8, 1))
b3_odometry = catalog.BY_CLASS[DifferentialDriveOdometry3d].example()
OPERATIONS += [
    ("batch.transformBy 3-D", lambda: _batch.transformBy(b3_frames, b3_frames[0])),
    ("batch.relativeTo 2-D", lambda: _batch.relativeTo(sp_rows, sp_rows)),
    ("batch.exp 3-D", lambda: _batch.exp(b3_twists)),
    ("batch.log 3-D", lambda: _batch.log(b3_frames)),
    ("batch.replay 3-D", lambda: _batch.replay(b3_odometry, b3_gyro, np.zeros((8, 2))), 10),
]
ERRORS += [
    ("batch.transformBy 3-D lengths", lambda: _batch.transformBy(b3_frames, b3_frames[:7]),
     ValueError),
    ("batch.replay 3-D gyro (N,)", lambda: _batch.replay(b3_odometry, np.zeros(8),
                                                         np.zeros((8, 2))), ValueError),
]

# --- every catalogued class, from its entry --------------------------------------------
# Examples that build kinematics solve a pseudo-inverse (up to ~0.1 ms a call): those
# kinds run a hundredth of the count; the helpers (a buffer filled in Python, ~4 µs) and
# a copy (~2 µs through copyreg) a tenth at most.
EXAMPLE_DIVISOR = {"kinematics": 100, "odometry": 100, "estimator": 100, "odometry3d": 100,
                   "estimator3d": 100, "helper": 10}

for _e in catalog.ENTRIES:
    if _e.example is None:
        continue                                  # no instances (Units)
    _div = EXAMPLE_DIVISOR.get(_e.kind, 1)
    OPERATIONS.append((f"{_e.cls.__name__} example", _e.example, _div))
    if _e.kind in ("value", "kinematics"):        # odometry and estimators do not copy
        OPERATIONS.append((f"copy.copy({_e.cls.__name__} example)",
                           lambda obj=_e.example(): copy.copy(obj), max(_div, 10)))


def expect(fn, exc):
    """A callable that runs ``fn`` and requires it to raise ``exc``."""
    def call():
        try:
            fn()
        except exc:
            return
        raise AssertionError(f"did not raise {exc.__name__}")
    return call


def measure(fn, count):
    """(block growth over ``count`` calls, traced-byte growth over ``count // 10``)."""
    # Warm up twice around a full collection: some one-off allocations (dozens of blocks,
    # e.g. caches behind an error message) happen only after the first gc.collect() and
    # would otherwise count as growth in short runs.
    for _ in range(2):
        for _ in itertools.repeat(None, WARMUP):
            fn()
        gc.collect()
    loop = itertools.repeat(None, count)
    start = sys.getallocatedblocks()
    for _ in loop:
        fn()
    gc.collect()
    blocks = sys.getallocatedblocks() - start
    loop = itertools.repeat(None, max(count // 10, 1))
    tracemalloc.start()
    try:
        gc.collect()
        start = tracemalloc.get_traced_memory()[0]
        for _ in loop:
            fn()
        gc.collect()
        return blocks, tracemalloc.get_traced_memory()[0] - start
    finally:
        tracemalloc.stop()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=1_000_000, help="calls per row (default 10**6)")
    ap.add_argument("-k", dest="only", default="", help="only rows whose name contains this")
    args = ap.parse_args(argv)
    if args.count < 1:
        ap.error("--count must be positive")
    rows = [(n, f, d) for n, f, d in ((*r, 1)[:3] for r in OPERATIONS)]
    rows += [(n, expect(f, e), 1) for n, f, e in ERRORS]
    rows = [r for r in rows if args.only in r[0]]
    failed = []
    t_all = time.perf_counter()
    for name, fn, divisor in rows:
        t0 = time.perf_counter()
        try:
            blocks, nbytes = measure(fn, max(args.count // divisor, 1))
        except Exception as e:                         # noqa: BLE001 -- reported, then fail
            failed.append(name)
            print(f"FAIL {name}: {type(e).__name__}: {e}")
            continue
        ok = blocks <= SLACK_BLOCKS and nbytes <= SLACK_BYTES
        if not ok:
            failed.append(name)
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {blocks:+d} blocks, {nbytes:+d} B "
              f"({time.perf_counter() - t0:.1f} s)", flush=True)
    print(f"{len(rows)} rows, up to {args.count} calls each, {time.perf_counter() - t_all:.0f} s")
    if failed:
        print("leak check FAILED: " + "; ".join(failed))
        return 1
    print("leak check passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
