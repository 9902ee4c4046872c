"""Shared set-up for the drivekin benchmarks: the fixed robot, the fixed inputs, the
prebuilt robotpy / drivekin argument objects, the loop compiler and the machine description.

drivekin's kinematics are the catalog's examples (``drivekin._core.catalog``), checked to
be the robot of :data:`INPUTS`, from which the robotpy objects (and the numpy code of
``batch_table.py``) are built independently. ``rp.kinematics`` / ``dk.kinematics`` and
``rp.ik_wheels`` / ``dk.ik_wheels`` hold them by the catalog's drivetrain key.

Used by ``registry.py`` and ``conftest.py`` for the ``bench_*.py`` files (pytest-benchmark;
``_bench.bench_tests`` writes their test functions) and by ``ratio_table.py`` (stand-alone
timer), so both measure exactly the same statements on exactly the same inputs. It imports
none of the other benchmark modules.

drivekin is imported from wherever ``python`` finds it: an installed copy, or the in-place
build with ``PYTHONPATH=src`` (from the repository root). Nothing here edits ``sys.path``;
the scripts find these modules because a script's own folder is on ``sys.path``, and pytest
puts this folder there for ``conftest.py`` and the ``bench_*.py`` files.
"""
from __future__ import annotations

import itertools
import os
import platform
import time
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path
from types import SimpleNamespace

try:
    import drivekin  # noqa: F401
except ImportError as e:  # pragma: no cover - depends on how the script is launched
    raise ImportError("the benchmarks need drivekin: install it, or run them from the "
                      "repository root with PYTHONPATH=src (the in-place build)") from e

# Calls per benchmarked body. Every call under test is sub-microsecond, so each timed body
# runs the statement INNER times in a local loop; the same count is used for every variant.
INNER = 100


# ---------------------------------------------------------------------------------------
# The fixed robot and inputs (same numbers as shared/reference/perf-floor.md)

@dataclass(frozen=True)
class Inputs:
    modules: tuple = ((0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3))  # FL, FR, BL, BR, m
    vx: float = 1.5          # m/s
    vy: float = -0.7         # m/s
    omega: float = 2.0       # rad/s
    dt: float = 0.02         # s
    robot_angle: float = 0.5  # rad (gyro heading for the field-relative conversion)
    # single-argument desaturate: module speeds from IK are 0.91 .. 2.47 m/s, so 1.0 scales
    max_speed: float = 1.0
    # five-argument desaturate: kT = |(vx, vy)|/3 = 0.55, kR = 2/6 = 0.33, scale = 0.89 < 1
    max_module: float = 4.0
    max_translation: float = 3.0
    max_rotation: float = 6.0
    pose: tuple = (1.0, 2.0, 0.5)         # x m, y m, heading rad
    twist: tuple = (0.02, 0.01, 0.03)     # dx m, dy m, dtheta rad
    # mecanum: wheels at `modules` (FL, FR, RL, RR); IK gives 1.0, 2.0, -0.4, 3.4 m/s.
    # differential: trackwidth W; IK gives left 0.9, right 2.1 m/s.
    trackwidth: float = 0.6               # m
    # desaturate with a limit above every wheel speed (no wheel is rescaled)
    max_speed_unsaturated: float = 5.0    # m/s
    # odometry: built at gyro `robot_angle` with zero wheel distances and initial pose
    # `pose`; the benchmarked update passes gyro robot_angle + omega*dt and the distances
    # of one dt at the IK wheel speeds (module angles of the IK states for swerve).


INPUTS = Inputs()


def build_robotpy(inp: Inputs = INPUTS) -> SimpleNamespace:
    """robotpy-wpimath 2026 objects; every argument object is prebuilt (as in perf-floor)."""
    from wpimath import geometry as g, kinematics as k

    kin = k.SwerveDrive4Kinematics(*(g.Translation2d(x, y) for x, y in inp.modules))
    cs = k.ChassisSpeeds(inp.vx, inp.vy, inp.omega)
    states = kin.toSwerveModuleStates(cs)             # tuple of 4 SwerveModuleState
    mkin = k.MecanumDriveKinematics(*(g.Translation2d(x, y) for x, y in inp.modules))
    mwheels = mkin.toWheelSpeeds(cs)
    dkin = k.DifferentialDriveKinematics(inp.trackwidth)
    dwheels = dkin.toWheelSpeeds(cs)
    dt = inp.dt
    return SimpleNamespace(
        g=g, k=k,
        # by the catalog's drivetrain key (registry.py's drivetrain loop reads these)
        kinematics={"swerve": kin, "mecanum": mkin, "differential": dkin},
        ik_wheels={"mecanum": mwheels, "differential": dwheels},
        Kinematics=k.SwerveDrive4Kinematics,
        ChassisSpeeds=k.ChassisSpeeds,
        kin=kin,
        cs=cs,
        states=states,
        rot=g.Rotation2d(inp.robot_angle),
        pose=g.Pose2d(inp.pose[0], inp.pose[1], g.Rotation2d(inp.pose[2])),
        twist=g.Twist2d(*inp.twist),
        # mecanum / differential
        mkin=mkin,
        MecanumDriveWheelSpeeds=k.MecanumDriveWheelSpeeds,
        mwheels=mwheels,                               # MecanumDriveWheelSpeeds (IK of cs)
        dkin=dkin,
        DifferentialDriveWheelSpeeds=k.DifferentialDriveWheelSpeeds,
        dwheels=dwheels,                               # DifferentialDriveWheelSpeeds
        # odometry inputs
        SwerveDrive4Odometry=k.SwerveDrive4Odometry,
        MecanumDriveOdometry=k.MecanumDriveOdometry,
        DifferentialDriveOdometry=k.DifferentialDriveOdometry,
        gyro1=g.Rotation2d(inp.robot_angle + inp.omega * dt),
        spos0=tuple(k.SwerveModulePosition(0.0, s.angle) for s in states),
        spos1=tuple(k.SwerveModulePosition(s.speed * dt, s.angle) for s in states),
        mpos0=k.MecanumDriveWheelPositions(),
        mpos1=_mecanum_positions(k.MecanumDriveWheelPositions, mwheels, dt),
        dpos1=(dwheels.left * dt, dwheels.right * dt),
    )


def _mecanum_positions(cls, w, dt):
    p = cls()
    p.frontLeft, p.frontRight = w.frontLeft * dt, w.frontRight * dt
    p.rearLeft, p.rearRight = w.rearLeft * dt, w.rearRight * dt
    return p


def build_drivekin_geometry(inp: Inputs = INPUTS) -> SimpleNamespace:
    from drivekin import geometry as g

    return SimpleNamespace(
        g=g,
        rot=g.Rotation2d(inp.robot_angle),
        pose=g.Pose2d(inp.pose[0], inp.pose[1], g.Rotation2d(inp.pose[2])),
        twist=g.Twist2d(*inp.twist),
    )


def kinematics_available() -> bool:
    try:
        import drivekin.kinematics  # noqa: F401
    except ImportError:
        return False
    return True


def catalog_kinematics(drivetrain: str, inp: Inputs = INPUTS):
    """A new instance of the catalog's example kinematics of ``drivetrain`` (a catalog
    drivetrain key), checked to be the robot of ``inp`` (ValueError if not)."""
    from drivekin._core import catalog

    (entry,) = catalog.entries("kinematics", drivetrain=drivetrain)
    kin = entry.example()
    got = entry.flatten(kin)               # the wire form: module positions, or trackwidth
    want = ((inp.trackwidth,) if drivetrain == "differential"
            else tuple(c for module in inp.modules for c in module))
    if got != want:
        raise ValueError(f"the catalog's {drivetrain} example {got} is not the benchmark "
                         f"robot {want} (Inputs)")
    return kin


def build_drivekin(inp: Inputs = INPUTS) -> SimpleNamespace:
    """drivekin objects. Needs drivekin.kinematics (ImportError otherwise)."""
    from drivekin import kinematics as k

    ns = build_drivekin_geometry(inp)
    kin = catalog_kinematics("swerve", inp)
    cv = k.ChassisVelocities(inp.vx, inp.vy, inp.omega)
    ns.k = k
    ns.Kinematics = k.SwerveDriveKinematics
    ns.ChassisVelocities = k.ChassisVelocities
    ns.SwerveModuleVelocity = k.SwerveModuleVelocity
    ns.kin = kin
    ns.cv = cv
    ns.states = kin.toSwerveModuleVelocities(cv)    # tuple of 4 SwerveModuleVelocity
    _add_drivetrains(ns, inp)
    return ns


def _add_drivetrains(ns: SimpleNamespace, inp: Inputs) -> None:
    """drivekin.mecanum / differential / odometry objects, the same inputs as robotpy's."""
    from drivekin import differential as d, mecanum as m, odometry as o

    k, dt = ns.k, inp.dt
    ns.m, ns.d, ns.o = m, d, o
    ns.mkin = catalog_kinematics("mecanum", inp)
    ns.MecanumDriveWheelVelocities = m.MecanumDriveWheelVelocities
    ns.mwheels = ns.mkin.toWheelVelocities(ns.cv)
    ns.dkin = catalog_kinematics("differential", inp)
    ns.DifferentialDriveWheelVelocities = d.DifferentialDriveWheelVelocities
    ns.dwheels = ns.dkin.toWheelVelocities(ns.cv)
    ns.kinematics = {"swerve": ns.kin, "mecanum": ns.mkin, "differential": ns.dkin}
    ns.ik_wheels = {"mecanum": ns.mwheels, "differential": ns.dwheels}
    ns.SwerveDriveOdometry = o.SwerveDriveOdometry
    ns.MecanumDriveOdometry = o.MecanumDriveOdometry
    ns.DifferentialDriveOdometry = o.DifferentialDriveOdometry
    ns.gyro1 = ns.g.Rotation2d(inp.robot_angle + inp.omega * dt)
    ns.spos0 = tuple(k.SwerveModulePosition(0.0, s.angle) for s in ns.states)
    ns.spos1 = tuple(k.SwerveModulePosition(s.velocity * dt, s.angle) for s in ns.states)
    ns.mpos0 = m.MecanumDriveWheelPositions()
    ns.mpos1 = m.MecanumDriveWheelPositions(*(x * dt for x in ns.mwheels))
    ns.dpos1 = (ns.dwheels.left * dt, ns.dwheels.right * dt)


def fresh_states(dk: SimpleNamespace) -> list:
    """A new list of N SwerveModuleVelocity equal to dk.states (for in-place variants)."""
    return [dk.SwerveModuleVelocity(s.velocity, s.angle) for s in dk.states]


def copy_wheels(w, values):
    """A new wheel object equal to ``w`` (desaturate mutates): its class called with
    ``values(w)``, the wheel values in constructor order (robotpy 2026's wheel speeds and
    drivekin's wheel velocities take the same)."""
    return type(w)(*values(w))


def positions_array(positions):
    """N SwerveModulePosition as a float64 C-contiguous (N, 2) array [distance m, angle rad]."""
    import numpy as np

    return np.array([[p.distance, p.angle.getRadians()] for p in positions], dtype=np.float64)


def states_array(dk: SimpleNamespace):
    """dk.states as a float64 C-contiguous (N, 2) array [velocity m/s, angle rad]."""
    import numpy as np

    return np.array([[s.velocity, s.angle.getRadians()] for s in dk.states], dtype=np.float64)


# ---------------------------------------------------------------------------------------
# Loop compiler: the statement runs in a local loop with every name bound as a default
# argument, so each name is a LOAD_FAST (same technique as timeit's `setup`).

def _check_names(env: dict) -> list:
    names = sorted(env)
    for n in names:
        if not n.isidentifier() or n.startswith("_"):
            raise ValueError(f"bad benchmark local name {n!r}")
    return names


def compile_body(stmt: str, env: dict, inner: int = INNER):
    """Return a zero-argument function that executes ``stmt`` ``inner`` times."""
    names = _check_names(env)
    params = "".join(f"{n}={n}, " for n in names)
    src = (f"def _body({params}_rep=_rep, _inner={inner}):\n"
           f"    for _ in _rep(None, _inner):\n"
           f"        {stmt}\n")
    ns = dict(env, _rep=itertools.repeat)
    exec(compile(src, f"<bench: {stmt}>", "exec"), ns)
    return ns["_body"]


def compile_timer(stmt: str, env: dict):
    """Return ``timer(n) -> seconds`` that executes ``stmt`` n times (timeit-style)."""
    names = _check_names(env)
    params = "".join(f"{n}={n}, " for n in names)
    src = (f"def _timer(_n, {params}_rep=_rep, _clock=_clock):\n"
           f"    _it = _rep(None, _n)\n"
           f"    _t0 = _clock()\n"
           f"    for _ in _it:\n"
           f"        {stmt}\n"
           f"    return _clock() - _t0\n")
    ns = dict(env, _rep=itertools.repeat, _clock=time.perf_counter)
    exec(compile(src, f"<timer: {stmt}>", "exec"), ns)
    return ns["_timer"]


# ---------------------------------------------------------------------------------------
# Machine description

def _version(dist: str) -> str:
    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return "not installed"


def cpu_model() -> str:
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def machine_description() -> list[str]:
    import numpy

    try:
        import drivekin
        dk = f"{getattr(drivekin, '__version__', '?')} from {Path(drivekin.__file__).parent}"
    except ImportError:
        dk = "not importable"
    try:
        cpus = sorted(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        cpus = []
    try:
        load = "load average %.2f %.2f %.2f" % os.getloadavg()
    except OSError:  # pragma: no cover
        load = "load average ?"
    return [
        f"CPU: {cpu_model()} ({os.cpu_count()} logical CPUs, {load}; this process pinned to "
        f"CPU {','.join(map(str, cpus)) or '?'})",
        f"OS: {platform.platform()}",
        f"Python: {platform.python_implementation()} {platform.python_version()} "
        f"({platform.python_compiler()})",
        f"robotpy-wpimath: {_version('robotpy-wpimath')}; numpy {numpy.__version__}; "
        f"Cython {_version('Cython')}; drivekin {dk}",
    ]
