"""Each drivetrain's calibration model for :mod:`drivekin.calibrate`: the parameters it
has, which of them the manoeuvre windows estimate and which the joint fit against a
reference varies, each wheel's lever per radian of robot rotation, the rotation its wheels
imply (forward kinematics), how fitted values correct its wheel samples and become replay
options. One object per drivetrain, held by its replay spec (``_core/replayspec``) on the
catalog; calibrate reaches them only through :func:`model_for`, never by comparing
names."""
from __future__ import annotations

import math
from typing import Any

import numpy as np


class CalibrationModel:
    """What every drivetrain shares: wheel distances scaled by ``wheelRadiusScale``, a
    gyro scaled by ``gyroScale``, nothing that the turning windows alone determine."""

    wheel = "wheel"                    # what one entry of a per-wheel parameter is
    #: Reported in this order; the window estimates come first, gyroScale last.
    parameters: tuple[str, ...] = ("wheelRadiusScale", "gyroScale")
    #: Estimated from the manoeuvre windows (without a reference), by name.
    windowEstimates: tuple[str, ...] = ()
    #: Parameters the windows cannot determine, and why (no estimator is run).
    undetermined: dict[str, str] = {}
    #: Varied by the joint fit against a reference (gyroScale always last); per-wheel.
    joint: tuple[str, ...] = ("wheelRadiusScale", "gyroScale")
    #: Of ``joint``: fitted as one common factor (offset) of the windows' per-wheel
    #: values when the windows determined them (forward kinematics averages the wheels).
    jointCommon: tuple[str, ...] = ()
    #: True: the reference is used by regressing the wheels on its motion instead.
    regressesOnReference = False
    #: True: no calibration without a gyro.
    needsGyro = False
    #: Replay configuration field of each parameter.
    configFields = {"wheelRadiusScale": "wheelScale", "gyroScale": "gyroScale"}
    #: Parameters whose best-known value configures the replay even when undetermined.
    bestKnown: tuple[str, ...] = ()

    def per_rad(self, kin: Any) -> np.ndarray | None:
        """Each wheel's distance per radian of robot rotation in place (None: none)."""
        return None

    def spin_distances(self, r: Any, s: slice, i: int) -> np.ndarray | None:
        """Wheel ``i``'s distances over a spin window ``s`` (None: not usable there)."""
        out: np.ndarray = r.positions[s][:, i]
        return out

    def step_rotations(self, r: Any) -> np.ndarray | None:
        """The robot's rotation (rad) between consecutive samples that the wheels imply
        through the configured geometry (forward kinematics, least squares over the
        wheels), or None when the geometry is itself unknown."""
        return None

    def correct(self, P: np.ndarray, values: dict[str, Any]) -> np.ndarray:
        """The wheel samples ``P`` corrected by ``values`` (a copy)."""
        out: np.ndarray = P * np.asarray(values.get("wheelRadiusScale", 1.0))
        return out

    def kinematics(self, r: Any, params: dict[str, Any]) -> Any:
        """The geometry the fitted replay uses (``r``'s, unless the parameters are it)."""
        return r.kinematics

    def config_fields(self, params: dict[str, Any]) -> dict[str, Any]:
        """The replay configuration fields that apply the determined parameters."""
        out: dict[str, Any] = {}
        for name, fieldname in self.configFields.items():
            p = params.get(name)
            if p is None or p.value is None or not (p.determined or name in self.bestKnown):
                continue
            v = p.value
            out[fieldname] = (float(v) if np.ndim(v) == 0 else
                              [tuple(w) if np.ndim(w) else w for w in v])
        return out


class _Holonomic(CalibrationModel):
    """Swerve and mecanum: the wheels imply a rotation through the configured geometry,
    so a turn against the gyro gives their common scale; a spin in place gives each's."""

    windowEstimates: tuple[str, ...] = ("wheelRadiusScale",)
    jointCommon: tuple[str, ...] = ("wheelRadiusScale",)

    def matrix(self, kin: Any) -> np.ndarray:
        """Inverse kinematics: the wheel increments of (dx, dy, dθ), one row each."""
        raise NotImplementedError

    def increments(self, P: np.ndarray) -> np.ndarray:
        """Per-step wheel increments, in the layout of :meth:`matrix`'s rows."""
        raise NotImplementedError

    def per_rad(self, kin: Any) -> np.ndarray:
        out: np.ndarray = np.abs(self.matrix(kin)[:, 2])
        return out

    def step_rotations(self, r: Any) -> np.ndarray:
        out: np.ndarray = (self.increments(r.positions)
                           @ np.linalg.pinv(self.matrix(r.kinematics))[2])
        return out


class SwerveCalibration(_Holonomic):
    wheel = "module"
    parameters = ("wheelRadiusScale", "steerOffsets", "gyroScale")
    windowEstimates = ("wheelRadiusScale", "steerOffsets")
    joint = ("wheelRadiusScale", "steerOffsets", "gyroScale")
    jointCommon = ("wheelRadiusScale", "steerOffsets")
    configFields = {"wheelRadiusScale": "wheelScale", "gyroScale": "gyroScale",
                    "steerOffsets": "steerOffsets"}
    TANGENT_TOLERANCE = math.radians(15.0)   # a spinning module this far off tangent

    def matrix(self, kin: Any) -> np.ndarray:
        # Module i moves (dx − y dθ, dy + x dθ): x and y rows, module after module.
        rows = []
        for m in kin.getModules():
            rows += [[1.0, 0.0, -m.getY()], [0.0, 1.0, m.getX()]]
        return np.array(rows)

    def per_rad(self, kin: Any) -> np.ndarray:
        return np.array([m.getNorm() for m in kin.getModules()])

    def increments(self, P: np.ndarray) -> np.ndarray:
        # Each step's distance along the angle at its end, as WPILib's odometry takes it.
        d = np.diff(P[:, :, 0], axis=0)
        a = P[1:, :, 1]
        return np.stack([d * np.cos(a), d * np.sin(a)], axis=2).reshape(len(d), -1)

    def spin_distances(self, r: Any, s: slice, i: int) -> np.ndarray | None:
        P = r.positions[s]
        m = r.kinematics.getModules()[i]
        tangent = math.atan2(m.getX(), -m.getY())
        dev = np.angle(np.exp(2j * (P[:, i, 1] - tangent))) / 2     # mod π
        if abs(float(np.mean(dev))) > self.TANGENT_TOLERANCE:
            return None
        out: np.ndarray = P[:, i, 0]
        return out

    def correct(self, P: np.ndarray, values: dict[str, Any]) -> np.ndarray:
        P = P.copy()
        P[:, :, 0] *= np.asarray(values.get("wheelRadiusScale", 1.0))
        P[:, :, 1] += np.asarray(values.get("steerOffsets", 0.0))
        return P


class MecanumCalibration(_Holonomic):

    def matrix(self, kin: Any) -> np.ndarray:
        from drivekin.chassis import ChassisVelocities
        cols = []
        for basis in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)):
            w = kin.toWheelVelocities(ChassisVelocities(*basis))
            cols.append([w.frontLeft, w.frontRight, w.rearLeft, w.rearRight])
        return np.array(cols).T

    def increments(self, P: np.ndarray) -> np.ndarray:
        return np.diff(P, axis=0)


class DifferentialCalibration(CalibrationModel):
    wheel = "side"
    parameters = ("wheelRadiusScale", "trackwidth", "gyroScale")
    windowEstimates = ("trackwidth",)
    undetermined = {"wheelRadiusScale": (
        "needs a reference pose (--truth ENTRY): from the gyro alone a differential "
        "drive's wheel scale and trackwidth are not separable")}
    configFields = {"wheelRadiusScale": "wheelScale", "gyroScale": "gyroScale",
                    "trackwidth": "trackwidth"}


class DeadWheelCalibration(CalibrationModel):
    parameters = ("deadWheelLevers", "deadWheelPoses", "gyroScale")
    windowEstimates = ("deadWheelLevers",)
    joint = ()
    regressesOnReference = True
    needsGyro = True
    configFields = {"gyroScale": "gyroScale", "deadWheelPoses": "deadWheels"}
    bestKnown = ("deadWheelPoses",)            # the replay needs them, best known

    def kinematics(self, r: Any, params: dict[str, Any]) -> Any:
        from drivekin.deadwheel import DeadWheelKinematics
        from drivekin.geometry import Pose2d, Rotation2d
        p = params.get("deadWheelPoses")
        if p is None or p.value is None:
            return r.kinematics
        return DeadWheelKinematics([Pose2d(x, y, Rotation2d.fromDegrees(d))
                                    for x, y, d in p.value])


def model_for(result: Any) -> CalibrationModel:
    """The calibration model of a replay's drivetrain (a :class:`ReplayResult`): its
    replay spec's, on the catalog."""
    from drivekin._core import catalog
    model: CalibrationModel = catalog.replay_spec(result.drivetrain).calibration
    return model
