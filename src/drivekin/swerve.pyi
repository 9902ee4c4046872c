"""N-module swerve kinematics (WPILib 2027). The swerve module values it takes and returns
are :mod:`drivekin.swervemodule`'s, importable from here too.

Units: m, m/s, m/s², rad, rad/s, rad/s², s. Robot frame: x forward, y left, CCW positive.

Every hot operation has two forms: an object-returning façade with WPILib's name, and an
allocation-free ``...Into`` / ``...InPlace`` form that writes into caller-owned objects or
numpy buffers. Kinematics objects carry heading memory and are not thread-safe (as in
WPILib); every method runs with the GIL held, so a call is never interleaved.
"""

# Hand-written stub for the compiled module drivekin.swerve (swerve.pyx). The docstrings
# are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, SwerveDriveKinematics derives from drivekin._core.drivetrain.Drivetrain
# (_core/drivetrain.pyi) and declares only the members it defines itself. The module
# values are drivekin.swervemodule's (swervemodule.pyi), re-exported here.

from collections.abc import Iterable, Sequence
from typing import final, overload

import numpy as np
import numpy.typing as npt

from drivekin._core.drivetrain import Drivetrain
from drivekin.chassis import ChassisAccelerations, ChassisVelocities
from drivekin.geometry import Rotation2d, Translation2d, Twist2d
from drivekin.swervemodule import SwerveModuleAcceleration as SwerveModuleAcceleration
from drivekin.swervemodule import SwerveModulePosition as SwerveModulePosition
from drivekin.swervemodule import SwerveModuleVelocity as SwerveModuleVelocity

__all__ = ["SwerveDriveKinematics", "SwerveModuleAcceleration", "SwerveModulePosition",
           "SwerveModuleVelocity"]

@final
class SwerveDriveKinematics(Drivetrain):
    """``SwerveDriveKinematics(*module_translations)``

    Kinematics of a swerve drive with N ≥ 2 modules at the given robot-relative
    positions (Translation2d, m), in the order used by every method. Pass the
    translations as separate arguments or as one sequence.

    Inverse kinematics remembers each module's last heading: when the commanded chassis
    velocity is exactly zero, or a module's own speed is at most 1e-6 m/s, the module keeps
    its previous angle instead of snapping to 0. The heading memory lives in this object.
    The forward (pseudo-inverse) matrices are computed once for a centre of rotation at
    the robot origin and never change; a ``center_of_rotation`` passed to inverse
    kinematics only moves the inverse rows, and stays in effect until a different one is
    passed (compared within 1e-9 m).
    """

    @overload
    def __init__(self, module_translations: Sequence[Translation2d], /) -> None: ...
    @overload
    def __init__(self, *module_translations: Translation2d) -> None: ...
    def getModules(self) -> tuple[Translation2d, ...]:
        """Return the module positions (tuple of Translation2d, m), constructor order."""

    def getNumModules(self) -> int:
        """Return the number of modules N."""

    @overload
    def resetHeadings(self, module_headings: Sequence[Rotation2d]) -> None:
        """Replace the remembered module headings (N Rotation2d, as arguments or one
        sequence); used when the chassis velocity is zero or a module is on the CoR."""

    @overload
    def resetHeadings(self, module_headings: Rotation2d, *more: Rotation2d) -> None: ...
    def toSwerveModuleVelocities(
        self, chassis_velocities: ChassisVelocities, center_of_rotation: Translation2d = ...
    ) -> tuple[SwerveModuleVelocity, ...]:
        """Return the N module velocities (tuple of SwerveModuleVelocity) that produce
        ``chassis_velocities`` (robot-relative, m/s and rad/s), rotating about
        ``center_of_rotation`` (robot frame, m). Module speeds are ≥ 0; the angles follow
        the heading-memory rules in the class docstring. Not desaturated."""

    def toWheelVelocities(
        self, chassis_velocities: ChassisVelocities
    ) -> tuple[SwerveModuleVelocity, ...]:
        """Same as :meth:`toSwerveModuleVelocities` about the robot origin."""

    def toSwerveModuleVelocitiesInto(
        self,
        chassis_velocities: ChassisVelocities,
        out: Sequence[SwerveModuleVelocity] | npt.NDArray[np.float64],
        center_of_rotation: Translation2d = ...,
    ) -> None:
        """Allocation-free :meth:`toSwerveModuleVelocities`.

        ``out`` is either a list/tuple of N SwerveModuleVelocity objects, updated in place,
        or a float64 C-contiguous writeable numpy array of shape (N, 2) that receives
        ``[velocity m/s, angle rad]`` per module. Returns None."""

    def desaturatedDiscretize(
        self,
        chassis_velocities: ChassisVelocities,
        dt: float,
        attainable_max_module_velocity: float,
    ) -> ChassisVelocities:
        """Return ``discretize(k·v, dt)`` for the largest k in [0, 1] at which no module
        (about the robot origin) goes faster than ``attainable_max_module_velocity`` (m/s).

        ``v`` is the robot-relative ``chassis_velocities`` (m/s, rad/s) and ``dt`` the loop
        period (s, > 0). Unlike ``discretize`` followed by
        :meth:`desaturateWheelVelocities`, which scales the modules after the discretize
        correction and so turns the direction of travel by (k − 1)·ω·dt/2 (the skew
        WPILib's ``discretize`` documentation warns about), the robot moves exactly in
        the commanded direction, and unlike desaturating before discretizing, no module
        ends above the limit. k is exact to 1e-14 relative; with no saturation the result
        is ``chassis_velocities.discretize(dt)``. Every input must be finite (the limit
        may be +inf) and the limit ≥ 0; with no limit, a result beyond the largest double
        is a ValueError."""
    def desaturatedDiscretizeInto(
        self,
        chassis_velocities: ChassisVelocities,
        dt: float,
        attainable_max_module_velocity: float,
        out: ChassisVelocities,
    ) -> None:
        """Allocation-free :meth:`desaturatedDiscretize`: the result goes into ``out``
        (which may be ``chassis_velocities``). Returns None."""
    @overload
    def toChassisVelocities(
        self, module_velocities: Sequence[SwerveModuleVelocity]
    ) -> ChassisVelocities:
        """Return the least-squares ChassisVelocities (robot-relative) for N measured
        module velocities (SwerveModuleVelocity, as arguments or one sequence, or an (N, 2)
        float64 array ``[velocity m/s, angle rad]``)."""

    @overload
    def toChassisVelocities(
        self, module_velocities: SwerveModuleVelocity, *more: SwerveModuleVelocity
    ) -> ChassisVelocities: ...
    def toChassisVelocitiesInto(
        self,
        module_velocities: Sequence[SwerveModuleVelocity] | npt.NDArray[np.float64],
        out: ChassisVelocities,
    ) -> None:
        """Allocation-free :meth:`toChassisVelocities`: ``module_velocities`` is a sequence
        of N SwerveModuleVelocity or an (N, 2) float64 array ``[velocity m/s, angle rad]``;
        the result is written into ``out``. Returns None."""

    @overload
    def toTwist2d(self, module_deltas: Sequence[SwerveModulePosition]) -> Twist2d:
        """toTwist2d(*module_deltas) or toTwist2d(start, end)

        Return the Twist2d (m, rad) of the robot for N module position deltas
        (SwerveModulePosition: distance driven since the last update and the current
        angle; or an (N, 2) float64 array ``[distance m, angle rad]``). With two sequences
        ``start`` and ``end``, the deltas are
        ``end.distance − start.distance`` at the **end** angle, as in WPILib."""

    @overload
    def toTwist2d(
        self, module_deltas: SwerveModulePosition, *more: SwerveModulePosition
    ) -> Twist2d: ...
    @overload
    def toTwist2d(
        self, start: Sequence[SwerveModulePosition], end: Sequence[SwerveModulePosition], /
    ) -> Twist2d: ...
    def toTwist2dInto(
        self,
        module_deltas: Sequence[SwerveModulePosition] | npt.NDArray[np.float64],
        out: Twist2d,
    ) -> None:
        """Allocation-free :meth:`toTwist2d` for N deltas (SwerveModulePosition objects or an
        (N, 2) float64 array ``[distance m, angle rad]``), written into ``out``."""

    def interpolate(
        self,
        start: Sequence[SwerveModulePosition],
        end: Sequence[SwerveModulePosition],
        t: float,
    ) -> tuple[SwerveModulePosition, ...]:
        """Return per-module ``SwerveModulePosition.interpolate`` (t not clamped)."""

    def copy(self, positions: Iterable[SwerveModulePosition]) -> tuple[SwerveModulePosition, ...]:
        """Return independent copies of the module positions (tuple)."""

    def copyInto(
        self,
        positions: Sequence[SwerveModulePosition],
        output: Sequence[SwerveModulePosition],
    ) -> None:
        """Copy each position's fields into the matching object of ``output``."""

    def toSwerveModuleAccelerations(
        self,
        chassis_accelerations: ChassisAccelerations,
        angular_velocity: float = 0.0,
        center_of_rotation: Translation2d = ...,
    ) -> tuple[SwerveModuleAcceleration, ...]:
        """Return the N module accelerations (SwerveModuleAcceleration: magnitude m/s² and
        direction) for ``chassis_accelerations`` while turning at ``angular_velocity``
        rad/s about ``center_of_rotation`` (m): a_i = a + α × r_i − ω² r_i.

        WPILib's rules are kept: an exactly zero ``chassis_accelerations`` gives all-zero
        results even when ``angular_velocity`` ≠ 0, and a module whose acceleration is at
        most 1e-6 gets angle 0 (there is no heading memory for accelerations)."""

    def toWheelAccelerations(
        self, chassis_accelerations: ChassisAccelerations
    ) -> tuple[SwerveModuleAcceleration, ...]:
        """Same as :meth:`toSwerveModuleAccelerations` with zero angular velocity about
        the robot origin."""

    @overload
    def toChassisAccelerations(
        self, module_accelerations: Sequence[SwerveModuleAcceleration]
    ) -> ChassisAccelerations:
        """Return the least-squares ChassisAccelerations for N module accelerations
        (as arguments or one sequence, or an (N, 2) float64 array ``[m/s², angle rad]``).
        The ω² estimate of the solve is discarded."""

    @overload
    def toChassisAccelerations(
        self, module_accelerations: SwerveModuleAcceleration, *more: SwerveModuleAcceleration
    ) -> ChassisAccelerations: ...
    @overload
    @staticmethod
    def desaturateWheelVelocities(
        module_velocities: Sequence[SwerveModuleVelocity],
        attainable_max_velocity: float,
        attainable_max_module_velocity: None = None,
        attainable_max_robot_translation_velocity: None = None,
        attainable_max_robot_rotation_velocity: None = None,
    ) -> tuple[SwerveModuleVelocity, ...]:
        """desaturateWheelVelocities(module_velocities, attainable_max_velocity) or
        desaturateWheelVelocities(module_velocities, desired_chassis_velocity,
        attainable_max_module_velocity, attainable_max_robot_translation_velocity,
        attainable_max_robot_rotation_velocity)

        Return new module velocities (tuple) scaled down so no wheel exceeds its limit,
        keeping their ratios and angles. The one-limit form scales only when the fastest
        wheel is above ``attainable_max_velocity`` (m/s). The five-argument form also
        scales by how hard the driver asks (``desired_chassis_velocity`` against the
        translational m/s and rotational rad/s limits), so it can slow unsaturated wheels;
        it leaves the velocities unchanged if either chassis limit or every wheel speed is
        zero. The input is not modified (2027). In the five-argument form the second
        parameter is the desired ChassisVelocities, passed by position (its keyword is the
        two-argument form's ``attainable_max_velocity``)."""

    @overload
    @staticmethod
    def desaturateWheelVelocities(
        module_velocities: Sequence[SwerveModuleVelocity],
        attainable_max_velocity: ChassisVelocities,
        attainable_max_module_velocity: float,
        attainable_max_robot_translation_velocity: float,
        attainable_max_robot_rotation_velocity: float,
    ) -> tuple[SwerveModuleVelocity, ...]: ...
    @overload
    @staticmethod
    def desaturateWheelVelocitiesInPlace(
        module_velocities: Sequence[SwerveModuleVelocity] | npt.NDArray[np.float64],
        attainable_max_velocity: float,
        attainable_max_module_velocity: None = None,
        attainable_max_robot_translation_velocity: None = None,
        attainable_max_robot_rotation_velocity: None = None,
    ) -> None:
        """Allocation-free :meth:`desaturateWheelVelocities` (same two forms) that rescales
        the caller's N SwerveModuleVelocity objects, or column 0 of an (N, 2) float64
        array ``[velocity m/s, angle rad]``, in place. Returns None."""

    @overload
    @staticmethod
    def desaturateWheelVelocitiesInPlace(
        module_velocities: Sequence[SwerveModuleVelocity] | npt.NDArray[np.float64],
        attainable_max_velocity: ChassisVelocities,
        attainable_max_module_velocity: float,
        attainable_max_robot_translation_velocity: float,
        attainable_max_robot_rotation_velocity: float,
    ) -> None: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    copy_into = copyInto
    desaturate_wheel_velocities = desaturateWheelVelocities
    desaturate_wheel_velocities_in_place = desaturateWheelVelocitiesInPlace
    desaturated_discretize = desaturatedDiscretize
    desaturated_discretize_into = desaturatedDiscretizeInto
    get_modules = getModules
    get_num_modules = getNumModules
    reset_headings = resetHeadings
    to_chassis_accelerations = toChassisAccelerations
    to_chassis_velocities = toChassisVelocities
    to_chassis_velocities_into = toChassisVelocitiesInto
    to_swerve_module_accelerations = toSwerveModuleAccelerations
    to_swerve_module_velocities = toSwerveModuleVelocities
    to_swerve_module_velocities_into = toSwerveModuleVelocitiesInto
    to_twist2d = toTwist2d
    to_twist2d_into = toTwist2dInto
    to_wheel_accelerations = toWheelAccelerations
    to_wheel_velocities = toWheelVelocities
