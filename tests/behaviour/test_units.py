"""drivekin.Units against WPILib 2027's Units.java (its constants and order of operations)
and against robotpy-wpimath 2026's ``wpimath.units``."""
from __future__ import annotations

import math
import struct
import sys

import numpy as np
import pytest
from hypothesis import example, given, strategies as st

import drivekin
from drivekin import Units
from drivekin._core import pynames

# Units.java (org.wpilib.math.util), restated operation by operation with its constants:
# INCHES_PER_FOOT 12, METERS_PER_INCH 0.0254, METERS_PER_MILE 1609.344,
# SECONDS_PER_MINUTE 60, MINUTES_PER_HOUR 60, MILLISECONDS_PER_SECOND 1000,
# KILOGRAMS_PER_LB 0.453592; Math.toRadians/toDegrees multiply by 0.017453292519943295 and
# 57.29577951308232 (JDK 9+).
JAVA = {
    "metersToFeet": lambda m: (m / 0.0254) / 12.0,
    "feetToMeters": lambda ft: (ft * 12.0) * 0.0254,
    "metersToInches": lambda m: m / 0.0254,
    "inchesToMeters": lambda i: i * 0.0254,
    "degreesToRadians": lambda d: d * 0.017453292519943295,
    "radiansToDegrees": lambda r: r * 57.29577951308232,
    "radiansToRotations": lambda r: r / (math.pi * 2),
    "degreesToRotations": lambda d: d / 360.0,
    "rotationsToDegrees": lambda r: r * 360.0,
    "rotationsToRadians": lambda r: r * 2.0 * math.pi,
    "rotationsPerMinuteToRadiansPerSecond": lambda rpm: rpm * math.pi / (60.0 / 2.0),
    "radiansPerSecondToRotationsPerMinute": lambda w: w * (60.0 / 2.0) / math.pi,
    "milesPerHourToMetersPerSecond": lambda mph: mph * 1609.344 / (60.0 * 60.0),
    "metersPerSecondToMilesPerHour": lambda v: v / 1609.344 * (60.0 * 60.0),
    "millisecondsToSeconds": lambda ms: ms / 1000.0,
    "secondsToMilliseconds": lambda s: s * 1000.0,
    "kilogramsToLbs": lambda kg: kg / 0.453592,
    "lbsToKilograms": lambda lb: lb * 0.453592,
}
# robotpy-wpimath 2026 computes this one as (rpm / 60) * tau: up to 2 ulp from Java's
# (rpm * pi) / 30 (each has three roundings, pi included; measured maximum: 2 ulp).
ROBOTPY_ORDER_DIFFERS = {"rotationsPerMinuteToRadiansPerSecond": 2}
NOT_IN_ROBOTPY = {"milesPerHourToMetersPerSecond", "metersPerSecondToMilesPerHour"}


def bits(x: float) -> bytes:
    return struct.pack("<d", x)


def static_methods() -> set[str]:
    # robotpy 2027's spellings (inches_to_meters) are these same functions: not counted.
    return {n for n, f in vars(Units).items() if isinstance(f, staticmethod)
            and not n.startswith("_") and n not in pynames.spellings(Units)}


def test_exactly_the_java_methods():
    assert static_methods() == set(JAVA)
    assert {n for n in dir(Units) if not n.startswith("_")
            and n not in pynames.spellings(Units)} == set(JAVA)
    for py, java in pynames.spellings(Units).items():
        assert vars(Units)[py] is vars(Units)[java]


def test_exported_from_drivekin():
    assert drivekin.Units is Units and "Units" in drivekin.__all__


def test_javas_private_constants_give_these_values():
    assert math.pi / 180.0 == 0.017453292519943295 and 180.0 / math.pi == 57.29577951308232
    assert Units.inchesToMeters(1.0) == 0.0254
    assert Units.feetToMeters(1.0) == 12.0 * 0.0254 == 0.30479999999999996  # via inches
    assert Units.metersToInches(0.0254) == 1.0
    assert Units.lbsToKilograms(1.0) == 0.453592
    assert Units.milesPerHourToMetersPerSecond(1.0) == 0.44704
    assert Units.metersPerSecondToMilesPerHour(0.44704) == 1.0
    assert Units.degreesToRadians(180.0) == math.pi
    assert Units.radiansToDegrees(math.pi) == 180.0
    assert Units.rotationsToRadians(1.0) == 2 * math.pi
    assert Units.radiansToRotations(2 * math.pi) == 1.0
    assert Units.rotationsToDegrees(0.25) == 90.0 and Units.degreesToRotations(90.0) == 0.25
    # Java's order of operations: 60 rpm is one ulp below 2π (robotpy gives 2π).
    assert Units.rotationsPerMinuteToRadiansPerSecond(60.0) == 6.283185307179585
    assert Units.radiansPerSecondToRotationsPerMinute(math.pi) == 29.999999999999996  # (π·30)/π
    assert Units.millisecondsToSeconds(20.0) == 0.02 and Units.secondsToMilliseconds(0.02) == 20.0


any_float = st.floats(allow_nan=True, allow_infinity=True)


@pytest.mark.parametrize("name", sorted(JAVA))
@given(x=any_float)
@example(x=-0.0)
@example(x=5e-324)
@example(x=1.7976931348623157e308)
def test_bit_exact_against_the_java_formula(name, x):
    got = getattr(Units, name)(x)
    assert type(got) is float
    assert bits(got) == bits(JAVA[name](x)) or (math.isnan(got) and math.isnan(JAVA[name](x)))


@pytest.mark.parametrize("name", sorted(set(JAVA) - NOT_IN_ROBOTPY))
@given(x=st.floats(allow_nan=False, allow_infinity=True))
def test_against_robotpy(name, x):
    units = pytest.importorskip("wpimath.units")
    got, theirs = getattr(Units, name)(x), getattr(units, name)(x)
    if name in ROBOTPY_ORDER_DIFFERS and 0.0 < abs(x) / 60.0 < sys.float_info.min:
        # robotpy's rpm / 60 is subnormal: its error is absolute, up to ½·2⁻¹⁰⁷⁴, and τ
        # scales it to π·2⁻¹⁰⁷⁴; both final roundings add up to one ulp of the result.
        assert abs(got - theirs) <= 4 * 5e-324 + math.ulp(got)
    elif name in ROBOTPY_ORDER_DIFFERS and math.isfinite(got):
        assert abs(got - theirs) <= ROBOTPY_ORDER_DIFFERS[name] * math.ulp(got)
    elif name in ROBOTPY_ORDER_DIFFERS and math.isfinite(theirs):
        assert math.isinf(x * math.pi)  # Java's rpm·π overflows first, robotpy's rpm/60 not
    else:
        assert bits(got) == bits(theirs)


def test_robotpy_lacks_exactly_the_miles_per_hour_pair():
    units = pytest.importorskip("wpimath.units")
    assert {n for n in JAVA if not hasattr(units, n)} == NOT_IN_ROBOTPY


@given(rpm=st.floats(min_value=-1e6, max_value=1e6, allow_subnormal=False))
def test_rpm_conversion_is_faithful(rpm):
    # Java's (rpm·π)/30 and robotpy's (rpm/60)·τ may differ; Java's stays within 1.5 ulp
    # of the exact rpm·π/30 (π itself carries 0.5 ulp, then two roundings).
    mpmath = pytest.importorskip("mpmath")
    with mpmath.workdps(50):
        exact = mpmath.mpf(rpm) * mpmath.pi / 30
        got = Units.rotationsPerMinuteToRadiansPerSecond(rpm)
        if rpm != 0.0:
            assert abs(mpmath.mpf(got) - exact) <= 1.5 * math.ulp(got)


@pytest.mark.parametrize("value", [3, True, np.float64(2.5), np.float32(0.5), np.int64(7)])
def test_numbers_with_float_or_index_are_accepted(value):
    assert Units.inchesToMeters(value) == float(value) * 0.0254


@pytest.mark.parametrize("value", ["1.0", b"1.0", None, 1j, [1.0], (1.0,),
                                   drivekin.Translation2d(1.0, 2.0), object()])
def test_non_numbers_are_refused(value):
    with pytest.raises(TypeError, match=r"Units\.inchesToMeters\(\) takes a number"):
        Units.inchesToMeters(value)


def test_a_raising_float_propagates():
    class Bad:
        def __float__(self):
            raise ZeroDivisionError("boom")
    with pytest.raises(ZeroDivisionError):
        Units.secondsToMilliseconds(Bad())


def test_not_instantiable_like_the_java_class():
    with pytest.raises(TypeError, match="utility class"):
        Units()
    with pytest.raises(TypeError, match="utility class"):
        Units.__new__(Units)
