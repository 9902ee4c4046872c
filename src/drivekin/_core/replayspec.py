"""What a log replay (and calibration) needs to know about one drivetrain: one spec
object per drivetrain, hung on its odometry entry in the catalog (``Entry.replay``), so
:mod:`drivekin.replay` and :mod:`drivekin.calibrate` iterate specs and never compare
drivetrain names.

A spec knows the shape of its positions stack, which part of it is wheel distance, how
the corrections (wheel scale, steer offsets) apply, how its geometry comes from the
options or the log, whether a gyro can be replaced by the wheels, and how a bare
``double[]`` entry maps onto it.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, TypeAlias

import numpy as np

from drivekin._core import calibrationmodels as models

if TYPE_CHECKING:
    # The catalog holds these specs, so a program that type-checks against drivekin's
    # classes reaches this module: the log types stay out of its import graph (Any).
    from drivekin._core.catalog import Entry
LogData: TypeAlias = Any
Signal: TypeAlias = Any
ReplayConfig: TypeAlias = Any


def _error(message: str) -> Exception:
    # datalog imports the catalog, which holds these specs: imported when first needed
    from drivekin.datalog import DataLogError
    return DataLogError(message)


class ReplaySpec:
    """The default: every column of the (N, k) positions stack is a wheel distance."""

    name = ""
    wheel = "wheel"                 # what one column is called in messages
    found_by_type = True            # positions found without --positions
    double_array = False            # a named double[] entry can hold these positions
    calibration: models.CalibrationModel    # its calibration model (drivekin.calibrate)

    # -- the catalog ----------------------------------------------------------------
    def _entry(self, kind: str) -> Entry:
        from drivekin._core import catalog
        return catalog.entries(kind, drivetrain=self.name)[0]

    @property
    def odometry(self) -> str:
        """The odometry class's name (what the replay report calls it)."""
        return self._entry("odometry").cls.__name__

    def start(self, kin: Any, gyro0: Any, row: np.ndarray, pose: Any) -> Any:
        """An odometry at the first sample (the catalog's start rule)."""
        return self._entry("odometry").start(kin, gyro0, row, pose)  # type: ignore[misc]

    # -- positions ------------------------------------------------------------------
    def width(self, P: np.ndarray, source: str) -> int:
        """Wheels (modules) per sample; DataLogError for a stack of the wrong shape."""
        return P.shape[1] if P.ndim >= 2 else 1

    def distances(self, P: np.ndarray) -> np.ndarray:
        """The wheel distances (m) of a stack, as (N, k)."""
        return P.reshape(len(P), -1)

    def correct(self, P: np.ndarray, cfg: ReplayConfig) -> np.ndarray:
        """Apply ``wheelScale`` (one number or one per wheel) and ``steerOffsets``."""
        if cfg.steerOffsets is not None:
            raise _error("steer offsets apply to swerve modules only")
        P *= self._scale(P, cfg)
        return P

    def _scale(self, P: np.ndarray, cfg: ReplayConfig) -> np.ndarray:
        width = P.shape[1] if P.ndim >= 2 else 1
        scale = np.asarray(cfg.wheelScale, dtype=np.float64)
        if scale.ndim == 1 and scale.shape[0] != width:
            raise _error(f"{scale.shape[0]} wheel scales given, the positions have "
                               f"{width} {self.wheel}s per sample")
        if not (np.isfinite(scale).all() and (scale > 0).all()):
            raise _error("wheel scales must be positive and finite")
        return scale

    def wheel_heading(self, P: np.ndarray, cfg: ReplayConfig) -> np.ndarray:
        """The heading (rad) from the wheels, where the drivetrain allows it."""
        raise _error(f"heading from the wheels is supported for differential drives "
                           f"only, not {self.name}")

    def geometry(self, log: LogData, width: int, cfg: ReplayConfig, pos: Signal
                 ) -> tuple[Any, str]:
        """The kinematics object (or None) and a description of the geometry used."""
        return None, "no geometry needed (heading from the gyro)"


class _Offsets(ReplaySpec):
    """Swerve and mecanum: wheels at offsets from the robot centre, from the options,
    the positions' own layout (YAGSL's wheelLocation), or the log's kinematics struct."""

    corners = "FL, FR, BL, BR"

    def count(self, width: int) -> int:
        return width

    def struct(self, width: int) -> str:
        raise NotImplementedError

    def geometry(self, log: LogData, width: int, cfg: ReplayConfig, pos: Signal
                 ) -> tuple[Any, str]:
        from drivekin._core.loglayouts import REPLAY_PREFIX
        count = self.count(width)
        what = self.wheel
        struct = self.struct(width)
        mods = cfg.modules
        src = "from the options"
        if mods is None and cfg.wheelbase is not None and cfg.trackwidth is not None:
            hl, hw = cfg.wheelbase / 2.0, cfg.trackwidth / 2.0
            mods = [(hl, hw), (hl, -hw), (-hl, hw), (-hl, -hw)]
            src = f"--wheelbase {cfg.wheelbase:g} --trackwidth {cfg.trackwidth:g}: {self.corners}"
        if mods is None and pos.offsets is not None:
            mods = list(pos.offsets)
            src = f"from {pos.offsetsFrom}"
        if mods is None:
            names = [e.name for e in log.entries.values() if e.type == struct and e.records
                     and not e.name.startswith(REPLAY_PREFIX)]
            if len(names) > 1:
                raise _error(f"several {struct} entries: {', '.join(names)}; give "
                                   f"the offsets with --module or --trackwidth/--wheelbase")
            if not names:
                raise _error(
                    f"no {what} offsets in the log: give --trackwidth W --wheelbase L for a "
                    f"rectangle, or --module X,Y for each of the {count} {what}s (in the "
                    f"log's order{self._order_hint()})")
            v = log.values(names[0])[1][-1]
            mods = [(float(v[2 * j]), float(v[2 * j + 1])) for j in range(count)]
            src = f"from {names[0]}"
        if len(mods) != count:
            raise _error(f"{len(mods)} {what} offsets given, the log's positions have "
                               f"{count} {what}s")
        kin = self._entry("kinematics").build(  # type: ignore[misc]
            *[c for xy in mods for c in xy])
        text = ", ".join(f"({x:g}, {y:g})" for x, y in mods)
        return kin, f"{count} {what}s at {text} m ({src})"

    def _order_hint(self) -> str:
        return ""


class SwerveSpec(_Offsets):
    """(N, M, 2) ``[distance m, angle rad]`` per module."""

    calibration = models.SwerveCalibration()
    name = "swerve"
    wheel = "module"

    def struct(self, width: int) -> str:
        return f"struct:SwerveDriveKinematics__{width}"

    def width(self, P: np.ndarray, source: str) -> int:
        width = super().width(P, source)
        if width < 2:
            raise _error(f"{source!r} has {width} module(s) per sample; a swerve "
                               f"drive has at least 2")
        return width

    def distances(self, P: np.ndarray) -> np.ndarray:
        return P[:, :, 0]

    def correct(self, P: np.ndarray, cfg: ReplayConfig) -> np.ndarray:
        P[:, :, 0] *= self._scale(P, cfg)
        if cfg.steerOffsets is not None:
            width = P.shape[1]
            if len(cfg.steerOffsets) != width:
                raise _error(f"{len(cfg.steerOffsets)} steer offsets given, the "
                                   f"positions have {width} modules per sample")
            P[:, :, 1] += np.asarray(cfg.steerOffsets, dtype=np.float64)
        return P


class MecanumSpec(_Offsets):
    """(N, 4) ``[fl, fr, rl, rr]`` m."""

    calibration = models.MecanumCalibration()
    name = "mecanum"
    corners = "FL, FR, RL, RR"
    double_array = True

    def count(self, width: int) -> int:
        return 4

    def struct(self, width: int) -> str:
        return "struct:MecanumDriveKinematics"

    def _order_hint(self) -> str:
        return ", FL, FR, RL, RR"


class DifferentialSpec(ReplaySpec):
    """(N, 2) ``[left, right]`` m; its heading may come from the wheels."""

    calibration = models.DifferentialCalibration()
    name = "differential"
    wheel = "side"
    double_array = True

    def width(self, P: np.ndarray, source: str) -> int:
        width = super().width(P, source)
        if width != 2:
            raise _error(f"differential positions must be [left, right], {source!r} "
                               f"has {width} values per sample")
        return width

    def wheel_heading(self, P: np.ndarray, cfg: ReplayConfig) -> np.ndarray:
        if not cfg.trackwidth:
            raise _error("heading from the wheels needs --trackwidth")
        heading: np.ndarray = (P[:, 1] - P[:, 0]) / float(cfg.trackwidth)
        return heading

    def geometry(self, log: LogData, width: int, cfg: ReplayConfig, pos: Signal
                 ) -> tuple[Any, str]:
        if cfg.heading == "wheels":
            return None, f"trackwidth {cfg.trackwidth:g} m (heading from the wheels)"
        return super().geometry(log, width, cfg, pos)


class DeadWheelSpec(ReplaySpec):
    """(N, k) wheel distances of dead wheels at the poses ``--dead-wheel`` gives."""

    calibration = models.DeadWheelCalibration()
    name = "deadwheel"
    wheel = "dead wheel"
    found_by_type = False
    double_array = True

    def geometry(self, log: LogData, width: int, cfg: ReplayConfig, pos: Signal
                 ) -> tuple[Any, str]:
        from drivekin.deadwheel import DeadWheelKinematics
        from drivekin.geometry import Pose2d, Rotation2d
        wheels = cfg.deadWheels
        if not wheels:
            raise _error("dead wheels need their poses: --dead-wheel X,Y,DEG for "
                               "each wheel, in the order of the positions array")
        if len(wheels) != width:
            raise _error(f"{len(wheels)} dead wheels given, the positions entry has "
                               f"{width} values per sample")
        kin = DeadWheelKinematics([Pose2d(x, y, Rotation2d.fromDegrees(d))
                                   for x, y, d in wheels])
        text = ", ".join(f"({x:g}, {y:g}, {d:g}°)" for x, y, d in wheels)
        return kin, f"{width} dead wheels at {text}"


SWERVE = SwerveSpec()
MECANUM = MecanumSpec()
DIFFERENTIAL = DifferentialSpec()
DEADWHEEL = DeadWheelSpec()
