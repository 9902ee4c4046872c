"""ChoreoTrajectory.check() and moduleSetpoints() on the real trajectories of
../shared/choreo/trajs (SOURCES.md there) and on copies made infeasible on purpose.

The oracle here recomputes every limit sample by sample from the file's JSON (complex
numbers, Choreo's module positions FL, BL, BR, FR from the file's config, the motor
through DCMotor's own getCurrent/getTorque), independently of drivekin's vectorised code."""
from __future__ import annotations

import cmath
import copy
import json
import math

import numpy as np
import pytest

from drivekin import choreo
from tests._support.choreo_files import TRAJS, params

REAL = sorted(TRAJS.glob("*.traj")) if TRAJS.is_dir() else []
ROTATING = ["choreo_test_swerve", "icrobotics_Center", "steelhawks_FourMeterSpinTest",
            "titanware_FirstSweep"]
STOPPED = 0.01


def _json(name: str) -> dict:
    path = TRAJS / f"{name}.traj"
    if not path.is_file():
        pytest.skip(f"{path} is not here (../shared/choreo/trajs)")
    return json.loads(path.read_text())


def _positions(c: dict) -> list[complex]:
    fl = complex(c["frontLeft"]["x"], c["frontLeft"]["y"])
    bl = complex(c["backLeft"]["x"], c["backLeft"]["y"])
    return [fl, bl, bl.conjugate(), fl.conjugate()]           # Choreo: FL, BL, BR, FR


def oracle(data: dict, motor, current_limit: float, max_steer: float | None = None) -> dict:
    """Largest value/limit per quantity, and the largest torque-balance residual (N·m)."""
    c = data["trajectory"]["config"]
    samples = data["trajectory"]["samples"]
    pos = _positions(c)
    r = c["radius"]
    vmax = min(r * c["vmax"] / c["gearing"], motor.freeSpeed * r)
    grip = c["cof"] * c["mass"] * 9.8 / 4
    worst = {"moduleSpeed": 0.0, "driveTorque": 0.0, "current": 0.0, "friction": 0.0,
             "steerRate": 0.0, "residual": 0.0}
    previous = None
    for s in samples:
        turn = cmath.exp(1j * s["heading"])
        angles = []
        torque = 0.0
        for i, p in enumerate(pos):
            arm = p * turn
            v = complex(s["vx"], s["vy"]) + 1j * s["omega"] * arm
            f = complex(s["fx"][i], s["fy"][i])
            torque += (arm.conjugate() * f).imag
            speed = abs(v)
            wheel = v / speed if speed >= STOPPED else (f / abs(f) if abs(f) else 1)
            tau = (f * wheel.conjugate()).real * r
            w = speed / r
            curve = motor.getTorque(motor.getCurrent(w if tau >= 0 else -w, 12.0))
            worst["moduleSpeed"] = max(worst["moduleSpeed"], speed / vmax)
            worst["driveTorque"] = max(worst["driveTorque"], abs(tau) / max(curve, 1e-300))
            worst["current"] = max(worst["current"],
                                   motor.getCurrent(torque=abs(tau)) / current_limit)
            worst["friction"] = max(worst["friction"], abs(f) / grip)
            angles.append(cmath.phase(v / turn) if speed >= STOPPED else None)
        if max_steer is not None and previous is not None:
            dt = s["t"] - previous[0]
            for a, b in zip(previous[1], angles):
                if a is not None and b is not None:
                    d = math.remainder(b - a, math.pi)     # modulo π: reverse the drive
                    worst["steerRate"] = max(worst["steerRate"], abs(d) / dt / max_steer)
        previous = (s["t"], angles)
        worst["residual"] = max(worst["residual"], abs(torque - c["inertia"] * s["alpha"]))
    return worst


def _load(tmp_path, data: dict) -> choreo.ChoreoTrajectory:
    path = tmp_path / f"{data['name']}.traj"
    path.write_text(json.dumps(data))
    return choreo.load(path)


def _violated(report) -> set[str]:
    return {v.quantity for v in report.violations}


def _expected(w: dict) -> set[str]:
    """Verdicts of the oracle for trajectories far from every limit's edge."""
    out = {q for q in ("moduleSpeed", "driveTorque", "current", "friction", "steerRate")
           if w[q] > 1 + 1e-3}
    return out | ({"moduleOrder"} if w["residual"] > 0.01 else set())


@pytest.mark.parametrize("path", params(REAL))
def test_real_trajectories_are_feasible_under_their_own_config(path):
    traj = choreo.load(path)
    report = traj.check()
    records = report.violations + report.warnings
    assert report.ok, report.violations[:3]
    assert report.worst.value <= report.worst.limit * (1 + 1e-4)
    assert not [r for r in records if r.quantity in ("moduleOrder", "steerRate")]
    assert set(report.margins) == {"moduleSpeed", "driveTorque", "current", "friction",
                                   "moduleOrder"}
    if traj.kind == "swerve":
        data = json.loads(path.read_text())
        mc = traj.config.moduleConfig
        w = oracle(data, mc.driveMotor, mc.driveCurrentLimit)
        for q in ("moduleSpeed", "driveTorque", "current", "friction"):
            assert report.margins[q] == pytest.approx(1 - w[q], abs=1e-9), q
        assert w["residual"] < 1e-3           # Choreo's order balances to the rounding


@pytest.mark.parametrize("name", ROTATING)
def test_forces_in_the_documented_order_break_the_torque_balance(tmp_path, name):
    data = _json(name)
    for s in data["trajectory"]["samples"]:              # FL, BL, BR, FR -> FL, FR, BL, BR
        for key in ("fx", "fy"):
            fl, bl, br, fr = s[key]
            s[key] = [fl, fr, bl, br]
    traj = _load(tmp_path, data)
    mc = traj.config.moduleConfig
    w = oracle(data, mc.driveMotor, mc.driveCurrentLimit)
    report = traj.check()
    assert "moduleOrder" in _expected(w)
    assert _violated(report) == _expected(w)
    assert all(v.module == -1 for v in report.violations if v.quantity == "moduleOrder")


@pytest.mark.parametrize("name", ["gwhs_B_Cycle2", "titanware_FirstSweep"])
def test_a_compressed_time_scale_exceeds_the_limits(tmp_path, name):
    data = _json(name)
    k = 1.6                       # the same path 1.6 times faster, rounded as Choreo writes
    for s in data["trajectory"]["samples"]:
        s["t"] = round(s["t"] / k, 5)
        for key in ("vx", "vy", "omega"):
            s[key] = round(s[key] * k, 5)
        for key in ("ax", "ay", "alpha"):
            s[key] = round(s[key] * k * k, 5)
        for key in ("fx", "fy"):
            s[key] = [round(f * k * k, 5) for f in s[key]]
    traj = _load(tmp_path, data)
    mc = traj.config.moduleConfig
    w = oracle(data, mc.driveMotor, mc.driveCurrentLimit)
    report = traj.check()
    assert not report.ok
    assert _violated(report) == _expected(w)
    assert "moduleOrder" not in _violated(report)     # J·α and the forces scale together
    assert report.margins["moduleSpeed"] == pytest.approx(1 - w["moduleSpeed"], abs=1e-9)
    assert report.margins["moduleSpeed"] < 0


@pytest.mark.parametrize("shift", [math.pi, math.pi / 2])
def test_a_heading_jump_at_speed(tmp_path, shift):
    data = _json("titanware_FirstSweep")
    samples = data["trajectory"]["samples"]
    mc = choreo.load(TRAJS / "titanware_FirstSweep.traj").config.moduleConfig
    steer = 1.5 * oracle(data, mc.driveMotor, mc.driveCurrentLimit, 1.0)["steerRate"]
    fast = max(range(len(samples)), key=lambda k: math.hypot(samples[k]["vx"],
                                                             samples[k]["vy"]))
    for s in samples[fast:]:
        s["heading"] += shift
    traj = _load(tmp_path, data)
    w = oracle(data, mc.driveMotor, mc.driveCurrentLimit, steer)
    report = traj.check(maxSteerVelocity=steer)
    assert _violated(report) == _expected(w)
    # Reversing the heading reverses each module's drive, no steering; a quarter turn in
    # one sample step is steering no module does.
    assert ("steerRate" in _violated(report)) == (shift != math.pi)
    assert "moduleOrder" in _violated(report)         # the forces now act on other corners
    if shift != math.pi:
        jump = [v for v in report.violations if v.quantity == "steerRate"]
        assert {v.time for v in jump} == {samples[fast]["t"]}


def test_module_setpoints_match_the_forces_and_motion():
    data = _json("steelhawks_FourMeterSpinTest")
    traj = choreo.load(TRAJS / "steelhawks_FourMeterSpinTest.traj")
    sp = traj.moduleSetpoints()
    mc = traj.config.moduleConfig
    assert set(sp) == {"speed", "angle", "acceleration", "current"}
    assert all(a.shape == (len(traj.samples), 4) for a in sp.values())
    pos = _positions(data["trajectory"]["config"])
    for k, s in enumerate(data["trajectory"]["samples"]):
        turn = cmath.exp(1j * s["heading"])
        for i, p in enumerate(pos):
            arm = p * turn
            v = complex(s["vx"], s["vy"]) + 1j * s["omega"] * arm
            a = complex(s["ax"], s["ay"]) + 1j * s["alpha"] * arm - s["omega"] ** 2 * arm
            assert sp["speed"][k, i] == pytest.approx(abs(v), abs=1e-12)
            if abs(v) < STOPPED:
                continue
            assert math.remainder(sp["angle"][k, i] - cmath.phase(v / turn),
                                  2 * math.pi) == pytest.approx(0, abs=1e-12)
            u = v / abs(v)
            f = complex(s["fx"][i], s["fy"][i])
            assert sp["acceleration"][k, i] == pytest.approx((a * u.conjugate()).real,
                                                             abs=1e-9)
            current = mc.driveMotor.getCurrent(
                torque=(f * u.conjugate()).real * mc.wheelRadiusMeters)
            assert sp["current"][k, i] == pytest.approx(current, abs=1e-9)


def test_the_shifted_differential_file_is_read_where_choreo_put_the_forces():
    traj = choreo.load(TRAJS / "choreo_test_differential.traj") if (
        TRAJS / "choreo_test_differential.traj").is_file() else pytest.skip("no trajs")
    s = traj.samples
    report = traj.check()
    assert [w.quantity for w in report.warnings] == ["columnShift"]
    # fl + fr = m·(al + ar)/2 only when read shifted (alpha is the left force).
    m = traj.config.massKG
    ma = m * (s[:-1, 7] + s[:-1, 8]) / 2                 # the last sample has a = 0
    assert np.allclose(s[:-1, 9] + s[:-1, 10], ma, atol=1e-3)
    assert not np.allclose(s[:-1, 10] + s[:-1, 11], ma, atol=1.0)
    assert report.ok


def test_bad_arguments(tmp_path):
    traj = choreo.load(TRAJS / "choreo_test_swerve.traj") if REAL else pytest.skip("no trajs")
    with pytest.raises(ValueError, match="maxSteerVelocity"):
        traj.check(maxSteerVelocity=-1.0)
    with pytest.raises(ValueError, match="voltage"):
        traj.check(voltage=float("nan"))
    with pytest.raises(TypeError, match="RobotConfig"):
        traj.check(config="robot")
    data = copy.deepcopy(_json("choreo_test_swerve"))
    data["trajectory"]["config"] = None
    with pytest.raises(ValueError, match="no robot config"):
        _load(tmp_path, data).check()


def test_a_config_in_another_module_order_gets_the_forces_of_its_corners():
    if not REAL:
        pytest.skip("no trajs")
    from drivekin import RobotConfig
    traj = choreo.load(TRAJS / "titanware_FirstSweep.traj")
    c = traj.config
    fl, bl, br, fr = c.moduleLocations                        # Choreo's order
    wpilib = RobotConfig(c.massKG, c.MOI, c.moduleConfig, [fl, fr, bl, br])
    mine, theirs = traj.moduleSetpoints(wpilib), traj.moduleSetpoints()
    for key in mine:
        assert np.array_equal(mine[key], theirs[key][:, [0, 3, 1, 2]]), key
    assert traj.check(wpilib).margins == traj.check().margins


def test_differential_setpoints():
    path = TRAJS / "synthetic" / "differential_scurve.traj"
    if not path.is_file():
        pytest.skip(f"{path} is not here")
    traj = choreo.load(path)
    data = json.loads(path.read_text())
    mc = traj.config.moduleConfig
    sp = traj.moduleSetpoints()
    for k, s in enumerate(data["trajectory"]["samples"]):
        for i, side in enumerate("lr"):
            v, a, f = s["v" + side], s["a" + side], s["f" + side]
            if abs(v) < STOPPED:
                continue
            sign = math.copysign(1.0, v)
            assert sp["speed"][k, i] == pytest.approx(abs(v), abs=1e-12)
            assert sp["angle"][k, i] == pytest.approx(0.0 if v > 0 else math.pi, abs=1e-9)
            assert sp["acceleration"][k, i] == pytest.approx(sign * a, abs=1e-9)
            assert sp["current"][k, i] == pytest.approx(
                mc.driveMotor.getCurrent(torque=sign * f * mc.wheelRadiusMeters), abs=1e-9)
