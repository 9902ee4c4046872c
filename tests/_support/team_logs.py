"""``.wpilog`` files laid out the way FRC teams' robots write them, written by
robotpy-wpiutil / ntcore (never by drivekin), with the truth robotpy-wpimath computes.

The same simulated robot and motion as :mod:`tests._support.real_logs` (26 s: rest,
straight, arcs, turning in place, strafing, a combined move, reversing, rest), logged as:

* :func:`yagsl_swerve`: YAGSL's swerve telemetry at ``HIGH`` verbosity (2025 sources:
  ``SwerveDrive.updateOdometry``, ``SwerveModule.updateTelemetry``,
  ``SwerveDriveTelemetry``), mirrored by ntcore as DataLogManager does (``NT:``);
* :func:`sysid_swerve`: a WPILib SysId drive routine (``SysIdRoutineLog``'s
  ``voltage-/position-/velocity-<motor>-<log>`` entries written straight into the
  DataLog) with the same robot's module angles, gyro and Field2d pose under YAGSL's
  names, mirrored by ntcore into the same file (as the real YAGSL log pairs them);
* :func:`team_named_swerve`: per-module doubles under a team's own names (Team 302's
  ``NT:/Left Front Swerve Encoders/Left Front Drive`` / ``... Turn``), a ``Robot Angle``
  gyro and a ``struct:Pose2d`` pose written straight into the DataLog;
* :func:`module_states_only`: module velocity states and no distances, either per
  module (``Module N/Drive Velocity Feet`` + ``Steer Degrees``) or as one
  ``struct:SwerveModuleState[]``.

NetworkTables writes a value only when it changed, so entries thin out where the robot
rests. Values a real robot publishes one after another carry their own instants
(``set()`` takes wpi::Now()): YAGSL's cycle spans about 0.5 ms in the real log
(``Field/Robot`` first, then each module, the IMU inside the module loop, the summary
arrays last); here each record of a cycle is ``stagger_us`` after the previous one.

``truth[i]`` is the robot's odometry (x m, y m, θ rad) at its ``i``-th odometry cycle,
which starts at ``t_us[i]``: SwerveDrive4Odometry constructed at the first cycle with
``notes["initial_pose"]`` and fed, in the robot's order, exactly the logged values."""
from __future__ import annotations

import math
import pathlib

import numpy as np
from wpimath.geometry import Pose2d, Rotation2d, Rotation3d, Translation2d
from wpimath.kinematics import (
    ChassisSpeeds,
    SwerveDrive4Kinematics,
    SwerveDrive4Odometry,
    SwerveModulePosition,
    SwerveModuleState,
)

from tests._support.real_logs import (
    _KNOTS_HOLONOMIC,
    DT_US,
    START,
    T0_US,
    RealLog,
    _cycles,
    _flushing,
    _Motion,
    _nt_close,
    _nt_logging,
    _pose_row,
    _start_pose,
    _StructEntry,
    _swerve_wheels,
)

PERIOD_US = 20_000                       # a roboRIO's 50 Hz loop / YAGSL's odometry Notifier
NT_WRITER = "pyntcore 2026.2.2 startEntryDataLog (NT: mirroring)"


def _java_round(x: float) -> float:
    """Java's Math.round (half up), which YAGSL applies to module locations in inches."""
    return float(math.floor(x + 0.5))


class _Odometry:
    """SwerveDrive4Odometry started at START on its first update."""

    def __init__(self, kin) -> None:
        self.kin, self.odo, self.rows = kin, None, []

    def update(self, gyro: Rotation2d, mods) -> Pose2d:
        if self.odo is None:
            self.odo = SwerveDrive4Odometry(self.kin, gyro, tuple(mods), _start_pose())
            pose = self.odo.getPose()
        else:
            pose = self.odo.update(gyro, tuple(mods))
        self.rows.append(_pose_row(pose))
        return pose


class _Stamps:
    """A cycle's record instants: each ``set`` ``step`` µs after the previous one."""

    def __init__(self, start: int, step: int) -> None:
        self.t, self.step = start - step, step

    def __call__(self) -> int:
        self.t += self.step
        return self.t


def _imu_degrees(yaw: float) -> float:
    # SwerveDrive.getYaw(): Rotation2d.fromRadians(imu Rotation3d.getZ()), so the logged
    # imu/raw is wrapped to (-180°, 180°].
    return Rotation2d(Rotation3d(0.0, 0.0, yaw).Z()).degrees()


def _absolute_degrees(angle: float) -> float:
    # SwerveModule.getRawAbsolutePosition() with state optimisation on: [0°, 360°).
    a = math.fmod(math.degrees(angle), 360.0)
    return a + 360.0 if a < 0.0 else a


# ---------------------------------------------------------------------------------------
# 1. YAGSL

YAGSL_NAMES = ("frontleft", "frontright", "backleft", "backright")   # swervedrive.json order
# The modules' ``location`` (front, left) in inches as a team's JSON gives them; YAGSL
# rounds them (Java Math.round) before use: (12, 12), (12, -11), (-11, 12), (-11, -11).
YAGSL_JSON_INCHES = ((12.4, 11.6), (12.4, -10.7), (-11.5, 11.6), (-11.5, -10.7))
YAGSL_ABS_OFFSETS_DEG = (88.2, 130.7, 173.9, 266.0)   # absolute encoder offsets


def _yagsl_geometry():
    used = [(_java_round(f) * 0.0254, _java_round(l) * 0.0254) for f, l in YAGSL_JSON_INCHES]
    physical = [(f * 0.0254, l * 0.0254) for f, l in YAGSL_JSON_INCHES]
    # SwerveDriveTelemetry.wheelLocations: Units.metersToInches of the locations used.
    wheel_location = [c / 0.0254 for xy in used for c in xy]
    return used, physical, wheel_location


class _YagslTelemetry:
    """The NetworkTables topics YAGSL publishes under /SmartDashboard (2025)."""

    def __init__(self, inst, names, *, drive_encoders: bool = True) -> None:
        sd = inst.getTable("SmartDashboard")
        self.field_type = sd.getStringTopic("Field/.type").publish()
        self.field_name = sd.getStringTopic("Field/.name").publish()
        self.field_robot = sd.getDoubleArrayTopic("Field/Robot").publish()
        self.modules = []
        for n in names:
            p = f"swerve/modules/{n}/"
            topics = ["Raw Absolute Encoder", "Raw Angle Encoder"]
            if drive_encoders:
                topics += ["Raw Drive Encoder", "Raw Drive Velocity"]
            topics += ["Adjusted Absolute Encoder"]
            self.modules.append({k: sd.getDoubleTopic(p + k).publish() for k in topics}
                                | {"Absolute Encoder Read Issue":
                                   sd.getBooleanTopic(p + "Absolute Encoder Read Issue").publish()})
        self.imu_raw = sd.getDoubleTopic("swerve/imu/raw").publish()
        self.imu_adjusted = sd.getDoubleTopic("swerve/imu/adjusted").publish()
        d = sd.getDoubleTopic
        self.settings = [
            (sd.getDoubleArrayTopic("swerve/wheelLocation").publish(), "wheelLocation"),
            (d("swerve/maxSpeed").publish(), "maxSpeed"),
            (sd.getStringTopic("swerve/rotationUnit").publish(), "rotationUnit"),
            (d("swerve/sizeLeftRight").publish(), "sizeLeftRight"),
            (d("swerve/sizeFrontBack").publish(), "sizeFrontBack"),
            (sd.getStringTopic("swerve/forwardDirection").publish(), "forwardDirection"),
        ]
        self.module_count = d("swerve/moduleCount").publish()
        self.measured = sd.getDoubleArrayTopic("swerve/measuredStates").publish()
        self.desired = sd.getDoubleArrayTopic("swerve/desiredStates").publish()
        self.robot_rotation = d("swerve/robotRotation").publish()
        self.max_angular = d("swerve/maxAngularVelocity").publish()
        self.measured_speeds = sd.getDoubleArrayTopic("swerve/measuredChassisSpeeds").publish()
        self.desired_speeds = sd.getDoubleArrayTopic("swerve/desiredChassisSpeeds").publish()
        a = "swerve/advantagescope/"
        self.desired_struct = sd.getStructArrayTopic(a + "desiredStates", SwerveModuleState).publish()
        self.current_struct = sd.getStructArrayTopic(a + "currentStates", SwerveModuleState).publish()
        self.desired_speeds_struct = sd.getStructTopic(a + "desiredChassisSpeeds", ChassisSpeeds).publish()
        self.measured_speeds_struct = sd.getStructTopic(a + "measuredChassisSpeeds", ChassisSpeeds).publish()
        self.rotation_struct = sd.getStructTopic(a + "robotRotation", Rotation2d).publish()


def _yagsl_publish_cycle(tel: _YagslTelemetry, stamp: _Stamps, k: int, pose: Pose2d,
                         modules: list[dict], imu_deg: float, speeds: ChassisSpeeds,
                         settings: dict) -> None:
    """One SwerveDrive.updateOdometry() at HIGH verbosity, in its order: Field/Robot
    (field.setRobotPose), each module's updateTelemetry with the IMU after it, then
    SwerveDriveTelemetry.updateData (settings once first)."""
    heading_deg = pose.rotation().degrees()
    tel.field_robot.set([pose.X(), pose.Y(), heading_deg], stamp())
    for pubs, m in zip(tel.modules, modules):
        for key, pub in pubs.items():
            pub.set(m[key], stamp())
        tel.imu_raw.set(imu_deg, stamp())
        tel.imu_adjusted.set(heading_deg, stamp())
    if k == 0:
        for pub, key in tel.settings:
            pub.set(settings[key], stamp())
    tel.module_count.set(float(len(modules)), stamp())
    measured = [SwerveModuleState(m["speed"], Rotation2d.fromDegrees(m["Adjusted Absolute Encoder"]))
                for m in modules]
    desired = [SwerveModuleState(1.02 * s.speed + 0.01, s.angle) for s in measured]
    tel.measured.set([v for s in measured for v in (s.angle.degrees(), s.speed)], stamp())
    tel.desired.set([v for s in desired for v in (s.angle.degrees(), s.speed)], stamp())
    tel.robot_rotation.set(heading_deg, stamp())
    tel.max_angular.set(settings["maxAngularVelocity"], stamp())
    tel.measured_speeds.set([speeds.vx, speeds.vy, math.degrees(speeds.omega)], stamp())
    tel.desired_speeds.set([speeds.vx, speeds.vy, math.degrees(speeds.omega)], stamp())
    tel.desired_struct.set(desired, stamp())
    tel.current_struct.set(measured, stamp())
    tel.desired_speeds_struct.set(speeds, stamp())
    tel.measured_speeds_struct.set(speeds, stamp())
    tel.rotation_struct.set(pose.rotation(), stamp())


def _yagsl_settings(used) -> dict:
    wl = [c / 0.0254 for xy in used for c in xy]
    return {"wheelLocation": wl, "maxSpeed": 4.4196, "rotationUnit": "degrees",
            "sizeLeftRight": (used[0][1] + used[2][1]) / 0.0254,
            "sizeFrontBack": (used[0][0] + used[1][0]) / 0.0254,
            "forwardDirection": "up", "maxAngularVelocity": 7.9}


def _yagsl_module_values(motion: _Motion, i: int, j: int, drive: bool = True) -> dict:
    dist, speed, angle = motion.wheels[j]
    adjusted = _absolute_degrees(float(angle[i]))
    out = {"Raw Absolute Encoder": math.fmod(adjusted + YAGSL_ABS_OFFSETS_DEG[j], 360.0),
           "Raw Angle Encoder": math.degrees(float(angle[i])),     # the relative encoder
           "Adjusted Absolute Encoder": adjusted,
           "Absolute Encoder Read Issue": False,
           "speed": float(speed[i]), "distance": float(dist[i])}
    if drive:
        out["Raw Drive Encoder"] = float(dist[i])
        out["Raw Drive Velocity"] = float(speed[i])
    return out


def yagsl_swerve(directory, *, stagger_us: int = 18, filename: str = "yagsl_swerve.wpilog") -> RealLog:
    """YAGSL's HIGH-verbosity telemetry, mirrored by ntcore (``NT:/SmartDashboard/...``).

    Per module (``frontleft``, ``frontright``, ``backleft``, ``backright``, the
    swervedrive.json order): ``Raw Drive Encoder`` (m, what the odometry uses),
    ``Adjusted Absolute Encoder`` (degrees in [0, 360), what the odometry uses),
    ``Raw Absolute Encoder`` (before the offset), ``Raw Angle Encoder`` (relative,
    unwrapped degrees), ``Raw Drive Velocity`` (m/s), ``Absolute Encoder Read Issue``;
    ``swerve/imu/raw`` (degrees in (-180, 180], the odometry's gyro), ``swerve/imu/adjusted``
    and ``swerve/robotRotation`` (the odometry heading, degrees); ``Field/Robot`` (x m,
    y m, degrees: the odometry pose) with ``Field/.type`` = Field2d;
    ``swerve/wheelLocation`` (inches, x y per module: the rounded locations the odometry
    uses, published once), ``sizeLeftRight``, ``sizeFrontBack``, ``maxSpeed``,
    ``rotationUnit``, ``forwardDirection`` (once), ``moduleCount``, ``measuredStates`` /
    ``desiredStates`` (double[]: degrees, m/s per module), ``measuredChassisSpeeds``,
    ``desiredChassisSpeeds``, ``maxAngularVelocity`` and the ``swerve/advantagescope/``
    structs (``currentStates``, ``desiredStates`` SwerveModuleState[], chassis speeds,
    ``robotRotation`` Rotation2d).

    The robot's odometry (YAGSL's pose estimator without vision) runs every 20 ms at
    ``t_us[i]``; that cycle's records follow, ``stagger_us`` apart (``Field/Robot``
    first). Truth: SwerveDrive4Odometry with the rounded locations, fed
    ``Rotation2d.fromDegrees(imu/raw)`` and (``Raw Drive Encoder``,
    ``Rotation2d.fromDegrees(Adjusted Absolute Encoder)``) of each cycle."""
    path = pathlib.Path(directory) / filename
    used, physical, _ = _yagsl_geometry()
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in used])
    motion = _Motion(_KNOTS_HOLONOMIC, _swerve_wheels(physical))
    cyc = _cycles(PERIOD_US)
    idx = motion.at(cyc)
    settings = _yagsl_settings(used)
    ntcore, log, inst, handle = _nt_logging(path)
    tick = _flushing(log, 40)
    tel = _YagslTelemetry(inst, YAGSL_NAMES)
    tel.field_type.set("Field2d", int(cyc[0]) - 5000)
    tel.field_name.set("Field", int(cyc[0]) - 5000)
    odo = _Odometry(kin)
    span = 0
    try:
        for k, i in enumerate(idx):
            mods = [_yagsl_module_values(motion, i, j) for j in range(4)]
            imu = _imu_degrees(float(motion.yaw[i]))
            pose = odo.update(Rotation2d.fromDegrees(imu), [
                SwerveModulePosition(m["Raw Drive Encoder"],
                                     Rotation2d.fromDegrees(m["Adjusted Absolute Encoder"]))
                for m in mods])
            stamp = _Stamps(int(cyc[k]), stagger_us)
            speeds = ChassisSpeeds(float(motion.vx[i]), float(motion.vy[i]), float(motion.omega[i]))
            _yagsl_publish_cycle(tel, stamp, k, pose, mods, imu, speeds, settings)
            span = max(span, stamp.t - int(cyc[k]))
            tick()
    finally:
        _nt_close(ntcore, log, inst, handle)
    m = "NT:/SmartDashboard/swerve/modules/{}/"
    entries = {
        "drive_positions": [m.format(n) + "Raw Drive Encoder" for n in YAGSL_NAMES],
        "turn_angles": [m.format(n) + "Adjusted Absolute Encoder" for n in YAGSL_NAMES],
        "gyro_deg": "NT:/SmartDashboard/swerve/imu/raw",
        "pose": "NT:/SmartDashboard/Field/Robot",
        "wheel_location": "NT:/SmartDashboard/swerve/wheelLocation",
        "decoys": [m.format(n) + k for n in YAGSL_NAMES
                   for k in ("Raw Absolute Encoder", "Raw Angle Encoder", "Raw Drive Velocity")]
                  + ["NT:/SmartDashboard/swerve/imu/adjusted", "NT:/SmartDashboard/swerve/robotRotation",
                     "NT:/SmartDashboard/swerve/advantagescope/currentStates",
                     "NT:/SmartDashboard/swerve/advantagescope/desiredStates"],
    }
    geometry = {"modules": tuple(used), "json_inches": YAGSL_JSON_INCHES,
                "wheel_location_inches": settings["wheelLocation"], "module_names": YAGSL_NAMES,
                "drive_units": "m", "turn_units": "deg", "gyro_units": "deg"}
    notes = {"initial_pose": START, "rate_hz": 50, "cycle_us": cyc, "period_us": PERIOD_US,
             "cycle_span_us": span, "order": "Field/Robot first, then the modules, IMU after each module",
             "duplicates_dropped": "NT logs a value only when it changed; hold the last"}
    return RealLog(path, NT_WRITER + " of YAGSL 2025 telemetry", "swerve", geometry, entries,
                   cyc, np.array(odo.rows), notes)


# ---------------------------------------------------------------------------------------
# 2. WPILib SysId drive routine + YAGSL's angles, IMU and Field2d

SYSID_LOG_NAME = "SwerveSubsystem"       # SysIdRoutineLog's logName: the subsystem's name
SYSID_MOTOR_US = 900                     # CAN reads: each module's values ~0.9 ms apart
SYSID_TELEMETRY_US = 4_000               # the odometry telemetry after the SysId frame
# (state, start s, end s, peak speed m/s); the robot stops inside each test.
SYSID_TESTS = (("quasistatic-forward", 1.0, 6.0, 1.2), ("quasistatic-reverse", 7.0, 12.0, -1.2),
               ("dynamic-forward", 13.0, 16.0, 2.5), ("dynamic-reverse", 17.0, 20.0, -2.5))
SYSID_DURATION_S = 21.0
SYSID_YAW_PER_M = 0.02                   # the robot yaws a little as it drives (rad per m)


def _sysid_motion():
    """Modules centred at 0° (YAGSL's SwerveDriveTest.centerModules); each test a
    smooth speed pulse from rest to rest; slight yaw; wheel speeds vx - ω y."""
    n = round(SYSID_DURATION_S * 1e6) // DT_US + 1
    t = np.arange(n) * DT_US * 1e-6
    v = np.zeros(n)
    for _, a, b, peak in SYSID_TESTS:
        u = np.clip((t - a) / (b - a), 0.0, 1.0)
        v += peak * np.sin(np.pi * u) ** 2
    omega = SYSID_YAW_PER_M * np.abs(v)
    return t, v, omega


def sysid_swerve(directory, *, stagger_us: int = 18, filename: str = "sysid_swerve.wpilog") -> RealLog:
    """A WPILib SysId drive routine as ``SysIdRoutineLog`` writes it (DataLog entries
    ``voltage-drive-<module>-SwerveSubsystem`` metadata ``Volt``,
    ``position-...`` ``Meter``, ``velocity-...`` ``Meter per Second``, and
    ``sysid-test-state-SwerveSubsystem`` string), written with robotpy-wpiutil's typed
    log entries into the log ntcore mirrors YAGSL-named telemetry into: per module
    ``Adjusted Absolute Encoder`` / ``Raw Absolute Encoder`` (degrees), ``swerve/imu/raw``
    (degrees), ``Field/Robot`` (the odometry pose); no ``Raw Drive Encoder``, so the
    distances are only in the SysId entries.

    Each 50 Hz cycle at ``t_us[i]`` during a test: the four modules' voltage, position,
    velocity (``SYSID_MOTOR_US`` apart per module, ``stagger_us`` within), then the
    state, then (``SYSID_TELEMETRY_US`` after the cycle start) the telemetry. Outside the
    tests only the telemetry (unchanged at rest, so NT drops it) and one ``none`` state
    at each test's end. Truth: the robot's odometry, run every cycle on that cycle's
    SysId positions, module angles and IMU."""
    from wpiutil.log import DoubleLogEntry, StringLogEntry

    path = pathlib.Path(directory) / filename
    used, _, _ = _yagsl_geometry()
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in used])
    tg, v, omega = _sysid_motion()
    dt = DT_US * 1e-6
    yaw = 0.3 + np.concatenate([[0.0], np.cumsum(0.5 * (omega[1:] + omega[:-1]) * dt)])
    speeds = [v - omega * y for _, y in used]
    dists = [np.concatenate([[0.0], np.cumsum(0.5 * (s[1:] + s[:-1]) * dt)]) for s in speeds]
    accel = np.gradient(v, dt)
    n_cyc = round(SYSID_DURATION_S * 1e6) // PERIOD_US + 1
    cyc = T0_US + PERIOD_US * np.arange(n_cyc, dtype=np.int64)
    idx = (cyc - T0_US) // DT_US
    ntcore, log, inst, handle = _nt_logging(path)
    tick = _flushing(log, 40)
    tel = _YagslTelemetry(inst, YAGSL_NAMES, drive_encoders=False)
    tel.field_type.set("Field2d", int(cyc[0]) - 5000)
    t0 = int(cyc[0])
    e = {(kind, n): DoubleLogEntry(log, f"{kind}-drive-{n}-{SYSID_LOG_NAME}", unit, t0)
         for n in YAGSL_NAMES
         for kind, unit in (("voltage", "Volt"), ("position", "Meter"), ("velocity", "Meter per Second"))}
    state = StringLogEntry(log, f"sysid-test-state-{SYSID_LOG_NAME}", t0)
    odo = _Odometry(kin)
    test_of = np.full(n_cyc, -1)
    ts_s = (cyc - T0_US) * 1e-6
    for q, (_, a, b, _) in enumerate(SYSID_TESTS):
        test_of[(ts_s >= a) & (ts_s <= b)] = q
    try:
        for k, i in enumerate(idx):
            T = int(cyc[k])
            pos = [float(d[i]) for d in dists]
            ang = [_absolute_degrees(0.0)] * 4
            imu = _imu_degrees(float(yaw[i]))
            pose = odo.update(Rotation2d.fromDegrees(imu),
                              [SwerveModulePosition(p, Rotation2d.fromDegrees(a)) for p, a in zip(pos, ang)])
            q = test_of[k]
            if q >= 0:
                for j, n in enumerate(YAGSL_NAMES):
                    base = T + SYSID_MOTOR_US * j
                    volts = 0.15 * np.sign(speeds[j][i]) + 2.4 * speeds[j][i] + 0.4 * accel[i]
                    e["voltage", n].append(float(volts), base)
                    e["position", n].append(pos[j], base + stagger_us)
                    e["velocity", n].append(float(speeds[j][i]), base + 2 * stagger_us)
                state.append(SYSID_TESTS[q][0], T + SYSID_MOTOR_US * 4)
            elif k > 0 and test_of[k - 1] >= 0:
                state.append("none", T + SYSID_MOTOR_US * 4)
            stamp = _Stamps(T + SYSID_TELEMETRY_US, stagger_us)
            tel.field_robot.set([pose.X(), pose.Y(), pose.rotation().degrees()], stamp())
            for j, pubs in enumerate(tel.modules):
                pubs["Raw Absolute Encoder"].set(math.fmod(ang[j] + YAGSL_ABS_OFFSETS_DEG[j], 360.0), stamp())
                pubs["Raw Angle Encoder"].set(0.0, stamp())
                pubs["Adjusted Absolute Encoder"].set(ang[j], stamp())
                pubs["Absolute Encoder Read Issue"].set(False, stamp())
                tel.imu_raw.set(imu, stamp())
                tel.imu_adjusted.set(pose.rotation().degrees(), stamp())
            if k == 0:
                settings = _yagsl_settings(used)
                for pub, key in tel.settings:
                    pub.set(settings[key], stamp())
            tick()
    finally:
        _nt_close(ntcore, log, inst, handle)
    m = "NT:/SmartDashboard/swerve/modules/{}/"
    entries = {
        "drive_positions": [f"position-drive-{n}-{SYSID_LOG_NAME}" for n in YAGSL_NAMES],
        "turn_angles": [m.format(n) + "Adjusted Absolute Encoder" for n in YAGSL_NAMES],
        "gyro_deg": "NT:/SmartDashboard/swerve/imu/raw",
        "pose": "NT:/SmartDashboard/Field/Robot",
        "state": f"sysid-test-state-{SYSID_LOG_NAME}",
        "decoys": [f"{k}-drive-{n}-{SYSID_LOG_NAME}" for n in YAGSL_NAMES for k in ("voltage", "velocity")],
    }
    geometry = {"modules": tuple(used), "module_names": YAGSL_NAMES, "drive_units": "m (metadata Meter)",
                "turn_units": "deg", "gyro_units": "deg"}
    notes = {"initial_pose": START, "rate_hz": 50, "cycle_us": cyc, "period_us": PERIOD_US,
             "tests": SYSID_TESTS, "test_cycles": test_of}
    return RealLog(path, "robotpy-wpiutil 2026.2.2 DataLogWriter (SysIdRoutineLog's entries) + " + NT_WRITER,
                   "swerve", geometry, entries, cyc, np.array(odo.rows), notes)



# ---------------------------------------------------------------------------------------
# 3. A team's own per-module names (Team 302's layout)

TEAM_NAMES = ("Left Front", "Right Front", "Left Back", "Right Back")     # FL FR BL BR
TEAM_MODULES = ((0.3, 0.27), (0.3, -0.27), (-0.3, 0.27), (-0.3, -0.27))
TEAM_STAGGER_US = 110                    # the real Team 302 log: ~100 µs between entries


def team_named_swerve(directory, *, filename: str = "team_named_swerve.wpilog") -> RealLog:
    """Per-module doubles under a team's own names, mirrored by ntcore:
    ``NT:/<M> Swerve Encoders/<M> Drive`` (m) and ``<M> Turn`` (degrees in (-180, 180])
    for M in Left Front, Right Front, Left Back, Right Back, the gyro
    ``NT:/Chassis/Robot Angle`` (degrees, continuous), and the robot's odometry pose
    ``/Chassis/Pose`` (struct:Pose2d, written straight into the DataLog as Team 302's
    C++ robot does); decoys ``/Chassis/StoredHeadingDegrees`` (a heading setpoint) and
    ``NT:/<M> Swerve Encoders/<M> Drive Speed``. 50 Hz; within a cycle each module's
    Turn then Drive, the gyro, the pose, ``TEAM_STAGGER_US`` apart.

    Truth: SwerveDrive4Odometry at every cycle from exactly the logged values."""
    from wpiutil.log import DoubleLogEntry

    path = pathlib.Path(directory) / filename
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in TEAM_MODULES])
    motion = _Motion(_KNOTS_HOLONOMIC, _swerve_wheels(TEAM_MODULES))
    cyc = _cycles(PERIOD_US)
    idx = motion.at(cyc)
    ntcore, log, inst, handle = _nt_logging(path)
    tick = _flushing(log, 40)
    drive, turn, speed = [], [], []
    for n in TEAM_NAMES:
        t = inst.getTable(f"{n} Swerve Encoders")
        drive.append(t.getDoubleTopic(f"{n} Drive").publish())
        turn.append(t.getDoubleTopic(f"{n} Turn").publish())
        speed.append(t.getDoubleTopic(f"{n} Drive Speed").publish())
    gyro = inst.getTable("Chassis").getDoubleTopic("Robot Angle").publish()
    e_pose = _StructEntry(log, "/Chassis/Pose", Pose2d, int(cyc[0]))
    e_stored = DoubleLogEntry(log, "/Chassis/StoredHeadingDegrees", int(cyc[0]))
    odo = _Odometry(kin)
    try:
        for k, i in enumerate(idx):
            stamp = _Stamps(int(cyc[k]), TEAM_STAGGER_US)
            mods = []
            for j in range(4):
                dist, spd, ang = (float(a[i]) for a in motion.wheels[j])
                deg = math.degrees(math.remainder(ang, 2 * math.pi))
                turn[j].set(deg, stamp())
                drive[j].set(dist, stamp())
                speed[j].set(spd, stamp())
                mods.append(SwerveModulePosition(dist, Rotation2d.fromDegrees(deg)))
            yaw_deg = math.degrees(float(motion.yaw[i]))
            gyro.set(yaw_deg, stamp())
            pose = odo.update(Rotation2d.fromDegrees(yaw_deg), mods)
            e_pose.append(pose, stamp())
            if k % 50 == 0:              # the heading the driver last locked
                e_stored.append(round(pose.rotation().degrees(), 1), stamp())
            tick()
    finally:
        _nt_close(ntcore, log, inst, handle)
    entries = {
        "drive_positions": [f"NT:/{n} Swerve Encoders/{n} Drive" for n in TEAM_NAMES],
        "turn_angles": [f"NT:/{n} Swerve Encoders/{n} Turn" for n in TEAM_NAMES],
        "gyro_deg": "NT:/Chassis/Robot Angle", "pose": "/Chassis/Pose",
        "decoys": ["/Chassis/StoredHeadingDegrees",
                   *[f"NT:/{n} Swerve Encoders/{n} Drive Speed" for n in TEAM_NAMES]],
    }
    geometry = {"modules": TEAM_MODULES, "module_names": TEAM_NAMES, "drive_units": "m",
                "turn_units": "deg", "gyro_units": "deg"}
    notes = {"initial_pose": START, "rate_hz": 50, "cycle_us": cyc, "period_us": PERIOD_US}
    return RealLog(path, NT_WRITER + " + robotpy-wpiutil DataLogWriter (struct pose)", "swerve",
                   geometry, entries, cyc, np.array(odo.rows), notes)


# ---------------------------------------------------------------------------------------
# 4. Module velocity states only

STATES_MODULES = ((0.23495, 0.23495), (0.23495, -0.23495), (-0.23495, 0.23495), (-0.23495, -0.23495))
STATES_NOISE = 1e-6                      # m/s: velocity readings jitter, so every cycle logs
FEET = 0.3048


def module_states_only(directory, variant: str = "per_module", *, filename: str | None = None) -> RealLog:
    """Module velocity states and no distances, mirrored by ntcore, 50 Hz, every value of
    a cycle at the cycle's instant:

    * ``"per_module"`` (the mcm001 robots): ``NT:/SmartDashboard/Module N/Drive Velocity Feet``
      (ft/s) and ``Module N/Steer Degrees`` (degrees in (-180, 180]), N = 1..4 = FL, FR,
      BL, BR; decoys ``Drive Velocity Target Feet``, ``Steer Target Degrees``; gyro
      ``NT:/SmartDashboard/Drive/Heading`` (degrees, continuous); pose Field2d
      ``NT:/SmartDashboard/Field/Robot``;
    * ``"struct"``: ``NT:/Drive/MeasuredStates`` struct:SwerveModuleState[] (m/s, FL FR BL
      BR), decoy ``NT:/Drive/DesiredStates``; gyro ``NT:/Drive/Gyro`` struct:Rotation2d;
      pose ``NT:/Drive/Pose`` struct:Pose2d.

    Each reading is the module's speed plus a uniform jitter of at most ``STATES_NOISE``
    (seeded), so no value repeats and NetworkTables drops none.

    ``truth``: the robot's own odometry, which integrated its (unlogged) wheel distances.
    ``notes["truth_from_velocities"]``: SwerveDrive4Odometry fed distances integrated
    trapezoidally between consecutive records of exactly the logged velocities (the
    replay's rule). ``notes["bound_m"]``: the bound on their distance, Σ over cycles of
    h³/12·max|v''| (the trapezoid rule's error, v'' from the 4 kHz motion) plus h·noise,
    summed, not rooted: odometry's translation error per cycle is at most the largest
    module's distance error (the least-squares translation is a mean of module vectors,
    and the pose exponential does not lengthen it)."""
    if variant not in ("per_module", "struct"):
        raise ValueError("variant is 'per_module' or 'struct'")
    path = pathlib.Path(directory) / (filename or f"module_states_{variant}.wpilog")
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in STATES_MODULES])
    motion = _Motion(_KNOTS_HOLONOMIC, _swerve_wheels(STATES_MODULES))
    cyc = _cycles(PERIOD_US)
    idx = motion.at(cyc)
    noise = np.random.default_rng(30).uniform(-STATES_NOISE, STATES_NOISE, (len(cyc), 4))
    ntcore, log, inst, handle = _nt_logging(path)
    tick = _flushing(log, 40)
    if variant == "per_module":
        sd = inst.getTable("SmartDashboard")
        vel = [sd.getDoubleTopic(f"Module {j + 1}/Drive Velocity Feet").publish() for j in range(4)]
        steer = [sd.getDoubleTopic(f"Module {j + 1}/Steer Degrees").publish() for j in range(4)]
        vel_t = [sd.getDoubleTopic(f"Module {j + 1}/Drive Velocity Target Feet").publish() for j in range(4)]
        steer_t = [sd.getDoubleTopic(f"Module {j + 1}/Steer Target Degrees").publish() for j in range(4)]
        gyro = sd.getDoubleTopic("Drive/Heading").publish()
        field = sd.getDoubleArrayTopic("Field/Robot").publish()
        sd.getStringTopic("Field/.type").publish().set("Field2d", int(cyc[0]) - 5000)
    else:
        dt_ = inst.getTable("Drive")
        measured = dt_.getStructArrayTopic("MeasuredStates", SwerveModuleState).publish()
        desired = dt_.getStructArrayTopic("DesiredStates", SwerveModuleState).publish()
        gyro = dt_.getStructTopic("Gyro", Rotation2d).publish()
        pose_pub = dt_.getStructTopic("Pose", Pose2d).publish()
    robot = _Odometry(kin)
    logged_v, logged_a, logged_g = [], [], []
    try:
        for k, i in enumerate(idx):
            ts = int(cyc[k])
            v_mps = [float(motion.wheels[j][1][i]) + float(noise[k, j]) for j in range(4)]
            ang = [math.remainder(float(motion.wheels[j][2][i]), 2 * math.pi) for j in range(4)]
            yaw = float(motion.yaw[i])
            if variant == "per_module":
                v_log = [v / FEET for v in v_mps]
                a_log = [math.degrees(a) for a in ang]
                for j in range(4):
                    vel[j].set(v_log[j], ts)
                    steer[j].set(a_log[j], ts)
                    vel_t[j].set(1.02 * v_log[j], ts)
                    steer_t[j].set(a_log[j], ts)
                g_log = math.degrees(yaw)
                gyro.set(g_log, ts)
                logged_v.append([v * FEET for v in v_log])
                logged_a.append([Rotation2d.fromDegrees(a) for a in a_log])
                logged_g.append(Rotation2d.fromDegrees(g_log))
            else:
                states = [SwerveModuleState(v_mps[j], Rotation2d(ang[j])) for j in range(4)]
                measured.set(states, ts)
                desired.set([SwerveModuleState(1.02 * s.speed, s.angle) for s in states], ts)
                gyro.set(Rotation2d(yaw), ts)
                logged_v.append(v_mps)
                logged_a.append([s.angle for s in states])
                logged_g.append(Rotation2d(yaw))
            pose = robot.update(logged_g[-1], [SwerveModulePosition(float(motion.wheels[j][0][i]),
                                                                    logged_a[-1][j]) for j in range(4)])
            if variant == "per_module":
                field.set([pose.X(), pose.Y(), pose.rotation().degrees()], ts)
            else:
                pose_pub.set(pose, ts)
            tick()
    finally:
        _nt_close(ntcore, log, inst, handle)
    h = PERIOD_US * 1e-6
    v = np.array(logged_v)
    dist = np.zeros_like(v)
    dist[1:] = np.cumsum(0.5 * (v[1:] + v[:-1]) * (np.diff(cyc) * 1e-6)[:, None], axis=0)
    oracle = _Odometry(kin)
    for k in range(len(cyc)):
        oracle.update(logged_g[k], [SwerveModulePosition(float(dist[k, j]), logged_a[k][j]) for j in range(4)])
    dt = DT_US * 1e-6
    acc2 = np.max([np.abs(np.diff(motion.wheels[j][1], 2)) / dt ** 2 for j in range(4)], axis=0)
    per = PERIOD_US // DT_US
    step_max = np.array([acc2[max(0, s - 1):s + per].max() for s in idx[:-1]])
    bound = float(np.sum(h ** 3 / 12 * step_max) + (len(cyc) - 1) * h * STATES_NOISE)
    if variant == "per_module":
        entries = {"velocities_ftps": [f"NT:/SmartDashboard/Module {j + 1}/Drive Velocity Feet" for j in range(4)],
                   "turn_angles": [f"NT:/SmartDashboard/Module {j + 1}/Steer Degrees" for j in range(4)],
                   "gyro_deg": "NT:/SmartDashboard/Drive/Heading", "pose": "NT:/SmartDashboard/Field/Robot",
                   "decoys": [f"NT:/SmartDashboard/Module {j + 1}/{n}" for j in range(4)
                              for n in ("Drive Velocity Target Feet", "Steer Target Degrees")]}
    else:
        entries = {"module_states": "NT:/Drive/MeasuredStates", "gyro": "NT:/Drive/Gyro",
                   "pose": "NT:/Drive/Pose", "decoys": ["NT:/Drive/DesiredStates"]}
    geometry = {"modules": STATES_MODULES, "velocity_units": "ft/s" if variant == "per_module" else "m/s"}
    notes = {"initial_pose": START, "rate_hz": 50, "cycle_us": cyc, "period_us": PERIOD_US,
             "truth_from_velocities": np.array(oracle.rows), "bound_m": bound,
             "rule": "distances integrated trapezoidally between consecutive velocity records"}
    return RealLog(path, NT_WRITER, "swerve", geometry, entries, cyc, np.array(robot.rows), notes)


# ---------------------------------------------------------------------------------------
# Reading back, with robotpy-wpiutil's reader (the generators' own check)

def records(path) -> dict[str, tuple[str, str, list[int], list]]:
    """Every entry of ``path`` read with robotpy-wpiutil's DataLogReader:
    name -> (type, metadata, timestamps µs, values); structs decoded with wpistruct."""
    from wpiutil import wpistruct
    from wpiutil.log import DataLogReader

    structs = {"struct:Pose2d": Pose2d, "struct:Rotation2d": Rotation2d,
               "struct:SwerveModuleState": SwerveModuleState, "struct:ChassisSpeeds": ChassisSpeeds}
    getters = {"double": "getDouble", "double[]": "getDoubleArray", "string": "getString",
               "boolean": "getBoolean", "int64": "getInteger"}
    starts, out = {}, {}
    for rec in DataLogReader(str(path)):
        if rec.isStart():
            d = rec.getStartData()
            starts[d.entry] = d.name
            out[d.name] = (d.type, d.metadata, [], [])
        elif not rec.isControl():
            typ, _, ts, vs = out[starts[rec.getEntry()]]
            if typ in getters:
                v = getattr(rec, getters[typ])()
                v = list(v) if typ == "double[]" else v
            elif typ.endswith("[]") and typ[:-2] in structs:
                v = wpistruct.unpackArray(structs[typ[:-2]], rec.getRaw())
            elif typ in structs:
                v = wpistruct.unpack(structs[typ], rec.getRaw())
            else:
                v = bytes(rec.getRaw())
            ts.append(rec.getTimestamp())
            vs.append(v)
    return out


def held(recs, name: str, t_us) -> np.ndarray:
    """Entry ``name``'s latest value at or before each of ``t_us`` (NaN before its first)."""
    _, _, ts, vs = recs[name]
    k = np.searchsorted(np.asarray(ts), np.asarray(t_us), side="right") - 1
    return np.array([vs[i] if i >= 0 else math.nan for i in k], dtype=object)
