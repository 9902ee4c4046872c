"""``.wpilog`` files written by real, independent writers (not drivekin's), with the
ground truth robotpy-wpimath's own odometry computes from exactly the logged samples.

Each generator drives the same kind of deterministic motion (rest, straight, arcs,
turning in place, strafing where the drivetrain can, a combined move, reversing, rest:
26 s of robot time), makes the wheel/module and gyro measurements of a simulated robot
consistent with it (inverse kinematics of a smooth chassis-speed profile, integrated on a
4 kHz grid), logs them the way a Python team's robot program would, and returns a
:class:`RealLog`:

* :func:`pykit_swerve`: robotpy-pykit 1.0.5's ``Logger`` with its ``WPILOGWriter``,
  ``@autolog`` dataclasses as in the AdvantageKit swerve template (high-rate odometry
  arrays), run on the simulation HAL by driving the logger's cycle by hand;
* :func:`ntcore_differential`: ntcore's DataLog mirroring (``NT:/...``) of a local
  NetworkTables instance, Field2d-style pose;
* :func:`writer_mecanum`: robotpy-wpiutil ``DataLogWriter`` with its typed log entries;
* :func:`writer_swerve_per_module_doubles`: the same, one double per module signal;
* :func:`ctre_drivestate`: ntcore mirroring of CTRE Phoenix 6's generated ``Telemetry``
  (``DriveState`` table), which publishes no gyro.

``truth[i]`` is the robot's odometry pose (x m, y m, θ rad) at ``t_us[i]``: the
odometry is constructed at ``t_us[0]`` with ``notes["initial_pose"]`` (so ``truth[0]``
is that pose) and updated at every later sample, so a replay that starts from the same
pose at the same sample and feeds the logged values to a correct odometry reproduces it
to ~1e-12 m.
"""
from __future__ import annotations

import dataclasses
import math
import pathlib
from dataclasses import dataclass, field

import numpy as np
from wpimath.geometry import Pose2d, Rotation2d, Translation2d
from wpimath.kinematics import (
    ChassisSpeeds,
    DifferentialDriveOdometry,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelPositions,
    SwerveDrive4Kinematics,
    SwerveDrive4Odometry,
    SwerveModulePosition,
    SwerveModuleState,
)


@dataclass
class RealLog:
    """One generated log and its truth.

    ``entries`` maps a role (``"positions"``, ``"gyro"``, ``"pose"``, ...) to the entry
    name(s) in the file; ``geometry`` holds what a replay must be told or must detect
    (module offsets / trackwidth / wheel locations, wheel radius, units); ``notes`` holds
    everything else (initial pose, rates, decoys, alternative truths)."""

    path: pathlib.Path
    writer: str
    drivetrain: str                      # "swerve" | "differential" | "mecanum"
    geometry: dict
    entries: dict
    t_us: np.ndarray                     # int64 (N,) µs, the log's clock
    truth: np.ndarray                    # float64 (N, 3) [x m, y m, θ rad]
    notes: dict = field(default_factory=dict)


# ---------------------------------------------------------------------------------------
# The motion

DT_US = 250                              # simulation grid: 4 kHz
DURATION_S = 26.0
T0_US = 2_000_000                        # the log clock (FPGA µs) at motion time 0
START = (2.0, 4.0, math.pi / 6)          # initial odometry pose (x m, y m, θ rad)
GYRO0 = -0.4                             # the gyro's yaw at time 0, rad (≠ the pose heading)

# (t s, vx m/s, vy m/s, ω rad/s), robot-relative; smoothstep between knots.
_KNOTS_HOLONOMIC = (
    (0.0, 0, 0, 0), (0.5, 0, 0, 0),            # rest
    (2.5, 1.5, 0, 0),                          # accelerate straight
    (4.0, 1.5, 0, 0.8), (8.0, 1.5, 0, 0.8),    # arc left
    (9.0, 0, 0, 0),
    (10.0, 0, 0, 2.0), (12.5, 0, 0, 2.0),      # turn in place
    (13.5, 0, 1.2, 0), (16.5, 0, 1.2, 0),      # strafe left
    (17.5, 1.0, -0.8, -1.0), (21.0, 1.0, -0.8, -1.0),   # drive + strafe + rotate
    (22.0, -0.8, 0, 0.4), (24.5, -0.8, 0, 0.4),  # reverse arc
    (25.5, 0, 0, 0), (26.0, 0, 0, 0),          # rest
)
_KNOTS_DIFFERENTIAL = (
    (0.0, 0, 0, 0), (0.5, 0, 0, 0),
    (2.5, 1.5, 0, 0),
    (4.0, 1.5, 0, 0.8), (8.0, 1.5, 0, 0.8),    # arc left
    (9.0, 0, 0, 0),
    (10.0, 0, 0, 2.0), (12.5, 0, 0, 2.0),      # turn in place
    (13.5, 1.2, 0, -0.9), (16.5, 1.2, 0, -0.9),  # arc right
    (17.5, 0.6, 0, 1.6), (21.0, 0.6, 0, 1.6),  # tight arc left
    (22.0, -0.8, 0, 0.4), (24.5, -0.8, 0, 0.4),  # reverse arc
    (25.5, 0, 0, 0), (26.0, 0, 0, 0),
)


def _grid() -> np.ndarray:
    return np.arange(0, round(DURATION_S * 1e6) + 1, DT_US, dtype=np.int64)


def _speeds(t_s: np.ndarray, knots) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    k = np.array(knots, dtype=float)
    i = np.clip(np.searchsorted(k[:, 0], t_s, side="right") - 1, 0, len(k) - 2)
    u = np.clip((t_s - k[i, 0]) / (k[i + 1, 0] - k[i, 0]), 0.0, 1.0)
    s = u * u * (3 - 2 * u)
    v = k[i, 1:] + (k[i + 1, 1:] - k[i, 1:]) * s[:, None]
    return v[:, 0], v[:, 1], v[:, 2]


def _cumtrapz(v: np.ndarray, dt: float) -> np.ndarray:
    out = np.zeros_like(v)
    out[1:] = np.cumsum(0.5 * (v[1:] + v[:-1]) * dt)
    return out


class _Motion:
    """The simulated robot on the 4 kHz grid: robot-relative speeds, gyro yaw, and for
    each wheel/module its travelled distance, velocity and (swerve) steering angle."""

    def __init__(self, knots, wheel_velocity) -> None:
        self.t = _grid()                                   # µs from motion start
        ts = self.t * 1e-6
        dt = DT_US * 1e-6
        self.vx, self.vy, self.omega = _speeds(ts, knots)
        self.yaw = GYRO0 + _cumtrapz(self.omega, dt)        # gyro, rad (unwrapped)
        # wheel_velocity: (vx, vy, ω) -> list of (signed speed m/s, angle rad or None)
        self.wheels = []
        for speed, angle in wheel_velocity(self.vx, self.vy, self.omega):
            self.wheels.append((_cumtrapz(speed, dt), speed, angle))

    def at(self, t_us) -> np.ndarray:
        """Grid indices of log-clock times ``t_us`` (which must lie on the grid)."""
        rel = np.asarray(t_us, dtype=np.int64) - T0_US
        assert (rel % DT_US == 0).all() and (rel >= 0).all() and (rel <= self.t[-1]).all()
        return rel // DT_US


def _swerve_wheels(modules):
    def wheels(vx, vy, w):
        out = []
        for mx, my in modules:
            ux, uy = vx - w * my, vy + w * mx
            speed = np.hypot(ux, uy)
            angle = np.arctan2(uy, ux)
            # A module standing still keeps its last angle (0 before it first moves).
            moving = speed > 1e-9
            idx = np.where(moving, np.arange(len(speed)), 0)
            np.maximum.accumulate(idx, out=idx)
            angle = np.where(moving[idx], angle[idx], 0.0)
            out.append((speed, angle))
        return out
    return wheels


def _linear_wheels(matrix):
    """Wheels whose signed speeds are ``matrix @ (vx, vy, ω)`` (differential, mecanum)."""
    def wheels(vx, vy, w):
        v = np.asarray(matrix) @ np.vstack([vx, vy, w])
        return [(row, None) for row in v]
    return wheels


def _mecanum_matrix(kin: MecanumDriveKinematics) -> np.ndarray:
    cols = []
    for basis in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):     # linear: read it off wpimath
        s = kin.toWheelSpeeds(ChassisSpeeds(*map(float, basis)))
        cols.append((s.frontLeft, s.frontRight, s.rearLeft, s.rearRight))
    return np.array(cols).T


def _pose_row(p: Pose2d) -> tuple[float, float, float]:
    return (p.X(), p.Y(), p.rotation().radians())


def _start_pose() -> Pose2d:
    return Pose2d(START[0], START[1], Rotation2d(START[2]))


def _swerve_truth(kin, gyro_rad, positions_m, angles_rad) -> np.ndarray:
    """SwerveDrive4Odometry over samples: gyro (N,), distances (N, 4) m, angles (N, 4)."""
    def mods(i):
        return tuple(SwerveModulePosition(float(positions_m[i, j]), Rotation2d(float(angles_rad[i, j])))
                     for j in range(4))
    odo = SwerveDrive4Odometry(kin, Rotation2d(float(gyro_rad[0])), mods(0), _start_pose())
    out = [_pose_row(odo.getPose())]
    for i in range(1, len(gyro_rad)):
        out.append(_pose_row(odo.update(Rotation2d(float(gyro_rad[i])), mods(i))))
    return np.array(out)


def _flushing(log, every: int = 200):
    """A callable that flushes ``log`` every ``every`` calls: robotpy-wpiutil 2026.2.2's
    DataLogWriter blocks forever once about 1 MiB is buffered."""
    n = [0]

    def tick():
        n[0] += 1
        if n[0] % every == 0:
            log.flush()
    return tick


class _StructEntry:
    """A struct entry on a DataLogWriter, with robotpy-wpiutil's own struct support
    (``addStructSchema`` + ``wpistruct.pack``). robotpy-wpiutil 2026.2.2's
    ``wpiutil.log.StructLogEntry`` / ``StructArrayLogEntry`` cannot be constructed on a
    ``DataLogWriter`` (``ValueError: Object is closed``), so this does what they would."""

    def __init__(self, log, name: str, struct_type, timestamp: int, *, array: bool = False) -> None:
        from wpiutil import wpistruct

        self._log, self._ws, self._array = log, wpistruct, array
        log.addStructSchema(struct_type, timestamp)
        type_string = "struct:" + wpistruct.getTypeName(struct_type) + ("[]" if array else "")
        self._id = log.start(name, type_string, "", timestamp)

    def append(self, value, timestamp: int) -> None:
        data = self._ws.packArray(value) if self._array else self._ws.pack(value)
        self._log.appendRaw(self._id, data, timestamp)


# ---------------------------------------------------------------------------------------
# 1. robotpy-pykit (AdvantageKit-style swerve template)

PYKIT_MODULES = ((0.2921, 0.2921), (0.2921, -0.2921), (-0.2921, 0.2921), (-0.2921, -0.2921))
PYKIT_WHEEL_RADIUS = 0.0508
PYKIT_PERIOD_US = 20_000                 # the 50 Hz main loop
PYKIT_ODOMETRY_PHASE_US = 1_500          # odometry-thread samples sit 1.5 ms after a grid line


def _pykit_classes(high_rate: bool):
    # Imported here: pykit imports wpilib (and so initialises the simulation HAL).
    from pykit.autolog import autolog

    if high_rate:
        @autolog
        @dataclasses.dataclass
        class ModuleIOInputs:
            driveConnected: bool = False
            drivePositionRad: float = 0.0
            driveVelocityRadPerSec: float = 0.0
            turnConnected: bool = False
            turnPosition: Rotation2d = dataclasses.field(default_factory=Rotation2d)
            odometryTimestamps: list[float] = dataclasses.field(default_factory=list)
            odometryDrivePositionsRad: list[float] = dataclasses.field(default_factory=list)
            odometryTurnPositions: list[Rotation2d] = dataclasses.field(default_factory=list)

        @autolog
        @dataclasses.dataclass
        class GyroIOInputs:
            connected: bool = False
            yawPosition: Rotation2d = dataclasses.field(default_factory=Rotation2d)
            yawVelocityRadPerSec: float = 0.0
            odometryYawTimestamps: list[float] = dataclasses.field(default_factory=list)
            odometryYawPositions: list[Rotation2d] = dataclasses.field(default_factory=list)
    else:
        @autolog
        @dataclasses.dataclass
        class ModuleIOInputs:                       # type: ignore[no-redef]
            driveConnected: bool = False
            drivePositionRad: float = 0.0
            driveVelocityRadPerSec: float = 0.0
            turnConnected: bool = False
            turnPosition: Rotation2d = dataclasses.field(default_factory=Rotation2d)

        @autolog
        @dataclasses.dataclass
        class GyroIOInputs:                         # type: ignore[no-redef]
            connected: bool = False
            yawPosition: Rotation2d = dataclasses.field(default_factory=Rotation2d)
            yawVelocityRadPerSec: float = 0.0
    return ModuleIOInputs, GyroIOInputs


def _pykit_reset(Logger, LogTable) -> None:
    """pykit's Logger is one class-level singleton: give each log a fresh one."""
    Logger.replaySource = None
    Logger.running = False
    Logger.cycleCount = 0
    Logger.entry = LogTable(0)
    Logger.outputTable = LogTable(0)
    Logger.metadata = {}
    Logger.dataRecievers = []
    Logger.dashboardInputs = []
    Logger.checkConsole = False          # keep sys.stdout/sys.stderr alone (pytest's capture)


def pykit_swerve(directory, *, high_rate: bool = True, rate_hz: int = 250,
                 filename: str | None = None, moving_from_s: float = 0.0) -> RealLog:
    """A swerve log written by robotpy-pykit 1.0.5 (``Logger`` + ``WPILOGWriter``).

    Inputs as the AdvantageKit swerve template logs them with ``@autolog`` dataclasses
    (``Logger.processInputs("Drive/Module0", inputs)`` ...): per module
    ``drivePositionRad`` (wheel radians), ``turnPosition`` (Rotation2d), and with
    ``high_rate`` the odometry thread's ``odometryTimestamps`` (s), ``odometryDrivePositionsRad``,
    ``odometryTurnPositions``; the gyro's ``yawPosition``, ``connected`` and, with
    ``high_rate``, ``odometryYawTimestamps`` / ``odometryYawPositions``. The 50 Hz main
    loop carries the ``rate_hz / 50`` samples taken since the previous cycle.
    Outputs: ``Odometry/Robot`` (the robot's pose after the cycle's samples), decoys
    ``Odometry/TrajectorySetpoint`` (Pose2d) and ``SwerveStates/Measured``.

    ``moving_from_s`` starts the robot program (and its log) that far into the motion, so
    the robot is already moving when its first pose is logged.

    Truth: SwerveDrive4Odometry at every odometry-thread sample (``high_rate``), else at
    every cycle from the cycle values. With ``high_rate``, ``notes["t_us_50hz"]`` /
    ``notes["truth_50hz"]`` are what a replay using only the 50 Hz cycle values gets.
    """
    if rate_hz not in (100, 250):
        raise ValueError("rate_hz must be 100 (CAN) or 250 (CAN FD)")
    import hal.simulation as halsim
    from pykit.logger import Logger
    from pykit.logtable import LogTable
    from pykit.wpilog.wpilogwriter import WPILOGWriter

    directory = pathlib.Path(directory)
    name = filename or (f"pykit_swerve_{rate_hz}hz.wpilog" if high_rate else "pykit_swerve_50hz.wpilog")
    path = directory / name
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in PYKIT_MODULES])
    full = _Motion(_KNOTS_HOLONOMIC, _swerve_wheels(PYKIT_MODULES))
    shift = round(moving_from_s * 1e6) // DT_US * DT_US
    r = PYKIT_WHEEL_RADIUS

    class motion:                        # the same motion, seen from moving_from_s on
        wheels, yaw, omega = full.wheels, full.yaw, full.omega

        @staticmethod
        def at(t_us) -> np.ndarray:
            return full.at(np.asarray(t_us, dtype=np.int64) + shift)

    n_cycles = (round(DURATION_S * 1e6) - shift) // PYKIT_PERIOD_US
    # cycle k at T0 + 20 ms (k + 1); its odometry samples were taken since the previous one
    cycle_us = T0_US + PYKIT_PERIOD_US * np.arange(1, n_cycles + 1, dtype=np.int64)
    period = 1_000_000 // rate_hz
    per_cycle = PYKIT_PERIOD_US // period
    samples_of_cycle = list(cycle_us[:, None] - PYKIT_PERIOD_US + PYKIT_ODOMETRY_PHASE_US
                            + period * np.arange(per_cycle)[None, :])

    def rad_of(m):
        return m / r

    ModuleIOInputs, GyroIOInputs = _pykit_classes(high_rate)
    was_paused = bool(halsim.isTimingPaused())
    halsim.pauseTiming()
    halsim.restartTiming()               # deterministic clock: FPGA time 0 ...
    halsim.stepTiming(int(cycle_us[0]))  # ... then the first cycle
    _pykit_reset(Logger, LogTable)
    Logger.recordMetadata("RobotName", "drivekin-real-logs")
    Logger.addDataReciever(WPILOGWriter(name, str(directory)))
    modules = [ModuleIOInputs() for _ in range(4)]
    gyro = GyroIOInputs()
    odo = None
    hr_t, hr_pose = [], []               # the robot's high-rate odometry
    cyc_pose = []
    try:
        Logger.startReciever()
        Logger.start()                   # runs the first periodicBeforeUser itself
        for k in range(n_cycles):
            if k > 0:
                halsim.stepTiming(PYKIT_PERIOD_US)
                Logger.periodicBeforeUser()
            now = int(cycle_us[k])
            gi = int(motion.at([now])[0])
            s_us = samples_of_cycle[k]
            si = motion.at(s_us)
            # --- updateInputs (IO layer)
            for j, m in enumerate(modules):
                dist, speed, angle = motion.wheels[j]
                m.driveConnected = True
                m.turnConnected = True
                m.drivePositionRad = float(rad_of(dist[gi]))
                m.driveVelocityRadPerSec = float(rad_of(speed[gi]))
                m.turnPosition = Rotation2d(float(angle[gi]))
                if high_rate:
                    m.odometryTimestamps = [float(t) / 1e6 for t in s_us]
                    m.odometryDrivePositionsRad = [float(rad_of(dist[i])) for i in si]
                    m.odometryTurnPositions = [Rotation2d(float(angle[i])) for i in si]
            gyro.connected = True
            gyro.yawPosition = Rotation2d(float(motion.yaw[gi]))
            gyro.yawVelocityRadPerSec = float(motion.omega[gi])
            if high_rate:
                gyro.odometryYawTimestamps = [float(t) / 1e6 for t in s_us]
                gyro.odometryYawPositions = [Rotation2d(float(motion.yaw[i])) for i in si]
            for j, m in enumerate(modules):
                Logger.processInputs(f"Drive/Module{j}", m)
            Logger.processInputs("Drive/Gyro", gyro)
            # --- Drive.periodic: odometry from exactly the logged values
            if high_rate:
                updates = [
                    (gyro.odometryYawPositions[i],
                     tuple(SwerveModulePosition(m.odometryDrivePositionsRad[i] * r,
                                                m.odometryTurnPositions[i]) for m in modules),
                     round(modules[0].odometryTimestamps[i] * 1e6))
                    for i in range(len(modules[0].odometryTimestamps))]
            else:
                updates = [(gyro.yawPosition,
                            tuple(SwerveModulePosition(m.drivePositionRad * r, m.turnPosition)
                                  for m in modules), now)]
            for yaw, mods, t in updates:
                if odo is None:
                    odo = SwerveDrive4Odometry(kin, yaw, mods, _start_pose())
                    pose = odo.getPose()
                else:
                    pose = odo.update(yaw, mods)
                hr_t.append(t)
                hr_pose.append(_pose_row(pose))
            pose = odo.getPose()
            cyc_pose.append(_pose_row(pose))
            Logger.recordOutput("Odometry/Robot", pose)
            states = [SwerveModuleState(float(motion.wheels[j][1][gi]),
                                        Rotation2d(float(motion.wheels[j][2][gi])))
                      for j in range(4)]
            Logger.recordOutput("SwerveStates/Measured", states)
            # a trajectory setpoint leading the robot: a different Pose2d
            Logger.recordOutput("Odometry/TrajectorySetpoint",
                                pose.transformBy(_setpoint_offset(k)))
            Logger.periodicAfterUser(0, 0)
    finally:
        Logger.end()
        _pykit_reset(Logger, LogTable)
        if not was_paused:
            halsim.resumeTiming()

    t_us = np.array(hr_t, dtype=np.int64)
    truth = np.array(hr_pose)
    notes = {
        "initial_pose": START,
        "odometry_rate_hz": rate_hz if high_rate else 50,
        "cycle_rate_hz": 50,
        "cycle_us": cycle_us,
        "samples_per_cycle": [len(s) for s in samples_of_cycle] if high_rate else [1] * n_cycles,
        "logged_pose": np.array(cyc_pose),     # Odometry/Robot, one per cycle
        "timestamps_unit": "s (FPGA clock); ×1e6 and round for the log's µs",
        "change_only": "pykit writes a field only when its value changed (values held at rest)",
    }
    if high_rate:
        # What a replay that ignores the odometry arrays gets: odometry once per cycle from
        # the cycle values (read at the cycle time, not at the last sample).
        idx = motion.at(cycle_us)
        gyro_c = motion.yaw[idx]
        ang = np.column_stack([motion.wheels[j][2][idx] for j in range(4)])
        pos = np.column_stack([(motion.wheels[j][0][idx] / r) * r for j in range(4)])
        t50 = _swerve_truth(kin, gyro_c, pos, ang)
        last = np.cumsum(notes["samples_per_cycle"]) - 1
        notes["t_us_50hz"] = cycle_us
        notes["truth_50hz"] = t50
        notes["max_error_50hz_m"] = float(np.hypot(*(t50[:, :2] - truth[last, :2]).T).max())
        notes["final_error_50hz_m"] = float(np.hypot(*(t50[-1, :2] - truth[-1, :2])))
    prefix = "/Drive/Module{}/"
    entries = {
        "drive_positions_rad": [prefix.format(j) + "drivePositionRad" for j in range(4)],
        "turn_positions": [prefix.format(j) + "turnPosition" for j in range(4)],
        "gyro": "/Drive/Gyro/yawPosition",
        "gyro_connected": "/Drive/Gyro/connected",
        "pose": "/RealOutputs/Odometry/Robot",
        "decoy_pose": "/RealOutputs/Odometry/TrajectorySetpoint",
        "module_states": "/RealOutputs/SwerveStates/Measured",
        "timestamp": "/Timestamp",
    }
    if high_rate:
        entries.update({
            "odometry_timestamps": [prefix.format(j) + "odometryTimestamps" for j in range(4)],
            "odometry_drive_positions_rad": [prefix.format(j) + "odometryDrivePositionsRad"
                                             for j in range(4)],
            "odometry_turn_positions": [prefix.format(j) + "odometryTurnPositions" for j in range(4)],
            "odometry_yaw_timestamps": "/Drive/Gyro/odometryYawTimestamps",
            "odometry_yaw_positions": "/Drive/Gyro/odometryYawPositions",
        })
    geometry = {"modules": PYKIT_MODULES, "wheel_radius": r, "drive_units": "rad"}
    return RealLog(path, "robotpy-pykit 1.0.5 Logger + WPILOGWriter", "swerve", geometry,
                   entries, t_us, truth, notes)


def _setpoint_offset(k: int):
    from wpimath.geometry import Transform2d
    return Transform2d(0.15 + 0.05 * math.sin(0.05 * k), -0.04, Rotation2d(0.1))


# ---------------------------------------------------------------------------------------
# 2. ntcore DataLog mirroring: a differential drive as a robotpy team publishes it

DIFF_TRACKWIDTH = 0.6
DIFF_PERIOD_US = 20_000


def _nt_logging(path):
    import ntcore
    import wpiutil

    log = wpiutil.DataLogWriter(str(path))
    inst = ntcore.NetworkTableInstance.create()
    handle = inst.startEntryDataLog(log, "", "NT:")     # DataLogManager's prefix
    return ntcore, log, inst, handle


def _nt_close(ntcore, log, inst, handle) -> None:
    inst.stopEntryDataLog(handle)
    ntcore.NetworkTableInstance.destroy(inst)
    log.flush()
    log.stop()


def _cycles(period_us: int) -> np.ndarray:
    n = round(DURATION_S * 1e6) // period_us + 1
    return T0_US + period_us * np.arange(n, dtype=np.int64)


def ntcore_differential(directory, *, filename: str = "ntcore_differential.wpilog") -> RealLog:
    """A differential drive published on NetworkTables and mirrored into a DataLog by
    ntcore (``startEntryDataLog(log, "", "NT:")``, as DataLogManager does): doubles
    ``/Drive/LeftPosition``, ``/Drive/RightPosition`` (m), ``/Drive/GyroAngle``
    (degrees, CCW+), Field2d ``/SmartDashboard/Field/Robot`` (double[3]: x m, y m, deg)
    and its ``.type``; decoys ``/Drive/LeftVelocity``, ``/Drive/RightVelocity``.
    Published at 50 Hz with the cycle time as the value time; NetworkTables drops
    unchanged values, so records thin out where the robot rests.

    Truth: DifferentialDriveOdometry at every 50 Hz cycle from the published values."""
    path = pathlib.Path(directory) / filename
    tw = DIFF_TRACKWIDTH
    matrix = [[1, 0, -tw / 2], [1, 0, tw / 2]]
    motion = _Motion(_KNOTS_DIFFERENTIAL, _linear_wheels(matrix))
    cyc = _cycles(DIFF_PERIOD_US)
    idx = motion.at(cyc)
    ntcore, log, inst, handle = _nt_logging(path)
    tick = _flushing(log, 100)
    t = inst.getTable("Drive")
    pub_l = t.getDoubleTopic("LeftPosition").publish()
    pub_r = t.getDoubleTopic("RightPosition").publish()
    pub_g = t.getDoubleTopic("GyroAngle").publish()
    pub_lv = t.getDoubleTopic("LeftVelocity").publish()
    pub_rv = t.getDoubleTopic("RightVelocity").publish()
    field_t = inst.getTable("SmartDashboard").getSubTable("Field")
    pub_type = field_t.getStringTopic(".type").publish()
    pub_field = field_t.getDoubleArrayTopic("Robot").publish()
    odo = None
    truth = []
    try:
        for k, i in enumerate(idx):
            ts = int(cyc[k])
            left = float(motion.wheels[0][0][i])
            right = float(motion.wheels[1][0][i])
            deg = math.degrees(float(motion.yaw[i]))
            pub_l.set(left, ts)
            pub_r.set(right, ts)
            pub_g.set(deg, ts)
            pub_lv.set(float(motion.wheels[0][1][i]), ts)
            pub_rv.set(float(motion.wheels[1][1][i]), ts)
            rot = Rotation2d.fromDegrees(deg)
            if odo is None:
                odo = DifferentialDriveOdometry(rot, left, right, _start_pose())
                pose = odo.getPose()
            else:
                pose = odo.update(rot, left, right)
            truth.append(_pose_row(pose))
            if k == 0:
                pub_type.set("Field2d", ts)
            pub_field.set([pose.X(), pose.Y(), pose.rotation().degrees()], ts)
            tick()
    finally:
        _nt_close(ntcore, log, inst, handle)
    entries = {
        "left": "NT:/Drive/LeftPosition", "right": "NT:/Drive/RightPosition",
        "gyro_deg": "NT:/Drive/GyroAngle", "field2d_pose": "NT:/SmartDashboard/Field/Robot",
        "field2d_type": "NT:/SmartDashboard/Field/.type",
        "decoys": ["NT:/Drive/LeftVelocity", "NT:/Drive/RightVelocity"],
    }
    notes = {"initial_pose": START, "rate_hz": 50, "cycle_us": cyc, "gyro_units": "deg",
             "gyro_sign": "CCW positive",
             "duplicates_dropped": "NT logs a value only when it changed; hold the last"}
    return RealLog(path, "pyntcore 2026.2.2 startEntryDataLog (NT: mirroring)", "differential",
                   {"trackwidth": tw, "position_units": "m"}, entries, cyc, np.array(truth), notes)


# ---------------------------------------------------------------------------------------
# 3. DataLogWriter directly: mecanum

MECANUM_WHEELS = ((0.25, 0.3), (0.25, -0.3), (-0.25, 0.3), (-0.25, -0.3))   # FL FR RL RR
MECANUM_PERIOD_US = 10_000               # a 100 Hz loop


def writer_mecanum(directory, *, filename: str = "writer_mecanum.wpilog") -> RealLog:
    """Mecanum logged with robotpy-wpiutil's DataLogWriter and its typed entries:
    ``/Drive/WheelPositions`` double[4] (m, FL FR RL RR), ``/Drive/Gyro``
    struct:Rotation2d, ``/Drive/Pose`` struct:Pose2d (the robot's odometry), at 100 Hz;
    decoy ``/Drive/WheelSpeeds`` double[4].

    Truth: MecanumDriveOdometry at every record."""
    from wpiutil import DataLogWriter
    from wpiutil.log import DoubleArrayLogEntry

    path = pathlib.Path(directory) / filename
    kin = MecanumDriveKinematics(*[Translation2d(x, y) for x, y in MECANUM_WHEELS])
    motion = _Motion(_KNOTS_HOLONOMIC, _linear_wheels(_mecanum_matrix(kin)))
    cyc = _cycles(MECANUM_PERIOD_US)
    idx = motion.at(cyc)
    log = DataLogWriter(str(path))
    tick = _flushing(log)
    e_wheels = DoubleArrayLogEntry(log, "/Drive/WheelPositions", int(cyc[0]))
    e_speeds = DoubleArrayLogEntry(log, "/Drive/WheelSpeeds", int(cyc[0]))
    e_gyro = _StructEntry(log, "/Drive/Gyro", Rotation2d, int(cyc[0]))
    e_pose = _StructEntry(log, "/Drive/Pose", Pose2d, int(cyc[0]))
    odo = None
    truth = []
    try:
        for k, i in enumerate(idx):
            ts = int(cyc[k])
            w = [float(motion.wheels[j][0][i]) for j in range(4)]
            gyro = Rotation2d(float(motion.yaw[i]))
            e_wheels.append(w, ts)
            e_speeds.append([float(motion.wheels[j][1][i]) for j in range(4)], ts)
            e_gyro.append(gyro, ts)
            pos = MecanumDriveWheelPositions()
            pos.frontLeft, pos.frontRight, pos.rearLeft, pos.rearRight = w
            if odo is None:
                odo = MecanumDriveOdometry(kin, gyro, pos, _start_pose())
                pose = odo.getPose()
            else:
                pose = odo.update(gyro, pos)
            truth.append(_pose_row(pose))
            e_pose.append(pose, ts)
            tick()
    finally:
        log.flush()
        log.stop()
    entries = {"wheel_positions": "/Drive/WheelPositions", "gyro": "/Drive/Gyro",
               "pose": "/Drive/Pose", "decoys": ["/Drive/WheelSpeeds"]}
    notes = {"initial_pose": START, "rate_hz": 100, "wheel_order": "FL FR RL RR"}
    return RealLog(path, "robotpy-wpiutil 2026.2.2 DataLogWriter (log entries, addStructSchema + wpistruct)", "mecanum",
                   {"wheels": MECANUM_WHEELS, "position_units": "m"}, entries, cyc,
                   np.array(truth), notes)


# ---------------------------------------------------------------------------------------
# 4. DataLogWriter directly: swerve, one double per module signal

PER_MODULE_MODULES = ((0.3, 0.25), (0.3, -0.25), (-0.3, 0.25), (-0.3, -0.25))   # FL FR BL BR
PER_MODULE_NAMES = ("FL", "FR", "BL", "BR")
PER_MODULE_WHEEL_RADIUS = 0.05
PER_MODULE_PERIOD_US = 20_000


def writer_swerve_per_module_doubles(directory, drive_units: str = "rot", turn_units: str = "deg",
                                     *, filename: str | None = None) -> RealLog:
    """Swerve logged with DataLogWriter as per-module doubles at 50 Hz:
    ``/Swerve/{FL,FR,BL,BR}/DrivePosition`` (``drive_units``: ``"rot"`` wheel
    rotations, radius 0.05 m, or ``"m"``), ``/Swerve/{..}/TurnAngle`` (``turn_units``:
    ``"deg"`` or ``"rad"``, wrapped to ±180°), ``/Swerve/Gyro/Yaw`` (double, degrees),
    ``/Swerve/Pose`` struct:Pose2d; decoys ``/Swerve/{..}/DriveVelocity``.

    Truth: SwerveDrive4Odometry at every record, from the logged values converted as
    the robot does (``rot * 2π r``, ``Rotation2d.fromDegrees``)."""
    if drive_units not in ("rot", "m") or turn_units not in ("deg", "rad"):
        raise ValueError("drive_units in ('rot', 'm'), turn_units in ('deg', 'rad')")
    from wpiutil import DataLogWriter
    from wpiutil.log import DoubleLogEntry

    path = pathlib.Path(directory) / (filename or f"writer_swerve_{drive_units}_{turn_units}.wpilog")
    r = PER_MODULE_WHEEL_RADIUS
    circumference = 2 * math.pi * r
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in PER_MODULE_MODULES])
    motion = _Motion(_KNOTS_HOLONOMIC, _swerve_wheels(PER_MODULE_MODULES))
    cyc = _cycles(PER_MODULE_PERIOD_US)
    idx = motion.at(cyc)
    log = DataLogWriter(str(path))
    tick = _flushing(log, 100)
    t0 = int(cyc[0])
    e_drive = [DoubleLogEntry(log, f"/Swerve/{n}/DrivePosition", t0) for n in PER_MODULE_NAMES]
    e_turn = [DoubleLogEntry(log, f"/Swerve/{n}/TurnAngle", t0) for n in PER_MODULE_NAMES]
    e_vel = [DoubleLogEntry(log, f"/Swerve/{n}/DriveVelocity", t0) for n in PER_MODULE_NAMES]
    e_yaw = DoubleLogEntry(log, "/Swerve/Gyro/Yaw", t0)
    e_pose = _StructEntry(log, "/Swerve/Pose", Pose2d, t0)

    def to_log_drive(m):
        return m / circumference if drive_units == "rot" else m

    def from_log_drive(v):
        return v * circumference if drive_units == "rot" else v

    def to_log_turn(a):
        a = math.remainder(a, 2 * math.pi)
        return math.degrees(a) if turn_units == "deg" else a

    def from_log_turn(v):
        return Rotation2d.fromDegrees(v) if turn_units == "deg" else Rotation2d(v)

    odo = None
    truth = []
    try:
        for k, i in enumerate(idx):
            ts = int(cyc[k])
            drive = [to_log_drive(float(motion.wheels[j][0][i])) for j in range(4)]
            turn = [to_log_turn(float(motion.wheels[j][2][i])) for j in range(4)]
            yaw_deg = math.degrees(float(motion.yaw[i]))
            for j in range(4):
                e_drive[j].append(drive[j], ts)
                e_turn[j].append(turn[j], ts)
                e_vel[j].append(to_log_drive(float(motion.wheels[j][1][i])), ts)
            e_yaw.append(yaw_deg, ts)
            mods = tuple(SwerveModulePosition(from_log_drive(drive[j]), from_log_turn(turn[j]))
                         for j in range(4))
            rot = Rotation2d.fromDegrees(yaw_deg)
            if odo is None:
                odo = SwerveDrive4Odometry(kin, rot, mods, _start_pose())
                pose = odo.getPose()
            else:
                pose = odo.update(rot, mods)
            truth.append(_pose_row(pose))
            e_pose.append(pose, ts)
            tick()
    finally:
        log.flush()
        log.stop()
    entries = {
        "drive_positions": [f"/Swerve/{n}/DrivePosition" for n in PER_MODULE_NAMES],
        "turn_angles": [f"/Swerve/{n}/TurnAngle" for n in PER_MODULE_NAMES],
        "gyro_deg": "/Swerve/Gyro/Yaw", "pose": "/Swerve/Pose",
        "decoys": [f"/Swerve/{n}/DriveVelocity" for n in PER_MODULE_NAMES],
    }
    geometry = {"modules": PER_MODULE_MODULES, "module_names": PER_MODULE_NAMES,
                "wheel_radius": r, "drive_units": drive_units, "turn_units": turn_units,
                "gyro_units": "deg"}
    notes = {"initial_pose": START, "rate_hz": 50}
    return RealLog(path, "robotpy-wpiutil 2026.2.2 DataLogWriter (log entries, addStructSchema + wpistruct)", "swerve",
                   geometry, entries, cyc, np.array(truth), notes)


# ---------------------------------------------------------------------------------------
# 5. CTRE Phoenix 6 generated Telemetry (DriveState), mirrored by ntcore

CTRE_MODULES = ((0.2921, 0.2921), (0.2921, -0.2921), (-0.2921, 0.2921), (-0.2921, -0.2921))
CTRE_ODOMETRY_HZ = 250
CTRE_PUBLISH_DELAY_US = 800              # NT value time after the sample time


def ctre_drivestate(directory, *, filename: str = "ctre_drivestate.wpilog") -> RealLog:
    """The tables CTRE Phoenix 6's generated (Python) ``Telemetry.telemeterize`` publishes
    from the odometry thread (250 Hz), mirrored by ntcore (``NT:`` prefix):
    ``/DriveState/Pose`` struct:Pose2d, ``Speeds`` struct:ChassisSpeeds,
    ``ModuleStates`` / ``ModuleTargets`` struct:SwerveModuleState[],
    ``ModulePositions`` struct:SwerveModulePosition[], ``Timestamp`` (double s, the
    sample time), ``OdometryFrequency`` (double Hz); ``/Pose/robotPose`` double[3]
    (x, y, deg) and ``/Pose/.type``. The Telemetry publishes no gyro: the robot's heading
    is only in ``Pose``.

    Truth: SwerveDrive4Odometry at every sample from the (unlogged) Pigeon yaw and the
    logged module positions. ``t_us`` are the sample times (``Timestamp`` × 1e6); the NT
    record times are ``CTRE_PUBLISH_DELAY_US`` later. ``notes["truth_pose_heading"]``:
    the same odometry fed ``Pose``'s heading as its gyro (what a replay can do);
    ``notes["truth_kinematic_heading"]``: heading from module kinematics alone."""
    path = pathlib.Path(directory) / filename
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in CTRE_MODULES])
    motion = _Motion(_KNOTS_HOLONOMIC, _swerve_wheels(CTRE_MODULES))
    sample = _cycles(1_000_000 // CTRE_ODOMETRY_HZ)
    idx = motion.at(sample)
    ntcore, log, inst, handle = _nt_logging(path)
    tick = _flushing(log, 50)
    ds = inst.getTable("DriveState")
    pub_pose = ds.getStructTopic("Pose", Pose2d).publish()
    pub_speeds = ds.getStructTopic("Speeds", ChassisSpeeds).publish()
    pub_states = ds.getStructArrayTopic("ModuleStates", SwerveModuleState).publish()
    pub_targets = ds.getStructArrayTopic("ModuleTargets", SwerveModuleState).publish()
    pub_positions = ds.getStructArrayTopic("ModulePositions", SwerveModulePosition).publish()
    pub_ts = ds.getDoubleTopic("Timestamp").publish()
    pub_freq = ds.getDoubleTopic("OdometryFrequency").publish()
    pose_t = inst.getTable("Pose")
    pub_field = pose_t.getDoubleArrayTopic("robotPose").publish()
    pub_type = pose_t.getStringTopic(".type").publish()
    odo = None
    truth, logged_heading, logged_mods = [], [], []
    try:
        for k, i in enumerate(idx):
            ts = int(sample[k]) + CTRE_PUBLISH_DELAY_US
            mods = tuple(SwerveModulePosition(float(motion.wheels[j][0][i]),
                                              Rotation2d(float(motion.wheels[j][2][i])))
                         for j in range(4))
            yaw = Rotation2d(float(motion.yaw[i]))
            if odo is None:
                odo = SwerveDrive4Odometry(kin, yaw, mods, _start_pose())
                pose = odo.getPose()
            else:
                pose = odo.update(yaw, mods)
            truth.append(_pose_row(pose))
            logged_heading.append(pose.rotation().radians())
            logged_mods.append([(m.distance, m.angle.radians()) for m in mods])
            states = [SwerveModuleState(float(motion.wheels[j][1][i]),
                                        Rotation2d(float(motion.wheels[j][2][i]))) for j in range(4)]
            targets = [SwerveModuleState(1.02 * s.speed + 0.01, s.angle) for s in states]
            pub_pose.set(pose, ts)
            pub_speeds.set(ChassisSpeeds(float(motion.vx[i]), float(motion.vy[i]),
                                         float(motion.omega[i])), ts)
            pub_states.set(states, ts)
            pub_targets.set(targets, ts)
            pub_positions.set(list(mods), ts)
            pub_ts.set(int(sample[k]) / 1e6, ts)
            pub_freq.set(float(CTRE_ODOMETRY_HZ), ts)
            pub_type.set("Field2d", ts)
            pub_field.set([pose.X(), pose.Y(), pose.rotation().degrees()], ts)
            tick()
    finally:
        _nt_close(ntcore, log, inst, handle)
    truth = np.array(truth)
    logged_mods = np.array(logged_mods)
    heading = np.array(logged_heading)
    notes = {
        "initial_pose": START,
        "odometry_rate_hz": CTRE_ODOMETRY_HZ,
        "publish_delay_us": CTRE_PUBLISH_DELAY_US,
        "gyro": "none published: CTRE's Telemetry has no heading topic besides Pose",
        "truth_pose_heading": _swerve_truth(kin, heading, logged_mods[:, :, 0], logged_mods[:, :, 1]),
        "truth_kinematic_heading": _kinematic_heading_truth(kin, logged_mods),
    }
    entries = {
        "pose": "NT:/DriveState/Pose", "speeds": "NT:/DriveState/Speeds",
        "module_states": "NT:/DriveState/ModuleStates",
        "module_targets": "NT:/DriveState/ModuleTargets",
        "module_positions": "NT:/DriveState/ModulePositions",
        "timestamp_s": "NT:/DriveState/Timestamp",
        "odometry_frequency": "NT:/DriveState/OdometryFrequency",
        "field2d_pose": "NT:/Pose/robotPose", "field2d_type": "NT:/Pose/.type",
    }
    return RealLog(path, "pyntcore 2026.2.2 startEntryDataLog (NT: mirroring)", "swerve",
                   {"modules": CTRE_MODULES, "position_units": "m"}, entries, sample, truth, notes)


def _kinematic_heading_truth(kin, mods: np.ndarray) -> np.ndarray:
    """Pose from module positions alone (wpimath's twist of the module deltas, no gyro)."""
    pose = _start_pose()
    out = [_pose_row(pose)]
    for i in range(1, len(mods)):
        deltas = tuple(SwerveModulePosition(float(mods[i, j, 0] - mods[i - 1, j, 0]),
                                            Rotation2d(float(mods[i, j, 1]))) for j in range(4))
        pose = pose.exp(kin.toTwist2d(deltas))
        out.append(_pose_row(pose))
    return np.array(out)


ALL = {
    "pykit_swerve": pykit_swerve,
    "ntcore_differential": ntcore_differential,
    "writer_mecanum": writer_mecanum,
    "writer_swerve_per_module_doubles": writer_swerve_per_module_doubles,
    "ctre_drivestate": ctre_drivestate,
}

__all__ = ["RealLog", "ALL", *ALL]
