"""3-D pose estimators (drivekin.estimator3d): WPILib's Euler-angle scaling of the rotation
correction against an independent quaternion model, sampleAt's interpolation against
Pose3d.interpolate, and the 2-D estimators' safeguards in 3-D (huge or infinite standard
deviations, the clock warning, bounded memory, refused calls).

The drives use a DifferentialDrivePoseEstimator3d with equal wheel distances (forward motion
only), the gyro fixed unless a test turns it; the machinery is every drivetrain's.
"""
import math
import tracemalloc
import warnings

import numpy as np
import pytest

from drivekin import (
    ClockMismatchWarning,
    DifferentialDrivePoseEstimator3d,
    DifferentialDriveWheelPositions,
    MathSharedStore,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDrivePoseEstimator3d,
    SwerveModulePosition,
    Translation2d,
)
from drivekin.geometry3d import Pose3d, Quaternion, Rotation3d, Translation3d

R3 = Rotation3d


def estimator(state=(1.0,) * 4, vision=(1.0,) * 4, pose=Pose3d()):
    return DifferentialDrivePoseEstimator3d(R3(), 0.0, 0.0, pose, state, vision)


def drive_to(e, t, x, gyro=R3()):
    return e.updateWithTime(t, gyro, x, x)


def quat(r):
    q = r.getQuaternion()
    return np.array([q.getW(), q.getX(), q.getY(), q.getZ()])


# ---- the rotation gain: WPILib's Euler angles, not a geodesic ------------------------------
# Independent model: unit quaternions in numpy. Extrinsic roll, pitch, yaw about the fixed
# X, Y, Z axes is q = q_z(yaw)·q_y(pitch)·q_x(roll).

def hamilton(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
                     w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                     w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def euler_quat(roll, pitch, yaw):
    def about(axis, angle):
        q = np.zeros(4)
        q[0], q[axis] = math.cos(angle / 2), math.sin(angle / 2)
        return q
    return hamilton(about(3, yaw), hamilton(about(2, pitch), about(1, roll)))


def geodesic_scale(q, k):
    """The rotation k of the way along q's own axis (k times its rotation vector)."""
    if q[0] < 0:
        q = -q
    angle = 2 * math.atan2(np.linalg.norm(q[1:]), q[0])
    axis = q[1:] / np.linalg.norm(q[1:])
    return np.concatenate([[math.cos(k * angle / 2)], math.sin(k * angle / 2) * axis])


def angle_between(a, b):
    return 2 * math.acos(min(1.0, abs(float(a @ b))))


def rot_err(a, b):
    """How far apart two rotations' unit quaternions are, q and -q alike (no acos, whose
    noise floor near 1 is 1e-8)."""
    qa, qb = quat(a), quat(b)
    return min(np.abs(qa - qb).max(), np.abs(qa + qb).max())


@pytest.mark.parametrize("euler, difference_deg", [((0.3, 0.3, 0.3), 1.17), ((1.0, 1.0, 1.0), 13.9)])
def test_rotation_gain_scales_euler_angles_as_wpilib(euler, difference_deg):
    # θ gain 0.5 (state 1 | vision 1): the correction of a vision rotation with Euler angles
    # `euler` at the identity is Rotation3d(euler / 2), WPILib's rule. A geodesic scaling
    # (half the rotation about its own axis) would land 1.17° away for (0.3, 0.3, 0.3) rad
    # and 13.9° away for (1, 1, 1): the documented difference.
    e = estimator()
    drive_to(e, 0.0, 0.0)
    e.addVisionMeasurement(Pose3d(0, 0, 0, R3(*euler)), 0.0)
    got = quat(e.getEstimatedPosition().getRotation())
    wpilib = euler_quat(*(0.5 * a for a in euler))
    assert min(np.abs(got - wpilib).max(), np.abs(got + wpilib).max()) <= 1e-12
    geodesic = geodesic_scale(euler_quat(*euler), 0.5)
    assert math.degrees(angle_between(got, geodesic)) == pytest.approx(difference_deg, abs=0.05)


def test_translation_gains_per_axis_and_the_correction_in_the_sampled_frame():
    # k = (1/2, 1/3, 1/6) for x, y, z (state 1, 1, 0.2 | vision 1, 2, 1): a vision pose
    # (1, 1, 1) m off in the robot's frame, the robot yawed 90° and pitched: the estimate
    # moves by k·Δ along the robot's own axes.
    start = Pose3d(2, 3, 4, R3(0.0, -0.2, math.pi / 2))
    e = DifferentialDrivePoseEstimator3d(R3(), 0.0, 0.0, start, (1.0, 1.0, 0.2, 1.0),
                                         (1.0, 2.0, 1.0, 1.0))
    e.updateWithTime(0.0, R3(), 0.0, 0.0)
    vision = start.transformBy(_transform(1.0, 1.0, 1.0))
    e.addVisionMeasurement(vision, 0.0)
    expected = start.transformBy(_transform(0.5, 1 / 3, 1 / 6))
    got = e.getEstimatedPosition()
    np.testing.assert_allclose([got.getX(), got.getY(), got.getZ()],
                               [expected.getX(), expected.getY(), expected.getZ()],
                               rtol=0, atol=1e-12)
    assert rot_err(got.getRotation(), start.getRotation()) <= 1e-12


def _transform(x, y, z):
    from drivekin.geometry3d import Transform3d
    return Transform3d(x, y, z, R3())


# ---- sampleAt: the odometry-step shortcut against Pose3d.interpolate ------------------------

def _model_sample(history, t):
    times = sorted(history)
    if t <= times[0]:
        return history[times[0]]
    if t >= times[-1]:
        return history[times[-1]]
    hi = next(i for i, s in enumerate(times) if s >= t)
    a, b = times[hi - 1], times[hi]
    return history[b] if b == t else history[a].interpolate(history[b], (t - a) / (b - a))


@pytest.mark.parametrize("seed", range(3))
def test_sample_interpolation_with_appended_inserted_and_replaced_samples(seed):
    # Appended samples reuse the odometry's twist; times out of order (inserted, replaced)
    # and turns of 3 rad or more take the general form. A model of WPILib's buffer built
    # from Pose3d.interpolate must agree everywhere.
    rng = np.random.default_rng(seed)
    e = SwerveDrivePoseEstimator3d(
        SwerveDriveKinematics(*[Translation2d(x, y) for x, y in
                                ((0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3))]),
        R3(), [SwerveModulePosition()] * 4, Pose3d(1, 2, 0.5, R3(0.1, 0.2, 0.3)))
    history, t, d, gyro = {}, 0.0, 0.0, R3()
    for _ in range(60):
        step = rng.choice([0.02, 0.03, -0.01, 0.0])   # back in time: inserted or replaced
        t = t + step if step else t
        d += rng.uniform(0.0, 0.05)
        turn = rng.choice([0.01, 0.3, 3.1, -3.2]) * rng.normal(size=3) / math.sqrt(3)
        gyro = R3(turn.tolist()).rotateBy(gyro)
        # With no vision, the estimate returned is the odometry pose stored at t.
        pose = e.updateWithTime(t, gyro, [SwerveModulePosition(d, Rotation2d(0.2))] * 4)
        newest = max(history, default=t)
        history = {s: p for s, p in history.items() if max(newest, t) - s < 1.5}
        history[t] = pose
        times = sorted(history)
        probes = list(rng.uniform(times[0] - 0.05, times[-1] + 0.05, 3)) + times
        probes += [0.5 * (a + b) for a, b in zip(times, times[1:])]
        for q in probes:
            expected, got = _model_sample(history, q), e.sampleAt(q)
            assert abs(got.getX() - expected.getX()) <= 1e-12
            assert abs(got.getY() - expected.getY()) <= 1e-12
            assert abs(got.getZ() - expected.getZ()) <= 1e-12
            assert rot_err(got.getRotation(), expected.getRotation()) <= 1e-12


# ---- the 2-D estimators' safeguards, in 3-D ---------------------------------------------------

@pytest.mark.parametrize("state", [1e155, 1e200, 1.7e308, math.inf])
def test_huge_or_infinite_state_std_devs_take_vision_whole(state):
    # The gain's limit is 1 (q = sd² would overflow and give NaN): the vision pose at
    # t = 0.01 replaces the odometry's there, plus the 0.01 m driven since.
    e = estimator((state,) * 4, (0.5,) * 4)
    drive_to(e, 0.0, 0.0)
    drive_to(e, 0.02, 0.02)
    e.addVisionMeasurement(Pose3d(1.0, 0.0, 0.5, R3(0.1, 0.0, 0.0)), 0.01)
    p = e.getEstimatedPosition()
    expected = Pose3d(1.0, 0.0, 0.5, R3(0.1, 0.0, 0.0)).transformBy(_transform(0.01, 0, 0))
    np.testing.assert_allclose([p.getX(), p.getY(), p.getZ()],
                               [expected.getX(), expected.getY(), expected.getZ()],
                               rtol=0, atol=1e-12)
    assert rot_err(p.getRotation(), R3(0.1, 0.0, 0.0)) <= 1e-12


def test_infinite_vision_std_devs_ignore_vision_on_that_axis():
    e = estimator((0.1,) * 4, (math.inf, 0.5, math.inf, math.inf))
    drive_to(e, 0.0, 0.0)
    drive_to(e, 0.02, 0.02)
    e.addVisionMeasurement(Pose3d(1.0, 1.0, 1.0, R3(0.3, 0.2, 0.1)), 0.01)
    p = e.getEstimatedPosition()
    q, r = 0.1 ** 2, 0.5 ** 2
    assert p.getX() == pytest.approx(0.02, abs=1e-12)
    assert p.getY() == pytest.approx(q / (q + math.sqrt(q * r)), abs=1e-12)
    assert p.getZ() == 0.0
    assert rot_err(p.getRotation(), R3()) == 0.0


def test_ignored_measurement_leaves_the_estimate_bit_for_bit():
    e = estimator()
    t = 0.0
    while t < 4:
        drive_to(e, t, t, R3(0.01, -0.02, t))
        t += 0.02
    before = e.getEstimatedPosition()
    e.addVisionMeasurement(Pose3d(10, 10, 10, R3(0, 0, 0.1)), 1.0, (0.1,) * 4)
    after = e.getEstimatedPosition()
    assert quat(after.getRotation()).tobytes() == quat(before.getRotation()).tobytes()
    assert (after.getX(), after.getY(), after.getZ()) == (before.getX(), before.getY(),
                                                          before.getZ())


def test_a_clock_running_backwards_keeps_a_bounded_history():
    e = estimator()
    for i in range(200):
        drive_to(e, -0.02 * i, 0.001 * i)
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        for i in range(200, 10200):
            drive_to(e, -0.02 * i, 0.001 * i)
        grown = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    assert grown < 4096, grown
    assert e.sampleAt(-100.0).getX() == pytest.approx(0.074, abs=1e-12)   # oldest kept
    assert e.getEstimatedPosition().getX() == pytest.approx(10.199, abs=1e-9)


def test_vision_from_another_clock_warns_once_and_keeps_bounded_memory():
    e = estimator()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        drive_to(e, 0.0, 0.0)
        e.addVisionMeasurement(Pose3d(0.0, 1.0, 0.0, R3()), 1.7e9)
        e.addVisionMeasurement(Pose3d(0.0, 1.0, 0.0, R3()), 1.7e9 + 1)
    mismatch = [w for w in caught if issubclass(w.category, ClockMismatchWarning)]
    assert len(mismatch) == 1 and mismatch[0].filename == __file__
    assert "DifferentialDrivePoseEstimator3d.addVisionMeasurement" in str(mismatch[0].message)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ClockMismatchWarning)
        for i in range(300):
            drive_to(e, 0.02 * i, 0.01 * i)
            e.addVisionMeasurement(Pose3d(0.01 * i, 1.0, 0.0, R3()), 1.7e9 + 0.02 * i)
        tracemalloc.start()
        try:
            before = tracemalloc.get_traced_memory()[0]
            for i in range(300, 10300):
                drive_to(e, 0.02 * i, 0.01 * i)
                e.addVisionMeasurement(Pose3d(0.01 * i, 1.0, 0.0, R3()), 1.7e9 + 0.02 * i)
            grown = tracemalloc.get_traced_memory()[0] - before
        finally:
            tracemalloc.stop()
    assert grown < 4096, grown
    p = e.getEstimatedPosition()
    assert (p.getX(), p.getY()) == pytest.approx((0.01 * 10299, 0.5), abs=1e-9)


def test_update_reads_the_shared_clock_and_takes_wheel_positions():
    MathSharedStore.setTimestampSource(lambda: 10.0)
    try:
        e = estimator()
        e.update(R3(), 1.0, 1.0)
        e.update(R3(), DifferentialDriveWheelPositions(2.0, 2.0))   # replaces the t = 10 one
        assert e.sampleAt(0.0).getX() == 2.0
        e.resetPosition(R3(), DifferentialDriveWheelPositions(5.0, 5.0), Pose3d())
        assert e.sampleAt(0.0) is None
        assert e.updateWithTime(11.0, R3(), 6.0, 6.0).getX() == 1.0
    finally:
        MathSharedStore.setTimestampSource(None)


@pytest.mark.parametrize("call, exc, needle", [
    (lambda e: e.updateWithTime(math.nan, R3(), 0.0, 0.0), ValueError, "finite time"),
    (lambda e: e.addVisionMeasurement(Pose3d(), math.inf), ValueError, "finite time"),
    (lambda e: e.sampleAt(math.nan), ValueError, "finite time"),
    (lambda e: e.setVisionMeasurementStdDevs([1.0, 2.0, 3.0]), ValueError, "must hold 4"),
    (lambda e: e.setVisionMeasurementStdDevs([1.0, math.nan, 2.0, 1.0]), ValueError, "finite"),
    (lambda e: e.setVisionMeasurementStdDevs("abcd"), TypeError, "list or tuple of 4"),
    (lambda e: e.addVisionMeasurement(Pose2d(), 0.0), TypeError, "Pose3d"),
    (lambda e: e.addVisionMeasurement(Pose3d(), 0.0, (1.0,) * 3), ValueError, "must hold 4"),
    (lambda e: e.updateWithTime(1.0, Rotation2d(), 0.0, 0.0), TypeError, "Rotation3d"),
    (lambda e: e.update(R3(), 1.0), TypeError, "left and right distances"),
    (lambda e: e.resetTranslation(Translation2d()), TypeError, "Translation3d"),
    (lambda e: e.resetRotation(Rotation2d()), TypeError, "Rotation3d"),
    (lambda e: e.resetPose(Pose2d()), TypeError, "Pose3d"),
    (lambda e: e.resetPosition(R3(), 0.0, 0.0, Pose2d()), TypeError, "Pose3d"),
])
def test_bad_input_changes_nothing(call, exc, needle):
    e = estimator((1.0, 1.0, 1.0, 0.5))
    drive_to(e, 0.0, 0.0)
    drive_to(e, 0.02, 0.02, R3(0.0, 0.1, 0.2))
    e.addVisionMeasurement(Pose3d(0.1, 0.1, 0.1, R3(0.1, 0.0, 0.0)), 0.01)
    before = (e.getEstimatedPosition(), e.sampleAt(0.005), e.sampleAt(0.015))
    with pytest.raises(exc) as info:
        call(e)
    assert needle in str(info.value)
    after = (e.getEstimatedPosition(), e.sampleAt(0.005), e.sampleAt(0.015))
    for a, b in zip(before, after):
        assert (a.getX(), a.getY(), a.getZ()) == (b.getX(), b.getY(), b.getZ())
        assert quat(a.getRotation()).tobytes() == quat(b.getRotation()).tobytes()
    # The std devs were not touched either: the same measurement moves it the same way.
    e.addVisionMeasurement(Pose3d(0.5, 0.0, 0.0, R3()), 0.02)
    f = estimator((1.0, 1.0, 1.0, 0.5))
    drive_to(f, 0.0, 0.0)
    drive_to(f, 0.02, 0.02, R3(0.0, 0.1, 0.2))
    f.addVisionMeasurement(Pose3d(0.1, 0.1, 0.1, R3(0.1, 0.0, 0.0)), 0.01)
    f.addVisionMeasurement(Pose3d(0.5, 0.0, 0.0, R3()), 0.02)
    assert e.getEstimatedPosition() == f.getEstimatedPosition()


def test_swerve_module_count_change_is_refused_and_changes_nothing():
    kin = SwerveDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                Translation2d(-1, 1))
    e = SwerveDrivePoseEstimator3d(kin, R3(), [SwerveModulePosition()] * 3, Pose3d())
    e.updateWithTime(0.0, R3(), [SwerveModulePosition(1.0, Rotation2d())] * 3)
    before = e.getEstimatedPosition()
    for n in (2, 4):
        with pytest.raises(ValueError, match="expected 3"):
            e.updateWithTime(0.02, R3(), [SwerveModulePosition(2.0, Rotation2d())] * n)
    assert e.getEstimatedPosition() == before and e.sampleAt(0.02) == before
    assert e.updateWithTime(0.02, R3(), [SwerveModulePosition(2.0, Rotation2d())] * 3).getX() \
        == pytest.approx(2.0, abs=1e-12)


def test_estimate_exists_before_the_first_update_and_resets_keep_corrections():
    start = Pose3d(1, 2, 3, R3(0.1, 0.2, 0.3))
    e = estimator(pose=start)
    assert e.getEstimatedPosition() == start and e.sampleAt(0.0) is None
    e.addVisionMeasurement(Pose3d(), 0.0)                   # no history: ignored
    assert e.getEstimatedPosition() == start
    drive_to(e, 0.0, 0.0)
    e.addVisionMeasurement(start.transformBy(_transform(0.0, 0.0, 1.0)), 0.0)   # z + 0.5
    e.resetRotation(R3())                                    # keeps the translation's
    p = e.getEstimatedPosition()
    assert rot_err(p.getRotation(), R3()) == 0.0
    shifted = start.transformBy(_transform(0.0, 0.0, 0.5))
    np.testing.assert_allclose([p.getX(), p.getY(), p.getZ()],
                               [shifted.getX(), shifted.getY(), shifted.getZ()],
                               rtol=0, atol=1e-12)
    assert e.sampleAt(0.0) is None                           # the history is cleared
    e.resetTranslation(Translation3d(7, 8, 9))
    assert e.getEstimatedPosition().getTranslation() == Translation3d(7, 8, 9)


def test_five_modules_as_an_n_by_2_array_and_one_step_of_pitch_and_travel():
    # Pitch and travel in the same step: the pose moves along the arc of Twist3d(1, 0, 0,
    # 0, -θ, 0).exp(), x = 1 - θ²·C, z = θ·B·1 (θ = 0.5, B = (1 - cos θ)/θ²,
    # C = (θ - sin θ)/θ³), as WPILib's odometry does.
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in
                                  ((1, 1), (1, -1), (-1, 1), (-1, -1), (0, 1))])
    e = SwerveDrivePoseEstimator3d(kin, R3(), np.zeros((5, 2)), Pose3d())
    p = e.updateWithTime(0.0, R3(0.0, -0.5, 0.0), np.array([[1.0, 0.0]] * 5))
    th = 0.5
    b, c = (1 - math.cos(th)) / th ** 2, (th - math.sin(th)) / th ** 3
    np.testing.assert_allclose([p.getX(), p.getY(), p.getZ()], [1 - th * th * c, 0.0, th * b],
                               rtol=0, atol=1e-14)
