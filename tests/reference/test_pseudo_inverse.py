"""drivekin's pseudo-inverse (``drivekin._core.drivetrain.pseudo_inverse``), from which
swerve, mecanum and dead-wheel kinematics build their forward maps, against the exact one
(mpmath at 50 digits) and numpy's SVD ``pinv``: within 1e-15 relative of exact on the
inverse-kinematics matrices of real layouts, numpy's minimum-norm inverse on
rank-deficient ones, exact scaling, and its refusals. That it has the same bits on every
platform is the trig corpus's part "pseudo-inverse" (test_trig_corpus.py)."""
from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from drivekin import Rotation2d, SwerveDriveKinematics, SwerveModuleVelocity, Translation2d
from drivekin._core.drivetrain import pseudo_inverse
from tests._support.strategies import mecanum_inverse_matrix, swerve_inverse_matrix

LAYOUTS = {
    "square": [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)],
    "rectangle": [(0.29, 0.26), (0.29, -0.26), (-0.29, 0.26), (-0.29, -0.26)],
    "ftc": [(0.17, 0.16), (0.17, -0.16), (-0.17, 0.16), (-0.17, -0.16)],
    "off-centre": [(0.7, 0.3), (0.7, -0.3), (0.1, 0.3), (0.1, -0.3)],
    "uneven": [(0.31, 0.27), (0.29, -0.22), (-0.35, 0.2), (-0.1, -0.3)],
    "three": [(0.3, 0.0), (-0.15, 0.26), (-0.15, -0.26)],
    "two": [(0.0, 0.3), (0.0, -0.3)],
    "hexagon": [(0.35, 0.0), (0.175, 0.3), (-0.175, 0.3), (-0.35, 0.0), (-0.175, -0.3),
                (0.175, -0.3)],
}
# Dead wheels (x, y, rolling direction in rad): Pinpoint's two pods, three and four wheels.
DEAD_WHEELS = {
    "two": [(0.0, 0.12, 0.0), (-0.08, 0.0, math.pi / 2)],
    "three": [(0.0, 0.15, 0.0), (0.0, -0.15, 0.0), (-0.1, 0.0, math.pi / 2)],
    "four": [(0.1, 0.15, 0.1), (0.05, -0.15, -0.05), (-0.1, 0.02, 1.5), (0.2, 0.2, 2.5)],
}


def swerve_acceleration_matrix(points):
    """The 2N×4 matrix the swerve acceleration forward map inverts: rows
    [1, 0, −x, −y] and [0, 1, −y, x]."""
    rows = []
    for x, y in points:
        rows += [[1.0, 0.0, -x, -y], [0.0, 1.0, -y, x]]
    return np.array(rows)


def dead_wheel_matrix(wheels):
    """The dead-wheel model rows [cos φ, sin φ, x sin φ − y cos φ], from drivekin's own
    Rotation2d (the doubles DeadWheelKinematics builds its rows from)."""
    rows = []
    for x, y, phi in wheels:
        r = Rotation2d(phi)
        rows.append([r.getCos(), r.getSin(), x * r.getSin() - y * r.getCos()])
    return np.array(rows)


def matrices():
    for name, points in LAYOUTS.items():
        yield f"swerve {name}", swerve_inverse_matrix(points)
        yield f"swerve acceleration {name}", swerve_acceleration_matrix(points)
        if len(points) == 4:
            yield f"mecanum {name}", mecanum_inverse_matrix(points)
    for name, wheels in DEAD_WHEELS.items():
        m = dead_wheel_matrix(wheels)
        yield f"dead wheels {name} A", m[:, :2]
        if len(wheels) >= 3:
            yield f"dead wheels {name} M", m


MATRICES = dict(matrices())


def exact_pinv(a, rank=None):
    """The pseudo-inverse at 50 digits, of a matrix whose first ``rank`` columns (all, by
    default) are independent and span the rest: with B those columns and X = B⁺A (so
    A = B·X exactly), A⁺ = Xᵀ(XXᵀ)⁻¹(BᵀB)⁻¹Bᵀ."""
    with mp.workdps(50):
        A = mp.matrix(np.asarray(a).tolist())
        r = A.cols if rank is None else rank
        B = A[:, :r]
        bpinv = mp.inverse(B.T * B) * B.T
        X = bpinv * A
        return np.array((X.T * mp.inverse(X * X.T) * bpinv).tolist(), dtype=float)


def rel_error(p, q):
    return np.abs(p - q).max() / np.abs(q).max()


@pytest.mark.parametrize("name", MATRICES)
def test_real_layouts_are_within_1e_15_of_exact(name):
    a = MATRICES[name]
    exact = exact_pinv(a)
    ours = pseudo_inverse(a)
    assert ours.shape == a.shape[::-1] and ours.dtype == np.float64
    assert rel_error(ours, exact) <= 1e-15
    # numpy's SVD pinv (what drivekin used) is as close: the two agree to rounding.
    assert rel_error(ours, np.linalg.pinv(a)) <= 2e-15


def test_forward_kinematics_is_built_on_it():
    # The forward map of a swerve drive is the pseudo-inverse applied to the module
    # velocity components: within rounding of the exact inverse's product.
    points = LAYOUTS["uneven"]
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in points])
    states = [SwerveModuleVelocity(1.0 + 0.5 * i, Rotation2d(0.3 - 0.7 * i))
              for i in range(len(points))]
    w = np.array([c for s in states for c in (s.velocity * s.angle.getCos(),
                                               s.velocity * s.angle.getSin())])
    want = exact_pinv(swerve_inverse_matrix(points)) @ w
    got = kin.toChassisVelocities(states)
    assert np.abs(np.array([got.vx, got.vy, got.omega]) - want).max() <= 1e-15 * np.abs(w).max()


RANK_DEFICIENT = {
    # Coincident swerve modules: the rotation column is a combination of the other two.
    "swerve, three modules at one point": (swerve_inverse_matrix([(0.4, 0.1)] * 3), 2),
    "swerve, modules at the origin": (swerve_inverse_matrix([(0.0, 0.0)] * 2), 2),
    "swerve acceleration, modules at one point":
        (swerve_acceleration_matrix([(0.4, 0.1)] * 3), 2),
    "mecanum, wheels at one point": (mecanum_inverse_matrix([(0.2, 0.1)] * 4), 2),
    "mecanum, wheels at the origin": (mecanum_inverse_matrix([(0.0, 0.0)] * 4), 2),
}


@pytest.mark.parametrize("name", RANK_DEFICIENT)
def test_rank_deficient_layouts_get_the_minimum_norm_inverse(name):
    a, rank = RANK_DEFICIENT[name]
    assert np.linalg.matrix_rank(a) == rank
    ours = pseudo_inverse(a)
    # Two QR factorisations and a product: a few more roundings than the full-rank case.
    assert rel_error(ours, exact_pinv(a, rank)) <= 2e-15
    assert rel_error(ours, np.linalg.pinv(a)) <= 3e-15


def test_scaling_by_a_power_of_two_is_exact_and_nothing_overflows():
    rng = np.random.default_rng(3)
    a = rng.uniform(-2.0, 2.0, (6, 3))
    p = pseudo_inverse(a)
    for k in (600, -600, 1000):
        scaled = pseudo_inverse(a * 2.0 ** k)
        assert np.all(np.isfinite(scaled))
        assert scaled.tobytes() == (p * 2.0 ** -k).tobytes()


def test_wide_matrices_and_zero():
    rng = np.random.default_rng(4)
    a = rng.uniform(-2.0, 2.0, (3, 7))
    assert rel_error(pseudo_inverse(a), exact_pinv(a.T).T) <= 1e-15
    assert pseudo_inverse(np.zeros((5, 3))).tobytes() == np.zeros((3, 5)).tobytes()


@pytest.mark.parametrize("bad, what", [
    (np.array([[1.0, math.nan], [0.0, 1.0]]), "finite"),
    (np.array([[1.0, math.inf], [0.0, 1.0]]), "finite"),
    (np.ones((9, 9)), "8 columns"),
    (np.ones(3), "2-D"),
    (np.ones((0, 3)), "2-D"),
])
def test_refusals(bad, what):
    with pytest.raises(ValueError, match=what):
        pseudo_inverse(bad)
