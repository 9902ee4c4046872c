"""drivekin.datalog with the 3-D geometry: struct:Pose3d, Rotation3d, Translation3d[],
Quaternion, Transform3d and Twist3d entries written by robotpy-wpiutil's DataLogWriter
(robotpy-wpimath's values, packed by its wpistruct) read as arrays, with the log's
schemas and without them, and unpacked into drivekin values with WPILib's bits; drivekin's
writer read back by robotpy-wpiutil's reader."""
from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("wpiutil")

import wpiutil.log as wlog                                     # noqa: E402
import wpiutil.wpistruct as ws                                 # noqa: E402
import wpimath.geometry as wg                                  # noqa: E402

from drivekin import (  # noqa: E402
    Pose3d, Quaternion, Rotation3d, Transform3d, Translation3d, Twist3d, datalog, wpistruct,
)
from tests._support.wpilog_logs import robotpy_log             # noqa: E402

POSE_COLUMNS = ("translation.x", "translation.y", "translation.z", "rotation.q.w",
                "rotation.q.x", "rotation.q.y", "rotation.q.z")


def rp_quat(q) -> list[float]:
    return [q.W(), q.X(), q.Y(), q.Z()]


def rp_pose(p) -> list[float]:
    return [p.X(), p.Y(), p.Z(), *rp_quat(p.rotation().getQuaternion())]


def rp_poses(k: int):
    """Record k's robotpy values (a rocking robot, a camera transform, ...)."""
    r = wg.Rotation3d(0.05 * k, -0.1 * k, 0.7 * k)
    return {
        "/Robot/Pose3d": wg.Pose3d(1.0 * k, -0.5 * k, 0.01 * k, r),
        "/Robot/Attitude": r,
        "/Vision/RobotToCamera": wg.Transform3d(wg.Translation3d(0.3, -0.2, 0.5),
                                                wg.Rotation3d(0.0, -0.3, 0.1 * k)),
        "/Vision/Corners": [wg.Translation3d(k, j, -j) for j in range(3)],
        "/Imu/Quaternion": wg.Quaternion(1.0, 0.1 * k, 0.0, -0.2),   # not normalised
        "/Odometry/Twist": wg.Twist3d(0.1 * k, 0.0, 0.01, 0.0, 0.02, -0.3),
    }


TYPES = {"/Robot/Pose3d": "struct:Pose3d", "/Robot/Attitude": "struct:Rotation3d",
         "/Vision/RobotToCamera": "struct:Transform3d",
         "/Vision/Corners": "struct:Translation3d[]", "/Imu/Quaternion": "struct:Quaternion",
         "/Odometry/Twist": "struct:Twist3d"}


@pytest.fixture(scope="module")
def robotpy_3d_file(tmp_path_factory):
    """Five records of each 3-D type; Transform3d's schema is left out (drivekin knows it)."""
    path = tmp_path_factory.mktemp("log3d") / "robot3d.wpilog"
    with robotpy_log(path) as log:
        schema = {"/Robot/Pose3d": wg.Pose3d, "/Robot/Attitude": wg.Rotation3d,
                  "/Vision/Corners": wg.Translation3d, "/Imu/Quaternion": wg.Quaternion,
                  "/Odometry/Twist": wg.Twist3d}
        entries = {n: log.start(n, t, 1, schema.get(n)) for n, t in TYPES.items()}
        for k in range(1, 6):
            for name, value in rp_poses(k).items():
                data = ws.packArray(value) if isinstance(value, list) else ws.pack(value)
                log.raw(entries[name], data, 1000 * k)
    return path


def test_reads_3d_struct_entries_as_arrays(robotpy_3d_file):
    log = datalog.read(robotpy_3d_file)
    assert log.schemas["Pose3d"] == "Translation3d translation;Rotation3d rotation"
    assert log.schemas["Rotation3d"] == "Quaternion q"
    assert "Transform3d" not in log.schemas
    info = log.entries
    assert info["/Robot/Pose3d"].columns == POSE_COLUMNS
    assert info["/Vision/RobotToCamera"].columns == POSE_COLUMNS      # drivekin's schema
    assert info["/Robot/Attitude"].columns == ("q.w", "q.x", "q.y", "q.z")
    want = [rp_poses(k) for k in range(1, 6)]
    t, poses = log.values("/Robot/Pose3d")
    assert t.tolist() == [1000 * k for k in range(1, 6)] and poses.shape == (5, 7)
    assert poses.tolist() == [rp_pose(w["/Robot/Pose3d"]) for w in want]   # bit for bit
    _, cam = log.values("/Vision/RobotToCamera")
    assert cam.tolist() == [rp_pose(w["/Vision/RobotToCamera"]) for w in want]
    _, att = log.values("/Robot/Attitude")
    assert att.tolist() == [rp_quat(w["/Robot/Attitude"].getQuaternion()) for w in want]
    _, corners = log.values("/Vision/Corners")
    assert corners.shape == (5, 3, 3)
    assert corners.tolist() == [[[c.X(), c.Y(), c.Z()] for c in w["/Vision/Corners"]]
                                for w in want]
    _, q = log.values("/Imu/Quaternion")
    assert q.tolist() == [rp_quat(w["/Imu/Quaternion"]) for w in want]
    _, tw = log.values("/Odometry/Twist")
    assert tw.tolist() == [[w["/Odometry/Twist"].dx, w["/Odometry/Twist"].dy,
                            w["/Odometry/Twist"].dz, w["/Odometry/Twist"].rx,
                            w["/Odometry/Twist"].ry, w["/Odometry/Twist"].rz] for w in want]


@pytest.mark.parametrize("name, cls", [("/Robot/Pose3d", Pose3d), ("/Robot/Attitude", Rotation3d),
                                       ("/Vision/RobotToCamera", Transform3d),
                                       ("/Imu/Quaternion", Quaternion),
                                       ("/Odometry/Twist", Twist3d)])
def test_records_unpack_to_drivekin_values_with_wpilibs_bits(robotpy_3d_file, name, cls):
    log = datalog.read(robotpy_3d_file)
    _, records = log.records(name)
    rpcls = getattr(wg, cls.__name__)
    for data in records:
        ours = wpistruct.unpack(cls, data)
        assert type(ours) is cls
        # Unpacking normalises as robotpy's (WPILib's C++) unpack does.
        assert wpistruct.pack(ours) == ws.pack(ws.unpack(rpcls, data))
    corners = wpistruct.unpackArray(Translation3d, log.records("/Vision/Corners")[1][0])
    assert corners == [Translation3d(1.0, j, -j) for j in range(3)]


def test_writer_publishes_3d_schemas_for_robotpys_reader(tmp_path):
    path = tmp_path / "ours3d.wpilog"
    pose = Pose3d(Translation3d(1.0, 2.0, 0.25), Rotation3d(0.1, -0.2, 0.3))
    with datalog.Writer(path) as w:
        w.append("/Pose", pose, 1000)
        w.append("/Tags", [Translation3d(1.0, 2.0, 3.0), Translation3d(-1.0, 0.0, 0.5)], 1000)
        w.appendSeries("/Series", "struct:Pose3d", np.array([2000, 3000]),
                       np.array([np.frombuffer(wpistruct.pack(pose), np.float64)] * 2))
    reader = wlog.DataLogReader(str(path))
    starts, records, schemas = {}, {}, {}
    for rec in reader:
        if rec.isStart():
            s = rec.getStartData()
            starts[s.entry] = (s.name, s.type)
        elif not rec.isControl():
            name, type_string = starts[rec.getEntry()]
            if name.startswith("/.schema/"):
                schemas[name[len("/.schema/"):]] = bytes(rec.getRaw()).decode()
            else:
                records.setdefault(name, (type_string, []))[1].append(bytes(rec.getRaw()))
    assert schemas == {"struct:Translation3d": "double x;double y;double z",
                       "struct:Quaternion": "double w;double x;double y;double z",
                       "struct:Rotation3d": "Quaternion q",
                       "struct:Pose3d": "Translation3d translation;Rotation3d rotation"}
    assert records["/Pose"] == ("struct:Pose3d", [wpistruct.pack(pose)])
    # robotpy reads it as drivekin does (both renormalise the quaternion alike).
    theirs = ws.unpack(wg.Pose3d, records["/Pose"][1][0])
    assert ws.pack(theirs) == wpistruct.pack(wpistruct.unpack(Pose3d, records["/Pose"][1][0]))
    assert theirs.toPose2d().X() == 1.0 and theirs.Z() == 0.25
    assert records["/Tags"][0] == "struct:Translation3d[]"
    assert [(t.X(), t.Y(), t.Z()) for t in ws.unpackArray(wg.Translation3d,
                                                          records["/Tags"][1][0])] == \
        [(1.0, 2.0, 3.0), (-1.0, 0.0, 0.5)]
    assert records["/Series"][1] == [wpistruct.pack(pose)] * 2
