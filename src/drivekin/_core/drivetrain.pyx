"""The drivetrain contract's base class (declared in drivetrain.pxd): the centre-of-rotation
rule written once, defaults for what most drivetrains do not need, and map bodies that
keep a subclass that does not override them from computing; and the pseudo-inverse the
drivetrains build their forward maps with."""
from libc.math cimport fabs, frexp, ldexp, sqrt

import numpy as np

from drivekin._core.kernels cimport vec
from drivekin._core.types cimport vec2_t
from drivekin.geometry cimport Translation2d


cdef class Drivetrain:

    cdef int _ready(self) except -1:
        raise TypeError(f"{type(self).__name__} does not implement the drivetrain contract")

    cdef int _center(self, object center_of_rotation) except -1:
        # Callers have checked that center_of_rotation is None or a Translation2d.
        if center_of_rotation is None:
            self._set_cor(vec(0.0, 0.0))
        elif self.centered:
            self._set_cor((<Translation2d>center_of_rotation).v)
        else:
            raise TypeError(f"{type(self).__name__} has no centre of rotation argument")
        return 0

    cdef void _set_cor(self, vec2_t cor) noexcept:
        pass

    cdef int _forward_check(self, bint gyro, bint accel) except -1:
        return 0

    cdef Py_ssize_t _params(self, double* params, bint forward, bint accel) noexcept:
        return 0

    cdef void _inverse_many(self, Py_ssize_t k, const double* chassis, const double* omega,
                            bint accel, double* params,
                            double* m, double* c, double* s) noexcept nogil:
        pass

    cdef void _inverse_done(self, const double* params, bint accel) noexcept:
        pass

    cdef void _forward_many(self, Py_ssize_t k, const double* m, const double* c,
                            const double* s, const double* gyro, bint accel,
                            const double* params, double* out) noexcept nogil:
        pass

    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil:
        pass

    cdef void _twist(self, const double* d, const double* c, const double* s,
                     const double* dth, double* out) noexcept nogil:
        self._twists(1, d, c, s, dth, out)


# ---------------------------------------------------------------------------------------
# The forward maps' pseudo-inverse, drivekin's own: every drivetrain's forward kinematics
# is the least-squares inverse of its inverse-kinematics matrix, built once at
# construction. Plain loops in one fixed order, IEEE additions, multiplications,
# divisions and sqrt only (no fused multiply-add: setup.py's -ffp-contract=off), so every
# platform gets the same bits (LAPACK's, which numpy's pinv called, depend on the build).

cdef double RCOND = 1e-15   # numpy's pinv default: columns below this relative size are dependent


cdef void reflect(Py_ssize_t m, double[:, ::1] v, Py_ssize_t t, double h, double[:, ::1] x,
                  Py_ssize_t col) noexcept:
    # Column col of x times the reflection I − v·vᵀ/h of step t (v[:, t], zero above row t).
    cdef Py_ssize_t i
    cdef double s = 0.0, f
    for i in range(t, m):
        s = s + v[i, t] * x[i, col]
    f = s / h
    for i in range(t, m):
        x[i, col] = x[i, col] - f * v[i, t]


cdef Py_ssize_t householder(Py_ssize_t m, Py_ssize_t n, double[:, ::1] w, double[:, ::1] v,
                            double* h, Py_ssize_t* order) noexcept:
    # Householder QR of the m x n matrix w (m >= n, entries of moderate size) in place, the
    # columns in their order except that one whose part orthogonal to the columns taken
    # before it is shorter than RCOND times the longest column is deferred to the end (it
    # depends on them: the matrix is rank-deficient). Returns the rank r; order[0:n]
    # lists the taken columns, then the deferred ones. Afterwards w's rows 0..r-1 hold
    # R = Qᵀ·A in those columns (upper triangular in the first r) and v[:, t], h[t] the
    # reflection I − v·vᵀ/h of step t (h = vᵀv/2), v zero above row t.
    cdef Py_ssize_t i, j, q, t, r = 0, nd = 0
    cdef double s, x0, nrm, alpha, longest = 0.0
    cdef Py_ssize_t deferred[8]
    cdef bint taken[8]
    for j in range(n):
        s = 0.0
        for i in range(m):
            s = s + w[i, j] * w[i, j]
        longest = max(longest, sqrt(s))
        taken[j] = False
    for j in range(n):
        s = 0.0
        for i in range(r, m):
            s = s + w[i, j] * w[i, j]
        nrm = sqrt(s)
        if not nrm > RCOND * longest:
            deferred[nd] = j
            nd += 1
            continue
        x0 = w[r, j]
        alpha = -nrm if x0 >= 0.0 else nrm
        for i in range(m):
            v[i, r] = w[i, j] if i > r else 0.0
        v[r, r] = x0 - alpha
        h[r] = nrm * (nrm + fabs(x0))
        taken[j] = True
        for q in range(n):
            if not taken[q]:
                reflect(m, v, r, h[r], w, q)
        w[r, j] = alpha
        for i in range(r + 1, m):
            w[i, j] = 0.0
        order[r] = j
        r += 1
    for t in range(nd):
        order[r + t] = deferred[t]
    return r


cdef object pinv_scaled(double[:, ::1] a):
    # The pseudo-inverse (n x m) of a (m x n, m >= n, n <= 8, not zero, entries of
    # moderate size). Full column rank: R⁻¹·Q1ᵀ. Rank r < n: A·Π = Q1·T with
    # T = [R11 R12] (r x n, full row rank), so A⁺ = Π·T⁺·Q1ᵀ, the minimum-norm
    # least-squares inverse numpy's SVD gave, with T⁺ = ((Tᵀ)⁺)ᵀ from the full-rank case.
    cdef Py_ssize_t m = a.shape[0], n = a.shape[1], i, j, t, u, r
    cdef double s
    cdef double h[8]
    cdef Py_ssize_t order[8]
    w_arr = np.array(a)
    v_arr = np.zeros((m, n))
    q_arr = np.zeros((m, n))
    p_arr = np.zeros((n, m))
    cdef double[:, ::1] w = w_arr, v = v_arr, q1 = q_arr, p = p_arr
    r = householder(m, n, w, v, h, order)
    # Q1 = H0·H1·…·H(r−1) applied to the first r columns of the identity.
    for j in range(r):
        q1[j, j] = 1.0
    for t in range(r - 1, -1, -1):
        for j in range(r):
            reflect(m, v, t, h[t], q1, j)
    cdef double[:, ::1] tp
    if r == n:
        # Row i of Q1 through R⁻¹ by back-substitution: column i of A⁺.
        for i in range(m):
            for t in range(r - 1, -1, -1):
                s = q1[i, t]
                for u in range(t + 1, r):
                    s = s - w[t, order[u]] * p[order[u], i]
                p[order[t], i] = s / w[t, order[t]]
        return p_arr
    tt = np.zeros((n, r))
    for t in range(r):
        for j in range(n):
            tt[j, t] = w[t, order[j]]
    tp = pinv_scaled(tt)            # (Tᵀ)⁺, r x n
    for j in range(n):
        for i in range(m):
            s = 0.0
            for t in range(r):
                s = s + tp[t, j] * q1[i, t]
            p[order[j], i] = s
    return p_arr


def pseudo_inverse(a):
    """Return the Moore–Penrose pseudo-inverse of a finite 2-D float64 matrix with at most
    8 columns or rows, computed by drivekin in one fixed order of operations (Householder
    QR), so that it has the same bits on every platform: within about 1e-15 relative of
    the exact one for a well-conditioned matrix. Singular values below 1e-15 of the
    largest are treated as zero, as numpy's ``pinv`` does (the test is on each column's
    part independent of the columns before it)."""
    arr = np.array(a, dtype=np.float64)
    if arr.ndim != 2 or min(arr.shape) < 1 or min(arr.shape) > 8:
        raise ValueError(f"expected a 2-D matrix with 1 to 8 columns or rows, got shape "
                         f"{arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError("the matrix must be finite")
    if arr.shape[0] < arr.shape[1]:
        return pseudo_inverse(arr.T).T.copy()
    cdef double big = 0.0, x
    for x in arr.ravel():
        big = max(big, fabs(x))
    if big == 0.0:
        return np.zeros(arr.shape[::-1])
    # An exact power of two brings the largest entry into [1, 2): no square overflows or
    # underflows to matter, and scaling back is exact.
    cdef int e
    frexp(big, &e)
    out = pinv_scaled(np.ascontiguousarray(arr * ldexp(1.0, 1 - e)))
    return out * ldexp(1.0, 1 - e)
