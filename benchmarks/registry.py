"""Registry of benchmarked operations: one entry = robotpy baseline + drivekin façade +
drivekin allocation-free path (+ optional extra variants) + target ratios.

Both the pytest-benchmark files (``bench_*.py``) and ``ratio_table.py`` are generated from
this list, so adding a drivetrain is a few lines here, e.g.::

    register(Operation(
        key="mecanum.ik", title="mecanum IK toWheelVelocities", suite="mecanum",
        robotpy=Case("kin.toWheelSpeeds(cs)", lambda rp, dk: dict(kin=rp.mkin, cs=rp.cs),
                     value="wheels4(kin.toWheelSpeeds(cs))"),
        facade=Case("kin.toWheelVelocities(cv)", lambda rp, dk: dict(kin=dk.mkin, cv=dk.cv),
                    value="wheels4(kin.toWheelVelocities(cv))"),
        alloc_free=Case("kin.toWheelVelocitiesInto(cv, out)",
                        lambda rp, dk: dict(kin=dk.mkin, cv=dk.cv,
                                            out=dk.MecanumDriveWheelVelocities()),
                        value="wheels4(out)"),
        targets=(0.15, 0.08)))

plus building ``rp.mkin`` (``wpimath.kinematics.MecanumDriveKinematics``), ``dk.mkin`` and
``dk.MecanumDriveWheelVelocities`` (``drivekin.mecanum``) in ``_common.build_robotpy`` /
``build_drivekin``, and a ``bench_mecanum.py`` that is a copy of ``bench_chassis.py`` with
``SUITE = "mecanum"``. ``ratio_table.py`` picks new entries up by itself.

A :class:`Case` is a one-line statement plus a ``setup(rp, dk) -> dict`` that returns the
local names the statement uses. ``setup`` is called once per case, so mutable inputs and
output buffers are never shared between cases. ``value`` is an optional expression,
evaluated after the statement has run once, giving the numbers the case produced; all the
variants of one operation must agree with the robotpy baseline (checked by
``ratio_table.py`` and by ``test_values_agree`` in each bench file).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Optional

from _common import fresh_states, states_array

#: The three columns of the ratio table, in order.
VARIANTS = ("robotpy", "facade", "alloc_free")


@dataclass(frozen=True)
class Case:
    stmt: str
    setup: Callable[..., dict]
    value: Optional[str] = None
    note: str = ""


@dataclass(frozen=True)
class Operation:
    key: str                      # "swerve.ik": also the pytest id prefix
    title: str                    # pytest-benchmark group name and table row label
    suite: str                    # which bench_<suite>.py collects it
    robotpy: Case
    facade: Case
    alloc_free: Case
    targets: Optional[tuple] = None          # (façade ratio, alloc-free ratio) upper bounds
    extras: dict = field(default_factory=dict)  # label -> Case, reported separately
    needs_kinematics: bool = True            # False: drivekin.geometry is enough

    def variants(self) -> dict:
        v = {name: getattr(self, name) for name in VARIANTS}
        v.update(self.extras)
        return v


OPERATIONS: list[Operation] = []


def register(op: Operation) -> Operation:
    if any(o.key == op.key for o in OPERATIONS):
        raise ValueError(f"duplicate operation key {op.key!r}")
    OPERATIONS.append(op)
    return op


def suite(name: str) -> list[Operation]:
    return [op for op in OPERATIONS if op.suite == name]


# ---------------------------------------------------------------------------------------
# Helpers available to `value` expressions (flatten results into lists of floats).

def rp_states(states):
    return [x for s in states for x in (s.speed, s.angle.radians())]


def dk_states(states):
    return [x for s in states for x in (s.velocity, s.angle.getRadians())]


def speeds3(c):
    return [c.vx, c.vy, c.omega]


def rp_pose(p):
    return [p.X(), p.Y(), p.rotation().radians()]


def dk_pose(p):
    return [p.getX(), p.getY(), p.getRotation().getRadians()]


def flat_array(a):
    return [float(x) for x in a.ravel()]


def wheels4(w):
    # mecanum wheel speeds/velocities: the same field names in robotpy 2026 and drivekin
    return [w.frontLeft, w.frontRight, w.rearLeft, w.rearRight]


VALUE_HELPERS = dict(rp_states=rp_states, dk_states=dk_states, speeds3=speeds3,
                     rp_pose=rp_pose, dk_pose=dk_pose, flat_array=flat_array,
                     wheels4=wheels4)


def _np_zeros(shape):
    import numpy as np

    return np.zeros(shape, dtype=np.float64)


# ---------------------------------------------------------------------------------------
# Swerve (4 modules at (±0.3, ±0.3) m)

register(Operation(
    key="swerve.ik", title="swerve IK toSwerveModuleVelocities", suite="swerve",
    robotpy=Case("kin.toSwerveModuleStates(cs)",
                 lambda rp, dk: dict(kin=rp.kin, cs=rp.cs),
                 value="rp_states(kin.toSwerveModuleStates(cs))"),
    facade=Case("kin.toSwerveModuleVelocities(cv)",
                lambda rp, dk: dict(kin=dk.kin, cv=dk.cv),
                value="dk_states(kin.toSwerveModuleVelocities(cv))"),
    alloc_free=Case("kin.toSwerveModuleVelocitiesInto(cv, out)",
                    lambda rp, dk: dict(kin=dk.kin, cv=dk.cv, out=_np_zeros((4, 2))),
                    value="flat_array(out)", note="out: (4, 2) float64 ndarray"),
    extras={
        "alloc_free[objects]": Case(
            "kin.toSwerveModuleVelocitiesInto(cv, out)",
            lambda rp, dk: dict(kin=dk.kin, cv=dk.cv, out=fresh_states(dk)),
            value="dk_states(out)", note="out: list of 4 SwerveModuleVelocity"),
    },
    targets=(0.20, 0.10)))

register(Operation(
    key="swerve.fk", title="swerve FK toChassisVelocities", suite="swerve",
    robotpy=Case("kin.toChassisSpeeds(states)",
                 lambda rp, dk: dict(kin=rp.kin, states=rp.states),
                 value="speeds3(kin.toChassisSpeeds(states))"),
    facade=Case("kin.toChassisVelocities(states)",
                lambda rp, dk: dict(kin=dk.kin, states=dk.states),
                value="speeds3(kin.toChassisVelocities(states))"),
    alloc_free=Case("kin.toChassisVelocitiesInto(states, out)",
                    lambda rp, dk: dict(kin=dk.kin, states=dk.states,
                                        out=dk.ChassisVelocities()),
                    value="speeds3(out)", note="states: tuple of 4 SwerveModuleVelocity"),
    extras={
        "alloc_free[ndarray]": Case(
            "kin.toChassisVelocitiesInto(states, out)",
            lambda rp, dk: dict(kin=dk.kin, states=states_array(dk),
                                out=dk.ChassisVelocities()),
            value="speeds3(out)", note="states: (4, 2) ndarray, angles in rad"),
    },
    targets=(0.10, 0.06)))

# In-place desaturate: after the first call the speeds are within the limit, so later
# calls find R <= max and skip the 4 multiplies (robotpy and the façade rescale their
# unchanged input every call). That is the work a real loop does once saturated; the
# difference is 4 multiplies and stores (perf-floor.md, "Caveats").
register(Operation(
    key="swerve.desat1", title="swerve desaturateWheelVelocities(states, max)", suite="swerve",
    robotpy=Case("K.desaturateWheelSpeeds(states, m)",
                 lambda rp, dk: dict(K=rp.Kinematics, states=rp.states, m=1.0),
                 value="rp_states(K.desaturateWheelSpeeds(states, m))"),
    facade=Case("K.desaturateWheelVelocities(states, m)",
                lambda rp, dk: dict(K=dk.Kinematics, states=dk.states, m=1.0),
                value="dk_states(K.desaturateWheelVelocities(states, m))"),
    alloc_free=Case("K.desaturateWheelVelocitiesInPlace(states, m)",
                    lambda rp, dk: dict(K=dk.Kinematics, states=fresh_states(dk), m=1.0),
                    value="dk_states(states)", note="states: list of 4 SwerveModuleVelocity"),
    extras={
        "alloc_free[ndarray]": Case(
            "K.desaturateWheelVelocitiesInPlace(states, m)",
            lambda rp, dk: dict(K=dk.Kinematics, states=states_array(dk), m=1.0),
            value="flat_array(states)", note="states: (4, 2) ndarray"),
    },
    targets=(0.20, 0.06)))

register(Operation(
    key="swerve.desat5", title="swerve desaturateWheelVelocities(states, cv, 3 limits)",
    suite="swerve",
    robotpy=Case("K.desaturateWheelSpeeds(states, cs, mm, mt, mr)",
                 lambda rp, dk: dict(K=rp.Kinematics, states=rp.states, cs=rp.cs,
                                     mm=4.0, mt=3.0, mr=6.0),
                 value="rp_states(K.desaturateWheelSpeeds(states, cs, mm, mt, mr))"),
    facade=Case("K.desaturateWheelVelocities(states, cv, mm, mt, mr)",
                lambda rp, dk: dict(K=dk.Kinematics, states=dk.states, cv=dk.cv,
                                    mm=4.0, mt=3.0, mr=6.0),
                value="dk_states(K.desaturateWheelVelocities(states, cv, mm, mt, mr))"),
    alloc_free=Case("K.desaturateWheelVelocitiesInPlace(states, cv, mm, mt, mr)",
                    lambda rp, dk: dict(K=dk.Kinematics, states=fresh_states(dk), cv=dk.cv,
                                        mm=4.0, mt=3.0, mr=6.0),
                    value="dk_states(states)", note="states: list of 4 SwerveModuleVelocity"),
    targets=(0.20, 0.06)))


# ---------------------------------------------------------------------------------------
# ChassisVelocities

# robotpy baseline: the 4-double form ChassisSpeeds.discretize(vx, vy, omega, dt), the
# faster of robotpy's two overloads (perf-floor: 491 vs 559 ns), so the ratio is the
# conservative one. The (speeds, dt) overload is reported as an extra.
register(Operation(
    key="chassis.discretize", title="ChassisVelocities.discretize", suite="chassis",
    robotpy=Case("CS.discretize(vx, vy, omega, dt)",
                 lambda rp, dk: dict(CS=rp.ChassisSpeeds, vx=rp.cs.vx, vy=rp.cs.vy,
                                     omega=rp.cs.omega, dt=0.02),
                 value="speeds3(CS.discretize(vx, vy, omega, dt))"),
    facade=Case("cv.discretize(dt)",
                lambda rp, dk: dict(cv=dk.cv, dt=0.02),
                value="speeds3(cv.discretize(dt))"),
    alloc_free=Case("cv.discretizeInto(dt, out)",
                    lambda rp, dk: dict(cv=dk.cv, dt=0.02, out=dk.ChassisVelocities()),
                    value="speeds3(out)"),
    extras={
        "robotpy[speeds, dt]": Case(
            "CS.discretize(cs, dt)",
            lambda rp, dk: dict(CS=rp.ChassisSpeeds, cs=rp.cs, dt=0.02),
            value="speeds3(CS.discretize(cs, dt))"),
    },
    targets=(0.15, 0.10)))

register(Operation(
    key="chassis.robot_relative", title="field -> robot relative (toRobotRelative)",
    suite="chassis",
    robotpy=Case("CS.fromFieldRelativeSpeeds(cs, rot)",
                 lambda rp, dk: dict(CS=rp.ChassisSpeeds, cs=rp.cs, rot=rp.rot),
                 value="speeds3(CS.fromFieldRelativeSpeeds(cs, rot))"),
    facade=Case("cv.toRobotRelative(rot)",
                lambda rp, dk: dict(cv=dk.cv, rot=dk.rot),
                value="speeds3(cv.toRobotRelative(rot))"),
    alloc_free=Case("cv.toRobotRelativeInto(rot, out)",
                    lambda rp, dk: dict(cv=dk.cv, rot=dk.rot, out=dk.ChassisVelocities()),
                    value="speeds3(out)"),
    targets=None))


# ---------------------------------------------------------------------------------------
# Geometry

# drivekin's Pose2d/Transform2d are immutable; results come from freelists, so both
# drivekin forms make zero allocator calls in steady state. The façade column is the 2027
# spelling (two calls, one intermediate Transform2d), the alloc-free column the fused
# 2026-style Pose2d.exp.
register(Operation(
    key="geometry.pose_exp", title="pose + twist.exp()", suite="geometry",
    robotpy=Case("pose.exp(twist)",
                 lambda rp, dk: dict(pose=rp.pose, twist=rp.twist),
                 value="rp_pose(pose.exp(twist))"),
    facade=Case("pose.plus(twist.exp())",
                lambda rp, dk: dict(pose=dk.pose, twist=dk.twist),
                value="dk_pose(pose.plus(twist.exp()))"),
    alloc_free=Case("pose.exp(twist)",
                    lambda rp, dk: dict(pose=dk.pose, twist=dk.twist),
                    value="dk_pose(pose.exp(twist))"),
    targets=(0.15, 0.12),
    needs_kinematics=False))


# ---------------------------------------------------------------------------------------
# Calibration statements: not kinematics, just the call floors of each library, timed with
# the operations so a table from another machine can be compared with perf-floor.md
# (label, case, what perf-floor.md measured on its machine: time, instructions).

CALIBRATION = [
    ("empty loop iteration", Case("pass", lambda rp, dk: {}),
     "5.0 ns", "88 Ir"),
    ("drivekin 0-arg call returning a float: rot.getCos()",
     Case("rot.getCos()", lambda rp, dk: dict(rot=dk.rot)),
     "no-op 18.0 ns + about 8 ns to return a float", "no-op 217 Ir + about 65 Ir for the float"),
    ("robotpy 0-arg call returning a float: rot.radians()",
     Case("rot.radians()", lambda rp, dk: dict(rot=rp.rot)),
     "172.3 ns", "1,900 Ir"),
]


# ---------------------------------------------------------------------------------------
# Running one case once and reading its numbers (shared by ratio_table and the tests)

def evaluate(case: Case, env: dict):
    """Execute ``case.stmt`` once in ``env`` and return the flattened ``value`` (or None)."""
    scope = dict(VALUE_HELPERS)
    exec(compile(case.stmt, "<stmt>", "exec"), scope, env)
    if case.value is None:
        return None
    return list(eval(case.value, scope, env))


def values_agree(ref, got, tol=1e-9) -> bool:
    if ref is None or got is None:
        return True
    return len(ref) == len(got) and all(abs(a - b) <= tol * max(1.0, abs(a))
                                        for a, b in zip(ref, got))
