"""Registry of benchmarked operations: one entry = robotpy baseline + drivekin façade +
drivekin allocation-free path (+ optional extra variants) + target ratios.

Both the pytest-benchmark files (``bench_*.py``) and ``ratio_table.py`` are generated from
this list. The IK, FK and desaturate entries of the wheel drives are written by
``_wheel_drive_ops`` for every drivetrain of the catalog (``drivekin._core.catalog``) whose
kinematics implement the drivetrain contract with unsteered wheels and have a
robotpy-wpimath peer (today mecanum and differential); the mecanum IK entry is, spelled
out::

    register(Operation(
        key="mecanum.ik", title="mecanum IK toWheelVelocities", suite="mecanum",
        robotpy=Case("kin.toWheelSpeeds(cs)",
                     lambda rp, dk: dict(kin=rp.kinematics["mecanum"], cs=rp.cs),
                     value="wheels4(kin.toWheelSpeeds(cs))"),
        facade=Case("kin.toWheelVelocities(cv)",
                    lambda rp, dk: dict(kin=dk.kinematics["mecanum"], cv=dk.cv),
                    value="wheels4(kin.toWheelVelocities(cv))"),
        alloc_free=Case("kin.toWheelVelocitiesInto(cv, out)",
                        lambda rp, dk: dict(kin=dk.kinematics["mecanum"], cv=dk.cv,
                                            out=dk.MecanumDriveWheelVelocities()),
                        value="wheels4(out)", note="out: MecanumDriveWheelVelocities"),
        targets=DRIVETRAIN_TARGETS))        # (façade, alloc-free) = (0.25, 0.12)

A new such drivetrain needs its robotpy kinematics in ``_common.build_robotpy``
(``rp.kinematics`` and ``rp.ik_wheels``, by its catalog key; drivekin's come from the
catalog) and a bench file that collects its suite (``bench_drivetrains.py`` collects
``mecanum``, ``differential`` and ``odometry``; a new suite's file is
``test_bench, test_values_agree = _bench.bench_tests("<suite>")``). ``ratio_table.py``
picks new entries up by itself.

**drivekin-only operations** (no robotpy peer: ``robotpy=None``) report absolute times
instead of ratios to robotpy: ``target_ns`` gives optional upper bounds in ns (façade,
alloc-free), ``baseline`` names another operation (``"key"`` or ``"key:variant"``, the
variant defaulting to ``facade``) whose drivekin time, taken in the same run, is the
denominator of a ratio, and ``baseline_targets`` bounds those ratios (façade, alloc-free).
``ratio_table.py --only`` times the baseline too. Their values are checked against
``expected`` (a list of numbers) when given, else every variant against the façade. For
example dead-wheel odometry against ``DifferentialDriveOdometry.update``::

    register(Operation(
        key="deadwheel.odometry3", title="DeadWheelOdometry.update (3 wheels)",
        suite="deadwheel", robotpy=None, facade=Case(...), alloc_free=Case(...),
        baseline="odometry.differential", baseline_targets=(1.3, 1.3)))

A :class:`Group` holds rows to a target together: ``ratio_table.py`` reports the geometric
mean of their ratios to robotpy. The 3-D rows and their group live in ``registry3d.py``,
imported at the end of this module.

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

from _common import INPUTS, copy_wheels, fresh_states, positions_array, states_array

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
    robotpy: Optional[Case]       # None: a drivekin-only operation (see the module doc)
    facade: Case
    alloc_free: Case
    targets: Optional[tuple] = None          # (façade ratio, alloc-free ratio) upper bounds
    extras: dict = field(default_factory=dict)  # label -> Case, reported separately
    needs_kinematics: bool = True            # False: drivekin.geometry is enough
    # drivekin-only operations:
    target_ns: Optional[tuple] = None        # (façade ns, alloc-free ns) upper bounds
    baseline: Optional[str] = None           # "key" or "key:variant" of the denominator
    baseline_targets: Optional[tuple] = None  # (façade, alloc-free) / baseline upper bounds
    expected: Optional[list] = None          # the numbers the façade's `value` must give

    def variants(self) -> dict:
        v = {name: getattr(self, name) for name in VARIANTS if getattr(self, name) is not None}
        v.update(self.extras)
        return v

    @property
    def drivekin_only(self) -> bool:
        return self.robotpy is None


@dataclass(frozen=True)
class Group:
    """Rows held to a target together: the geometric mean of their ratios to robotpy (each
    drivekin column on its own) must not exceed ``target``."""
    title: str
    keys: tuple                   # operation keys
    target: float


OPERATIONS: list[Operation] = []
GROUPS: list[Group] = []


def register(op: Operation) -> Operation:
    if any(o.key == op.key for o in OPERATIONS):
        raise ValueError(f"duplicate operation key {op.key!r}")
    if op.drivekin_only and op.targets is not None:
        raise ValueError(f"{op.key}: no robotpy case, so no robotpy ratio targets "
                         "(use target_ns or baseline_targets)")
    if not op.drivekin_only and (op.target_ns or op.baseline or op.baseline_targets):
        raise ValueError(f"{op.key}: target_ns/baseline are for drivekin-only operations")
    if op.baseline_targets is not None and op.baseline is None:
        raise ValueError(f"{op.key}: baseline_targets needs a baseline")
    OPERATIONS.append(op)
    return op


def suite(name: str) -> list[Operation]:
    return [op for op in OPERATIONS if op.suite == name]


def baseline_of(op: Operation) -> Optional[tuple]:
    """(key, variant) of ``op``'s baseline, or None; ValueError if it names no case."""
    if op.baseline is None:
        return None
    key, _, variant = op.baseline.partition(":")
    variant = variant or "facade"
    base = next((o for o in OPERATIONS if o.key == key), None)
    if base is None or variant not in base.variants():
        raise ValueError(f"{op.key}: baseline {op.baseline!r} names no registered case")
    return key, variant


def with_baselines(ops: list) -> list:
    """``ops`` plus the operations their baselines name (registry order)."""
    keys = {o.key for o in ops} | {baseline_of(o)[0] for o in ops if o.baseline}
    return [o for o in OPERATIONS if o.key in keys]


def reference_value(op: Operation, rp, dk):
    """The numbers every variant of ``op`` must produce (None: nothing to check)."""
    if op.robotpy is not None:
        return evaluate(op.robotpy, op.robotpy.setup(rp, dk))
    if op.expected is not None:
        return list(op.expected)
    return evaluate(op.facade, op.facade.setup(rp, dk))


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


def wheels2(w):
    # differential wheel speeds/velocities: `left`, `right` in robotpy 2026 and drivekin
    return [w.left, w.right]


VALUE_HELPERS = dict(rp_states=rp_states, dk_states=dk_states, speeds3=speeds3,
                     rp_pose=rp_pose, dk_pose=dk_pose, flat_array=flat_array,
                     wheels4=wheels4, wheels2=wheels2)


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
# Mecanum (wheels at the swerve module positions, FL FR RL RR) and differential
# (trackwidth 0.6 m). Same chassis input as swerve; robotpy gets prebuilt ChassisSpeeds and
# wheel-speed objects.

#: targets for every mecanum / differential / odometry operation (façade, alloc-free)
DRIVETRAIN_TARGETS = (0.25, 0.12)

# Desaturate, two rows per drivetrain. robotpy's 2026 `desaturate` and drivekin's
# `desaturateInPlace` both mutate their object; drivekin's 2027 `desaturate` returns a new
# object and leaves its input alone. Re-setting the four wheel values before every call
# is not a fair fix: the setters would cost robotpy ~4 pybind11 attribute calls and drivekin
# ~4 Cython property stores, and that difference would dominate. Instead:
#   [saturated]   limit 1.0 m/s, below the IK wheel speeds. Every case has its own wheel
#                 object. robotpy and desaturateInPlace rescale on their first (warm-up)
#                 call only; from then on each call computes max|w|, finds it == the limit
#                 and returns: the same work on both sides. The façade reads its unchanged
#                 input, so it rescales and allocates the result on every timed call (more
#                 work than robotpy). The value check runs on fresh objects, so it compares
#                 one real rescale per case.
#   [unsaturated] limit 5.0 m/s, above every wheel: no case ever rescales; all three
#                 compute max|w| and compare, identical arithmetic on every call (the
#                 façade also allocates its returned copy).
def _desaturate_ops(drive, label, flat, wheels_note):
    values = VALUE_HELPERS[flat]

    def rp_wheels(rp):              # a new wheel object per case: desaturate mutates
        return copy_wheels(rp.ik_wheels[drive], values)

    def dk_wheels(dk):
        return copy_wheels(dk.ik_wheels[drive], values)

    for kind, m in (("saturated", INPUTS.max_speed),
                    ("unsaturated", INPUTS.max_speed_unsaturated)):
        if kind == "saturated":
            steady = (f"{wheels_note}, limit {m} m/s: rescales on its first call only, "
                      "then max|w| + compare, no rescale (its own object)")
            facade_note = ("returns a new object; its input is never changed, so it "
                           "rescales on every call")
        else:
            steady = f"{wheels_note}, limit {m} m/s: max|w| + compare, never rescales"
            facade_note = "returns a new (unscaled) copy on every call"
        register(Operation(
            key=f"{drive}.desat.{kind}", title=f"{label}.desaturate(max) [{kind}]",
            suite=drive,
            robotpy=Case("w.desaturate(m)",
                         lambda rp, dk, f=rp_wheels, m=m: dict(w=f(rp), m=m),
                         value=f"{flat}(w)", note="mutates, returns None; " + steady),
            facade=Case("w.desaturate(m)",
                        lambda rp, dk, f=dk_wheels, m=m: dict(w=f(dk), m=m),
                        value=f"{flat}(w.desaturate(m))", note=facade_note),
            alloc_free=Case("w.desaturateInPlace(m)",
                            lambda rp, dk, f=dk_wheels, m=m: dict(w=f(dk), m=m),
                            value=f"{flat}(w)", note="mutates, returns None; " + steady),
            targets=DRIVETRAIN_TARGETS))


def _wheel_drive_ops(drive, wheel_cls, flat, wheels_note):
    """IK, FK and the two desaturate rows of a drivetrain with a wheel-speed object.

    The prebuilt kinematics and IK wheel objects are ``rp.kinematics[drive]`` /
    ``rp.ik_wheels[drive]`` and the same on ``dk``; ``wheel_cls`` names drivekin's
    wheel-velocity class; ``flat`` the value helper that flattens a wheel object."""

    def out(dk):
        return type(dk.ik_wheels[drive])()             # a new drivekin wheel_cls

    register(Operation(
        key=f"{drive}.ik", title=f"{drive} IK toWheelVelocities", suite=drive,
        robotpy=Case("kin.toWheelSpeeds(cs)",
                     lambda rp, dk: dict(kin=rp.kinematics[drive], cs=rp.cs),
                     value=f"{flat}(kin.toWheelSpeeds(cs))"),
        facade=Case("kin.toWheelVelocities(cv)",
                    lambda rp, dk: dict(kin=dk.kinematics[drive], cv=dk.cv),
                    value=f"{flat}(kin.toWheelVelocities(cv))"),
        alloc_free=Case("kin.toWheelVelocitiesInto(cv, out)",
                        lambda rp, dk: dict(kin=dk.kinematics[drive], cv=dk.cv, out=out(dk)),
                        value=f"{flat}(out)", note=f"out: {wheel_cls}"),
        targets=DRIVETRAIN_TARGETS))

    register(Operation(
        key=f"{drive}.fk", title=f"{drive} FK toChassisVelocities", suite=drive,
        robotpy=Case("kin.toChassisSpeeds(w)",
                     lambda rp, dk: dict(kin=rp.kinematics[drive], w=rp.ik_wheels[drive]),
                     value="speeds3(kin.toChassisSpeeds(w))"),
        facade=Case("kin.toChassisVelocities(w)",
                    lambda rp, dk: dict(kin=dk.kinematics[drive], w=dk.ik_wheels[drive]),
                    value="speeds3(kin.toChassisVelocities(w))"),
        alloc_free=Case("kin.toChassisVelocitiesInto(w, out)",
                        lambda rp, dk: dict(kin=dk.kinematics[drive], w=dk.ik_wheels[drive],
                                            out=dk.ChassisVelocities()),
                        value="speeds3(out)", note="out: ChassisVelocities"),
        targets=DRIVETRAIN_TARGETS))

    _desaturate_ops(drive, f"{drive} {wheel_cls}", flat, wheels_note)


def _wheel_drives():
    """(drivetrain key, wheel-velocity class name, value helper, note) of every wheel drive
    in the catalog: kinematics implementing the drivetrain contract, with unsteered wheels
    and a robotpy-wpimath peer (the dead wheels have none: no robotpy baseline). The note
    gives the example robot's IK wheel values at the benchmark input."""
    try:
        from drivekin import ChassisVelocities
        from drivekin._core import catalog
        from drivekin._core.drivetrain import Drivetrain
    except ImportError:          # drivekin.kinematics not built: no drivetrain cases
        return
    cv = ChassisVelocities(INPUTS.vx, INPUTS.vy, INPUTS.omega)
    for e in catalog.entries("kinematics"):
        if not issubclass(e.cls, Drivetrain) or e.steered or e.peer is None:
            continue
        wheels = e.example().toWheelVelocities(cv)
        values = catalog.BY_CLASS[type(wheels)].flatten(wheels)
        # wheels4, wheels2: the same field names in robotpy 2026 and drivekin
        flat = f"wheels{len(values)}"
        if flat not in VALUE_HELPERS:
            raise ValueError(f"{e.drivetrain}: no value helper {flat} for its wheels")
        yield (e.drivetrain, type(wheels).__name__, flat,
               "wheels " + ", ".join(f"{v:.1f}" for v in values) + " m/s")


for _drive in _wheel_drives():
    _wheel_drive_ops(*_drive)


# ---------------------------------------------------------------------------------------
# Odometry update. Each case builds its own odometry object (gyro `robot_angle`, zero
# wheel distances, initial pose INPUTS.pose) and updates it with gyro + omega*dt and one
# dt of wheel travel. The value check is that first update (a real move). While timing,
# every later call sees zero wheel deltas and an unchanged gyro: neither library
# short-cuts that, so both run the full FK + Twist2d.exp + pose composition on every call
# and the pose stays put. drivekin has a single form (update returns a freelist Pose2d,
# no allocator calls), so the alloc-free column times the same statement again on its own
# odometry object.

_ODO_NOTE = ("same call as the façade: drivekin's odometry update has one form (the "
             "returned Pose2d comes from a freelist)")


def _odometry_op(key, title, rp_case, dk_stmt, dk_setup, extras=None):
    return register(Operation(
        key=key, title=title, suite="odometry", robotpy=rp_case,
        facade=Case(dk_stmt, dk_setup, value="dk_pose(odo.getPose())"),
        alloc_free=Case(dk_stmt, dk_setup, value="dk_pose(odo.getPose())", note=_ODO_NOTE),
        extras=extras or {}, targets=DRIVETRAIN_TARGETS))


_odometry_op(
    "odometry.swerve", "swerve odometry update(gyro, 4 positions)",
    Case("odo.update(gyro, pos)",
         lambda rp, dk: dict(odo=rp.SwerveDrive4Odometry(rp.kin, rp.rot, rp.spos0, rp.pose),
                             gyro=rp.gyro1, pos=rp.spos1),
         value="rp_pose(odo.getPose())",
         note="SwerveDrive4Odometry; pos: tuple of 4 SwerveModulePosition"),
    "odo.update(gyro, pos)",
    lambda rp, dk: dict(odo=dk.SwerveDriveOdometry(dk.kin, dk.rot, dk.spos0, dk.pose),
                        gyro=dk.gyro1, pos=dk.spos1),
    extras={
        "alloc_free[ndarray]": Case(
            "odo.update(gyro, pos)",
            lambda rp, dk: dict(odo=dk.SwerveDriveOdometry(dk.kin, dk.rot,
                                                           positions_array(dk.spos0), dk.pose),
                                gyro=dk.gyro1, pos=positions_array(dk.spos1)),
            value="dk_pose(odo.getPose())",
            note="pos: (4, 2) float64 ndarray [distance m, angle rad]"),
    })

_odometry_op(
    "odometry.mecanum", "mecanum odometry update(gyro, wheel positions)",
    Case("odo.update(gyro, pos)",
         lambda rp, dk: dict(odo=rp.MecanumDriveOdometry(rp.mkin, rp.rot, rp.mpos0, rp.pose),
                             gyro=rp.gyro1, pos=rp.mpos1),
         value="rp_pose(odo.getPose())", note="pos: MecanumDriveWheelPositions"),
    "odo.update(gyro, pos)",
    lambda rp, dk: dict(odo=dk.MecanumDriveOdometry(dk.mkin, dk.rot, dk.mpos0, dk.pose),
                        gyro=dk.gyro1, pos=dk.mpos1))

_odometry_op(
    "odometry.differential", "differential odometry update(gyro, left, right)",
    Case("odo.update(gyro, left, right)",
         lambda rp, dk: dict(odo=rp.DifferentialDriveOdometry(rp.rot, 0.0, 0.0, rp.pose),
                             gyro=rp.gyro1, left=rp.dpos1[0], right=rp.dpos1[1]),
         value="rp_pose(odo.getPose())", note="left, right: float distances, m"),
    "odo.update(gyro, left, right)",
    lambda rp, dk: dict(odo=dk.DifferentialDriveOdometry(dk.rot, 0.0, 0.0, dk.pose),
                        gyro=dk.gyro1, left=dk.dpos1[0], right=dk.dpos1[1]))


# ---------------------------------------------------------------------------------------
# Differential swerve pods (drivekin-only: no robotpy peer). One pod with R_A = 3, R_L = 5 and
# a 0.5 m wheel (quail's docs example: wheel 5 m/s = 10 rad/s, steering 2 rad/s -> motors
# 28, -22 rad/s), reset to 0.5 rad at motor positions (10, -4). Conversions are held to
# 40 ns and shown against the differential drive's IK (a comparable one-line conversion).

DIFFSWERVE_TARGET_NS = (40.0, 40.0)


def _dsk(rp, dk):
    from drivekin.diffswerve import DifferentialSwerveModuleKinematics

    k = DifferentialSwerveModuleKinematics(3.0, 5.0, 0.5)
    k.resetModulePosition(dk.g.Rotation2d(0.5), 10.0, -4.0)
    return k


def _ds_values(cls_name):
    import drivekin.diffswerve as ds

    return getattr(ds, cls_name)


register(Operation(
    key="diffswerve.motors", title="diffswerve toMotorVelocities(v, w)", suite="diffswerve",
    robotpy=None,
    facade=Case("k.toMotorVelocities(v, w)",
                lambda rp, dk: dict(k=_dsk(rp, dk), v=5.0, w=2.0),
                value="list(k.toMotorVelocities(v, w))"),
    alloc_free=Case("k.toMotorVelocitiesInto(v, w, out)",
                    lambda rp, dk: dict(k=_dsk(rp, dk), v=5.0, w=2.0,
                                        out=_ds_values("DifferentialSwerveMotorVelocities")()),
                    value="list(out)", note="out: DifferentialSwerveMotorVelocities"),
    expected=[28.0, -22.0], target_ns=DIFFSWERVE_TARGET_NS, baseline="differential.ik"))

register(Operation(
    key="diffswerve.module", title="diffswerve toModuleVelocities(m1, m2)", suite="diffswerve",
    robotpy=None,
    facade=Case("k.toModuleVelocities(m1, m2)",
                lambda rp, dk: dict(k=_dsk(rp, dk), m1=28.0, m2=-22.0),
                value="list(k.toModuleVelocities(m1, m2))"),
    alloc_free=Case("k.toModuleVelocitiesInto(m1, m2, out)",
                    lambda rp, dk: dict(k=_dsk(rp, dk), m1=28.0, m2=-22.0,
                                        out=_ds_values("DifferentialSwerveModuleVelocities")()),
                    value="list(out)", note="out: DifferentialSwerveModuleVelocities"),
    expected=[5.0, 2.0], target_ns=DIFFSWERVE_TARGET_NS, baseline="differential.ik"))

register(Operation(
    key="diffswerve.position", title="diffswerve toModulePosition(p1, p2)", suite="diffswerve",
    robotpy=None,
    facade=Case("k.toModulePosition(p1, p2)",
                lambda rp, dk: dict(k=_dsk(rp, dk), p1=23.0, p2=-11.0),
                value="(lambda p: [p.distance, p.angle.getRadians()])("
                      "k.toModulePosition(p1, p2))"),
    alloc_free=Case("k.toModulePositionInto(p1, p2, out)",
                    lambda rp, dk: dict(k=_dsk(rp, dk), p1=23.0, p2=-11.0,
                                        out=dk.k.SwerveModulePosition()),
                    value="[out.distance, out.angle.getRadians()]",
                    note="out: SwerveModulePosition"),
    expected=[2.0, 2.5], target_ns=DIFFSWERVE_TARGET_NS, baseline="differential.ik"))

# In place: the value check runs one real (steering-first) rescale on fresh motors; while
# timing, later calls find the motors at the limit and only compare (as the wheel
# desaturations above). The façade rescales its unchanged input on every call.
register(Operation(
    key="diffswerve.desat", title="diffswerve desaturateMotorVelocities(m, max)",
    suite="diffswerve", robotpy=None,
    facade=Case("k.desaturateMotorVelocities(m, lim)",
                lambda rp, dk: dict(k=_dsk(rp, dk), lim=20.0,
                                    m=_ds_values("DifferentialSwerveMotorVelocities")(28.0, -22.0)),
                value="list(k.desaturateMotorVelocities(m, lim))",
                note="motors 28, -22 rad/s, limit 20: rescales on every call"),
    alloc_free=Case("k.desaturateMotorVelocitiesInPlace(m, lim)",
                    lambda rp, dk: dict(k=_dsk(rp, dk), lim=20.0,
                                        m=_ds_values("DifferentialSwerveMotorVelocities")(
                                            28.0, -22.0)),
                    value="list(m)", note="rescales on its first call only, then compares"),
    extras={
        "alloc_free[proportional]": Case(
            "k.desaturateMotorVelocitiesInPlace(m, lim, proportional=True)",
            lambda rp, dk: dict(k=_dsk(rp, dk), lim=28.0,
                                m=_ds_values("DifferentialSwerveMotorVelocities")(28.0, -22.0)),
            note="limit 28: compares, never rescales (another rule: value not compared)"),
    },
    expected=[20.0, -14.0], baseline="differential.desat.saturated:alloc_free"))

# Drive level: 4 pods like the one above (wheel 0.05 m: 100 motor rad per m) under the
# swerve IK targets, steering 1, -2, 4, 0.5 rad/s, limit 100 rad/s: the first call scales
# every wheel by one factor; later calls find the pods at the limit.
register(Operation(
    key="diffswerve.drive_desat",
    title="diffswerve desaturateModuleVelocitiesInPlace(states, rates, max)",
    suite="diffswerve", robotpy=None,
    facade=Case("k.desaturateModuleVelocitiesInPlace(states, rates, lim)",
                lambda rp, dk: dict(k=_ds_drive(), states=fresh_states(dk),
                                    rates=[1.0, -2.0, 4.0, 0.5], lim=100.0),
                value="dk_states(states)",
                note="same call as the alloc-free column: the method has one (in-place) form"),
    alloc_free=Case("k.desaturateModuleVelocitiesInPlace(states, rates, lim)",
                    lambda rp, dk: dict(k=_ds_drive(), states=fresh_states(dk),
                                        rates=[1.0, -2.0, 4.0, 0.5], lim=100.0),
                    value="dk_states(states)",
                    note="states: list of 4 SwerveModuleVelocity, rates: list of 4 floats"),
    extras={
        "alloc_free[ndarray]": Case(
            "k.desaturateModuleVelocitiesInPlace(states, rates, lim)",
            lambda rp, dk: dict(k=_ds_drive(), states=states_array(dk),
                                rates=_np_array([1.0, -2.0, 4.0, 0.5]), lim=100.0),
            value="flat_array(states)", note="states: (4, 2) ndarray, rates: (4,) ndarray"),
    },
    baseline="swerve.desat1:alloc_free"))


def _ds_drive():
    from drivekin.diffswerve import DifferentialSwerveModuleKinematics

    return DifferentialSwerveModuleKinematics(3.0, 5.0, 0.05)


def _np_array(values):
    import numpy as np

    return np.array(values, dtype=np.float64)


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


# ---------------------------------------------------------------------------------------
# Dead wheels (drivekin-only: no robotpy peer). The odometry updates are held to 1.3× of
# DifferentialDriveOdometry.update in the same run (issue 7), with the differential case's
# inputs where they apply (one step's distances, gyro1). Three wheels: Road Runner's
# standard layout (parallel wheels at y = ±7.1 in, perpendicular at x = −3.75 in).

_RR_LAYOUT = (-7.1, 7.1, -3.75, 1.0)        # fromRoadRunner(par0_y, par1_y, perp_x, in_per_tick)
_DW_READINGS = [0.0121, 0.0183, 0.0027]     # m, one step's distances (par0, par1, perp)


def _dw_kin():
    from drivekin import DeadWheelKinematics

    return DeadWheelKinematics.fromRoadRunner(*_RR_LAYOUT)


def _dw_odometry(dk, gyro, readings):
    from drivekin import DeadWheelOdometry

    return DeadWheelOdometry(_dw_kin(), readings([0.0, 0.0, 0.0]), dk.rot if gyro else None,
                             dk.pose)


def _np_readings(values):
    import numpy as np

    return np.array(values, dtype=np.float64)


def _dw_case(gyro, readings=list, note=_ODO_NOTE):
    stmt = "odo.update(pos, gyro)" if gyro else "odo.update(pos)"
    return Case(stmt, lambda rp, dk: dict(odo=_dw_odometry(dk, gyro, readings),
                                          pos=readings(_DW_READINGS), gyro=dk.gyro1),
                value="dk_pose(odo.getPose())", note=note)


def _two_dead_wheel_case(note=""):
    return Case("odo.update(x, y, gyro)",
                lambda rp, dk: dict(odo=dk.o.TwoDeadWheelOdometry(0.1, -0.15, 0.0, 0.0,
                                                                  dk.rot, dk.pose),
                                    x=dk.dpos1[0], y=dk.dpos1[1], gyro=dk.gyro1),
                value="dk_pose(odo.getPose())", note=note)


register(Operation(
    key="deadwheel.odometry2", title="TwoDeadWheelOdometry.update(x, y, gyro)",
    suite="deadwheel", robotpy=None,
    facade=_two_dead_wheel_case(), alloc_free=_two_dead_wheel_case(_ODO_NOTE),
    baseline="odometry.differential", baseline_targets=(1.3, 1.3)))

register(Operation(
    key="deadwheel.odometry3", title="DeadWheelOdometry.update (3 wheels, no gyro)",
    suite="deadwheel", robotpy=None,
    facade=_dw_case(False, note="pos: list of 3 floats, m"), alloc_free=_dw_case(False),
    extras={"alloc_free[ndarray]": _dw_case(False, _np_readings,
                                            note="pos: (3,) float64 ndarray")},
    baseline="odometry.differential", baseline_targets=(1.3, 1.3)))

register(Operation(
    key="deadwheel.odometry3g", title="DeadWheelOdometry.update (3 wheels + gyro)",
    suite="deadwheel", robotpy=None,
    facade=_dw_case(True, note="pos: list of 3 floats, m; dθ from the gyro"),
    alloc_free=_dw_case(True),
    baseline="odometry.differential", baseline_targets=(1.3, 1.3)))

register(Operation(
    key="deadwheel.fk", title="DeadWheelKinematics.toChassisVelocities (3 wheels)",
    suite="deadwheel", robotpy=None,
    facade=Case("kin.toChassisVelocities(w)",
                lambda rp, dk: dict(kin=_dw_kin(), w=[1.2, 1.5, 0.3]),
                value="(lambda c: [c.vx, c.vy, c.omega])(kin.toChassisVelocities(w))",
                note="w: list of 3 floats, m/s"),
    alloc_free=Case("kin.toChassisVelocitiesInto(w, out)",
                    lambda rp, dk: dict(kin=_dw_kin(), w=[1.2, 1.5, 0.3],
                                        out=dk.k.ChassisVelocities()),
                    value="[out.vx, out.vy, out.omega]", note="out: ChassisVelocities"),
    baseline="mecanum.fk"))


# ---------------------------------------------------------------------------------------
# Pose estimators (issue 8 §2): drivekin's SwerveDrivePoseEstimator against robotpy's
# SwerveDrive4PoseEstimator. Every estimator is first driven for 1.5 s at 50 Hz (76
# updates, the whole history: module distances and gyro advancing as in the odometry
# inputs, one step of `dt` each) with a vision measurement 50 ms old after every third
# update, so the timed calls work on a full history and a realistic set of records.
# updateWithTime reads its time from an itertools.count (a C iterator, the same few ns on
# both sides), so time advances by dt every call and the history slides; its readings are
# the last fill step's, so after the first timed call the odometry twist is zero.

_EST_DT = 0.02
_EST_STEPS = 76                             # 1.5 s at 50 Hz, t = dt .. 76 dt
_EST_LATENCY = 0.05                         # s, vision measurement age
_EST_VISION_TS = _EST_STEPS * _EST_DT - 0.553   # inside the window, between two samples


def _est_fill(est, g, k, positions):
    """Drive ``est`` for _EST_STEPS updates; return the last (gyro, positions)."""
    from _common import INPUTS as inp

    vision = g.Pose2d(inp.pose[0] + 0.1, inp.pose[1] - 0.05, g.Rotation2d(inp.pose[2] + 0.02))
    for i in range(1, _EST_STEPS + 1):
        t = i * _EST_DT
        gyro = g.Rotation2d(inp.robot_angle + inp.omega * t)
        pos = tuple(k.SwerveModulePosition(p.distance * i, p.angle) for p in positions)
        est.updateWithTime(t, gyro, pos)
        if i % 3 == 0:
            est.addVisionMeasurement(vision, t - _EST_LATENCY)
    return gyro, pos


def _rp_estimator(rp):
    from wpimath.estimator import SwerveDrive4PoseEstimator

    est = SwerveDrive4PoseEstimator(rp.kin, rp.rot, rp.spos0, rp.pose, (0.1, 0.1, 0.1),
                                    (0.9, 0.9, 0.9))
    gyro, pos = _est_fill(est, rp.g, rp.k, rp.spos1)
    return dict(est=est, gyro=gyro, pos=pos)


def _dk_estimator(dk):
    from drivekin import SwerveDrivePoseEstimator

    est = SwerveDrivePoseEstimator(dk.kin, dk.rot, dk.spos0, dk.pose, (0.1, 0.1, 0.1),
                                   (0.9, 0.9, 0.9))
    gyro, pos = _est_fill(est, dk.g, dk.k, dk.spos1)
    return dict(est=est, gyro=gyro, pos=pos)


def _clock():
    import itertools

    return itertools.count((_EST_STEPS + 1) * _EST_DT, _EST_DT).__next__


def _vision(g):
    return g.Pose2d(1.12, 1.93, g.Rotation2d(0.55))


_EST_NOTE = ("same call as the façade: the estimator has one form (the returned Pose2d "
             "comes from a freelist)")


def _estimator_op(key, title, stmt, extra, value, targets, note):
    def rp_setup(rp, dk):
        return dict(_rp_estimator(rp), **extra(rp.g))

    def dk_setup(rp, dk):
        return dict(_dk_estimator(dk), **extra(dk.g))

    return register(Operation(
        key=key, title=title, suite="estimator",
        robotpy=Case(stmt, rp_setup, value=f"rp_pose({value})",
                     note=f"SwerveDrive4PoseEstimator; {note}"),
        facade=Case(stmt, dk_setup, value=f"dk_pose({value})", note=note),
        alloc_free=Case(stmt, dk_setup, value=f"dk_pose({value})", note=_EST_NOTE),
        targets=targets))


_estimator_op(
    "estimator.update", "SwerveDrivePoseEstimator.updateWithTime (4 modules)",
    "est.updateWithTime(clk(), gyro, pos)", lambda g: dict(clk=_clock()),
    "est.getEstimatedPosition()", (0.10, 0.10),
    "full 1.5 s history with vision records; time advances 20 ms a call")
_estimator_op(
    "estimator.vision", "SwerveDrivePoseEstimator.addVisionMeasurement (full 1.5 s buffer)",
    "est.addVisionMeasurement(vision, ts)",
    lambda g: dict(vision=_vision(g), ts=_EST_VISION_TS),
    "est.getEstimatedPosition()", (0.25, 0.25),
    "measurement 0.553 s old, between two samples, after 16 records")
_estimator_op(
    "estimator.sample", "SwerveDrivePoseEstimator.sampleAt (full 1.5 s buffer)",
    "est.sampleAt(ts)", lambda g: dict(ts=_EST_VISION_TS),
    "est.sampleAt(ts)", (0.15, 0.15),
    "between two samples, with vision records before it")


# The 3-D rows (issue 29) register themselves, with their group.
import registry3d  # noqa: E402,F401
