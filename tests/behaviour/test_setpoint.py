"""Behaviour of drivekin.setpoint beyond PathPlannerLib's numbers (those are in
tests/reference/test_setpoint_pathplanner.py, the limits in
tests/properties/test_setpoint_limits.py): value semantics, PathPlanner's settings.json,
bad input that changes nothing, and the allocation-free and batch forms giving the
per-call façade's bits."""
from __future__ import annotations

import copy
import json
import math
import pickle

import numpy as np
import pytest

import drivekin.batch as batch
from drivekin import (
    ChassisVelocities,
    DCMotor,
    DriveFeedforwards,
    ModuleConfig,
    PathConstraints,
    RobotConfig,
    Rotation2d,
    SwerveModuleVelocity,
    SwerveSetpoint,
    SwerveSetpointGenerator,
    Translation2d,
)

MOTOR = DCMotor.getKrakenX60(1).withReduction(6.75)


def _config(n=4, radius=0.3):
    module = ModuleConfig(0.0508, 4.5, 1.2, MOTOR, 60.0, 1)
    offsets = [Translation2d(radius * math.cos(2 * math.pi * i / n + 0.3),
                             radius * math.sin(2 * math.pi * i / n + 0.3)) for i in range(n)]
    return RobotConfig(55.0, 5.5, module, offsets)


def _zeros(n=4):
    return SwerveSetpoint(ChassisVelocities(), [SwerveModuleVelocity() for _ in range(n)],
                          DriveFeedforwards.zeros(n))


def _state(sp):
    v = sp.robotRelativeVelocities
    ff = sp.feedforwards
    return ((v.vx, v.vy, v.omega),
            tuple((m.velocity, m.angle.getCos(), m.angle.getSin()) for m in sp.moduleVelocities),
            (ff.accelerationsMPSSq, ff.linearForcesNewtons, ff.torqueCurrentsAmps,
             ff.robotRelativeForcesXNewtons, ff.robotRelativeForcesYNewtons))


# ---- values -------------------------------------------------------------------------

def test_module_config_derives_pathplanners_numbers():
    m = ModuleConfig(0.05, 4.0, 1.1, MOTOR, 40.0, 2)
    assert m.driveCurrentLimit == 80.0                       # per motor × numMotors
    assert m.maxDriveVelocityRadPerSec == 4.0 / 0.05
    at_top = MOTOR.getCurrent(4.0 / 0.05, 12.0)
    assert m.torqueLoss == max(MOTOR.getTorque(min(at_top, 80.0)), 0.0)
    assert m.torqueLoss > 0.0


def test_robot_config_derived_values():
    c = _config(3, 0.25)
    assert c.numModules == 3
    assert c.modulePivotDistance == pytest.approx((0.25,) * 3, abs=1e-15)
    assert c.wheelFrictionForce == 1.2 * ((55.0 / 3) * 9.8)
    assert c.maxTorqueFriction == c.wheelFrictionForce * 0.0508


@pytest.mark.parametrize("make", [
    lambda: ModuleConfig(0.05, 4.0, 1.1, MOTOR, 40.0, 2),
    lambda: _config(5),
    lambda: PathConstraints(1.0, 2.0, 3.0, 4.0, 11.0, True),
    lambda: DriveFeedforwards([1.0, 2.0], [3.0, 4.0], [5.0, 6.0], [7.0, 8.0], [9.0, 10.0]),
    lambda: SwerveSetpoint(ChassisVelocities(1.0, 2.0, 3.0),
                           [SwerveModuleVelocity(1.5, Rotation2d(0.4)),
                            SwerveModuleVelocity(-2.0, Rotation2d(-1.0))],
                           DriveFeedforwards([1.0, 2.0], [3.0, 4.0], [5.0, 6.0], [7.0, 8.0],
                                             [9.0, 10.0])),
], ids=["ModuleConfig", "RobotConfig", "PathConstraints", "DriveFeedforwards",
        "SwerveSetpoint"])
def test_values_pickle_copy_and_compare(make):
    a = make()
    for b in (pickle.loads(pickle.dumps(a)), copy.deepcopy(a), make()):
        assert b == a and type(b) is type(a)
        assert repr(b) == repr(a)
    assert a != object() and a.__eq__(object()) is NotImplemented
    with pytest.raises(TypeError):
        hash(a)
    with pytest.raises(TypeError, match="immutable"):
        a.__init__(*pickle.loads(pickle.dumps(a)).__reduce__()[1])


def test_generator_pickles_with_its_settings():
    g = SwerveSetpointGenerator(_config(), 8.0, 7.0, "pathplanner")
    h = pickle.loads(pickle.dumps(g))
    assert (h.config, h.maxSteerVelocityRadPerSec, h.brownoutVoltage, h.compatibility) == \
        (g.config, 8.0, 7.0, "pathplanner")


def test_setpoint_owns_copies():
    mods = [SwerveModuleVelocity(1.0, Rotation2d(0.5)) for _ in range(2)]
    cv = ChassisVelocities(1.0, 0.0, 0.0)
    sp = SwerveSetpoint(cv, mods, DriveFeedforwards.zeros(2))
    mods[0].velocity = 9.0
    cv.vx = 9.0
    assert sp.moduleVelocities[0].velocity == 1.0 and sp.robotRelativeVelocities.vx == 1.0
    assert sp.moduleVelocities[0] is not sp.moduleVelocities[1]


def test_unlimited_constraints():
    c = PathConstraints.unlimitedConstraints(11.0)
    assert c.unlimited and c.nominalVoltage == 11.0
    assert c.maxVelocityMps == c.maxAngularAccelerationRpsSq == math.inf


# ---- settings.json ------------------------------------------------------------------

SETTINGS = {"holonomicMode": True, "robotMass": 61.0, "robotMOI": 6.2,
            "driveWheelRadius": 0.048, "driveGearing": 5.9, "maxDriveSpeed": 4.7,
            "wheelCOF": 1.3, "driveMotorType": "NEO", "driveCurrentLimit": 50,
            "flModuleX": 0.28, "flModuleY": 0.26, "frModuleX": 0.28, "frModuleY": -0.26,
            "blModuleX": -0.28, "blModuleY": 0.26, "brModuleX": -0.28, "brModuleY": -0.26,
            "robotTrackwidth": 0.52, "defaultMaxVel": 3.0}


def test_from_gui_settings(tmp_path):
    p = tmp_path / "settings.json"
    p.write_text(json.dumps(SETTINGS))
    c = RobotConfig.fromGUISettings(p)
    expect = RobotConfig(61.0, 6.2, ModuleConfig(0.048, 4.7, 1.3,
                                                 DCMotor.getNEO(1).withReduction(5.9), 50.0, 1),
                         [Translation2d(0.28, 0.26), Translation2d(0.28, -0.26),
                          Translation2d(-0.28, 0.26), Translation2d(-0.28, -0.26)])
    assert c == expect
    assert RobotConfig.fromGUISettings(str(p)) == expect


@pytest.mark.parametrize("change, message", [
    ({"holonomicMode": False}, "differential drive"),
    ({"driveMotorType": "kraken"}, "driveMotorType 'kraken'"),
    ({"robotMass": "heavy"}, "'robotMass' .* must be a int or float"),
    ({"robotMass": None}, "robotMass"),
    ({"robotMOI": -1.0}, "MOI must be a positive"),
    ({"driveWheelRadius": 0.0}, "wheelRadiusMeters must be a positive"),
    ({"flModuleX": 0.0, "flModuleY": 0.0}, "at the robot's centre"),
    ({"brModuleY": None}, "brModuleY"),
])
def test_from_gui_settings_refuses_bad_files(tmp_path, change, message):
    p = tmp_path / "settings.json"
    p.write_text(json.dumps({**SETTINGS, **change}))
    with pytest.raises(ValueError, match=message):
        RobotConfig.fromGUISettings(p)


@pytest.mark.parametrize("text", ["", "{", "[1, 2]", "\xff\xfe"])
def test_from_gui_settings_refuses_files_that_are_not_settings(tmp_path, text):
    p = tmp_path / "settings.json"
    p.write_bytes(text.encode("latin-1"))
    with pytest.raises(ValueError, match="settings"):
        RobotConfig.fromGUISettings(p)
    with pytest.raises(ValueError, match="cannot read"):
        RobotConfig.fromGUISettings(tmp_path / "missing.json")


def test_from_gui_settings_missing_key(tmp_path):
    p = tmp_path / "settings.json"
    p.write_text(json.dumps({k: v for k, v in SETTINGS.items() if k != "wheelCOF"}))
    with pytest.raises(ValueError, match="no 'wheelCOF'"):
        RobotConfig.fromGUISettings(p)


# ---- bad input ----------------------------------------------------------------------

@pytest.mark.parametrize("args, message", [
    ((0.0, 6.0), "massKG must be a positive"), ((-5.0, 6.0), "massKG"),
    ((math.nan, 6.0), "massKG"), ((60.0, 0.0), "MOI must be a positive"),
    ((60.0, math.inf), "MOI"),
])
def test_robot_config_refuses_bad_mass_and_moi(args, message):
    module = ModuleConfig(0.05, 4.0, 1.0, MOTOR, 40.0)
    with pytest.raises(ValueError, match=message):
        RobotConfig(*args, module, [Translation2d(0.3, 0.3), Translation2d(-0.3, -0.3)])


@pytest.mark.parametrize("args, exc, message", [
    ((0.0, 4.0, 1.0, MOTOR, 40.0), ValueError, "wheelRadiusMeters"),
    ((0.05, -4.0, 1.0, MOTOR, 40.0), ValueError, "maxDriveVelocityMPS"),
    ((0.05, 4.0, 0.0, MOTOR, 40.0), ValueError, "wheelCOF"),
    ((0.05, 4.0, 1.0, MOTOR, 0.0), ValueError, "driveCurrentLimit"),
    ((0.05, 4.0, 1.0, MOTOR, -1.0), ValueError, "driveCurrentLimit"),
    ((0.05, 4.0, 1.0, MOTOR, 40.0, 0), ValueError, "numMotors"),
    ((0.05, 4.0, 1.0, MOTOR, 40.0, 1.0), TypeError, "numMotors"),
    ((0.05, 4.0, 1.0, None, 40.0), TypeError, "driveMotor must be a DCMotor"),
])
def test_module_config_refuses_bad_values(args, exc, message):
    with pytest.raises(exc, match=message):
        ModuleConfig(*args)


def test_motor_with_zero_free_speed_is_refused():
    with pytest.raises(ValueError, match="free_speed"):
        DCMotor(12.0, 4.69, 257.0, 1.5, 0.0)


@pytest.mark.parametrize("offsets, exc, message", [
    ([Translation2d(0.3, 0.3)], ValueError, "at least 2"),
    ([Translation2d(0.3, 0.3), None], TypeError, r"moduleOffsets\[1\]"),
    ([Translation2d(0.3, 0.3), Translation2d(math.nan, 0.0)], ValueError, "finite"),
    ([Translation2d(0.3, 0.3), Translation2d(0.0, 0.0)], ValueError, "centre"),
])
def test_robot_config_refuses_bad_offsets(offsets, exc, message):
    with pytest.raises(exc, match=message):
        RobotConfig(60.0, 6.0, ModuleConfig(0.05, 4.0, 1.0, MOTOR, 40.0), offsets)


@pytest.mark.parametrize("kwargs, message", [
    ({"maxSteerVelocityRadPerSec": 0.0}, "maxSteerVelocityRadPerSec"),
    ({"maxSteerVelocityRadPerSec": math.nan}, "maxSteerVelocityRadPerSec"),
    ({"brownoutVoltage": -1.0}, "brownoutVoltage"),
    ({"compatibility": "java"}, "compatibility"),
    ({"compatibility": 1}, "compatibility"),
])
def test_generator_refuses_bad_settings(kwargs, message):
    args = {"maxSteerVelocityRadPerSec": 10.0, **kwargs}
    with pytest.raises(ValueError, match=message):
        SwerveSetpointGenerator(_config(), **args)


def _moving(gen, n=4):
    sp = _zeros(n)
    for _ in range(10):
        sp = gen.generateSetpoint(sp, ChassisVelocities(2.0, 1.0, 1.0), 0.02)
    return sp


@pytest.mark.parametrize("call, exc, message", [
    (lambda g, sp, o: g.generateSetpoint(sp, ChassisVelocities(1, 0, 0), 0.0), ValueError, "dt"),
    (lambda g, sp, o: g.generateSetpoint(sp, ChassisVelocities(1, 0, 0), -0.02), ValueError, "dt"),
    (lambda g, sp, o: g.generateSetpoint(sp, ChassisVelocities(1, 0, 0), math.nan), ValueError,
     "dt"),
    (lambda g, sp, o: g.generateSetpoint(sp, ChassisVelocities(math.nan, 0, 0), 0.02),
     ValueError, "desiredRobotRelativeVelocities must be finite"),
    (lambda g, sp, o: g.generateSetpoint(sp, ChassisVelocities(1, 0, 0), 0.02, math.inf),
     ValueError, "inputVoltage"),
    (lambda g, sp, o: g.generateSetpoint(_zeros(3), ChassisVelocities(1, 0, 0), 0.02),
     ValueError, "prevSetpoint has 3 modules"),
    (lambda g, sp, o: g.generateSetpointInto(sp, ChassisVelocities(1, 0, 0), 0.02, _zeros(5)),
     ValueError, "out has 5 modules"),
    (lambda g, sp, o: g.generateSetpointInto(sp, ChassisVelocities(1, 0, 0), 0.02, o, 12.0,
                                             PathConstraints(1, 1, 1, 1) and object()),
     TypeError, "constraints must be a PathConstraints"),
    (lambda g, sp, o: g.generateSetpointInto(None, ChassisVelocities(1, 0, 0), 0.02, o),
     TypeError, "prevSetpoint must be a SwerveSetpoint"),
    (lambda g, sp, o: g.generateSetpointInto(sp, (1.0, 0.0, 0.0), 0.02, o), TypeError,
     "desiredRobotRelativeVelocities must be a ChassisVelocities"),
])
def test_bad_calls_change_nothing(call, exc, message):
    gen = SwerveSetpointGenerator(_config(), 10.0)
    sp = _moving(gen)
    out = _moving(SwerveSetpointGenerator(_config(), 10.0))
    before, out_before = _state(sp), _state(out)
    twin = SwerveSetpointGenerator(_config(), 10.0)
    _moving(twin)
    with pytest.raises(exc, match=message):
        call(gen, sp, out)
    assert _state(sp) == before and _state(out) == out_before
    # The heading memory did not move either: the next call matches an untouched twin's.
    cmd = ChassisVelocities(0.0, 0.0, 0.0)
    assert _state(gen.generateSetpoint(sp, cmd, 0.02)) == _state(twin.generateSetpoint(sp, cmd, 0.02))


def test_prev_setpoint_must_be_finite():
    gen = SwerveSetpointGenerator(_config(), 10.0)
    sp = SwerveSetpoint(ChassisVelocities(math.inf, 0.0, 0.0),
                        [SwerveModuleVelocity() for _ in range(4)], DriveFeedforwards.zeros(4))
    with pytest.raises(ValueError, match="prevSetpoint's velocities must be finite"):
        gen.generateSetpoint(sp, ChassisVelocities(), 0.02)


# Finite arguments whose arithmetic overflowed (NaN or inf setpoints): each is refused,
# naming the argument, or computed finite, and the generator stays as it was.
EXTREMES = [
    (ChassisVelocities(2.0, 1.0, 1.0), 1.7e308, "dt must be a loop period from 1e-09 to 1e"),
    (ChassisVelocities(2.0, 1.0, 1.0), 5e-324, "dt must be a loop period"),
    (ChassisVelocities(1e308, 1e308, 1e308), 0.02, "desiredRobotRelativeVelocities must be "
     "finite and at most 1e"),
    (ChassisVelocities(0.0, 0.0, -1e101), 0.02, "desiredRobotRelativeVelocities"),
]


@pytest.mark.parametrize("compatibility", [None, "pathplanner"])
@pytest.mark.parametrize("desired, dt, message", EXTREMES)
def test_extreme_arguments_are_refused_and_change_nothing(compatibility, desired, dt, message):
    gen, twin = (SwerveSetpointGenerator(_config(), 10.0, compatibility=compatibility)
                 for _ in range(2))
    sp = _moving(gen)
    _moving(twin)
    before = _state(sp)
    with pytest.raises(ValueError, match=message):
        gen.generateSetpoint(sp, desired, dt)
    with pytest.raises(ValueError, match="sample 1: " + message):
        batch.generateSetpoints(gen, sp, np.array([[1.0, 0.0, 0.0], [desired.vx, desired.vy,
                                                                    desired.omega]]),
                                np.array([0.02, dt]))
    assert _state(sp) == before
    cmd = ChassisVelocities(1.0, -0.5, 2.0)
    assert _state(gen.generateSetpoint(sp, cmd, 0.02)) == _state(twin.generateSetpoint(sp, cmd, 0.02))


@pytest.mark.parametrize("compatibility", [None, "pathplanner"])
@pytest.mark.parametrize("desired, dt", [((1e100, -1e100, 1e100), 0.02), ((3.0, 1.0, 2.0), 1e6),
                                         ((1e100, 0.0, -1e100), 1e6), ((3.0, 1.0, 2.0), 1e-9),
                                         ((1e100, 1e100, 0.0), 1e-9)])
def test_arguments_at_their_bounds_give_finite_setpoints(compatibility, desired, dt):
    module = ModuleConfig(0.0508, 4.5, 1.2, MOTOR, 60.0, 1)
    for config in (_config(), RobotConfig(1e100, 1e100, module, _config().moduleLocations)):
        gen = SwerveSetpointGenerator(config, 10.0, compatibility=compatibility)
        sp = _moving(gen)
        for _ in range(3):
            sp = gen.generateSetpoint(sp, ChassisVelocities(*desired), dt, 1e300)
            assert all(math.isfinite(x) for part in _state(sp) for row in part
                       for x in (row if isinstance(row, tuple) else (row,)))


@pytest.mark.parametrize("args, message", [((1e308, 6.0), "massKG must be at most 1e100"),
                                           ((60.0, 1e308), "MOI must be at most 1e100")])
def test_robot_config_refuses_mass_and_moi_that_overflow_the_feedforwards(args, message):
    # RobotConfig(MOI=1e308) gave ±inf torque feedforwards.
    with pytest.raises(ValueError, match=message):
        RobotConfig(*args, ModuleConfig(0.05, 4.0, 1.0, MOTOR, 40.0),
                    [Translation2d(0.3, 0.3), Translation2d(-0.3, -0.3)])


def test_an_overflowing_setpoint_is_refused_and_changes_nothing():
    # Module positions of 1e300 m: the PathPlanner mode's inverse kinematics of a turning
    # command overflows. Nothing may come out, and the heading memory stays.
    offsets = [Translation2d(1e300 * x, 1e300 * y) for x, y in ((1, 1), (1, -1), (-1, 1))]
    config = RobotConfig(60.0, 6.0, ModuleConfig(0.05, 4.0, 1.0, MOTOR, 40.0), offsets)
    gen, twin = (SwerveSetpointGenerator(config, 10.0, compatibility="pathplanner")
                 for _ in range(2))
    sp = _zeros(3)
    for g in (gen, twin):
        g.generateSetpoint(sp, ChassisVelocities(1.0, 1.0, 0.0), 0.02)
    with pytest.raises(ValueError, match="the setpoint overflowed"):
        gen.generateSetpoint(sp, ChassisVelocities(0.0, 0.0, 1e10), 0.02)
    with pytest.raises(ValueError, match="sample 1: the setpoint overflowed"):
        batch.generateSetpoints(gen, sp, np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1e10]]), 0.02)
    cmd = ChassisVelocities(-1.0, 0.5, 0.0)
    assert _state(gen.generateSetpoint(sp, cmd, 0.02)) == _state(twin.generateSetpoint(sp, cmd, 0.02))


# ---- the three forms give the same numbers ------------------------------------------

COMMANDS = [(3.0, 0.0, 0.0), (3.0, 2.0, 4.0), (-3.0, -1.0, 0.0), (0.0, 0.0, 6.0),
            (0.0, 0.0, 0.0), (1.0, -4.0, -2.0)]


@pytest.mark.parametrize("compatibility", [None, "pathplanner"])
@pytest.mark.parametrize("n", [2, 3, 4, 6])
def test_into_and_batch_give_the_facades_bits(compatibility, n):
    rows = np.array([c for c in COMMANDS for _ in range(15)])
    dts = np.linspace(0.01, 0.03, len(rows))
    volts = np.where(np.arange(len(rows)) % 3 == 0, np.nan, 10.5)
    limits = PathConstraints(3.5, 6.0, 5.0, 12.0)
    a, b, c = (SwerveSetpointGenerator(_config(n), 9.0, compatibility=compatibility)
               for _ in range(3))
    sp, out = _zeros(n), _zeros(n)
    states = []
    for row, dt, v in zip(rows, dts, volts):
        sp = a.generateSetpoint(sp, ChassisVelocities(*row), dt, v, limits)
        b.generateSetpointInto(out, ChassisVelocities(*row), dt, out, v, limits)
        assert _state(out) == _state(sp)
        states.append(_state(sp))
    vel, mods, ffs = batch.generateSetpoints(c, _zeros(n), rows, dts, volts, limits)
    assert vel.shape == (len(rows), 3) and mods.shape == (len(rows), n, 2)
    assert ffs.shape == (len(rows), 5, n)
    for i, (v, m, f) in enumerate(states):
        assert tuple(vel[i]) == v
        assert tuple(mods[i, :, 0]) == tuple(x[0] for x in m)
        # The angles as the per-call path computes them (drivekin's own atan2, not libm's).
        sin_, cos_ = np.array([x[2] for x in m]), np.array([x[1] for x in m])
        assert np.array_equal(mods[i, :, 1], batch._trig("atan2", sin_, cos_, scalar=True))
        assert tuple(map(tuple, ffs[i])) == f
    # The batch left the generator's heading memory where the calls left theirs.
    cmd = ChassisVelocities(0.0, 0.0, 0.0)
    assert _state(c.generateSetpoint(sp, cmd, 0.02)) == _state(a.generateSetpoint(sp, cmd, 0.02))


def test_batch_checks_every_row_first():
    gen = SwerveSetpointGenerator(_config(), 9.0)
    rows = np.array([[1.0, 0.0, 0.0], [np.nan, 0.0, 0.0]])
    with pytest.raises(ValueError, match="sample 1"):
        batch.generateSetpoints(gen, _zeros(), rows, 0.02)
    with pytest.raises(ValueError, match="sample 0: dt"):
        batch.generateSetpoints(gen, _zeros(), rows[:1], np.array([0.0]))
    with pytest.raises(TypeError, match="SwerveSetpointGenerator"):
        batch.generateSetpoints(None, _zeros(), rows[:1], 0.02)


def test_all_modules_flip_stops_first():
    # Moving forward, then straight back: every module would turn by π, so the generator
    # brakes (PathPlannerLib's rule) and then flips in place at standstill.
    gen = SwerveSetpointGenerator(_config(), 4 * math.pi)
    sp = _zeros()
    for _ in range(100):
        sp = gen.generateSetpoint(sp, ChassisVelocities(3.0, 0.0, 0.0), 0.02)
    assert sp.robotRelativeVelocities.vx == pytest.approx(3.0)
    speeds = [sp.robotRelativeVelocities.vx]
    for _ in range(150):
        sp = gen.generateSetpoint(sp, ChassisVelocities(-3.0, 0.0, 0.0), 0.02)
        speeds.append(sp.robotRelativeVelocities.vx)
    assert all(b <= a + 1e-12 for a, b in zip(speeds, speeds[1:]))   # never speeds up forwards
    assert speeds[-1] == pytest.approx(-3.0)


class _Meddling:
    """Duck-typed constraints whose getter writes bad values into the call's arrays (NaN
    rows, dt 0 and -1, an infinite voltage) and then gives a limit."""

    def __init__(self, rows, dts, volts):
        self.rows, self.dts, self.volts = rows, dts, volts
        self.maxAccelerationMpsSq = 6.0
        self.maxAngularVelocityRps = 5.0
        self.maxAngularAccelerationRpsSq = 12.0

    @property
    def maxVelocityMps(self):
        self.rows[:] = np.nan
        self.dts[0], self.dts[1:] = 0.0, -1.0
        self.volts[:] = np.inf
        return 3.5


def test_batch_reads_every_input_before_the_constraints_run_code():
    rows = np.array([c for c in COMMANDS for _ in range(5)])
    dts = np.linspace(0.01, 0.03, len(rows))
    volts = np.full(len(rows), 11.0)
    expect = batch.generateSetpoints(SwerveSetpointGenerator(_config(), 9.0), _zeros(),
                                     rows.copy(), dts.copy(), volts.copy(),
                                     PathConstraints(3.5, 6.0, 5.0, 12.0))
    meddling = _Meddling(rows, dts, volts)
    got = batch.generateSetpoints(SwerveSetpointGenerator(_config(), 9.0), _zeros(), rows,
                                  dts, volts, meddling)
    assert np.isnan(rows).all() and dts[0] == 0.0 and (volts == np.inf).all()   # it ran
    for a, b in zip(got, expect):
        assert np.array_equal(a, b) and np.isfinite(a).all()
