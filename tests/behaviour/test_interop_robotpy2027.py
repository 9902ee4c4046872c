"""drivekin.interop with robotpy-wpimath 2027 installed: every class in ``wpimath`` itself,
WPILib 2027's class names, snake_case members. Exact round trips both ways for every
catalogued peer, fromWpimath3d, sequences, refusals and error hints, on the stand-ins of
``tests/behaviour/robotpy2027.py``, which are checked against robotpy 2027's names table
(``tests/data/robotpy2027-names.json``), as is everything interop reads on them; and
robotpy 2026 converting again once 2027 is gone (its own tests: ``test_interop.py``)."""
from __future__ import annotations

import contextlib
import inspect
import json
import math
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from drivekin import (
    ChassisVelocities,
    DCMotor,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModuleVelocity,
    Transform2d,
    Translation2d,
)
from drivekin import interop
from drivekin._core import catalog
from drivekin.interop import fromWpimath, fromWpimath3d, toWpimath
from tests.behaviour import robotpy2027 as R27
from tests.behaviour.test_interop import (
    PAIRS,
    angle_values,
    anything,
    bits,
    dk_fields,
    dk_strategy,
    position,
    vectors,
)

TABLE = json.loads((Path(__file__).resolve().parents[1] / "data"
                    / "robotpy2027-names.json").read_text())["classes"]
FAKE = R27.package()


def table_names(name: str) -> set[str]:
    """Every public name robotpy 2027's class ``name`` has."""
    return set(TABLE[name]["methods"]) | set(TABLE[name]["properties"])


@contextlib.contextmanager
def robotpy_2027(package=FAKE):
    """robotpy-wpimath 2027 (the stand-ins) installed as ``wpimath``; interop finds it anew,
    and finds whatever was installed before again afterwards."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setitem(sys.modules, "wpimath", package)
        mp.setattr(interop, "_wpimath", None)
        yield package


@pytest.fixture
def wp27():
    with robotpy_2027() as package:
        yield package


# The fixture only swaps modules: it holds for every example of a test.
over_examples = settings(suppress_health_check=[HealthCheck.function_scoped_fixture])


# ---- the stand-ins are robotpy 2027's names --------------------------------------------------

@pytest.mark.parametrize("cls", R27.CLASSES, ids=lambda c: c.__name__)
def test_stand_ins_have_robotpy_2027s_names_and_kinds(cls):
    name = cls.__name__
    entry = TABLE[name]
    assert cls.__module__ == "wpimath._wpimath" and cls.__qualname__ == name
    public = {n for n in dir(cls) if not n.startswith("_")}
    assert public <= table_names(name), sorted(public - table_names(name))
    for n in public:
        attr = inspect.getattr_static(cls, n)
        if isinstance(attr, property):
            assert n in entry["properties"], f"{name}.{n} is a method in robotpy 2027"
            assert (attr.fset is None) == (n in entry["readonlyProperties"]), f"{name}.{n}"
        else:
            assert n in entry["methods"], f"{name}.{n} is a property in robotpy 2027"
            assert isinstance(attr, staticmethod) == (n in entry["static"]), f"{name}.{n}"
    params = inspect.signature(cls.__init__).parameters
    if not any(p.kind is p.VAR_POSITIONAL for p in params.values()):
        keywords = [p for p in params if p != "self"]
        # The table lists the constructors semiwrap parses from the C++ header; the value
        # types' constructors are hand-written in the YAML with their fields as keywords.
        assert keywords in entry["init"] or (not entry["init"]
                                             and set(keywords) <= set(entry["properties"]))


def _robotpy_2027_classes(e: catalog.Entry) -> list[str]:
    """robotpy 2027's classes for a drivekin class, by the table (not by the catalog)."""
    return [n for n, c in TABLE.items() if c["drivekinName"] == e.cls.__name__]


@pytest.mark.parametrize("e", [e for e in catalog.ENTRIES if e.peer is not None],
                         ids=lambda e: e.cls.__name__)
def test_every_peer_has_its_robotpy_2027_class_and_a_stand_in(e):
    assert sorted(e.peer.names2027) == sorted(_robotpy_2027_classes(e))
    for new, old in zip(e.peer.names2027, e.peer.names):
        assert isinstance(getattr(FAKE, new), type)
        assert new == old or old not in TABLE      # "No 2026 names remain"


# ---- field pictures of robotpy 2027 objects (the same order as test_interop's) ------------

def rp_rot(r):
    return (bits(r.cos()), bits(r.sin()))


MOTOR = ("nominal_voltage", "stall_torque", "stall_current", "free_current", "free_speed")


def rp_fields(o):
    n = type(o).__name__
    if n == "Translation2d":
        return (bits(o.x), bits(o.y))
    if n == "Rotation2d":
        return rp_rot(o)
    if n in ("Pose2d", "Transform2d"):
        return (bits(o.x), bits(o.y), *rp_rot(o.rotation()))
    if n == "Twist2d":
        return (bits(o.dx), bits(o.dy), bits(o.dtheta))
    if n == "ChassisVelocities":
        return (bits(o.vx), bits(o.vy), bits(o.omega))
    if n == "SwerveModuleVelocity":
        return (bits(o.velocity), *rp_rot(o.angle))
    if n == "SwerveModulePosition":
        return (bits(o.distance), *rp_rot(o.angle))
    if n in ("MecanumDriveWheelVelocities", "MecanumDriveWheelPositions"):
        return tuple(bits(v) for v in (o.front_left, o.front_right, o.rear_left, o.rear_right))
    if n in ("DifferentialDriveWheelVelocities", "DifferentialDriveWheelPositions"):
        return (bits(o.left), bits(o.right))
    if n.startswith("SwerveDrive") and n.endswith("Kinematics"):
        return tuple(rp_fields(m) for m in o.get_modules())
    if n == "MecanumDriveKinematics":
        return tuple(rp_fields(m) for m in (o.get_front_left(), o.get_front_right(),
                                            o.get_rear_left(), o.get_rear_right()))
    if n == "DifferentialDriveKinematics":
        return (bits(o.trackwidth),)
    if n == "DCMotor":
        return tuple(bits(getattr(o, f)) for f in MOTOR)
    raise AssertionError(f"no picture for {type(o)}")


def rp_strategy(name):
    R = FAKE.Rotation2d
    r = st.one_of(angle_values.map(R), vectors.map(lambda v: R(*v)))

    def with_fields(cls, *names):
        def make(values):
            o = cls()
            for n, v in zip(names, values):
                setattr(o, n, v)
            return o
        return st.tuples(*[anything] * len(names)).map(make)

    modules = st.builds(FAKE.Translation2d, position, position)
    return {
        "Translation2d": st.builds(FAKE.Translation2d, anything, anything),
        "Rotation2d": r,
        "Pose2d": st.builds(FAKE.Pose2d, anything, anything, r),
        "Transform2d": st.builds(FAKE.Transform2d, anything, anything, r),
        "Twist2d": st.builds(FAKE.Twist2d, anything, anything, anything),
        "ChassisVelocities": st.builds(FAKE.ChassisVelocities, anything, anything, anything),
        "SwerveModuleVelocity": st.builds(FAKE.SwerveModuleVelocity, anything, r),
        "SwerveModulePosition": st.builds(FAKE.SwerveModulePosition, anything, r),
        "MecanumDriveWheelVelocities": st.builds(FAKE.MecanumDriveWheelVelocities,
                                                 *[anything] * 4),
        "MecanumDriveWheelPositions": st.builds(FAKE.MecanumDriveWheelPositions,
                                                *[anything] * 4),
        "DifferentialDriveWheelVelocities": st.builds(FAKE.DifferentialDriveWheelVelocities,
                                                      anything, anything),
        "DifferentialDriveWheelPositions": with_fields(FAKE.DifferentialDriveWheelPositions,
                                                       "left", "right"),
        "SwerveDriveKinematics": st.sampled_from([2, 3, 4, 6]).flatmap(
            lambda n: st.lists(modules, min_size=n, max_size=n).map(
                lambda m: getattr(FAKE, f"SwerveDrive{n}Kinematics")(*m))),
        "MecanumDriveKinematics": st.lists(modules, min_size=4, max_size=4).map(
            lambda m: FAKE.MecanumDriveKinematics(*m)),
        "DifferentialDriveKinematics": st.floats(5e-324, 1.7976931348623157e308).map(
            FAKE.DifferentialDriveKinematics),
    }[name]


# ---- round trips ---------------------------------------------------------------------------

@pytest.mark.parametrize("name", sorted(PAIRS))
@over_examples
@given(data=st.data())
def test_drivekin_to_robotpy_2027_and_back_is_bit_exact(wp27, name, data):
    obj = data.draw(dk_strategy(name))
    w = toWpimath(obj)
    names = _robotpy_2027_classes(catalog.BY_CLASS[type(obj)])
    if type(obj) is SwerveDriveKinematics:
        names = [n for n in names if n == f"SwerveDrive{obj.getNumModules()}Kinematics"]
    assert [type(w)] == [getattr(wp27, n) for n in names]
    assert rp_fields(w) == dk_fields(obj)
    back = fromWpimath(w)
    assert type(back) is type(obj) and dk_fields(back) == dk_fields(obj)


@pytest.mark.parametrize("name", sorted(PAIRS))
@over_examples
@given(data=st.data())
def test_robotpy_2027_to_drivekin_and_back_is_bit_exact(wp27, name, data):
    obj = data.draw(rp_strategy(name))
    d = fromWpimath(obj)
    assert type(d).__name__ == name and type(d).__module__.startswith("drivekin.")
    assert dk_fields(d) == rp_fields(obj)
    back = toWpimath(d)
    assert type(back) is type(obj) and rp_fields(back) == rp_fields(obj)


def dk_motor(m):
    return tuple(bits(v) for v in (m.nominalVoltage, m.stallTorque, m.stallCurrent,
                                   m.freeCurrent, m.freeSpeed, m.R, m.Kv, m.Kt))


@pytest.mark.parametrize("motor", [DCMotor.getNEO(2), DCMotor.getRomiBuiltIn(3),
                                   DCMotor.getKrakenX60Foc(1).withReduction(6.75),
                                   DCMotor(12.0, 2.6, 105.0, 1.8, 594.4)])
def test_motors_round_trip_both_ways(wp27, motor):
    w = toWpimath(motor)
    assert type(w) is wp27.DCMotor and rp_fields(w) == dk_motor(motor)[:5]
    assert dk_motor(fromWpimath(w)) == dk_motor(motor)
    theirs = wp27.DCMotor(12.0, 3.6, 211.0, 3.615, 710.4, 3)    # a 3-motor gearbox
    assert rp_fields(toWpimath(fromWpimath(theirs))) == rp_fields(theirs)


def test_rotations_robotpy_2027_would_round_go_through_from_matrix(wp27):
    inexact = 0
    for i in range(2000):
        d = Rotation2d(0.001 * i - 1.0)
        inexact += rp_rot(wp27.Rotation2d(d.getCos(), d.getSin())) != dk_fields(d)
        assert rp_rot(toWpimath(d)) == dk_fields(d)
    assert inexact > 0  # the from_matrix path was exercised
    # A non-finite angle's NaN pair, which Rotation2d(x, y) would make (1, 0).
    nan = toWpimath(Rotation2d(math.inf))
    assert math.isnan(nan.cos()) and math.isnan(nan.sin())
    assert math.isnan(fromWpimath(nan).getCos())


def test_sequences_keep_their_kind(wp27):
    items = [Pose2d(1.0, 2.0, Rotation2d(0.5)), SwerveModuleVelocity(2.0, Rotation2d(1.0))]
    out = toWpimath(items)
    assert type(out) is list and [type(o) for o in out] == [wp27.Pose2d,
                                                            wp27.SwerveModuleVelocity]
    back = fromWpimath(tuple(out))
    assert type(back) is tuple and [dk_fields(o) for o in back] == [dk_fields(o) for o in items]


def test_from_wpimath_3d_takes_robotpy_2027s_projection(wp27):
    r3 = wp27.Rotation3d(0.1, 0.2, 2.5)
    p3 = wp27.Pose3d(1.5, -2.0, 0.7, r3)
    assert dk_fields(fromWpimath3d(p3)) == rp_fields(p3.to_pose2d())
    t = fromWpimath3d(wp27.Transform3d(wp27.Translation3d(0.5, 0.25, 9.0), r3))
    assert type(t) is Transform2d and dk_fields(t) == (
        bits(0.5), bits(0.25), *rp_rot(r3.to_rotation2d()))
    assert fromWpimath3d([wp27.Translation3d(1.0, 2.0, 3.0), r3]) == [
        Translation2d(1.0, 2.0), fromWpimath(r3.to_rotation2d())]
    with pytest.raises(TypeError, match="cannot convert wpimath._wpimath.Pose2d"):
        fromWpimath3d(wp27.Pose2d())


# ---- refusals and error messages -----------------------------------------------------------

def test_refusals_name_the_robotpy_2027_class(wp27):
    for obj, needle in [(wp27.DifferentialDriveOdometry(), "stateful"),
                        (wp27.ChassisAccelerations(1.0, 2.0, 3.0), "new in WPILib 2027")]:
        with pytest.raises(TypeError, match=rf"cannot convert wpimath\._wpimath\."
                                            rf"{type(obj).__name__}: .*{needle}"):
            fromWpimath(obj)
    with pytest.raises(TypeError, match="already a robotpy-wpimath object"):
        toWpimath(wp27.Pose2d())
    five = SwerveDriveKinematics([Translation2d(math.cos(i), math.sin(i)) for i in range(5)])
    with pytest.raises(ValueError, match="6Kinematics only.*5 modules"):
        toWpimath(five)


def test_a_robotpy_2027_object_passed_to_drivekin_gets_the_conversion(wp27):
    with pytest.raises(TypeError, match=r"got wpimath\._wpimath\.Pose2d \(a robotpy-wpimath "
                                        r"object: convert it with drivekin\.interop\."
                                        r"fromWpimath\(value\)\)"):
        Pose2d().relativeTo(wp27.Pose2d())
    with pytest.raises(TypeError, match=r"Pose3d \(a robotpy-wpimath 3-D object.*"
                                        r"fromWpimath3d"):
        Pose2d().relativeTo(wp27.Pose3d(0.0, 0.0, 0.0, wp27.Rotation3d()))


def test_the_2027_path_reads_only_names_in_the_table(wp27):
    # Everything interop reads on robotpy 2027's classes and objects, in both directions.
    R27.READS.clear()
    for cls, peer in interop._PEERS:
        fromWpimath(toWpimath(catalog.BY_CLASS[cls].example()))
    fromWpimath(toWpimath([Rotation2d(math.nan), Rotation2d(0.1)]))   # from_matrix, and not
    fromWpimath3d([wp27.Pose3d(1.0, 2.0, 3.0, wp27.Rotation3d(0.0, 0.0, 1.0)),
                   wp27.Transform3d(wp27.Translation3d(), wp27.Rotation3d()),
                   wp27.Translation3d(), wp27.Rotation3d()])
    reads = set(R27.READS)
    outside = sorted((c, a) for c, a in reads if a not in table_names(c))
    assert not outside, outside
    # The members whose spelling changed were read (so the recording saw the 2027 path).
    assert {("SwerveModuleVelocity", "velocity"), ("SwerveDrive4Kinematics", "get_modules"),
            ("MecanumDriveKinematics", "get_front_left"),
            ("MecanumDriveWheelVelocities", "front_left"),
            ("MecanumDriveWheelPositions", "rear_right"),
            ("DifferentialDriveKinematics", "trackwidth"), ("DCMotor", "nominal_voltage"),
            ("Rotation2d", "from_matrix"), ("Pose3d", "to_pose2d"),
            ("Translation3d", "to_translation2d"), ("Rotation3d", "to_rotation2d")} <= reads


# ---- the installed generation is found by names --------------------------------------------

def test_the_flat_2027_layout_is_found_and_2026_comes_back():
    with robotpy_2027() as package:
        assert interop._load().flat
        assert type(toWpimath(ChassisVelocities(1.0, 2.0, 3.0))) is package.ChassisVelocities
    k = pytest.importorskip("wpimath.kinematics")
    # robotpy 2026 again: its modules, its names.
    assert not interop._load().flat
    assert type(toWpimath(ChassisVelocities(1.0, 2.0, 3.0))) is k.ChassisSpeeds
    assert fromWpimath(k.SwerveModuleState(2.0)).velocity == 2.0


def test_a_class_the_installed_robotpy_lacks_is_an_import_error():
    partial = R27.package()
    del partial.DCMotor
    with robotpy_2027(partial):
        assert type(toWpimath(Pose2d())) is partial.Pose2d
        with pytest.raises(ImportError, match="robotpy-wpimath .* has no DCMotor"):
            toWpimath(DCMotor.getNEO(1))
