"""Bad input gives a clear ValueError/TypeError that says what was expected — never a
crash, a silent wrong answer, or a write into memory the caller did not offer.
"""
from __future__ import annotations

import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Transform2d,
    Translation2d,
    Twist2d,
)

T = Translation2d
MV = SwerveModuleVelocity
MP = SwerveModulePosition
desat = SwerveDriveKinematics.desaturateWheelVelocities
desat_in_place = SwerveDriveKinematics.desaturateWheelVelocitiesInPlace


def kin4():
    return SwerveDriveKinematics(T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.3))


CV = ChassisVelocities(1.0, 2.0, 3.0)


def raises(exc, *needles):
    """Context manager: ``exc`` whose message contains every needle (case-insensitive)."""
    pattern = "".join(f"(?=.*{re.escape(n)})" for n in needles)
    return pytest.raises(exc, match=re.compile(pattern, re.IGNORECASE | re.DOTALL))


def readonly(shape=(4, 2)):
    a = np.zeros(shape)
    a.flags.writeable = False
    return a


def misaligned(n=4):
    buf = np.zeros(n * 2 * 8 + 1, dtype=np.uint8)
    a = buf[1:].view(np.float64).reshape(n, 2)
    assert not a.flags.aligned
    return a


# ---------------------------------------------------------------------------------------
# Constructor


@pytest.mark.parametrize("args, needles", [
    ((), ("at least 2", "0")),
    ((T(1.0, 1.0),), ("at least 2", "1")),
    (([T(1.0, 1.0)],), ("at least 2", "1")),
    (([],), ("at least 2", "0")),
])
def test_kinematics_needs_two_modules(args, needles):
    with raises(ValueError, *needles):
        SwerveDriveKinematics(*args)


@pytest.mark.parametrize("args, index, got", [
    ((T(1.0, 1.0), (1.0, 2.0)), "1", "tuple"),
    ((1.0, 2.0), "0", "float"),
    ((T(1.0, 1.0), T(1.0, -1.0), None), "2", "NoneType"),
    (("ab",), "0", "str"),
    (([T(1.0, 1.0), T(1.0, -1.0)], T(2.0, 2.0)), "0", "list"),
])
def test_kinematics_rejects_non_translations(args, index, got):
    with raises(TypeError, "Translation2d", index, got):
        SwerveDriveKinematics(*args)


def test_kinematics_rejects_none_with_a_clear_message():
    # A lone None is neither a Translation2d nor a sequence of them; the message should
    # say what was expected rather than "'NoneType' object is not iterable".
    with raises(TypeError, "Translation2d"):
        SwerveDriveKinematics(None)


def test_kinematics_cannot_be_initialised_twice():
    k = kin4()
    with pytest.raises((RuntimeError, TypeError, ValueError)):
        k.__init__(T(0.0, 0.0), T(1.0, 1.0))
    assert len(k.getModules()) == 4


# ---------------------------------------------------------------------------------------
# Module counts


@pytest.mark.parametrize("call, needles", [
    (lambda k: k.toChassisVelocities([MV()] * 3), ("4", "3", "SwerveModuleVelocity")),
    (lambda k: k.toChassisVelocities(MV(), MV()), ("4", "2")),
    (lambda k: k.toChassisVelocities([MV()] * 5), ("4", "5")),
    (lambda k: k.toTwist2d([MP()] * 3), ("4", "3", "SwerveModulePosition")),
    (lambda k: k.toTwist2d([MP()] * 3, [MP()] * 3), ("4", "3")),
    (lambda k: k.toTwist2d([MP()] * 4, [MP()] * 3), ("inconsistent", "4", "3")),
    (lambda k: k.toTwist2d([MP()] * 3, [MP()] * 4), ("inconsistent", "3", "4")),
    (lambda k: k.resetHeadings([Rotation2d()] * 3), ("4", "3", "heading")),
    (lambda k: k.resetHeadings(Rotation2d()), ("4", "1")),
    (lambda k: k.toSwerveModuleVelocitiesInto(CV, [MV()] * 3), ("4", "3")),
    (lambda k: k.toSwerveModuleVelocitiesInto(CV, [MV()] * 5), ("4", "5")),
    (lambda k: k.toChassisVelocitiesInto([MV()] * 3, ChassisVelocities()), ("4", "3")),
    (lambda k: k.toTwist2dInto([MP()] * 5, Twist2d()), ("4", "5")),
    (lambda k: k.toChassisAccelerations([SwerveModuleAcceleration()] * 3), ("4", "3")),
    (lambda k: k.interpolate([MP()] * 4, [MP()] * 3, 0.5), ("inconsistent", "4", "3")),
    (lambda k: k.copyInto([MP()] * 4, [MP()] * 3), ("4", "3")),
])
def test_wrong_module_count(call, needles):
    k = kin4()
    with raises(ValueError, *needles):
        call(k)


def test_wrong_count_into_objects_does_not_write_partially():
    k = kin4()
    out = [MV(7.0) for _ in range(3)]
    with pytest.raises(ValueError):
        k.toSwerveModuleVelocitiesInto(CV, out)
    assert [o.velocity for o in out] == [7.0] * 3
    out = [MV(7.0), MV(7.0), MP(), MV(7.0)]
    with raises(TypeError, "out[2]", "SwerveModuleVelocity", "SwerveModulePosition"):
        k.toSwerveModuleVelocitiesInto(CV, out)
    assert [out[i].velocity for i in (0, 1, 3)] == [7.0] * 3


# ---------------------------------------------------------------------------------------
# Wrong element types


@pytest.mark.parametrize("call, needles", [
    (lambda k: k.toChassisVelocities([MP()] * 4), ("SwerveModuleVelocity", "SwerveModulePosition")),
    (lambda k: k.toChassisVelocities([1, 2, 3, 4]), ("SwerveModuleVelocity", "int")),
    (lambda k: k.toChassisVelocities(None), ("sequence", "NoneType")),
    (lambda k: k.toChassisVelocities(5), ("sequence", "int")),
    (lambda k: k.toTwist2d([MV()] * 4), ("SwerveModulePosition", "SwerveModuleVelocity")),
    (lambda k: k.resetHeadings([1.0] * 4), ("Rotation2d", "float")),
    (lambda k: k.resetHeadings(None), ("sequence", "NoneType")),
    (lambda k: k.toSwerveModuleVelocitiesInto(CV, [MP()] * 4), ("SwerveModuleVelocity",)),
    (lambda k: k.toSwerveModuleVelocitiesInto(CV, [[0.0, 0.0]] * 4), ("SwerveModuleVelocity",)),
    (lambda k: k.toSwerveModuleVelocitiesInto(CV, None), ("sequence", "NoneType")),
    (lambda k: k.toSwerveModuleVelocitiesInto(CV, 5), ("sequence", "int")),
    (lambda k: k.toSwerveModuleVelocitiesInto(None, [MV()] * 4), ("ChassisVelocities",)),
    (lambda k: k.toSwerveModuleVelocitiesInto(CV, [MV()] * 4, (0.0, 0.0)), ("Translation2d",)),
    (lambda k: k.toSwerveModuleVelocities(None), ("ChassisVelocities",)),
    (lambda k: k.toSwerveModuleVelocities((1.0, 2.0, 3.0)), ("ChassisVelocities", "tuple")),
    (lambda k: k.toSwerveModuleVelocities(ChassisAccelerations()), ("ChassisVelocities",)),
    (lambda k: k.toSwerveModuleVelocities(CV, None), ("Translation2d",)),
    (lambda k: k.toChassisVelocitiesInto([MV()] * 4, None), ("ChassisVelocities",)),
    (lambda k: k.toChassisVelocitiesInto([MV()] * 4, ChassisAccelerations()),
     ("ChassisVelocities",)),
    (lambda k: k.toTwist2dInto([MP()] * 4, ChassisVelocities()), ("Twist2d",)),
    (lambda k: k.toSwerveModuleAccelerations(None), ("ChassisAccelerations",)),
    (lambda k: k.toSwerveModuleAccelerations(CV), ("ChassisAccelerations",)),
])
def test_wrong_argument_types(call, needles):
    with raises(TypeError, *needles):
        call(kin4())


# ---------------------------------------------------------------------------------------
# ndarray arguments


ARRAY_METHODS = {
    "ik_into": lambda k, a: k.toSwerveModuleVelocitiesInto(CV, a),
    "fk_into": lambda k, a: k.toChassisVelocitiesInto(a, ChassisVelocities()),
    "twist_into": lambda k, a: k.toTwist2dInto(a, Twist2d()),
    "desat1": lambda k, a: desat_in_place(a, 1.0),
    "desat5": lambda k, a: desat_in_place(a, ChassisVelocities(1.0, 0.0, 0.0), 1.0, 1.0, 1.0),
}
WRITES = {"ik_into", "desat1", "desat5"}


@pytest.mark.parametrize("method", list(ARRAY_METHODS))
@pytest.mark.parametrize("make, exc, needles", [
    (lambda: np.zeros((3, 2)), ValueError, ("shape", "(4, 2)", "(3, 2)")),
    (lambda: np.zeros((4, 3)), ValueError, ("shape", "(4, 2)", "(4, 3)")),
    (lambda: np.zeros((4, 1)), ValueError, ("shape", "(4, 2)", "(4, 1)")),
    (lambda: np.zeros((4, 2), np.float32), TypeError, ("float64", "float32")),
    (lambda: np.zeros((4, 2), np.int64), TypeError, ("float64", "int64")),
    (lambda: np.zeros((4, 2), complex), TypeError, ("float64", "complex")),
    (lambda: np.zeros((4, 2), object), TypeError, ("float64", "object")),
    (lambda: np.zeros((4, 2), ">f8"), TypeError, ("float64", "byte order")),
    (lambda: np.zeros((8, 2))[::2], ValueError, ("contiguous",)),
    (lambda: np.zeros((4, 4))[:, ::2], ValueError, ("contiguous",)),
    (lambda: np.zeros((4, 2), order="F"), ValueError, ("contiguous",)),
    (lambda: np.zeros((2, 4)).T, ValueError, ("contiguous",)),
    (misaligned, ValueError, ("aligned",)),
], ids=["rows", "cols", "one-col", "float32", "int64", "complex", "object", "big-endian",
        "row-slice", "col-slice", "fortran", "transposed", "misaligned"])
def test_bad_arrays(method, make, exc, needles):
    a = make()
    before = np.array(a, copy=True)
    if method.startswith("desat") and a.shape == (3, 2) and a.flags.c_contiguous:
        # The static desaturation takes any number of modules: (3, 2) is valid there.
        ARRAY_METHODS[method](kin4(), a)
        return
    if method.startswith("desat"):
        # Any number of rows is fine there, so the expected shape is named "(N, 2)".
        needles = tuple("(N, 2)" if n == "(4, 2)" else n for n in needles)
    with raises(exc, *needles):
        ARRAY_METHODS[method](kin4(), a)
    assert np.array_equal(np.asarray(a), before, equal_nan=a.dtype.kind == "f")


@pytest.mark.parametrize("method", sorted(WRITES))
def test_read_only_output_array(method):
    a = readonly()
    with raises(ValueError, "writeable"):
        ARRAY_METHODS[method](kin4(), a)


@pytest.mark.parametrize("method", sorted(set(ARRAY_METHODS) - WRITES))
def test_read_only_input_array_is_fine(method):
    ARRAY_METHODS[method](kin4(), readonly())  # only read: no error


@pytest.mark.parametrize("shape", [(8,), (2, 2, 2), ()])
def test_in_place_desaturate_names_the_expected_shape(shape):
    """The in-place desaturation accepts any N, so the message should say (N, 2) — not
    report a made-up expected shape like (-1, 2)."""
    with raises(ValueError, "shape", "2)") as info:
        desat_in_place(np.zeros(shape), 1.0)
    assert "-1" not in str(info.value), str(info.value)


# ---------------------------------------------------------------------------------------
# Desaturation arguments


@pytest.mark.parametrize("args, exc, needles", [
    (("fast",), TypeError, ("real number", "str")),
    ((None,), TypeError, ("real number", "NoneType")),
    ((CV, 1.0), TypeError, ("three limits",)),
    ((CV, 1.0, 1.0), TypeError, ("three limits",)),
    ((1.0, 1.0, 1.0, 1.0), TypeError, ("ChassisVelocities", "float")),
    ((CV, "a", 1.0, 1.0), TypeError, ("real number", "str")),
])
@pytest.mark.parametrize("fn", [desat, desat_in_place], ids=["returning", "in_place"])
def test_desaturate_bad_arguments(fn, args, exc, needles):
    states = [MV(3.0), MV(-4.0)]
    with raises(exc, *needles):
        fn(states, *args)
    assert [s.velocity for s in states] == [3.0, -4.0]


@pytest.mark.parametrize("fn", [desat, desat_in_place], ids=["returning", "in_place"])
def test_desaturate_bad_states(fn):
    with raises(TypeError, "SwerveModuleVelocity", "SwerveModulePosition"):
        fn([MV(1.0), MP(1.0)], 0.5)
    with raises(TypeError, "sequence", "NoneType"):
        fn(None, 0.5)
    states = [MV(3.0), MV(-4.0), "x"]
    with raises(TypeError, "module_velocities[2]", "str"):
        fn(states, 1.0)
    assert [s.velocity for s in states[:2]] == [3.0, -4.0], "no partial update"


# ---------------------------------------------------------------------------------------
# Scalars and value constructors


@pytest.mark.parametrize("call", [
    lambda: ChassisVelocities("a"),
    lambda: ChassisVelocities(None),
    lambda: ChassisVelocities(1.0, omega="x"),
    lambda: ChassisAccelerations(alpha=None),
    lambda: CV.discretize("x"),
    lambda: CV.discretize(None),
    lambda: CV.toTwist2d("x"),
    lambda: CV.times("x"),
    lambda: MV("a"),
    lambda: MP(None),
    lambda: Translation2d("a", 1.0),
    lambda: Translation2d(1.0, "b"),
    lambda: Translation2d(None, 1.0),
    lambda: Rotation2d("a"),
    lambda: Rotation2d(None),
    lambda: Rotation2d(1.0, "b"),
    lambda: Twist2d("a"),
    lambda: Pose2d("a", 2.0, Rotation2d()),
    lambda: Rotation2d(1.0).times(None),
    lambda: Translation2d(1.0, 2.0).div("2"),
])
def test_non_numbers_raise_type_error(call):
    with pytest.raises(TypeError, match=re.compile("real number|float|Rotation2d", re.I)):
        call()


@pytest.mark.parametrize("call, needles", [
    (lambda: Pose2d(1.0, 2.0, "3"), ("Rotation2d",)),
    (lambda: Pose2d(1.0, 2.0), ("Rotation2d", "missing")),
    (lambda: Transform2d(1.0), ("Rotation2d",)),
    (lambda: Pose2d().transformBy(Pose2d()), ("Transform2d", "Pose2d")),
    (lambda: Pose2d().relativeTo(None), ("Pose2d", "NoneType")),
    (lambda: Pose2d().exp(None), ("Twist2d",)),
    (lambda: MV(1.0, "2"), ("Rotation2d", "str")),
    (lambda: MV(1.0).optimize(None), ("Rotation2d",)),
    (lambda: MV(1.0).optimize(1.0), ("Rotation2d", "float")),
    (lambda: MV(1.0).cosineScale(1.0), ("Rotation2d",)),
    (lambda: CV.toRobotRelative(1.0), ("Rotation2d", "float")),
    (lambda: CV.toFieldRelative(None), ("Rotation2d",)),
    (lambda: CV.discretizeInto(0.02, None), ("ChassisVelocities",)),
    (lambda: CV.discretizeInto(0.02, ChassisAccelerations()), ("ChassisVelocities",)),
    (lambda: CV.toRobotRelativeInto(Rotation2d(), ChassisAccelerations()),
     ("ChassisVelocities", "ChassisAccelerations")),
    (lambda: CV.toFieldRelativeInto(Rotation2d(), ChassisAccelerations()),
     ("ChassisVelocities", "ChassisAccelerations")),
    (lambda: CV.toFieldRelativeInto(Rotation2d(), None), ("out",)),
    (lambda: CV.interpolate(ChassisAccelerations(), 0.5), ("ChassisVelocities",)),
])
def test_wrong_object_types(call, needles):
    with raises(TypeError, *needles):
        call()


def test_into_methods_leave_out_untouched_on_error():
    out = ChassisVelocities(7.0, 8.0, 9.0)
    with pytest.raises(TypeError):
        kin4().toChassisVelocitiesInto([MV()] * 3 + [MP()], out)
    with pytest.raises(ValueError):
        kin4().toChassisVelocitiesInto(np.zeros((3, 2)), out)
    assert (out.vx, out.vy, out.omega) == (7.0, 8.0, 9.0)
    tw = Twist2d(1.0, 2.0, 3.0)
    with pytest.raises(TypeError):
        kin4().toTwist2dInto(np.zeros((4, 2), np.float32), tw)
    assert (tw.dx, tw.dy, tw.dtheta) == (1.0, 2.0, 3.0)


# ---------------------------------------------------------------------------------------
# Never a crash: misuse that could reach uninitialised C memory runs in a subprocess, so
# a segfault shows up as a failed test instead of killing the session.


def test_misuse_does_not_crash_the_interpreter():
    code = textwrap.dedent("""
        import numpy as np
        from drivekin import *
        cv = ChassisVelocities(1.0, 2.0, 3.0)
        k = SwerveDriveKinematics.__new__(SwerveDriveKinematics)   # __init__ skipped
        calls = [
            lambda: k.toSwerveModuleVelocities(cv),
            lambda: k.toSwerveModuleVelocitiesInto(cv, np.zeros((4, 2))),
            lambda: k.toChassisVelocities([SwerveModuleVelocity()] * 4),
            lambda: k.toTwist2d([SwerveModulePosition()] * 4),
            lambda: k.resetHeadings([Rotation2d()] * 4),
            lambda: k.toSwerveModuleAccelerations(ChassisAccelerations(1.0, 2.0, 3.0), 2.0),
            lambda: k.getModules(),
            lambda: repr(k),
            lambda: SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(np.zeros((0, 2)), 1.0),
            lambda: SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(np.zeros(()), 1.0),
            lambda: SwerveDriveKinematics.desaturateWheelVelocities([], 1.0),
        ]
        for c in calls:
            try:
                c()
            except Exception:
                pass
        print("survived")
    """)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0 and "survived" in r.stdout, (r.returncode, r.stderr[-2000:])


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_non_finite_module_positions_are_rejected(bad):
    # A non-finite layout has no pseudo-inverse; say so instead of failing inside numpy.
    from drivekin import MecanumDriveKinematics, SwerveDriveKinematics, Translation2d
    with raises(ValueError, "finite"):
        SwerveDriveKinematics(Translation2d(0.3, bad), Translation2d(-0.3, 0.3))
    with raises(ValueError, "finite"):
        MecanumDriveKinematics(Translation2d(bad, 0.3), Translation2d(0.3, -0.3),
                               Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))


# ---- the setpoint generator's values (issue 27) -------------------------------------

@pytest.mark.parametrize("make, given", [
    (lambda: (x for x in [1.0]), "generator"), (lambda: {1.0}, "set"),
    (lambda: iter([1.0]), "list_iterator"), (lambda: 1.0, "float"), (lambda: None, "NoneType"),
])
def test_drive_feedforwards_names_what_it_takes_and_what_it_got(make, given):
    from drivekin import DriveFeedforwards
    with pytest.raises(TypeError) as e:
        DriveFeedforwards(make(), [1.0], [1.0], [1.0], [1.0])
    message = str(e.value)
    assert message.startswith("accelerationsMPSSq must be a list or tuple of floats (one per "
                              "module) or a 1-D float64 array, got " + given)
    assert "0 floats" not in message


@pytest.mark.parametrize("ratio, grown", [(1e-320, "free speed inf"), (1e-310, "free speed inf"),
                                          (1e308, "stall torque inf")])
def test_with_reduction_blames_the_ratio(ratio, grown):
    from drivekin import DCMotor
    expected = re.escape(f"gearbox_reduction {ratio!r} is out of range")
    with pytest.raises(ValueError, match=expected) as e:
        DCMotor.getKrakenX60(1).withReduction(ratio)
    assert grown in str(e.value) and "must be positive and finite" in str(e.value)
