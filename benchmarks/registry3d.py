"""The 3-D rows of the registry (issue 29): drivekin's 3-D geometry, SwerveDriveOdometry3d
and SwerveDrivePoseEstimator3d against robotpy-wpimath 2026.2.2, held together to a
geometric mean of at most 0.10 of robotpy's time (:data:`GROUP`). ``registry.py`` imports
this module at its end; suites ``geometry3d`` and ``estimator3d`` (``bench_geometry3d.py``,
``bench_estimator3d.py``).

robotpy 2026 has no ``Twist3d.exp`` nor ``Transform3d.log``: its spellings are
``Pose3d().exp(twist)`` and ``Pose3d().log(Pose3d(t.translation(), t.rotation()))`` (the
end pose prebuilt), against drivekin's ``twist.exp()`` and ``t.log()``. The rotations are
moderate (0.4 rad and less, above 1e-3), where robotpy's closed forms are exact to 1e-9.
Quaternions are compared with w >= 0 (q and −q are one rotation).

The odometry starts with its pose's rotation equal to the gyro's reading, where robotpy's
gyro offset (pose₀·gyro₀⁻¹·gyro) and WPILib 2027's composition of gyro changes give the
same pose. The estimator is driven as the 2-D one (registry.py, "Pose estimators"), the
gyro also rolling and pitching, with 3-D vision poses off the estimate about every axis.
"""
from __future__ import annotations

from _common import INPUTS
from registry import GROUPS, VALUE_HELPERS, Case, Group, Operation, register

RPY = (0.1, -0.2, 0.5)                          # Rotation3d(roll, pitch, yaw), rad
POSE = (1.0, 2.0, 0.3, (0.05, -0.1, 0.5))       # x, y, z m, (roll, pitch, yaw) rad
OTHER = (2.0, -1.0, 0.1, (-0.1, 0.05, 1.2))     # relativeTo's frame
TRANSFORM = (0.3, -0.1, 0.2, (0.02, 0.03, -0.4))
TWIST = (0.02, 0.01, 0.005, 0.01, -0.02, 0.03)  # dx, dy, dz m, rx, ry, rz rad
TILT = (0.02, -0.01)                            # the gyro's roll and pitch at the start, rad
TILT_RATE = (0.5, -0.5)                         # and their rates, rad/s


def _canonical(v):
    return v[:3] + ([-c for c in v[3:]] if v[3] < 0 else v[3:])


def rp_pose3(p):
    q = p.rotation().getQuaternion()
    return _canonical([p.X(), p.Y(), p.Z(), q.W(), q.X(), q.Y(), q.Z()])


def dk_pose3(p):
    q = p.getRotation().getQuaternion()
    return _canonical([p.getX(), p.getY(), p.getZ(), q.getW(), q.getX(), q.getY(), q.getZ()])


def rp_quat(r):
    q = r.getQuaternion()
    return _canonical([0.0, 0.0, 0.0, q.W(), q.X(), q.Y(), q.Z()])[3:]


def dk_quat(r):
    q = r.getQuaternion()
    return _canonical([0.0, 0.0, 0.0, q.getW(), q.getX(), q.getY(), q.getZ()])[3:]


def twist6(t):
    return [t.dx, t.dy, t.dz, t.rx, t.ry, t.rz]


VALUE_HELPERS.update(rp_pose3=rp_pose3, dk_pose3=dk_pose3, rp_quat=rp_quat, dk_quat=dk_quat,
                     twist6=twist6)


def _rp3():
    from wpimath import geometry

    return geometry


def _dk3():
    from drivekin import geometry3d

    return geometry3d


def _frame(g, cls, spec):
    x, y, z, rpy = spec
    return getattr(g, cls)(x, y, z, g.Rotation3d(*rpy))


_SAME = "same call as the façade: the result comes from a freelist, no allocator calls"


def _geometry_op(key, title, stmt, env, value, rp_stmt=None, rp_env=None, note=""):
    """A row whose cases run ``stmt`` with the locals ``env(g)``, ``g`` each library's
    geometry module (robotpy 2026's own spelling: ``rp_stmt``, ``rp_env``). ``value`` is
    the check's expression, with ``{lib}`` ("rp" or "dk") and ``{stmt}`` to fill in."""
    rp_stmt = rp_stmt or stmt
    dk = Case(stmt, lambda rp, dk: env(_dk3()), value=value.format(lib="dk", stmt=stmt),
              note=note)
    return register(Operation(
        key=key, title=title, suite="geometry3d",
        robotpy=Case(rp_stmt, lambda rp, dk: (rp_env or env)(_rp3()),
                     value=value.format(lib="rp", stmt=rp_stmt)),
        facade=dk, alloc_free=Case(stmt, dk.setup, value=dk.value, note=_SAME),
        needs_kinematics=False))


_geometry_op("geometry3d.rotation", "Rotation3d(roll, pitch, yaw)", "R(r, p, y)",
             lambda g: dict(R=g.Rotation3d, r=RPY[0], p=RPY[1], y=RPY[2]), "{lib}_quat({stmt})")
_geometry_op("geometry3d.transform_by", "Pose3d.transformBy", "pose.transformBy(t)",
             lambda g: dict(pose=_frame(g, "Pose3d", POSE), t=_frame(g, "Transform3d", TRANSFORM)),
             "{lib}_pose3({stmt})")
_geometry_op("geometry3d.relative_to", "Pose3d.relativeTo", "pose.relativeTo(other)",
             lambda g: dict(pose=_frame(g, "Pose3d", POSE), other=_frame(g, "Pose3d", OTHER)),
             "{lib}_pose3({stmt})")
_geometry_op("geometry3d.twist_exp", "Twist3d.exp", "twist.exp()",
             lambda g: dict(twist=g.Twist3d(*TWIST)), "{lib}_pose3({stmt})",
             rp_stmt="zero.exp(twist)", rp_env=lambda g: dict(zero=g.Pose3d(),
                                                              twist=g.Twist3d(*TWIST)),
             note="robotpy 2026: Pose3d().exp(twist)")
_geometry_op("geometry3d.transform_log", "Transform3d.log", "t.log()",
             lambda g: dict(t=_frame(g, "Transform3d", TRANSFORM)), "twist6({stmt})",
             rp_stmt="zero.log(end)", rp_env=lambda g: dict(zero=g.Pose3d(),
                                                            end=_frame(g, "Pose3d", TRANSFORM)),
             note="robotpy 2026: Pose3d().log(end), end the transform as a prebuilt Pose3d")
_geometry_op("geometry3d.to_pose2d", "Pose3d.toPose2d", "pose.toPose2d()",
             lambda g: dict(pose=_frame(g, "Pose3d", POSE)), "{lib}_pose({stmt})")
# Not in the group: the 2026 spelling of pose + twist.exp(), fused in both libraries.
_geometry_op("geometry3d.pose_exp", "Pose3d.exp(twist) (pose + twist.exp())", "pose.exp(twist)",
             lambda g: dict(pose=_frame(g, "Pose3d", POSE), twist=g.Twist3d(*TWIST)),
             "{lib}_pose3({stmt})")


# ---------------------------------------------------------------------------------------
# SwerveDriveOdometry3d.update (4 modules): as the 2-D odometry rows, built at gyro0 with
# zero distances and the pose at POSE's position with gyro0's rotation, updated once with
# gyro1 and one dt of module travel (the value check); later calls see no change.

def _angles(t):
    """The gyro's roll, pitch and yaw at time t (rad)."""
    return (TILT[0] + TILT_RATE[0] * t, TILT[1] + TILT_RATE[1] * t,
            INPUTS.robot_angle + INPUTS.omega * t)


def _gyro(g, t):
    return g.Rotation3d(*_angles(t))


def _start(g):
    return g.Pose3d(g.Translation3d(*POSE[:3]), _gyro(g, 0.0))


def _odometry(g, cls, kin, spos0, spos1):
    return dict(odo=cls(kin, _gyro(g, 0.0), spos0, _start(g)), gyro=_gyro(g, INPUTS.dt),
                pos=spos1)


def _rp_odometry(rp, dk):
    from wpimath import kinematics

    return _odometry(_rp3(), kinematics.SwerveDrive4Odometry3d, rp.kin, rp.spos0, rp.spos1)


def _dk_odometry(rp, dk):
    from drivekin import SwerveDriveOdometry3d

    return _odometry(_dk3(), SwerveDriveOdometry3d, dk.kin, dk.spos0, dk.spos1)


_dk_odo_case = Case("odo.update(gyro, pos)", _dk_odometry, value="dk_pose3(odo.getPose())")
register(Operation(
    key="odometry3d.swerve", title="SwerveDriveOdometry3d.update (4 modules)",
    suite="estimator3d",
    robotpy=Case("odo.update(gyro, pos)", _rp_odometry, value="rp_pose3(odo.getPose())",
                 note="SwerveDrive4Odometry3d; pos: tuple of 4 SwerveModulePosition"),
    facade=_dk_odo_case,
    alloc_free=Case(_dk_odo_case.stmt, _dk_odometry, value=_dk_odo_case.value,
                    note="same call as the façade: the returned Pose3d comes from a freelist")))


# ---------------------------------------------------------------------------------------
# SwerveDrivePoseEstimator3d: 1.5 s of updates at 50 Hz with a vision pose 50 ms old after
# every third, then updateWithTime on a sliding clock and addVisionMeasurement 0.553 s
# back, as the 2-D rows.

_DT, _STEPS, _LATENCY = 0.02, 76, 0.05
_VISION_TS = _STEPS * _DT - 0.553


def _vision(g, t):
    roll, pitch, yaw = _angles(t)
    return g.Pose3d(POSE[0] + 0.1, POSE[1] - 0.05, POSE[2] + 0.02,
                    g.Rotation3d(roll + 0.01, pitch - 0.02, yaw + 0.02))


def _estimator(g, cls, kin, k, spos1):
    est = cls(kin, _gyro(g, 0.0), tuple(k.SwerveModulePosition(0.0, p.angle) for p in spos1),
              _start(g), (0.1, 0.1, 0.1, 0.1), (0.9, 0.9, 0.9, 0.9))
    for i in range(1, _STEPS + 1):
        t = i * _DT
        pos = tuple(k.SwerveModulePosition(p.distance * i, p.angle) for p in spos1)
        est.updateWithTime(t, _gyro(g, t), pos)
        if i % 3 == 0:
            est.addVisionMeasurement(_vision(g, t - _LATENCY), t - _LATENCY)
    return dict(est=est, gyro=_gyro(g, _STEPS * _DT), pos=pos)


def _rp_estimator(rp, dk):
    from wpimath.estimator import SwerveDrive4PoseEstimator3d

    return _estimator(_rp3(), SwerveDrive4PoseEstimator3d, rp.kin, rp.k, rp.spos1)


def _dk_estimator(rp, dk):
    from drivekin import SwerveDrivePoseEstimator3d

    return _estimator(_dk3(), SwerveDrivePoseEstimator3d, dk.kin, dk.k, dk.spos1)


def _clock():
    import itertools

    return itertools.count((_STEPS + 1) * _DT, _DT).__next__


def _estimator_op(key, title, stmt, extra, note):
    def rp_setup(rp, dk):
        return dict(_rp_estimator(rp, dk), **extra(_rp3()))

    def dk_setup(rp, dk):
        return dict(_dk_estimator(rp, dk), **extra(_dk3()))

    value = "pose3(est.getEstimatedPosition())"
    return register(Operation(
        key=key, title=title, suite="estimator3d",
        robotpy=Case(stmt, rp_setup, value="rp_" + value,
                     note=f"SwerveDrive4PoseEstimator3d; {note}"),
        facade=Case(stmt, dk_setup, value="dk_" + value, note=note),
        alloc_free=Case(stmt, dk_setup, value="dk_" + value,
                        note="same call as the façade: the estimator has one form")))


_estimator_op("estimator3d.update", "SwerveDrivePoseEstimator3d.updateWithTime (4 modules)",
              "est.updateWithTime(clk(), gyro, pos)", lambda g: dict(clk=_clock()),
              "full 1.5 s history with vision records; time advances 20 ms a call")
_estimator_op("estimator3d.vision",
              "SwerveDrivePoseEstimator3d.addVisionMeasurement (full 1.5 s buffer)",
              "est.addVisionMeasurement(vision, ts)",
              lambda g: dict(vision=_vision(g, _VISION_TS), ts=_VISION_TS),
              "measurement 0.553 s old, between two samples, with vision records before it")


GROUP = Group("3-D (issue 29)", ("geometry3d.rotation", "geometry3d.transform_by",
                                 "geometry3d.relative_to", "geometry3d.twist_exp",
                                 "geometry3d.transform_log", "geometry3d.to_pose2d",
                                 "odometry3d.swerve", "estimator3d.update",
                                 "estimator3d.vision"), 0.10)
GROUPS.append(GROUP)
