# 3-D geometry kernels: `cdef inline ... noexcept nogil` on the quat_t / vec3_t / pose3_t /
# twist3_t structs (_core/types.pxd), defined once here so every module that cimports them
# gets them inlined. No Python objects, no numpy.
#
# Formulas follow WPILib 2027 (Java org.wpilib.math.geometry; C++ wpi/math/geometry for
# Twist3d.exp / Transform3d.log). Where WPILib spends a square root and divisions on
# quaternions that are already unit (every stored Rotation3d's is, to a few ulps), the
# kernels use the equivalent division-free forms (rot3_apply, q_renorm, the conjugate as
# inverse): the same values to the last few bits, at a fraction of the latency. What the
# user hands in (Quaternion, Rotation3d(Quaternion), Rotation3d(initial, final)) is
# normalised exactly as WPILib does. setup.py builds with -ffp-contract=off, so a*b + c is
# never fused, and Cython keeps the parentheses.
# Trigonometry is drivekin's own (_core/dkmath.h: sincos, atan2; no asin, see rot3_y), the
# same on every platform. exp and log, for the public Quaternion.exp/log/pow of general
# quaternions only, are libm's; no rotation goes through them.
# Twist3d.exp and Transform3d.log are drivekin's cancellation-free forms (see there).

from libc.float cimport DBL_MAX, DBL_MIN
from libc.math cimport INFINITY, M_LN2, M_PI, copysign, exp, fabs, frexp, ldexp, log, sqrt
from drivekin._core.dkmath cimport atan2, sincos
from drivekin._core.types cimport pose3_t, quat_t, rot2_t, twist3_t, vec3_t

# ---------------------------------------------------------------------------------------
# Builders and plain vector algebra

cdef inline quat_t quat(double w, double x, double y, double z) noexcept nogil:
    cdef quat_t q
    q.w = w
    q.x = x
    q.y = y
    q.z = z
    return q

cdef inline vec3_t vec3(double x, double y, double z) noexcept nogil:
    cdef vec3_t v
    v.x = x
    v.y = y
    v.z = z
    return v

cdef inline pose3_t pose3(vec3_t t, quat_t q) noexcept nogil:
    cdef pose3_t p
    p.t = t
    p.q = q
    return p

cdef inline twist3_t twist3(double dx, double dy, double dz, double rx, double ry,
                            double rz) noexcept nogil:
    cdef twist3_t t
    t.dx = dx
    t.dy = dy
    t.dz = dz
    t.rx = rx
    t.ry = ry
    t.rz = rz
    return t

cdef inline quat_t q_identity() noexcept nogil:
    return quat(1.0, 0.0, 0.0, 0.0)

cdef inline vec3_t v3_add(vec3_t a, vec3_t b) noexcept nogil:
    return vec3(a.x + b.x, a.y + b.y, a.z + b.z)

cdef inline vec3_t v3_sub(vec3_t a, vec3_t b) noexcept nogil:
    return vec3(a.x - b.x, a.y - b.y, a.z - b.z)

cdef inline vec3_t v3_scale(vec3_t a, double k) noexcept nogil:
    return vec3(a.x * k, a.y * k, a.z * k)

cdef inline double v3_dot(vec3_t a, vec3_t b) noexcept nogil:
    return a.x * b.x + a.y * b.y + a.z * b.z

cdef inline vec3_t v3_cross(vec3_t a, vec3_t b) noexcept nogil:
    # WPILib's Translation3d.cross / Vector.cross order of operations.
    return vec3(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y)

cdef inline bint v3_eq(vec3_t a, vec3_t b) noexcept nogil:
    # Translation3d.equals: each component within 1e-9 m.
    return fabs(a.x - b.x) < 1e-9 and fabs(a.y - b.y) < 1e-9 and fabs(a.z - b.z) < 1e-9

cdef inline double norm3(double x, double y, double z) noexcept nogil:
    # sqrt(x² + y² + z²) as Java's Math.sqrt of the sum (the same bits wherever the squares
    # neither overflow nor underflow); outside that range the vector is scaled by its
    # largest component first, so a finite vector never gets an infinite or zero norm.
    cdef double r = sqrt(x * x + y * y + z * z)
    cdef double m
    if 1e-150 < r < 1e150 or r != r:
        return r
    m = fabs(x)
    if fabs(y) > m:
        m = fabs(y)
    if fabs(z) > m:
        m = fabs(z)
    if m == 0.0 or m == INFINITY:
        return m
    x = x / m
    y = y / m
    z = z / m
    return m * sqrt(x * x + y * y + z * z)

# ---------------------------------------------------------------------------------------
# Quaternion (WPILib's Quaternion.java, operation for operation)

cdef inline double q_dot(quat_t a, quat_t b) noexcept nogil:
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z

cdef inline double q_max_abs(quat_t q) noexcept nogil:
    # NaN if any component is: the scaled paths below then keep the NaN, as WPILib's do
    # (a bare maximum would skip it, and (0, 0, 0, NaN) would normalise to the identity).
    cdef double m = fabs(q.w)
    if fabs(q.x) > m:
        m = fabs(q.x)
    if fabs(q.y) > m:
        m = fabs(q.y)
    if fabs(q.z) > m:
        m = fabs(q.z)
    if q.x != q.x or q.y != q.y or q.z != q.z:
        return q.x + q.y + q.z
    return m

cdef inline int q_exponent(quat_t q) noexcept nogil:
    # e with q's largest component in [2^(e-1), 2^e) (0 for a zero, infinite or NaN one):
    # q_ldexp(q, -e) brings it into [0.5, 1), where the squared norm, in [0.25, 4],
    # neither overflows nor underflows. Scaling by a power of two changes no bit that
    # matters (ldexp is exact; it can drop only bits far below the largest component's).
    cdef double m = q_max_abs(q)
    cdef int e = 0
    if m == 0.0 or not m < INFINITY:
        return 0
    frexp(m, &e)
    return e

cdef inline quat_t q_ldexp(quat_t q, int e) noexcept nogil:
    return quat(ldexp(q.w, e), ldexp(q.x, e), ldexp(q.y, e), ldexp(q.z, e))

cdef inline double q_norm(quat_t q) noexcept nogil:
    # sqrt(((w² + x²) + y²) + z²), WPILib's bits wherever the squared norm is a normal
    # double; outside (a subnormal or zero sum of nonzero squares, or an overflowing one)
    # the norm of q scaled by an exact power of two, scaled back: never 0 or inf for a
    # finite nonzero q whose norm is representable.
    cdef double s = q_dot(q, q)
    cdef int e
    if DBL_MIN <= s <= DBL_MAX:
        return sqrt(s)
    e = q_exponent(q)
    q = q_ldexp(q, -e)
    return ldexp(sqrt(q_dot(q, q)), e)

cdef inline quat_t q_mul(quat_t a, quat_t b) noexcept nogil:
    # Hamilton product a·b: r = r₁r₂ − v₁·v₂, v = r₁v₂ + r₂v₁ + v₁×v₂.
    cdef double dot = a.x * b.x + a.y * b.y + a.z * b.z
    cdef double cx = a.y * b.z - b.y * a.z
    cdef double cy = b.x * a.z - a.x * b.z
    cdef double cz = a.x * b.y - b.x * a.y
    return quat(a.w * b.w - dot,
                a.w * b.x + b.w * a.x + cx,
                a.w * b.y + b.w * a.y + cy,
                a.w * b.z + b.w * a.z + cz)

cdef inline quat_t q_scale(quat_t q, double k) noexcept nogil:
    return quat(q.w * k, q.x * k, q.y * k, q.z * k)

cdef inline quat_t q_div(quat_t q, double k) noexcept nogil:
    return quat(q.w / k, q.x / k, q.y / k, q.z / k)

cdef inline quat_t q_conjugate(quat_t q) noexcept nogil:
    return quat(q.w, -q.x, -q.y, -q.z)

cdef inline quat_t q_inverse(quat_t q) noexcept nogil:
    # conjugate / norm² (norm squared, as WPILib computes it: not the dot product).
    cdef double s = q_dot(q, q)
    cdef double n
    cdef int e
    if DBL_MIN <= s <= DBL_MAX:
        n = sqrt(s)
        return q_div(q_conjugate(q), n * n)
    # q⁻¹ = p⁻¹·2^-e for p = q·2^-e, whose norm² is normal.
    e = q_exponent(q)
    q = q_ldexp(q, -e)
    n = sqrt(q_dot(q, q))
    return q_ldexp(q_div(q_conjugate(q), n * n), -e)

cdef inline quat_t q_normalize(quat_t q) noexcept nogil:
    # n = sqrt(((w² + x²) + y²) + z²), each component / n (WPILib C++'s bits) wherever the
    # squared norm is a normal double. Outside, q is first scaled by the exact power of
    # two that brings its largest component into [0.5, 1): a subnormal squared norm loses
    # the low bits of the sum (0, 0, 0, 4.2e-160) would become z = 1.0000018) and an
    # overflowing one gives (0, 0, 0, 0). A zero quaternion gives the identity.
    cdef double s = q_dot(q, q)
    if DBL_MIN <= s <= DBL_MAX:
        return q_div(q, sqrt(s))
    if q_max_abs(q) == 0.0:
        return q_identity()
    q = q_ldexp(q, -q_exponent(q))
    return q_div(q, sqrt(q_dot(q, q)))

cdef inline bint q_eq(quat_t a, quat_t b) noexcept nogil:
    # Quaternion.equals: the same direction and the same norm (q and −q differ).
    cdef double na = q_norm(a), nb = q_norm(b)
    return fabs(q_dot(a, b) - na * nb) < 1e-9 and fabs(na - nb) < 1e-9

cdef inline quat_t q_exp(quat_t q) noexcept nogil:
    # (The vector norm is norm3's: sqrt of the sum of squares, WPILib's bits, wherever
    # that sum is representable.)
    cdef double scalar = exp(q.w)
    cdef double m = norm3(q.x, q.y, q.z)
    cdef double s, c, k, m2
    sincos(m, &s, &c)
    if m < 1e-9:
        m2 = m * m
        k = 1.0 - m2 / 6.0 + m2 * m2 / 120.0
    else:
        k = s / m
    return quat(c * scalar, q.x * k * scalar, q.y * k * scalar, q.z * k * scalar)

cdef inline quat_t q_log(quat_t q) noexcept nogil:
    # The factor atan2(‖v‖, w)/‖v‖ does not depend on q's norm, so it is computed on q
    # scaled by an exact power of two where the largest component is outside
    # [1e-90, 1e90], and its series taken for ‖v‖ < 1e-9·|w| (see q_to_rvec).
    cdef double n = q_norm(q)
    cdef double scalar, vn, w, k, m
    cdef quat_t p = q
    cdef int e
    if n == 0.0:
        return quat(0.0, 0.0, 0.0, 0.0)
    scalar = log(n)
    m = q_max_abs(q)
    if not 1e-90 <= m <= 1e90:
        e = q_exponent(q)
        p = q_ldexp(q, -e)
        if not n < INFINITY:    # ln‖q‖ = ln‖p‖ + e ln 2 (‖q‖ itself overflows)
            scalar = log(sqrt(q_dot(p, p))) + e * M_LN2
    vn = sqrt(p.x * p.x + p.y * p.y + p.z * p.z)
    w = p.w
    if fabs(q.w / n + 1.0) < 1e-9:
        return quat(scalar, -M_PI, 0.0, 0.0)
    if vn < 1e-9 * fabs(w):
        k = 1.0 / w - 1.0 / 3.0 * vn * vn / (w * w * w)
    elif vn == 0.0:
        k = 0.0
    else:
        k = atan2(vn, w) / vn
    return quat(scalar, k * p.x, k * p.y, k * p.z)

cdef inline quat_t q_pow(quat_t q, double t) noexcept nogil:
    return q_exp(q_scale(q_log(q), t))

cdef inline vec3_t q_to_rvec(quat_t q) noexcept nogil:
    # Quaternion.toRotationVector: the short way round, |θ| <= π. The result does not
    # depend on q's norm, so a q whose largest component is outside [1e-90, 1e90] is
    # first scaled by an exact power of two (the series' n²/w³ and the 1/n cannot then
    # underflow or overflow). WPILib's series is taken for n < 1e-9·|w| (for a unit q,
    # |w| rounds to 1 there, so that is its n < 1e-9; for another q, n < 1e-9 alone would
    # take the series where n is not small against w: (1e-12, 1e-12, 0, 0) would give 2
    # rad, not π/2). A zero quaternion (no rotation; normalize() makes it the identity)
    # gives (0, 0, 0).
    cdef double m = q_max_abs(q)
    cdef double n, k
    if not 1e-90 <= m <= 1e90:
        if m == 0.0:
            return vec3(0.0, 0.0, 0.0)
        q = q_ldexp(q, -q_exponent(q))
    n = sqrt(q.x * q.x + q.y * q.y + q.z * q.z)
    if n < 1e-9 * fabs(q.w):
        k = 2.0 / q.w - 2.0 / 3.0 * n * n / (q.w * q.w * q.w)
    elif q.w < 0.0:
        k = 2.0 * atan2(-n, -q.w) / n
    else:
        k = 2.0 * atan2(n, q.w) / n
    return vec3(k * q.x, k * q.y, k * q.z)

cdef inline double half_norm(vec3_t r, double theta) noexcept nogil:
    # θ/2 for θ = ‖r‖; for a finite r whose norm is beyond the largest double (up to √3
    # times it), ‖r/2‖, which is not.
    if theta < INFINITY or theta != theta:
        return theta / 2.0
    return norm3(r.x * 0.5, r.y * 0.5, r.z * 0.5)

cdef inline quat_t q_from_rvec_static(vec3_t r) noexcept nogil:
    # Quaternion.fromRotationVector (static): (cos θ/2, r·sin(θ/2)/θ), not normalised.
    cdef double theta = norm3(r.x, r.y, r.z)
    cdef double half = half_norm(r, theta)
    cdef double s, c, k
    sincos(half, &s, &c)
    if theta < 1e-9:
        k = 1.0 / 2.0 - theta * theta / 48.0
    elif theta > 1e300:
        # sin(θ/2)/θ would be subnormal (or 0) and lose the bits k·r keeps; (r/2)/(θ/2)
        # is r/θ exactly, and finite where θ overflows.
        return quat(c, r.x * 0.5 / half * s, r.y * 0.5 / half * s, r.z * 0.5 / half * s)
    else:
        k = s / theta
    return quat(c, k * r.x, k * r.y, k * r.z)

# ---------------------------------------------------------------------------------------
# Rotation3d constructors (the stored quaternion)

cdef inline quat_t q_from_euler(double roll, double pitch, double yaw) noexcept nogil:
    # Extrinsic X (roll), then Y (pitch), then Z (yaw), about the fixed axes.
    cdef double cr, sr, cp, sp, cy, sy
    sincos(roll * 0.5, &sr, &cr)
    sincos(pitch * 0.5, &sp, &cp)
    sincos(yaw * 0.5, &sy, &cy)
    return quat(cr * cp * cy + sr * sp * sy,
                sr * cp * cy - cr * sp * sy,
                cr * sp * cy + sr * cp * sy,
                cr * cp * sy - sr * sp * cy)

cdef inline quat_t q_from_axis_half(vec3_t axis, double half) noexcept nogil:
    # Rotation3d(axis, angle) with half = angle/2: Java's axis·(1/‖axis‖)·sin(angle/2); a
    # zero axis gives the identity (silently, as WPILib). An axis whose norm is outside
    # [1e-300, 1e300] is first scaled by an exact power of two: a subnormal norm's
    # 1/‖axis‖ is inf (0·inf is NaN), a huge one's subnormal (imprecise) or 0.
    cdef double n = norm3(axis.x, axis.y, axis.z)
    cdef double s, c, inv
    cdef quat_t q
    if n == 0.0:
        return q_identity()
    if not 1e-300 <= n <= 1e300:
        q = q_ldexp(quat(0.0, axis.x, axis.y, axis.z), -q_exponent(
            quat(0.0, axis.x, axis.y, axis.z)))
        axis = vec3(q.x, q.y, q.z)
        n = norm3(axis.x, axis.y, axis.z)
    sincos(half, &s, &c)
    inv = 1.0 / n
    return quat(c, axis.x * inv * s, axis.y * inv * s, axis.z * inv * s)

cdef inline quat_t q_from_axis_angle(vec3_t axis, double angle) noexcept nogil:
    return q_from_axis_half(axis, angle / 2.0)

cdef inline quat_t q_from_rvec(vec3_t r) noexcept nogil:
    # Rotation3d(rvec) = Rotation3d(rvec, ‖rvec‖) (the half angle finite where the norm
    # overflows).
    return q_from_axis_half(r, half_norm(r, norm3(r.x, r.y, r.z)))

cdef inline quat_t q_from_matrix(const double* R) noexcept nogil:
    # Rotation3d(Matrix3): the trace / largest-diagonal branches (R row-major, already
    # checked to be a rotation), then normalised: WPILib keeps the quaternion as it comes
    # out (unit only to about the 1e-9 of the checks), drivekin keeps every stored
    # rotation unit (see q_renorm).
    cdef double trace = R[0] + R[4] + R[8]
    cdef double s
    cdef quat_t q
    if trace > 0.0:
        s = 0.5 / sqrt(trace + 1.0)
        q = quat(0.25 / s, (R[7] - R[5]) * s, (R[2] - R[6]) * s, (R[3] - R[1]) * s)
    elif R[0] > R[4] and R[0] > R[8]:
        s = 2.0 * sqrt(1.0 + R[0] - R[4] - R[8])
        q = quat((R[7] - R[5]) / s, 0.25 * s, (R[1] + R[3]) / s, (R[2] + R[6]) / s)
    elif R[4] > R[8]:
        s = 2.0 * sqrt(1.0 + R[4] - R[0] - R[8])
        q = quat((R[2] - R[6]) / s, (R[1] + R[3]) / s, 0.25 * s, (R[5] + R[7]) / s)
    else:
        s = 2.0 * sqrt(1.0 + R[8] - R[0] - R[4])
        q = quat((R[3] - R[1]) / s, (R[2] + R[6]) / s, (R[5] + R[7]) / s, 0.25 * s)
    return q_normalize(q)

cdef inline double matrix_orthogonality(const double* R) noexcept nogil:
    # ‖R·Rᵀ − I‖_F (row-major R).
    cdef double acc = 0.0, d
    cdef int i, j
    for i in range(3):
        for j in range(3):
            d = R[3 * i] * R[3 * j] + R[3 * i + 1] * R[3 * j + 1] + R[3 * i + 2] * R[3 * j + 2]
            if i == j:
                d = d - 1.0
            acc = acc + d * d
    return sqrt(acc)

cdef inline double matrix_det(const double* R) noexcept nogil:
    return (R[0] * (R[4] * R[8] - R[5] * R[7])
            - R[1] * (R[3] * R[8] - R[5] * R[6])
            + R[2] * (R[3] * R[7] - R[4] * R[6]))

cdef inline vec3_t v3_tame(vec3_t v) noexcept nogil:
    cdef quat_t q = quat(0.0, v.x, v.y, v.z)
    cdef double m = q_max_abs(q)
    if 1e-75 <= m <= 1e75:
        return v
    q = q_ldexp(q, -q_exponent(q))
    return vec3(q.x, q.y, q.z)

cdef inline quat_t q_from_vectors(vec3_t a, vec3_t b) noexcept nogil:
    # Rotation3d(initial, last): the shortest rotation taking a's direction onto b's.
    # Only the directions matter, so a vector whose largest component is outside
    # [1e-75, 1e75] is first scaled by an exact power of two (its dot and cross products
    # would underflow or overflow: a NaN c, then the identity, for a right angle).
    cdef double dot, np_, c
    cdef double ax, ay, az, n
    cdef vec3_t e, axis
    a = v3_tame(a)
    b = v3_tame(b)
    dot = v3_dot(a, b)
    np_ = norm3(a.x, a.y, a.z) * norm3(b.x, b.y, b.z)
    c = dot / np_
    if c > 1.0 - 1e-9:
        return q_identity()
    if c < -1.0 + 1e-9:
        # Antiparallel: a half turn about a × e, e the basis axis WPILib picks.
        ax = fabs(a.x)
        ay = fabs(a.y)
        az = fabs(a.z)
        if ax < ay:
            e = vec3(1.0, 0.0, 0.0) if ax < az else vec3(0.0, 0.0, 1.0)
        else:
            e = vec3(0.0, 1.0, 0.0) if ay < az else vec3(0.0, 0.0, 1.0)
        axis = v3_cross(a, e)
        n = norm3(axis.x, axis.y, axis.z)
        return quat(0.0, axis.x / n, axis.y / n, axis.z / n)
    # (A NaN c, from a zero vector, lands here too and ends as the identity, as in WPILib.)
    axis = v3_cross(a, b)
    return q_normalize(quat(np_ + dot, axis.x, axis.y, axis.z))

# ---------------------------------------------------------------------------------------
# Rotation3d operations. A stored rotation's quaternion is unit to a few ulps (or NaN):
# every constructor normalises, and products are renormalised by q_renorm.

cdef inline quat_t q_renorm(quat_t q) noexcept nogil:
    # q/‖q‖ for a product of unit quaternions (‖q‖² = 1 + δ, |δ| a few ulps): one Newton
    # step for 1/sqrt(‖q‖²) from 1, q·(1.5 − ‖q‖²/2), leaves |δ|²-sized error, below the
    # rounding of the multiplications: WPILib's sqrt and four divisions without either.
    return q_scale(q, 1.5 - 0.5 * q_dot(q, q))

cdef inline quat_t rot3_inverse(quat_t q) noexcept nogil:
    # The conjugate: WPILib's normalize(conjugate / norm²) of a unit quaternion.
    return q_conjugate(q)

cdef inline quat_t rot3_rotate_by(quat_t q, quat_t o) noexcept nogil:
    # q.rotateBy(o) = o·q: o applied about the fixed (extrinsic) axes.
    return q_renorm(q_mul(o, q))

cdef inline quat_t rot3_relative_to(quat_t q, quat_t o) noexcept nogil:
    # q.relativeTo(o) = o⁻¹·q.
    return q_renorm(q_mul(q_conjugate(o), q))

cdef inline quat_t q_exp_pure(double x, double y, double z) noexcept nogil:
    # Quaternion.exp of (0, x, y, z) without its scalar factor e^0: (cos m, v·sin m/m),
    # m = ‖v‖, the series below 1e-9 as in Quaternion.exp.
    cdef double m = norm3(x, y, z)
    cdef double s, c, k, m2
    sincos(m, &s, &c)
    if m < 1e-9:
        m2 = m * m
        k = 1.0 - m2 / 6.0 + m2 * m2 / 120.0
    else:
        k = s / m
    return quat(c, x * k, y * k, z * k)

cdef inline quat_t rot3_interpolate(quat_t q0, quat_t q1, double t) noexcept nogil:
    # Slerp the short way, t not clamped: (q1·q0⁻¹)^t·q0, the power as WPILib's
    # (log(d)·t).exp() but without its scalar part e^(t·ln‖d‖): that scales the result
    # uniformly and the renormalisation takes it out again, so it is left away (no libm
    # call, and a huge t cannot blow the norm up).
    cdef quat_t d = q_mul(q1, q_conjugate(q0))
    cdef double vn, k
    if d.w < 0.0:
        d = quat(-d.w, -d.x, -d.y, -d.z)
    vn = sqrt(d.x * d.x + d.y * d.y + d.z * d.z)
    if vn < 1e-9 and d.w != 0.0:
        k = 1.0 / d.w - 1.0 / 3.0 * vn * vn / (d.w * d.w * d.w)
    elif vn == 0.0:
        k = 0.0
    else:
        k = atan2(vn, d.w) / vn
    k = k * t
    return q_renorm(q_mul(q_exp_pure(d.x * k, d.y * k, d.z * k), q0))

cdef inline quat_t rot3_times(quat_t q, double k) noexcept nogil:
    # Rotation3d.times(k) = kZero.interpolate(this, k).
    return rot3_interpolate(q_identity(), q, k)

cdef inline quat_t rot3_integrate(quat_t q, double p, double r, double y,
                                  double dt) noexcept nogil:
    # q·exp((0, p, r, y)·dt/2): body-frame rates (roll, pitch, yaw), rad/s, over dt s.
    cdef double h = dt / 2.0
    return q_renorm(q_mul(q, q_exp_pure(p * h, r * h, y * h)))

cdef inline bint rot3_eq(quat_t a, quat_t b) noexcept nogil:
    # Rotation3d.equals: q and −q alike; within about 8.9e-5 rad.
    return fabs(fabs(q_dot(a, b)) - q_norm(a) * q_norm(b)) < 1e-9

cdef inline double rot3_x(quat_t q) noexcept nogil:
    # Roll; 0 at gimbal lock.
    cdef double cxcy = 1.0 - 2.0 * (q.x * q.x + q.y * q.y)
    cdef double sxcy = 2.0 * (q.w * q.x + q.y * q.z)
    if cxcy * cxcy + sxcy * sxcy > 1e-20:
        return atan2(sxcy, cxcy)
    return 0.0

cdef inline double rot3_y(quat_t q) noexcept nogil:
    # Pitch, ±π/2 once the sine 2(wy − zx) reaches ±1. WPILib takes asin of that sine,
    # whose slope is infinite at ±1: a sine 1e-16 short of 1, one rounding, is 1.5e-8 rad
    # short of π/2 (WPILib's own gimbal-lock test fails by that much on drivekin's bits).
    # atan2 of the sine over |cos pitch|, read off the roll terms as
    # sqrt((1 − 2(x² + y²))² + (2(wx + yz))²), is the same angle without that
    # amplification: a few ulps everywhere.
    cdef double ratio = 2.0 * (q.w * q.y - q.z * q.x)
    cdef double cxcy, sxcy
    if fabs(ratio) >= 1.0:
        return copysign(M_PI / 2.0, ratio)
    cxcy = 1.0 - 2.0 * (q.x * q.x + q.y * q.y)
    sxcy = 2.0 * (q.w * q.x + q.y * q.z)
    return atan2(ratio, sqrt(cxcy * cxcy + sxcy * sxcy))

cdef inline double rot3_z(quat_t q) noexcept nogil:
    # Yaw; at gimbal lock atan2(2wz, w² − z²).
    cdef double cycz = 1.0 - 2.0 * (q.y * q.y + q.z * q.z)
    cdef double cysz = 2.0 * (q.w * q.z + q.x * q.y)
    if cycz * cycz + cysz * cysz > 1e-20:
        return atan2(cysz, cycz)
    return atan2(2.0 * q.w * q.z, q.w * q.w - q.z * q.z)

cdef inline vec3_t q_to_euler(quat_t q) noexcept nogil:
    # (getX, getY, getZ): roll, pitch, yaw in rad.
    return vec3(rot3_x(q), rot3_y(q), rot3_z(q))

cdef inline double rot3_angle(quat_t q) noexcept nogil:
    # 2·atan2(‖v‖, w), in [0, 2π].
    return 2.0 * atan2(sqrt(q.x * q.x + q.y * q.y + q.z * q.z), q.w)

cdef inline vec3_t rot3_apply(quat_t q, vec3_t v) noexcept nogil:
    # Translation3d.rotateBy, q·(0, v)·q⁻¹ for a unit q: v + w·t + q_v × t with
    # t = 2 q_v × v (no square root, no division).
    cdef vec3_t qv = vec3(q.x, q.y, q.z)
    cdef vec3_t t = v3_cross(qv, v)
    cdef vec3_t c
    t = vec3(2.0 * t.x, 2.0 * t.y, 2.0 * t.z)
    c = v3_cross(qv, t)
    return vec3(v.x + q.w * t.x + c.x, v.y + q.w * t.y + c.y, v.z + q.w * t.z + c.z)

cdef inline rot2_t rot3_yaw(quat_t q) noexcept nogil:
    # Rotation2d(getZ()) as its (cos, sin): the vector whose atan2 getZ takes, normalised
    # (within an ulp of the cosine and sine of that angle; no trigonometry). A zero
    # vector (atan2(0, 0) = 0) gives the identity.
    cdef rot2_t r
    cdef double c = 1.0 - 2.0 * (q.y * q.y + q.z * q.z)
    cdef double s = 2.0 * (q.w * q.z + q.x * q.y)
    cdef double h
    if not c * c + s * s > 1e-20:
        c = q.w * q.w - q.z * q.z
        s = 2.0 * q.w * q.z
    h = sqrt(c * c + s * s)
    if h == 0.0:
        c = 1.0
        h = 1.0
    r.c = c / h
    r.s = s / h
    return r

cdef inline void rot3_matrix(quat_t q, double* R) noexcept nogil:   # OUT: 9, row-major
    cdef double w = q.w, x = q.x, y = q.y, z = q.z
    R[0] = 1.0 - 2.0 * (y * y + z * z)
    R[1] = 2.0 * (x * y - w * z)
    R[2] = 2.0 * (x * z + w * y)
    R[3] = 2.0 * (x * y + w * z)
    R[4] = 1.0 - 2.0 * (x * x + z * z)
    R[5] = 2.0 * (y * z - w * x)
    R[6] = 2.0 * (x * z - w * y)
    R[7] = 2.0 * (y * z + w * x)
    R[8] = 1.0 - 2.0 * (x * x + y * y)

# ---------------------------------------------------------------------------------------
# Pose3d / Transform3d (both pose3_t)

cdef inline pose3_t pose3_plus(pose3_t a, pose3_t b) noexcept nogil:
    # a.transformBy(b): a.t + b.t rotated by a's rotation; rotation b.R.rotateBy(a.R) = a·b.
    # Also Transform3d.plus (WPILib's kZero.transformBy(a).transformBy(b) seen from kZero).
    return pose3(v3_add(a.t, rot3_apply(a.q, b.t)), q_renorm(q_mul(a.q, b.q)))

cdef inline pose3_t pose3_relative_to(pose3_t a, pose3_t o) noexcept nogil:
    # a.relativeTo(o) = Transform3d(o, a): (a.t − o.t) rotated by o.R.inverse(), and
    # a.R.relativeTo(o.R).
    cdef quat_t inv = q_conjugate(o.q)
    return pose3(rot3_apply(inv, v3_sub(a.t, o.t)), q_renorm(q_mul(inv, a.q)))

cdef inline pose3_t pose3_rotate_by(pose3_t p, quat_t r) noexcept nogil:
    # Pose3d.rotateBy: both parts about the origin, extrinsically.
    return pose3(rot3_apply(r, p.t), rot3_rotate_by(p.q, r))

cdef inline pose3_t transform3_inverse(pose3_t tr) noexcept nogil:
    cdef quat_t inv = q_conjugate(tr.q)
    return pose3(rot3_apply(inv, vec3(-tr.t.x, -tr.t.y, -tr.t.z)), inv)

cdef inline pose3_t pose3_times(pose3_t p, double k) noexcept nogil:
    # Pose3d/Transform3d.times: the translation scaled, the rotation slerped from identity.
    return pose3(v3_scale(p.t, k), rot3_times(p.q, k))

# ---------------------------------------------------------------------------------------
# Twist3d.exp / Transform3d.log: exact where WPILib's closed forms cancel.
#
# With r = θ·n̂ the rotation vector and u the twist's translation, exp's translation is
# V·u = u + B (r × u) + C (r × (r × u)), B = (1 − cos θ)/θ², C = (θ − sin θ)/θ³, and log's
# is V⁻¹·u = u − ½ (r × u) + D (r × (r × u)), D = (1 − (θ/2) cot(θ/2))/θ². WPILib's
# B = (1 − cos θ)/θ² loses everything as cos θ rounds towards 1 (error ε/θ per metre: 2e-9
# at θ = 1e-7), and its D = (1 − A/2B)/θ² magnifies that (7e-3 per metre near 1e-7).
# Here, above θ = 1e-3: Bθ = 2 sin²(θ/2)/θ (no subtraction), Cθ² = 1 − sin θ/θ and
# Dθ² = 1 − (θ/2)·w/‖v‖ (the cotangent read off the unit quaternion), each subtracting
# from 1 a quantity known to a few ulps, so the error is a few ulps of |u|; the terms are
# applied to the unit axis n̂, so nothing overflows. Below 1e-3 the Taylor series to θ⁴,
# whose first omitted terms are below 1e-23 relative there. The rotation comes from the
# quaternion (cos θ/2, n̂ sin θ/2) directly, never through a matrix.

cdef inline pose3_t twist3_exp(twist3_t tw) noexcept nogil:
    cdef vec3_t u = vec3(tw.dx, tw.dy, tw.dz)
    cdef vec3_t r = vec3(tw.rx, tw.ry, tw.rz)
    cdef double theta = norm3(r.x, r.y, r.z)
    cdef double t2, sh, ch, k, b, c, inv
    cdef vec3_t a, c1, c2
    cdef double half = half_norm(r, theta)
    sincos(half, &sh, &ch)
    if theta < 1e-3:
        t2 = theta * theta
        k = 0.5 - t2 / 48.0 + t2 * t2 / 3840.0             # sin(θ/2)/θ
        b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0              # B
        c = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0      # C
        a = r
    elif theta > 1e300:
        # θ may overflow (a finite r up to √3 times the largest double): 2/θ = 1/(θ/2)
        # and n̂ = (r/2)/(θ/2), which do not.
        inv = 1.0 / half
        a = vec3(r.x * 0.5 * inv, r.y * 0.5 * inv, r.z * 0.5 * inv)
        b = sh * sh * inv
        c = 1.0 - sh * ch * inv
        r = a
        k = sh
    else:
        inv = 1.0 / theta                                  # one division for the five
        k = sh * inv
        b = 2.0 * sh * sh * inv                            # Bθ = (1 − cos θ)/θ
        c = 1.0 - 2.0 * sh * ch * inv                      # Cθ² = 1 − sin θ/θ
        a = vec3(r.x * inv, r.y * inv, r.z * inv)          # n̂
    c1 = v3_cross(a, u)
    c2 = v3_cross(a, c1)
    return pose3(vec3(u.x + b * c1.x + c * c2.x,
                      u.y + b * c1.y + c * c2.y,
                      u.z + b * c1.z + c * c2.z),
                 q_renorm(quat(ch, r.x * k, r.y * k, r.z * k)))

cdef inline twist3_t pose3_log(pose3_t tr) noexcept nogil:
    cdef twist3_t out
    cdef quat_t q = tr.q
    cdef vec3_t u = tr.t
    cdef double vn = sqrt(q.x * q.x + q.y * q.y + q.z * q.z)
    cdef double w = fabs(q.w)
    cdef double half = atan2(vn, w)                # θ/2, in [0, π/2]
    cdef double theta = 2.0 * half
    cdef double k, t2, d, sgn, inv
    cdef vec3_t r, n, c1, c2
    # The rotation part is WPILib's toRotationVector, the short way round (atan2 is odd in
    # its first argument, so −2·atan2(n, |w|)/n is Java's 2·atan2(−n, −w)/n for w < 0).
    if vn < 1e-9:
        k = 2.0 / q.w - 2.0 / 3.0 * vn * vn / (q.w * q.w * q.w)
        inv = 0.0
    else:
        inv = 1.0 / vn
        k = 2.0 * half * inv
        if q.w < 0.0:
            k = -k
    r = vec3(k * q.x, k * q.y, k * q.z)
    out.rx = r.x
    out.ry = r.y
    out.rz = r.z
    c1 = v3_cross(r, u)
    if theta < 1e-3:
        t2 = theta * theta
        d = 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0   # D
        c2 = v3_cross(r, c1)
    else:
        # n̂ = ±v/‖v‖ (the sign that makes w >= 0, as for r).
        sgn = -inv if q.w < 0.0 else inv
        n = vec3(q.x * sgn, q.y * sgn, q.z * sgn)
        d = 1.0 - half * w * inv                           # Dθ²
        c2 = v3_cross(n, v3_cross(n, u))
    out.dx = u.x - 0.5 * c1.x + d * c2.x
    out.dy = u.y - 0.5 * c1.y + d * c2.y
    out.dz = u.z - 0.5 * c1.z + d * c2.z
    return out

cdef inline pose3_t pose3_interpolate(pose3_t a, pose3_t b, double t) noexcept nogil:
    # Pose3d.interpolate for 0 <= t < 1 (the caller returns a for t < 0 and b for t >= 1):
    # a + ((b − a).log()·t).exp().
    cdef twist3_t tw = pose3_log(pose3_relative_to(b, a))
    tw.dx = tw.dx * t
    tw.dy = tw.dy * t
    tw.dz = tw.dz * t
    tw.rx = tw.rx * t
    tw.ry = tw.ry * t
    tw.rz = tw.rz * t
    return pose3_plus(a, twist3_exp(tw))
