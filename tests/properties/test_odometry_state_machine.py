"""Stateful (hypothesis RuleBasedStateMachine) tests of drivekin's odometry classes.

One machine per drivetrain (swerve with a random 2–6 module layout, mecanum,
differential). Rules move the wheels by random small distances (and the swerve module
angles), turn the gyro by random angles — also by whole extra turns, so the raw reading
wraps past ±180° — and exercise resetPose / resetRotation / resetTranslation /
resetPosition. The test keeps its own model of the pose and integrates the same twists
by hand:

* the twist's (dx, dy) comes from an independent ``numpy.linalg.lstsq`` solve of the
  kinematics matrix (swerve, mecanum) or the closed form (differential);
* the heading change is the wrapped gyro difference ``remainder(new − old, 2π)``;
* the pose is composed with a hand-written SE(2) exponential in plain ``math``.

The invariant compares ``getPose()`` with the model after every step within
``1e-9 · (1 + steps) · magnitude`` (magnitude = max(1, |coordinates| seen, path length)).
Both the model and drivekin compute 1 − cos θ without cancellation, so no allowance for
WPILib's small-angle rounding is needed (the robotpy oracle tests still carry one).
"""
from __future__ import annotations

import math

import numpy as np
from hypothesis import settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, initialize, invariant, rule

from tests._support import strategies as S
from drivekin import (
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

TAU = 2.0 * math.pi
REL = 1e-9

MACHINE_SETTINGS = settings(max_examples=40, stateful_step_count=30, deadline=None)

# ---------------------------------------------------------------------------------------
# The hand-written model


def wrapped(a):
    return math.remainder(a, TAU)


# ---------------------------------------------------------------------------------------
# Strategies

STEP = st.floats(-0.5, 0.5, allow_nan=False)
TURNS = st.one_of(st.sampled_from([0.0, 1e-12, -1e-10, 2e-9, 4e-5, math.pi / 2, -3.0, 3.0]),
                  st.floats(-3.0, 3.0, allow_nan=False))
GYROS = st.floats(-4 * math.pi, 4 * math.pi, allow_nan=False)
COORDS = st.floats(-10.0, 10.0, allow_nan=False)
HEADINGS = st.floats(-4 * math.pi, 4 * math.pi, allow_nan=False)
ABS_WHEEL = st.floats(-100.0, 100.0, allow_nan=False)


def make_pose(x, y, th):
    return Pose2d(x, y, Rotation2d(th))


class OdometryMachine(RuleBasedStateMachine):
    """Shared rules and the model; subclasses supply the drivetrain-specific parts:

    * ``_draw_move(data)`` → new wheel state after a small random move;
    * ``_draw_absolute(data)`` → an arbitrary wheel state (for resetPosition);
    * ``_model_twist(old, new)`` → (dx, dy) of the model;
    * ``_update(gyro, wheels, data)`` → drivekin's ``update`` return value;
    * ``_reset_position(gyro, wheels, pose)``.
    """

    odo = None

    def _start(self, gyro, wheels, pose):
        self.gyro = gyro
        self.wheels = wheels
        self.x, self.y, self.th = pose
        self.steps = 0
        self.path = 0.0
        self.mag = max(1.0, abs(self.x), abs(self.y))

    # --- helpers ----------------------------------------------------------------------
    def _step(self, new_wheels, new_gyro, data):
        dx, dy = self._model_twist(self.wheels, new_wheels)
        dth = wrapped(new_gyro - self.gyro)
        returned = self._update(Rotation2d(new_gyro), new_wheels, data)
        self.x, self.y, self.th = S.compose_exp(self.x, self.y, self.th, dx, dy, dth)
        self.wheels, self.gyro = new_wheels, new_gyro
        d = math.hypot(dx, dy)
        self.steps += 1
        self.path += d
        self._seen()
        got = self.odo.getPose()
        assert type(returned) is Pose2d
        assert ((returned.getX(), returned.getY(), S.rot_tuple(returned.getRotation()))
                == (got.getX(), got.getY(), S.rot_tuple(got.getRotation())))

    def _seen(self):
        self.mag = max(self.mag, abs(self.x), abs(self.y), self.path)

    # --- rules ------------------------------------------------------------------------
    @rule(data=st.data(), turn=TURNS)
    def drive(self, data, turn):
        self._step(self._draw_move(data), self.gyro + turn, data)

    @rule(data=st.data(), turn=TURNS)
    def turn_in_place(self, data, turn):
        self._step(self.wheels, self.gyro + turn, data)

    @rule(data=st.data(), turn=TURNS, winds=st.sampled_from([-2, -1, 1, 2]))
    def drive_with_gyro_wrap(self, data, turn, winds):
        """The raw gyro reading jumps by whole turns (e.g. 179° → −178°, or a gyro that
        reports continuous angles); only the wrapped difference may count."""
        self._step(self._draw_move(data), self.gyro + turn + winds * TAU, data)

    @rule(data=st.data())
    def stand_still(self, data):
        self._step(self.wheels, self.gyro, data)

    @rule(x=COORDS, y=COORDS, th=HEADINGS)
    def reset_pose(self, x, y, th):
        self.odo.resetPose(make_pose(x, y, th))
        self.x, self.y, self.th = x, y, th
        self._seen()

    @rule(th=HEADINGS)
    def reset_rotation(self, th):
        self.odo.resetRotation(Rotation2d(th))
        self.th = th

    @rule(x=COORDS, y=COORDS)
    def reset_translation(self, x, y):
        self.odo.resetTranslation(Translation2d(x, y))
        self.x, self.y = x, y
        self._seen()

    @rule(data=st.data(), gyro=GYROS, x=COORDS, y=COORDS, th=HEADINGS)
    def reset_position(self, data, gyro, x, y, th):
        wheels = self._draw_absolute(data)
        self._reset_position(Rotation2d(gyro), wheels, make_pose(x, y, th))
        self.gyro, self.wheels = gyro, wheels
        self.x, self.y, self.th = x, y, th
        self._seen()

    # --- the check --------------------------------------------------------------------
    @invariant()
    def pose_matches_model(self):
        if self.odo is None:
            return
        p = self.odo.getPose()
        bound = REL * (1 + self.steps) * self.mag
        for got, exp, name in ((p.getX(), self.x, "x"), (p.getY(), self.y, "y")):
            assert abs(got - exp) <= bound, (
                f"{name}: drivekin {got!r} vs model {exp!r} (|err| {abs(got - exp):.3g} > "
                f"{bound:.3g} after {self.steps} steps)")
        r = p.getRotation()
        herr = math.hypot(r.getCos() - math.cos(self.th), r.getSin() - math.sin(self.th))
        hbound = REL * (1 + self.steps)
        assert herr <= hbound, (
            f"heading: drivekin {r.getRadians()!r} vs model {wrapped(self.th)!r} "
            f"(|err| {herr:.3g} > {hbound:.3g} after {self.steps} steps)")


# ---------------------------------------------------------------------------------------
# Swerve: wheel state = tuple of (distance, angle) per module


class SwerveOdometryMachine(OdometryMachine):
    @initialize(layout=S.swerve_layouts(2, 6), data=st.data(), gyro=GYROS, x=COORDS,
                y=COORDS, th=HEADINGS)
    def setup(self, layout, data, gyro, x, y, th):
        self.layout = layout
        self.n = len(layout)
        self.matrix = S.swerve_inverse_matrix(layout)
        self.kin = SwerveDriveKinematics(*[Translation2d(px, py) for px, py in layout])
        wheels = self._draw_absolute(data)
        self.odo = SwerveDriveOdometry(self.kin, Rotation2d(gyro), self._objects(wheels),
                                       make_pose(x, y, th))
        self._start(gyro, wheels, (x, y, th))

    def _objects(self, wheels):
        return [SwerveModulePosition(d, Rotation2d(a)) for d, a in wheels]

    def _draw_absolute(self, data):
        return tuple(data.draw(st.lists(st.tuples(ABS_WHEEL, HEADINGS), min_size=self.n,
                                        max_size=self.n)))

    def _draw_move(self, data):
        steps = data.draw(st.lists(st.tuples(STEP, HEADINGS), min_size=self.n,
                                   max_size=self.n))
        return tuple((d + dd, a) for (d, _), (dd, a) in zip(self.wheels, steps))

    def _model_twist(self, old, new):
        # WPILib: distance change at the *new* module angle.
        w = []
        for (d0, _), (d1, a1) in zip(old, new):
            dd = d1 - d0
            w += [dd * math.cos(a1), dd * math.sin(a1)]
        sol = np.linalg.lstsq(self.matrix, np.array(w), rcond=None)[0]
        return float(sol[0]), float(sol[1])

    def _update(self, gyro, wheels, data):
        if data.draw(st.booleans(), label="array form"):
            return self.odo.update(gyro, np.array(wheels, dtype=np.float64).reshape(-1, 2))
        return self.odo.update(gyro, self._objects(wheels))

    def _reset_position(self, gyro, wheels, pose):
        self.odo.resetPosition(gyro, self._objects(wheels), pose)


# ---------------------------------------------------------------------------------------
# Mecanum: wheel state = (fl, fr, rl, rr) distances

MECANUM_LAYOUTS = st.one_of(
    st.tuples(st.floats(0.05, 2.0), st.floats(0.05, 2.0)).map(
        lambda ab: [(ab[0], ab[1]), (ab[0], -ab[1]), (-ab[0], ab[1]), (-ab[0], -ab[1])]),
    st.lists(st.tuples(st.floats(-3.0, 3.0), st.floats(-3.0, 3.0)), min_size=4, max_size=4)
    .filter(lambda pts: np.linalg.cond(S.mecanum_inverse_matrix(pts)) < 1e4),
)


class MecanumOdometryMachine(OdometryMachine):
    @initialize(layout=MECANUM_LAYOUTS, data=st.data(), gyro=GYROS, x=COORDS, y=COORDS,
                th=HEADINGS)
    def setup(self, layout, data, gyro, x, y, th):
        self.matrix = S.mecanum_inverse_matrix(layout)
        self.kin = MecanumDriveKinematics(*[Translation2d(px, py) for px, py in layout])
        wheels = self._draw_absolute(data)
        self.odo = MecanumDriveOdometry(self.kin, Rotation2d(gyro),
                                        MecanumDriveWheelPositions(*wheels),
                                        make_pose(x, y, th))
        self._start(gyro, wheels, (x, y, th))

    def _draw_absolute(self, data):
        return tuple(data.draw(st.lists(ABS_WHEEL, min_size=4, max_size=4)))

    def _draw_move(self, data):
        steps = data.draw(st.lists(STEP, min_size=4, max_size=4))
        return tuple(d + s for d, s in zip(self.wheels, steps))

    def _model_twist(self, old, new):
        deltas = np.array([b - a for a, b in zip(old, new)])
        sol = np.linalg.lstsq(self.matrix, deltas, rcond=None)[0]
        return float(sol[0]), float(sol[1])

    def _update(self, gyro, wheels, data):
        return self.odo.update(gyro, MecanumDriveWheelPositions(*wheels))

    def _reset_position(self, gyro, wheels, pose):
        self.odo.resetPosition(gyro, MecanumDriveWheelPositions(*wheels), pose)


# ---------------------------------------------------------------------------------------
# Differential: wheel state = (left, right) distances; closed-form twist


class DifferentialOdometryMachine(OdometryMachine):
    @initialize(data=st.data(), gyro=GYROS, x=COORDS, y=COORDS, th=HEADINGS)
    def setup(self, data, gyro, x, y, th):
        wheels = self._draw_absolute(data)
        self.odo = DifferentialDriveOdometry(Rotation2d(gyro), wheels[0], wheels[1],
                                             make_pose(x, y, th))
        self._start(gyro, wheels, (x, y, th))

    def _draw_absolute(self, data):
        return (data.draw(ABS_WHEEL), data.draw(ABS_WHEEL))

    def _draw_move(self, data):
        return (self.wheels[0] + data.draw(STEP), self.wheels[1] + data.draw(STEP))

    def _model_twist(self, old, new):
        # dx = mean wheel travel, dy = 0 (dθ comes from the gyro, so no trackwidth).
        return ((new[0] - old[0]) + (new[1] - old[1])) / 2.0, 0.0

    def _update(self, gyro, wheels, data):
        return self.odo.update(gyro, wheels[0], wheels[1])

    def _reset_position(self, gyro, wheels, pose):
        self.odo.resetPosition(gyro, wheels[0], wheels[1], pose)


TestSwerveOdometryStateMachine = SwerveOdometryMachine.TestCase
TestSwerveOdometryStateMachine.settings = MACHINE_SETTINGS
TestMecanumOdometryStateMachine = MecanumOdometryMachine.TestCase
TestMecanumOdometryStateMachine.settings = MACHINE_SETTINGS
TestDifferentialOdometryStateMachine = DifferentialOdometryMachine.TestCase
TestDifferentialOdometryStateMachine.settings = MACHINE_SETTINGS
