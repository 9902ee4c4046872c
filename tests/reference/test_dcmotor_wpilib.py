"""DCMotor against WPILib 2027 Java's constants and robotpy-wpimath 2026's DCMotor.

Every factory (robotpy 2026's name for each beside it), every method and withReduction
agree with robotpy-wpimath to 1e-12 relative (of the terms' magnitude, where a difference
cancels); the constants come out bit for bit. One difference is WPILib's own: Java's
getNeoVortex has a free current of 3.6 A, C++ (and so robotpy) 3.615 A; drivekin follows
Java, and that factory is compared with robotpy's constructor given Java's numbers.
"""
from __future__ import annotations

import math
import pickle

import pytest
from hypothesis import given
from hypothesis import strategies as st

from drivekin import DCMotor

plant = pytest.importorskip("wpimath.system.plant")
W = plant.DCMotor

# drivekin (WPILib 2027 Java) name -> robotpy-wpimath 2026 name, and Java's constants.
FACTORIES = {
    "getCIM": ("CIM", (12, 2.42, 133, 2.7, 5310)),
    "getVex775Pro": ("vex775Pro", (12, 0.71, 134, 0.7, 18730)),
    "getNEO": ("NEO", (12, 2.6, 105, 1.8, 5676)),
    "getMiniCIM": ("miniCIM", (12, 1.41, 89, 3, 5840)),
    "getBag": ("bag", (12, 0.43, 53, 1.8, 13180)),
    "getAndymarkRs775_125": ("RS775_125", (12, 0.28, 18, 1.6, 5800)),
    "getBanebotsRs775": ("banebotsRS775", (12, 0.72, 97, 2.7, 13050)),
    "getAndymark9015": ("andymark9015", (12, 0.36, 71, 3.7, 14270)),
    "getBanebotsRs550": ("banebotsRS550", (12, 0.38, 84, 0.4, 19000)),
    "getNeo550": ("NEO550", (12, 0.97, 100, 1.4, 11000)),
    "getFalcon500": ("falcon500", (12, 4.69, 257, 1.5, 6380)),
    "getFalcon500Foc": ("falcon500FOC", (12, 5.84, 304, 1.5, 6080)),
    "getRomiBuiltIn": ("romiBuiltIn", (4.5, 0.1765, 1.25, 0.13, 150)),
    "getKrakenX60": ("krakenX60", (12, 7.09, 366, 2, 6000)),
    "getKrakenX60Foc": ("krakenX60FOC", (12, 9.37, 483, 2, 5800)),
    "getKrakenX44": ("krakenX44", (12, 4.11, 279, 2, 7758)),
    "getKrakenX44Foc": ("krakenX44FOC", (12, 5.01, 329, 2, 7368)),
    "getMinion": ("minion", (12, 3.17, 211, 2, 7704)),
    "getNeoVortex": ("neoVortex", (12, 3.60, 211, 3.6, 6784)),
}
FIELDS = ("nominalVoltage", "stallTorque", "stallCurrent", "freeCurrent", "freeSpeed",
          "R", "Kv", "Kt")
REL = 1e-12


def rpm(x):
    return x * math.pi / 30.0


def oracle(name, n):
    """robotpy's motor with Java's constants (Java and C++ differ for the NEO Vortex)."""
    if name == "getNeoVortex":
        v, ts, cs, fc, r = FACTORIES[name][1]
        return W(v, ts, cs, fc, rpm(r), n)
    return getattr(W, FACTORIES[name][0])(n)


def close(a, b, scale=0.0):
    assert math.isclose(a, b, rel_tol=REL, abs_tol=REL * scale), (a, b)


def same_constants(d, w):
    for f in FIELDS:
        close(getattr(d, f), getattr(w, f))


@pytest.mark.parametrize("name", sorted(FACTORIES))
@pytest.mark.parametrize("n", [1, 2, 3, 4, 8])
def test_factory_matches_robotpy(name, n):
    d = getattr(DCMotor, name)(n)
    same_constants(d, oracle(name, n))
    v, ts, cs, fc, r = FACTORIES[name][1]
    assert d == DCMotor(v, ts, cs, fc, rpm(r), n)        # Java's numbers, Java's rpm
    assert getattr(DCMotor, name)() == getattr(DCMotor, name)(1)


def test_every_java_factory_is_here():
    assert {n for n in dir(DCMotor) if n.startswith("get") and n not in
            ("getCurrent", "getTorque", "getVoltage", "getVelocity")} == set(FACTORIES)


def test_the_neo_vortex_follows_java():
    assert DCMotor.getNeoVortex().freeCurrent == 3.6
    assert W.neoVortex().freeCurrent == 3.615          # robotpy-wpimath 2026 (C++)


def test_constructor_fields():
    m = DCMotor(12.0, 2.6, 105.0, 1.8, 594.0, 3)
    assert (m.nominalVoltage, m.stallTorque, m.stallCurrent, m.freeCurrent, m.freeSpeed) \
        == (12.0, 2.6 * 3, 105.0 * 3, 1.8 * 3, 594.0)
    assert m.R == 12.0 / (105.0 * 3)
    assert m.Kv == 594.0 / (12.0 - m.R * (1.8 * 3))
    assert m.Kt == (2.6 * 3) / (105.0 * 3)
    same_constants(m, W(12.0, 2.6, 105.0, 1.8, 594.0, 3))
    assert DCMotor(nominal_voltage=12.0, stall_torque=2.6, stall_current=105.0,
                   free_current=1.8, free_speed=594.0, num_motors=3) == m


motors = st.builds(lambda name, n: (name, n), st.sampled_from(sorted(FACTORIES)),
                   st.integers(1, 12))
speeds = st.floats(-2000.0, 2000.0)
volts = st.floats(-16.0, 16.0)
torques = st.floats(-50.0, 50.0)
currents = st.floats(-600.0, 600.0)
reductions = st.floats(0.01, 500.0)


@given(motors, speeds, volts)
def test_current_from_velocity_and_voltage(m, w, u):
    d, o = getattr(DCMotor, m[0])(m[1]), oracle(*m)
    close(d.getCurrent(w, u), o.current(w, u), abs(w / d.Kv / d.R) + abs(u / d.R))
    close(d.getCurrent(velocity=w, input_voltage=u), o.current(w, u),
          abs(w / d.Kv / d.R) + abs(u / d.R))


@given(motors, torques)
def test_current_from_torque(m, t):
    d, o = getattr(DCMotor, m[0])(m[1]), oracle(*m)
    close(d.getCurrent(t), o.current(t))
    assert d.getCurrent(torque=t) == d.getCurrent(t)


@given(motors, currents)
def test_torque(m, i):
    close(getattr(DCMotor, m[0])(m[1]).getTorque(i), oracle(*m).torque(i))


@given(motors, torques, speeds)
def test_voltage(m, t, w):
    d = getattr(DCMotor, m[0])(m[1])
    close(d.getVoltage(t, w), oracle(*m).voltage(t, w), abs(w / d.Kv) + abs(d.R * t / d.Kt))


@given(motors, torques, volts)
def test_velocity(m, t, u):
    d = getattr(DCMotor, m[0])(m[1])
    close(d.getVelocity(t, u), oracle(*m).speed(t, u),
          abs(u * d.Kv) + abs(t * d.R * d.Kv / d.Kt))


@given(motors, reductions, torques, volts)
def test_with_reduction(m, g, t, u):
    d, o = getattr(DCMotor, m[0])(m[1]).withReduction(g), oracle(*m).withReduction(g)
    same_constants(d, o)
    close(d.getVelocity(t, u), o.speed(t, u), abs(u * d.Kv) + abs(t * d.R * d.Kv / d.Kt))
    base = getattr(DCMotor, m[0])(m[1])
    assert d.stallCurrent == base.stallCurrent and d.freeCurrent == base.freeCurrent
    assert d.stallTorque == base.stallTorque * g and d.freeSpeed == base.freeSpeed / g


@given(motors, reductions)
def test_pickle_round_trip(m, g):
    for d in (getattr(DCMotor, m[0])(m[1]), getattr(DCMotor, m[0])(m[1]).withReduction(g)):
        again = pickle.loads(pickle.dumps(d))
        assert type(again) is DCMotor and again == d
        assert all(getattr(again, f) == getattr(d, f) for f in FIELDS)


def test_repr_rebuilds_the_motor():
    d = DCMotor.getKrakenX60(2).withReduction(6.75)
    assert repr(d).startswith("DCMotor(nominal_voltage=12.0, stall_torque=")
    assert eval(repr(d), {"DCMotor": DCMotor}) == d


def test_equality_and_hashing():
    assert DCMotor.getNEO(2) == DCMotor.getNEO(2)
    assert DCMotor.getNEO(2) != DCMotor.getNEO(1)
    assert DCMotor.getNEO() != DCMotor.getNeo550()
    assert DCMotor.getNEO() != "NEO"
    with pytest.raises(TypeError):
        hash(DCMotor.getNEO())


def test_immutable():
    d = DCMotor.getNEO()
    with pytest.raises(AttributeError):
        d.Kv = 1.0
    with pytest.raises(TypeError, match="immutable"):
        d.__init__(12.0, 1.0, 10.0, 1.0, 100.0)
    with pytest.raises(RuntimeError, match="has not completed"):
        DCMotor.__new__(DCMotor).getTorque(1.0)


@pytest.mark.parametrize("args, name", [
    ((0.0, 2.6, 105.0, 1.8, 594.0), "nominal_voltage"),
    ((-12.0, 2.6, 105.0, 1.8, 594.0), "nominal_voltage"),
    ((math.nan, 2.6, 105.0, 1.8, 594.0), "nominal_voltage"),
    ((12.0, 0.0, 105.0, 1.8, 594.0), "stall_torque"),
    ((12.0, math.inf, 105.0, 1.8, 594.0), "stall_torque"),
    ((12.0, 2.6, 0.0, 0.0, 594.0), "stall_current"),
    ((12.0, 2.6, 105.0, -1.0, 594.0), "free_current"),
    ((12.0, 2.6, 105.0, 105.0, 594.0), "free_current"),
    ((12.0, 2.6, 105.0, math.nan, 594.0), "free_current"),
    ((12.0, 2.6, 105.0, 1.8, 0.0), "free_speed"),
    ((12.0, 2.6, 105.0, 1.8, -math.inf), "free_speed"),
    ((12.0, 2.6, 105.0, 1.8, 594.0, 0), "num_motors"),
    ((12.0, 2.6, 105.0, 1.8, 594.0, -2), "num_motors"),
    ((12.0, 2.6, 105.0, 1.8, 594.0, 2**31), "num_motors"),
    ((12.0, 1e308, 105.0, 1.8, 594.0, 10), "num_motors"),
])
def test_bad_constants_are_value_errors(args, name):
    with pytest.raises(ValueError, match=name):
        DCMotor(*args)


@pytest.mark.parametrize("n", [0, -1, 2**31])
def test_bad_motor_counts_in_factories(n):
    with pytest.raises(ValueError, match="num_motors"):
        DCMotor.getCIM(n)


@pytest.mark.parametrize("n, got", [(2.0, "float"), (True, "bool"), ("2", "str"),
                                    (None, "NoneType")])
def test_motor_count_must_be_an_int(n, got):
    with pytest.raises(TypeError, match=f"num_motors must be an int, got {got}"):
        DCMotor.getNEO(n)
    with pytest.raises(TypeError, match=f"num_motors must be an int, got {got}"):
        DCMotor(12.0, 2.6, 105.0, 1.8, 594.0, n)


@pytest.mark.parametrize("g", [0.0, -2.0, math.nan, math.inf])
def test_bad_reduction(g):
    with pytest.raises(ValueError, match="gearbox_reduction"):
        DCMotor.getNEO().withReduction(g)


def test_wrong_types_name_the_type():
    d = DCMotor.getNEO()
    with pytest.raises(TypeError, match="str"):
        DCMotor("12", 2.6, 105.0, 1.8, 594.0)
    with pytest.raises(TypeError, match="NoneType"):
        d.getTorque(None)
    with pytest.raises(TypeError, match="str"):
        d.getCurrent("1")
    with pytest.raises(TypeError, match="str"):
        d.getCurrent(1.0, "1")


@pytest.mark.parametrize("args, kw", [((), {}), ((1.0,), {"torque": 2.0}),
                                      ((), {"velocity": 1.0}), ((1.0,), {"velocity": 1.0}),
                                      ((1.0, 2.0, 3.0), {}),
                                      ((1.0, 2.0), {"torque": 2.0}),
                                      ((), {"input_voltage": 1.0, "torque": 2.0})])
def test_get_current_takes_one_of_its_two_forms(args, kw):
    with pytest.raises(TypeError, match=r"getCurrent\(\) takes"):
        DCMotor.getNEO().getCurrent(*args, **kw)


def test_robotpy_names_point_to_2027():
    with pytest.raises(AttributeError, match="getVelocity"):
        DCMotor.getNEO().speed  # noqa: B018
    with pytest.raises(AttributeError, match="getFalcon500Foc"):
        DCMotor.falcon500FOC  # noqa: B018
