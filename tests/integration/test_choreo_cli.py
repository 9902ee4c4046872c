"""``python -m drivekin choreo check``: every exit status, the lines it prints and the files
it writes, on the real trajectories of ../shared/choreo/trajs."""
from __future__ import annotations

import json

import pytest

from drivekin import choreo
from drivekin.app import cli
from tests._support.choreo_files import TRAJS

QUANTITIES = ("moduleSpeed", "driveTorque", "current", "friction", "steerRate", "moduleOrder")


@pytest.fixture
def trajs():
    if not TRAJS.is_dir():
        pytest.skip(f"{TRAJS} is not here")
    return TRAJS


def _run(capsys, *argv):
    try:
        code = cli.main(["choreo", *map(str, argv)])
    except SystemExit as e:            # argparse's usage errors
        code = e.code
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return code, out, err


def test_feasible(trajs, tmp_path, capsys):
    out_json, png = tmp_path / "r.json", tmp_path / "r.png"
    pytest.importorskip("matplotlib")
    code, out, err = _run(capsys, "check", trajs / "gwhs_B_Cycle2.traj", "--json", out_json,
                          "--plot", png)
    assert code == 0, err
    assert out.count("\n") == 1 and "feasible" in out
    data = json.loads(out_json.read_text())
    assert data["ok"] is True and data["violations"] == []
    report = choreo.load(trajs / "gwhs_B_Cycle2.traj").check()
    assert data["margins"] == pytest.approx(report.margins, abs=0)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_project_config_is_the_embedded_one(trajs, tmp_path, capsys):
    out_json = tmp_path / "r.json"
    code, _, err = _run(capsys, "check", trajs / "titanware_FirstSweep.traj", "--config",
                        trajs / "projects" / "titanware_choreo.chor", "--json", out_json)
    assert code == 0, err
    report = choreo.load(trajs / "titanware_FirstSweep.traj").check()
    assert json.loads(out_json.read_text())["margins"] == pytest.approx(report.margins,
                                                                        abs=1e-12)


def test_infeasible_prints_one_line_per_violated_quantity(trajs, tmp_path, capsys):
    data = json.loads((trajs / "titanware_FirstSweep.traj").read_text())
    for s in data["trajectory"]["samples"]:              # the documented FL, FR, BL, BR
        for key in ("fx", "fy"):
            fl, bl, br, fr = s[key]
            s[key] = [fl, fr, bl, br]
    path = tmp_path / "permuted.traj"
    path.write_text(json.dumps(data))
    out_json = tmp_path / "r.json"
    code, out, err = _run(capsys, "check", path, "--max-steer-velocity", "2",
                          "--json", out_json)
    assert code == 1, err
    lines = out.splitlines()
    assert 2 <= len(lines) <= 12
    report = json.loads(out_json.read_text())
    violated = {v["quantity"] for v in report["violations"]}
    assert report["ok"] is False and {"moduleOrder", "steerRate"} <= violated
    for q in QUANTITIES:
        naming = [line for line in lines if q in line]
        assert len(naming) == (q in violated), (q, lines)
        if naming:
            assert naming[0].startswith(q + ":")


@pytest.mark.parametrize("argv, message", [
    (["check"], "required"),
    (["verify", "{traj}"], "invalid choice"),
    (["check", "{traj}", "--max-steer-velocity", "-3"], "--max-steer-velocity"),
    (["check", "{traj}", "--voltage", "nan"], "--voltage"),
    (["check", "{traj}", "--json", "{tmp}/missing/out.json"], "does not exist"),
    (["check", "{dir}/legacy/choreo_v2_swerve.traj"], "schema version 2"),
    (["check", "{tmp}/absent.traj"], "cannot be read"),
    (["check", "{traj}", "--config", "{traj}"], "no robot config"),
    (["check", "{noconfig}"], "--config FILE.chor"),
], ids=["no-file", "no-command", "steer", "voltage", "json-folder", "legacy", "absent",
        "not-a-project", "no-config"])
def test_bad_usage(trajs, tmp_path, capsys, argv, message):
    data = json.loads((trajs / "gwhs_B_Cycle2.traj").read_text())
    data["trajectory"]["config"] = None
    (tmp_path / "noconfig.traj").write_text(json.dumps(data))
    fill = {"traj": trajs / "gwhs_B_Cycle2.traj", "dir": trajs, "tmp": tmp_path,
            "noconfig": tmp_path / "noconfig.traj"}
    code, out, err = _run(capsys, *(a.format(**fill) for a in argv))
    assert code == 2
    assert out == "" and message in err


def test_the_json_is_strict_when_a_module_outruns_its_motor(trajs, tmp_path, capsys):
    data = json.loads((trajs / "gwhs_B_Cycle2.traj").read_text())
    k = 2.0                                 # twice as fast: past the motor's free speed
    for s in data["trajectory"]["samples"]:
        s["t"] /= k
        for key in ("vx", "vy", "omega"):
            s[key] *= k
    path = tmp_path / "fast.traj"
    path.write_text(json.dumps(data))
    out_json = tmp_path / "r.json"
    code, out, _ = _run(capsys, "check", path, "--json", out_json)
    assert code == 1 and out.splitlines()[0].endswith("violations")

    def refuse(name):
        raise AssertionError(f"{name} in the JSON")
    report = json.loads(out_json.read_text(), parse_constant=refuse)
    assert report["ok"] is False
    assert report["margins"]["driveTorque"] is None          # a torque where the curve is 0
    assert report["margins"]["moduleSpeed"] < 0
