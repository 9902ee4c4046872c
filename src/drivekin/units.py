"""WPILib 2027's ``Units`` helper class (``org.wpilib.math.util.Units``, 2026:
``edu.wpi.first.math.util.Units``): conversions between the units FRC teams use and SI.

Every method computes with the same constants and in the same order of operations as the
Java source, so the results are the Java results bit for bit (Java ``double`` arithmetic
is IEEE 754 binary64, as Python's ``float`` is). robotpy-wpimath 2026's ``wpimath.units``
has most of these functions; a few of them (``rotationsPerMinuteToRadiansPerSecond``,
``radiansPerSecondToRotationsPerMinute``) use a different order of operations there and
can differ from Java's in the last bit.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, final

from drivekin._core.numbers import as_double

__all__ = ["Units"]

# The constants of Units.java (private there). Java's Math.PI is math.pi; Math.toRadians
# and Math.toDegrees multiply by these two constants (JDK 9 and later).
_INCHES_PER_FOOT = 12.0
_METERS_PER_INCH = 0.0254
_METERS_PER_MILE = 1609.344
_SECONDS_PER_MINUTE = 60.0
_MINUTES_PER_HOUR = 60.0
_MILLISECONDS_PER_SECOND = 1000.0
_KILOGRAMS_PER_LB = 0.453592
_PI = 3.141592653589793
_DEGREES_TO_RADIANS = 0.017453292519943295
_RADIANS_TO_DEGREES = 57.29577951308232


def _real(value: object, method: str) -> float:
    # As Java's double parameter takes it (never a string or a container, which float()
    # would parse or a multiplication would repeat).
    return as_double(value, f"Units.{method}() takes a number")


@final
class Units:
    """Units conversions used in FRC, as static methods (WPILib's ``Units`` class).

    Lengths: metres, inches, feet; angles: radians, degrees, rotations (turns); angular
    velocity: rad/s and rotations per minute; speed: m/s and miles per hour; time: seconds
    and milliseconds; mass: kilograms and pounds (pound-mass, 0.453592 kg as in WPILib).
    Each method takes and returns a float. ``Units`` is not instantiable (TypeError), like
    the Java class.
    """

    __slots__ = ()

    def __new__(cls) -> Units:
        raise TypeError("Units is a utility class: call its static methods, e.g. "
                        "Units.inchesToMeters(12.0), without creating an instance")

    @staticmethod
    def metersToFeet(meters: float) -> float:
        """Convert metres to feet: ``metersToInches(meters) / 12``."""
        return _real(meters, "metersToFeet") / _METERS_PER_INCH / _INCHES_PER_FOOT

    @staticmethod
    def feetToMeters(feet: float) -> float:
        """Convert feet to metres: ``inchesToMeters(feet * 12)``."""
        return _real(feet, "feetToMeters") * _INCHES_PER_FOOT * _METERS_PER_INCH

    @staticmethod
    def metersToInches(meters: float) -> float:
        """Convert metres to inches: ``meters / 0.0254``."""
        return _real(meters, "metersToInches") / _METERS_PER_INCH

    @staticmethod
    def inchesToMeters(inches: float) -> float:
        """Convert inches to metres: ``inches * 0.0254``."""
        return _real(inches, "inchesToMeters") * _METERS_PER_INCH

    @staticmethod
    def degreesToRadians(degrees: float) -> float:
        """Convert degrees to radians (Java's ``Math.toRadians``: ``degrees * (π/180)``)."""
        return _real(degrees, "degreesToRadians") * _DEGREES_TO_RADIANS

    @staticmethod
    def radiansToDegrees(radians: float) -> float:
        """Convert radians to degrees (Java's ``Math.toDegrees``: ``radians * (180/π)``)."""
        return _real(radians, "radiansToDegrees") * _RADIANS_TO_DEGREES

    @staticmethod
    def radiansToRotations(radians: float) -> float:
        """Convert radians to rotations (turns): ``radians / (2π)``."""
        return _real(radians, "radiansToRotations") / (_PI * 2.0)

    @staticmethod
    def degreesToRotations(degrees: float) -> float:
        """Convert degrees to rotations (turns): ``degrees / 360``."""
        return _real(degrees, "degreesToRotations") / 360.0

    @staticmethod
    def rotationsToDegrees(rotations: float) -> float:
        """Convert rotations (turns) to degrees: ``rotations * 360``."""
        return _real(rotations, "rotationsToDegrees") * 360.0

    @staticmethod
    def rotationsToRadians(rotations: float) -> float:
        """Convert rotations (turns) to radians: ``rotations * 2 * π``."""
        return _real(rotations, "rotationsToRadians") * 2.0 * _PI

    @staticmethod
    def rotationsPerMinuteToRadiansPerSecond(rpm: float) -> float:
        """Convert rotations per minute to rad/s: ``rpm * π / 30``."""
        return (_real(rpm, "rotationsPerMinuteToRadiansPerSecond") * _PI
                / (_SECONDS_PER_MINUTE / 2.0))

    @staticmethod
    def radiansPerSecondToRotationsPerMinute(radiansPerSecond: float) -> float:
        """Convert rad/s to rotations per minute: ``radiansPerSecond * 30 / π``."""
        return (_real(radiansPerSecond, "radiansPerSecondToRotationsPerMinute")
                * (_SECONDS_PER_MINUTE / 2.0) / _PI)

    @staticmethod
    def milesPerHourToMetersPerSecond(mph: float) -> float:
        """Convert miles per hour to m/s: ``mph * 1609.344 / 3600``."""
        return (_real(mph, "milesPerHourToMetersPerSecond") * _METERS_PER_MILE
                / (_SECONDS_PER_MINUTE * _MINUTES_PER_HOUR))

    @staticmethod
    def metersPerSecondToMilesPerHour(metersPerSecond: float) -> float:
        """Convert m/s to miles per hour: ``metersPerSecond / 1609.344 * 3600``."""
        return (_real(metersPerSecond, "metersPerSecondToMilesPerHour") / _METERS_PER_MILE
                * (_SECONDS_PER_MINUTE * _MINUTES_PER_HOUR))

    @staticmethod
    def millisecondsToSeconds(milliseconds: float) -> float:
        """Convert milliseconds to seconds: ``milliseconds / 1000``."""
        return _real(milliseconds, "millisecondsToSeconds") / _MILLISECONDS_PER_SECOND

    @staticmethod
    def secondsToMilliseconds(seconds: float) -> float:
        """Convert seconds to milliseconds: ``seconds * 1000``."""
        return _real(seconds, "secondsToMilliseconds") * _MILLISECONDS_PER_SECOND

    @staticmethod
    def kilogramsToLbs(kilograms: float) -> float:
        """Convert kilograms to pounds (pound-mass): ``kilograms / 0.453592``."""
        return _real(kilograms, "kilogramsToLbs") / _KILOGRAMS_PER_LB

    @staticmethod
    def lbsToKilograms(lbs: float) -> float:
        """Convert pounds (pound-mass) to kilograms: ``lbs * 0.453592``."""
        return _real(lbs, "lbsToKilograms") * _KILOGRAMS_PER_LB

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    if TYPE_CHECKING:
        degrees_to_radians = degreesToRadians
        degrees_to_rotations = degreesToRotations
        feet_to_meters = feetToMeters
        inches_to_meters = inchesToMeters
        kilograms_to_lbs = kilogramsToLbs
        lbs_to_kilograms = lbsToKilograms
        meters_per_second_to_miles_per_hour = metersPerSecondToMilesPerHour
        meters_to_feet = metersToFeet
        meters_to_inches = metersToInches
        miles_per_hour_to_meters_per_second = milesPerHourToMetersPerSecond
        milliseconds_to_seconds = millisecondsToSeconds
        radians_per_second_to_rotations_per_minute = radiansPerSecondToRotationsPerMinute
        radians_to_degrees = radiansToDegrees
        radians_to_rotations = radiansToRotations
        rotations_per_minute_to_radians_per_second = rotationsPerMinuteToRadiansPerSecond
        rotations_to_degrees = rotationsToDegrees
        rotations_to_radians = rotationsToRadians
        seconds_to_milliseconds = secondsToMilliseconds
