# Kernels: `cdef inline ... noexcept nogil` on C doubles, defined here once so every
# module that cimports them gets them inlined. No Python objects, no numpy.
# Output parameters come last and are marked OUT. Formulas follow WPILib 2027
# (docs/DESIGN.md says where drivekin's numbers differ); the comments say where the
# formulas are subtle.

from libc.math cimport INFINITY, fabs, signbit, sqrt
from drivekin._core.dkmath cimport atan2, hypot, sincos, sincos_product
from drivekin._core.types cimport desat_t, dswerve_t, pose2_t, rot2_t, twist2_t, vec2_t, vec3_t

# ---------------------------------------------------------------------------------------
# Java Math.max/min: NaN wins (C fmax/fmin would drop it and change which branch runs).

cdef inline double jmax(double a, double b) noexcept nogil:
    if a != a:
        return a
    if b != b:
        return b
    return a if a >= b else b

cdef inline double jmin(double a, double b) noexcept nogil:
    if a != a:
        return a
    if b != b:
        return b
    return a if a <= b else b

cdef inline bint java_equals(double a, double b) noexcept nogil:
    # Double.compare(a, b) == 0: NaN equals NaN, 0.0 differs from -0.0.
    if a != a or b != b:
        return a != a and b != b
    return a == b and signbit(a) == signbit(b)

cdef inline double clamp01(double t) noexcept nogil:
    # MathUtil.clamp(t, 0, 1); NaN stays NaN.
    return jmax(0.0, jmin(t, 1.0))

cdef inline double fhypot(double x, double y) noexcept nogil:
    # sqrt(x² + y²) inlines (-fno-math-errno) and is within an ulp of hypot, a call that
    # costs more than the rest of a module's inverse kinematics. hypot (dkmath's) is kept
    # where squaring could overflow or underflow and for non-finite input (hypot(inf, nan)
    # = inf).
    cdef double r = sqrt(x * x + y * y)
    if 1e-150 < r < 1e150:
        return r
    return hypot(x, y)

# robotpy-wpimath's fromFeet factories convert through the C++ units library, which
# multiplies by the numerator of 1 ft = 381/1250 m and then divides by the denominator;
# the same two roundings give the same bits. Where the product overflows (|feet| above
# about 4.7e305) the length in metres still fits: dividing first gives it, never inf.
cdef inline double feet_to_meters(double feet) noexcept nogil:
    cdef double m = feet * 381.0 / 1250.0
    if fabs(m) == INFINITY and fabs(feet) < INFINITY:
        m = feet / 1250.0 * 381.0
    return m

# ---------------------------------------------------------------------------------------
# Rotation2d

cdef inline rot2_t rot_scaled(double x, double y, double m) noexcept nogil:
    # (x, y) / m with m = |(x, y)|; a vector shorter than 1e-6 (or NaN) gives the identity,
    # as the Rotation2d(x, y) constructor does. The quotients are computed either way and
    # then selected, so loops over rotations (the batch replay's gyro turns) vectorise.
    cdef rot2_t r
    cdef double c = x / m, s = y / m
    cdef bint ok = m > 1e-6
    r.c = c if ok else 1.0
    r.s = s if ok else 0.0
    return r

cdef inline rot2_t rot_xy(double x, double y) noexcept nogil:
    # Rotation2d(x, y) for arbitrary (user) vectors. Where |(x, y)| overflows although x
    # and y are finite (x/inf would make the pair (0, 0)), (x/4, y/4) has the same
    # direction: exactly, as a component that large is, and the other can lose only bits
    # far below the quotient's last.
    cdef double m = hypot(x, y)
    if m == INFINITY and fabs(x) < INFINITY and fabs(y) < INFINITY:
        x = 0.25 * x
        y = 0.25 * y
        m = hypot(x, y)
    return rot_scaled(x, y, m)

cdef inline rot2_t rot_unit(double x, double y) noexcept nogil:
    # Re-normalising products of rotations (unit length up to rounding): sqrt(x² + y²)
    # inlines where libm hypot is a call guarding against overflow these cannot reach.
    return rot_scaled(x, y, sqrt(x * x + y * y))

cdef inline rot2_t rot_rad(double theta) noexcept nogil:
    cdef double c, s
    sincos(theta, &s, &c)
    return rot_cs(c, s)

cdef inline rot2_t rot_cs(double c, double s) noexcept nogil:
    # A rotation from cos θ and sin θ already computed (no normalisation).
    cdef rot2_t r
    r.c = c
    r.s = s
    return r

cdef inline double rot_radians(rot2_t r) noexcept nogil:
    return atan2(r.s, r.c)

cdef inline rot2_t rot_plus(rot2_t a, rot2_t b) noexcept nogil:
    # a.rotateBy(b), re-normalised through the (x, y) constructor as in WPILib.
    return rot_unit(a.c * b.c - a.s * b.s, a.c * b.s + a.s * b.c)

cdef inline rot2_t rot_neg(rot2_t a) noexcept nogil:
    return rot_unit(a.c, -a.s)

cdef inline rot2_t rot_minus(rot2_t a, rot2_t b) noexcept nogil:
    return rot_plus(a, rot_neg(b))

cdef inline rot2_t rot_times(rot2_t a, double k) noexcept nogil:
    # Scales the *wrapped* angle (2027): 270 deg * 0.5 = -45 deg.
    return rot_rad(rot_radians(a) * k)

cdef inline rot2_t rot_interp(rot2_t a, rot2_t b, double t) noexcept nogil:
    # Shortest way round, t not clamped (2027).
    return rot_plus(a, rot_times(rot_minus(b, a), t))

cdef inline bint rot_eq(rot2_t a, rot2_t b) noexcept nogil:
    return hypot(a.c - b.c, a.s - b.s) < 1e-9

# ---------------------------------------------------------------------------------------
# Translation2d

cdef inline vec2_t vec(double x, double y) noexcept nogil:
    cdef vec2_t v
    v.x = x
    v.y = y
    return v

cdef inline vec2_t vec_rotate(vec2_t v, rot2_t r) noexcept nogil:
    return vec(v.x * r.c - v.y * r.s, v.x * r.s + v.y * r.c)

cdef inline bint vec_eq(vec2_t a, vec2_t b) noexcept nogil:
    return fabs(a.x - b.x) < 1e-9 and fabs(a.y - b.y) < 1e-9

# ---------------------------------------------------------------------------------------
# Pose2d / Transform2d (both pose2_t)

cdef inline pose2_t pose(vec2_t t, rot2_t r) noexcept nogil:
    cdef pose2_t p
    p.t = t
    p.r = r
    return p

cdef inline pose2_t pose_transform_by(pose2_t p, pose2_t tr) noexcept nogil:
    cdef vec2_t d = vec_rotate(tr.t, p.r)
    return pose(vec(p.t.x + d.x, p.t.y + d.y), rot_plus(tr.r, p.r))

cdef inline pose2_t pose_relative_to(pose2_t p, pose2_t o) noexcept nogil:
    # Transform2d(o, p): the pose of p seen from o.
    return pose(vec_rotate(vec(p.t.x - o.t.x, p.t.y - o.t.y), rot_neg(o.r)),
                rot_minus(p.r, o.r))

cdef inline pose2_t transform_inverse(pose2_t tr) noexcept nogil:
    cdef rot2_t ninv = rot_neg(tr.r)
    return pose(vec_rotate(vec(-tr.t.x, -tr.t.y), ninv), ninv)

cdef inline pose2_t pose_times(pose2_t p, double k) noexcept nogil:
    return pose(vec(p.t.x * k, p.t.y * k), rot_times(p.r, k))

# ---------------------------------------------------------------------------------------
# Twist2d.exp / Transform2d.log

cdef inline pose2_t twist_exp(double dx, double dy, double dtheta) noexcept nogil:
    cdef double c, s
    sincos(dtheta, &s, &c)
    return twist_exp_cs(dx, dy, dtheta, c, s)

cdef inline pose2_t twist_exp_cs(double dx, double dy, double dtheta,
                                 double ct, double st) noexcept nogil:
    # twist_exp with cos θ and sin θ already known (odometry has the heading change as a
    # rotation before it has the angle).
    cdef double s, c
    if fabs(dtheta) < 1e-9:
        # Series (exact to rounding here): sin θ/θ = 1 − θ²/6, (1 − cos θ)/θ = θ/2.
        s = 1.0 - dtheta * dtheta / 6.0
        c = 0.5 * dtheta
    else:
        s = st / dtheta
        # WPILib's (1 − cos θ)/θ cancels for small θ (cos θ rounds towards 1: at θ = 1e-8
        # it loses everything); sin²θ / (1 + cos θ) is the same quantity without the
        # subtraction while cos θ > 0, and beyond that 1 − cos θ ≥ 1 does not cancel.
        c = (st * st / (1.0 + ct) if ct > 0.0 else 1.0 - ct) / dtheta
    return pose(vec(dx * s - dy * c, dx * c + dy * s), rot_unit(ct, st))

cdef inline double log_k(double theta, double c, double s) noexcept nogil:
    # k = (θ/2)·cot(θ/2) for θ = atan2(s, c). WPILib computes (θ/2)·sin θ / (cos θ − 1),
    # whose cos θ − 1 cancels (relative error ε/|cos θ − 1|: 1e-7 at θ = 5e-5). For
    # cos θ > 0 the same value is (θ/2)(1 + cos θ)/sin θ, with no subtraction; elsewhere
    # cos θ − 1 ≤ −1 is harmless.
    cdef double h = 0.5 * theta
    if fabs(theta) < 1e-9:
        return 1.0 - theta * theta / 12.0
    if c > 0.0:
        return h * (1.0 + c) / s
    return -(h * s) / (c - 1.0)

cdef inline twist2_t transform_log_angle(pose2_t tr, double theta) noexcept nogil:
    # theta must equal atan2(tr.r.s, tr.r.c); callers that already know it skip the atan2.
    cdef twist2_t tw
    cdef double h = 0.5 * theta
    cdef double k = log_k(theta, tr.r.c, tr.r.s)
    # WPILib rotates by the normalised (k, -h) and rescales by hypot(k, h); that is the
    # linear map below up to rounding (k >= 0 here, so the normalisation never degenerates).
    tw.dx = k * tr.t.x + h * tr.t.y
    tw.dy = -h * tr.t.x + k * tr.t.y
    tw.dtheta = theta
    return tw

cdef inline twist2_t transform_log(pose2_t tr) noexcept nogil:
    return transform_log_angle(tr, rot_radians(tr.r))

cdef inline pose2_t pose_interpolate(pose2_t a, pose2_t b, double t) noexcept nogil:
    # Pose2d.interpolate: along the constant-curvature arc from a to b; t < 0 gives a and
    # t >= 1 gives b (WPILib's clamp); a NaN t propagates.
    cdef twist2_t tw
    if t < 0.0:
        return a
    if t >= 1.0:
        return b
    tw = transform_log(pose_relative_to(b, a))
    return pose_transform_by(a, twist_exp(tw.dx * t, tw.dy * t, tw.dtheta * t))

# ---------------------------------------------------------------------------------------
# ChassisVelocities

cdef inline vec3_t chassis_discretize(double vx, double vy, double omega, double dt) noexcept nogil:
    cdef double theta = omega * dt, c, s
    sincos(theta, &s, &c)
    return chassis_discretize_cs(vx, vy, omega, dt, theta, c, s)

cdef inline vec3_t chassis_discretize_cs(double vx, double vy, double omega, double dt,
                                         double theta, double ct, double st) noexcept nogil:
    # chassis_discretize with theta = omega*dt and its cos and sin already known (the batch
    # module computes those four at a time).
    # WPILib's Transform2d.log of (vx·dt, vy·dt, Rotation2d(θ)) over dt, with dt cancelled:
    # (k·vx + h·vy, −h·vx + k·vy, φ/dt), φ = θ wrapped by the Rotation2d, h = φ/2,
    # k = h·cot h (so 0 ≤ k ≤ 1, |h| ≤ π/2). Neither v·dt nor any quotient by dt is formed,
    # so finite input gives a finite result unless that result exceeds the doubles.
    cdef vec3_t out
    cdef double phi, h, k
    if dt == 0.0:
        # WPILib divides the log (0, 0, 0) by dt unguarded: 0/0 in every field.
        out.x = out.y = out.z = 0.0 / dt
        return out
    if fabs(theta) < 3.0:
        # atan2(sin θ, cos θ) returns θ (to rounding) inside (−π, π), so no wrap: ω itself
        # (θ/dt to rounding, and still ω where θ underflowed).
        phi = theta
        out.z = omega
    else:
        if theta == INFINITY or theta == -INFINITY:
            if fabs(omega) < INFINITY and fabs(dt) < INFINITY:
                # θ overflowed: its 53 bits with a wider exponent, wrapped as any angle.
                sincos_product(omega, dt, &st, &ct)
        phi = atan2(st, ct)
        out.z = phi / dt
    h = 0.5 * phi
    k = log_k(phi, ct, st)
    if fabs(vx) > 1e300 or fabs(vy) > 1e300:
        # h·vy can overflow although the sum fits (|h| < 2): a sixteenth, then scaled
        # back; exact for the large component, and a small one loses only bits far below
        # the result's last.
        vx = vx * 0.0625
        vy = vy * 0.0625
        out.x = (k * vx + h * vy) * 16.0
        out.y = (-h * vx + k * vy) * 16.0
    else:
        out.x = k * vx + h * vy
        out.y = -h * vx + k * vy
    return out

# ---------------------------------------------------------------------------------------
# Swerve module loops. Module i sits at (rx[i], ry[i]) relative to the centre of rotation.
# Headings (hc, hs) are the kinematics object's heading memory, read and written here.

cdef inline void swerve_ik(Py_ssize_t n, const double* rx, const double* ry,
                           double vx, double vy, double omega,
                           double* hc, double* hs,                  # IN/OUT heading memory
                           double* speed, double* oc, double* os    # OUT
                           ) noexcept nogil:
    cdef Py_ssize_t i
    cdef double x, y, v
    if vx == 0.0 and vy == 0.0 and omega == 0.0:
        # Exact zero: report the remembered headings and leave them alone.
        for i in range(n):
            speed[i] = 0.0
            oc[i] = hc[i]
            os[i] = hs[i]
        return
    for i in range(n):
        # Row pair of the 2N x 3 matrix [1, 0, -ry; 0, 1, rx], summed in matrix order so
        # that a non-finite input spreads exactly as it does in WPILib (0 * inf = NaN).
        x = vx + 0.0 * vy + (-ry[i]) * omega
        y = 0.0 * vx + vy + rx[i] * omega
        v = fhypot(x, y)
        if v > 1e-6:
            # Rotation2d(x, y) normalises by this same length.
            hc[i] = x / v
            hs[i] = y / v
        speed[i] = v
        oc[i] = hc[i]
        os[i] = hs[i]

cdef inline void swerve_ik_accel(Py_ssize_t n, const double* rx, const double* ry,
                                 double ax, double ay, double omega, double alpha,
                                 double* acc, double* oc, double* os   # OUT
                                 ) noexcept nogil:
    cdef Py_ssize_t i
    cdef double x, y, a, w2 = omega * omega
    if ax == 0.0 and ay == 0.0 and alpha == 0.0:
        # WPILib skips the centripetal term here even when omega != 0.
        for i in range(n):
            acc[i] = 0.0
            oc[i] = 1.0
            os[i] = 0.0
        return
    for i in range(n):
        # Rows [1, 0, -rx, -ry; 0, 1, -ry, rx] times [ax, ay, omega^2, alpha].
        x = ax + 0.0 * ay + (-rx[i]) * w2 + (-ry[i]) * alpha
        y = 0.0 * ax + ay + (-ry[i]) * w2 + rx[i] * alpha
        a = fhypot(x, y)
        acc[i] = a
        if a > 1e-6:
            oc[i] = x / a
            os[i] = y / a
        else:
            # No heading memory for accelerations: zero magnitude points along +x.
            oc[i] = 1.0
            os[i] = 0.0

cdef inline void forward_solve(Py_ssize_t rows, Py_ssize_t n, const double* f,
                               const double* mag, const double* c, const double* s,
                               double* out                               # OUT, rows values
                               ) noexcept nogil:
    # out = F . w with w = [mag_i cos_i, mag_i sin_i, ...]; F is rows x 2n, row-major
    # (the pseudo-inverse of the inverse-kinematics matrix, fixed at CoR = 0).
    cdef Py_ssize_t k, i
    cdef double wx, wy
    for k in range(rows):
        out[k] = 0.0
    for i in range(n):
        wx = mag[i] * c[i]
        wy = mag[i] * s[i]
        for k in range(rows):
            out[k] = out[k] + f[k * 2 * n + 2 * i] * wx + f[k * 2 * n + 2 * i + 1] * wy

cdef inline void forward_solve_many(Py_ssize_t rows, Py_ssize_t n, Py_ssize_t count,
                                    const double* f, const double* mag, const double* c,
                                    const double* s,
                                    double* out                 # OUT, rows x count values
                                    ) noexcept nogil:
    # forward_solve for count samples stored module-major (module i of sample t at
    # [i * count + t]; row k of sample t goes to out[k * count + t]), for the batch replay.
    # Each sample gets forward_solve's operations in its order (tests/behaviour/
    # test_batch.py compares the bits), but the innermost loop runs over the independent samples, so it vectorises.
    # forward_solve itself stays separate: with count = 1 this form recomputes the products
    # for every row (out may alias them), about 3 % more instructions per call.
    cdef Py_ssize_t k, i, t
    cdef double fx, fy
    cdef const double* mi
    cdef const double* ci
    cdef const double* si
    cdef double* ok
    for k in range(rows * count):
        out[k] = 0.0
    for i in range(n):
        mi = mag + i * count
        ci = c + i * count
        si = s + i * count
        for k in range(rows):
            fx = f[k * 2 * n + 2 * i]
            fy = f[k * 2 * n + 2 * i + 1]
            ok = out + k * count
            for t in range(count):
                ok[t] = ok[t] + fx * (mi[t] * ci[t]) + fy * (mi[t] * si[t])

cdef inline double swerve_top_speed(Py_ssize_t n, const double* mx, const double* my,
                                    vec3_t v) noexcept nogil:
    # The fastest module's speed (m/s) for robot velocities v about the robot origin.
    cdef Py_ssize_t i
    cdef double top = 0.0, s
    for i in range(n):
        s = fhypot(v.x + (-my[i]) * v.z, v.y + mx[i] * v.z)
        if s > top:
            top = s
    return top

cdef inline double desaturated_discretize_scale(Py_ssize_t n, const double* mx,
                                                const double* my, double vx, double vy,
                                                double omega, double dt,
                                                double limit) noexcept nogil:
    # The largest k in [0, 1] for which discretize(k·v, dt) keeps every module at most
    # `limit`. Scaling before discretizing keeps the direction of motion (scaling after
    # turns it by (k − 1)·ω·dt/2). The top speed is close to linear in k but not exactly
    # (the discretize correction grows with k·ω·dt), so the largest feasible point of a
    # 16-point grid is found first, and the crossing after it by the Illinois variant of
    # regula falsi, to 1e-14 relative; the bracket's feasible end is returned.
    cdef double lo, hi, mid, glo, ghi, gm
    cdef int j, side = 0
    ghi = swerve_top_speed(n, mx, my, chassis_discretize(vx, vy, omega, dt)) - limit
    if ghi <= 0.0 or limit == INFINITY:     # (an overflowing top speed minus inf is NaN)
        return 1.0
    lo = 0.0
    glo = -limit
    hi = 1.0
    for j in range(15, 0, -1):
        mid = j / 16.0
        gm = swerve_top_speed(n, mx, my, chassis_discretize(mid * vx, mid * vy,
                                                            mid * omega, dt)) - limit
        if gm <= 0.0:
            lo, glo = mid, gm
            break
        hi, ghi = mid, gm
    for j in range(200):
        if hi - lo <= 1e-14 * hi:
            break
        mid = (lo * ghi - hi * glo) / (ghi - glo)
        if not (lo < mid < hi):
            mid = 0.5 * (lo + hi)
        gm = swerve_top_speed(n, mx, my, chassis_discretize(mid * vx, mid * vy,
                                                            mid * omega, dt)) - limit
        if gm <= 0.0:
            lo, glo = mid, gm
            if side == -1:
                ghi *= 0.5
            side = -1
        else:
            hi, ghi = mid, gm
            if side == 1:
                glo *= 0.5
            side = 1
    return lo

cdef inline double max_abs(Py_ssize_t n, const double* v, Py_ssize_t stride) noexcept nogil:
    # max |v_i| from 0 with Java Math.max semantics (a NaN speed makes the result NaN).
    cdef Py_ssize_t i
    cdef double r = 0.0
    for i in range(n):
        r = jmax(r, fabs(v[i * stride]))
    return r

cdef inline void desaturate_factors(double real_max, const desat_t* p,
                                    double* div, double* mul     # OUT: v' = v / div * mul
                                    ) noexcept nogil:
    # real_max = max |v_i| (jmax from 0, so a NaN speed disables scaling, as in Java).
    cdef double kt, kr
    div[0] = 1.0
    mul[0] = 1.0
    if not p.five:
        if real_max > p.max_speed:
            # WPILib's order of operations: v / realMax * attainableMax.
            div[0] = real_max
            mul[0] = p.max_speed
        return
    # Joystick normalisation: may slow wheels that are not saturated.
    if p.max_trans == 0.0 or p.max_rot == 0.0 or real_max == 0.0:
        return
    kt = fhypot(p.desired.x, p.desired.y) / p.max_trans
    kr = fabs(p.desired.z) / p.max_rot
    mul[0] = jmin(jmax(kt, kr) * p.max_module / real_max, 1.0)

# ---------------------------------------------------------------------------------------
# Small dense products (mecanum, differential) and the odometry step

cdef inline void mat_vec_step(Py_ssize_t rows, Py_ssize_t cols, const double* m,
                              const double* x, Py_ssize_t step,
                              double* out                             # OUT, rows values
                              ) noexcept nogil:
    # Row-major m times the vector x[0], x[step], x[2·step], ...; summed left to right like
    # EJML, so 0 * inf spreads NaN as in WPILib.
    cdef Py_ssize_t r, c
    cdef double acc
    for r in range(rows):
        acc = m[r * cols] * x[0]
        for c in range(1, cols):
            acc = acc + m[r * cols + c] * x[c * step]
        out[r] = acc

cdef inline void mat_vec(Py_ssize_t rows, Py_ssize_t cols, const double* m, const double* x,
                         double* out                                  # OUT, rows values
                         ) noexcept nogil:
    mat_vec_step(rows, cols, m, x, 1, out)

cdef inline pose2_t odometry_motion(double dx, double dy, double dtheta,
                                    double ct, double st, bint unit) noexcept nogil:
    # The pose change of an odometry step with the twist (dx, dy, dtheta), given cos and sin
    # of dtheta. ``unit``: they come from a normalised rotation (the gyro turn) and become
    # the step's rotation as they are; otherwise (sincos values) they are normalised, as
    # WPILib's exp does through the Rotation2d(x, y) constructor. Normalising a unit pair
    # again would move only the last bit, and it sits on the update's critical path (about
    # 12 ns here). It does not depend on the pose, so the batch replay computes it for a
    # whole chunk ahead of the sequential compositions.
    cdef pose2_t step = twist_exp_cs(dx, dy, dtheta, ct, st)
    if unit:
        step.r = rot_cs(ct, st)
    return step

cdef inline void odometry_move_cs(pose2_t* p,                          # IN/OUT
                                  twist2_t* tw,                        # OUT
                                  double dx, double dy, double dtheta,
                                  double ct, double st, bint unit) noexcept nogil:
    # Move p by the twist (dx, dy, dtheta) (see odometry_motion).
    # The twist is kept: it is the log of the new pose relative to the old one, which the
    # pose estimators' interpolation would otherwise recompute with an atan2.
    tw.dx = dx
    tw.dy = dy
    tw.dtheta = dtheta
    p[0] = pose_transform_by(p[0], odometry_motion(dx, dy, dtheta, ct, st, unit))

cdef inline void odometry_move(pose2_t* p,                             # IN/OUT
                               twist2_t* tw,                           # OUT
                               double dx, double dy, double dtheta) noexcept nogil:
    cdef double c, s
    sincos(dtheta, &s, &c)
    odometry_move_cs(p, tw, dx, dy, dtheta, c, s, False)

cdef inline rot2_t gyro_turn(rot2_t gyro, rot2_t* prev_gyro) noexcept nogil:   # IN/OUT
    # The heading change since the last reading, as a rotation (its angle is wrapped to
    # (−π, π]: 170° -> -170° is +20°); the reading becomes the last one. The rotation gives
    # cos dθ and sin dθ directly (within an ulp of WPILib's cos/sin of the angle), saving a
    # sincos per step.
    cdef rot2_t d = rot_minus(gyro, prev_gyro[0])
    prev_gyro[0] = gyro
    return d

cdef inline void odometry_step(pose2_t* p, rot2_t* prev_gyro,          # IN/OUT
                               twist2_t* tw,                           # OUT
                               double dx, double dy, rot2_t gyro) noexcept nogil:
    # The heading change always comes from the gyro.
    cdef rot2_t d = gyro_turn(gyro, prev_gyro)
    odometry_move_cs(p, tw, dx, dy, rot_radians(d), d.c, d.s, True)

cdef inline void wheels_desaturate(Py_ssize_t n, const double* w, double attainable,
                                   double* out                        # OUT (may be w)
                                   ) noexcept nogil:
    # Scale every wheel by attainable / max|w| if the fastest exceeds it, keeping ratios;
    # WPILib's order of operations (w / max * attainable) and Java Math.max NaN rules.
    cdef double real_max = max_abs(n, w, 1)
    cdef Py_ssize_t i
    if real_max > attainable:
        for i in range(n):
            out[i] = w[i] / real_max * attainable
    elif out != w:
        for i in range(n):
            out[i] = w[i]

# ---------------------------------------------------------------------------------------
# Dead (tracking) wheels: wheel i reads d_i = M_i · (dx, dy, dθ) with M_i = (cos φ_i,
# sin φ_i, x_i sin φ_i − y_i cos φ_i). The pseudo-inverses are built once per layout.

cdef inline void deadwheel_solve(Py_ssize_t n, const double* p3, const double* p2,
                                 const double* g, const double* d, Py_ssize_t step,
                                 bint gyro, double w,
                                 double* out                         # OUT, 3 values
                                 ) noexcept nogil:
    # Without a gyro: t = M⁺·d (p3, 3 x n). With one, dθ = w is fixed and only (dx, dy)
    # is fitted: A⁺·(d − c·w) = A⁺·d − (A⁺c)·w, with p2 = A⁺ (2 x n) and g = A⁺c.
    # Wheel j's reading is d[j·step].
    if gyro:
        mat_vec_step(2, n, p2, d, step, out)
        out[0] = out[0] - g[0] * w
        out[1] = out[1] - g[1] * w
        out[2] = w
    else:
        mat_vec_step(3, n, p3, d, step, out)

cdef inline double deadwheel_reading(const double* row, double x, double y, double z) noexcept nogil:
    # One wheel's reading for the chassis vector (x, y, z): the inverse map, row by row.
    return row[0] * x + row[1] * y + row[2] * z


# ---------------------------------------------------------------------------------------
# Differential swerve pods: two motors drive one pod through a differential. Their sum
# turns the pod, their difference spins the wheel:
#     R_A·ω_pod = ω_m1 + ω_m2,    R_L·ω_wheel = ω_m1 − ω_m2,    ω_wheel = v / r
# (R = motor turns per output turn). A reversed motor 2 reads and takes −ω_m2.

cdef inline void dswerve_motors(const dswerve_t* g, double v, double w,
                                double* m1, double* m2       # OUT, rad/s as the motors read
                                ) noexcept nogil:
    # Halves taken before the sum so that large finite inputs cannot overflow in between.
    cdef double a = 0.5 * g.ra * w, b = 0.5 * g.kv * v
    m1[0] = a + b
    m2[0] = g.s2 * (a - b)

cdef inline void dswerve_module(const dswerve_t* g, double m1, double m2,
                                double* v, double* w         # OUT, m/s and rad/s
                                ) noexcept nogil:
    cdef double w2 = g.s2 * m2
    w[0] = (m1 + w2) * g.ira
    v[0] = (m1 - w2) * g.ikv

cdef inline double clamp_abs(double x, double limit) noexcept nogil:
    # Rounding in a + (limit − |a|) can land one ulp past the limit; this puts it back.
    if x > limit:
        return limit
    if x < -limit:
        return -limit
    return x

cdef inline void dswerve_desaturate(double s2, double m1, double m2, double limit,
                                    bint proportional,
                                    double* o1, double* o2   # OUT (may alias the inputs)
                                    ) noexcept nogil:
    # Java Math.max: a NaN motor makes peak NaN and the comparison false, so the pair
    # passes unchanged (as a NaN wheel speed does in WPILib's desaturation).
    cdef double peak = jmax(fabs(m1), fabs(m2))
    cdef double a, b, w2
    if not peak > limit:
        o1[0] = m1
        o2[0] = m2
        return
    if proportional:
        # WPILib's order of operations (m / peak * limit): the fastest lands on the limit.
        o1[0] = m1 / peak * limit
        o2[0] = m2 / peak * limit
        return
    # Steering part a (the pod's rate) and wheel part b: ω1 = a + b, ω2 = a − b, so the
    # fastest motor is |a| + |b|. Shrink b first; only a steering part beyond the limit
    # by itself is cut (and then the wheel stops).
    w2 = s2 * m2
    a = 0.5 * m1 + 0.5 * w2
    b = 0.5 * m1 - 0.5 * w2
    if fabs(a) >= limit:
        a = limit if a > 0.0 else -limit
        b = 0.0
    else:
        b = limit - fabs(a) if b > 0.0 else fabs(a) - limit
    o1[0] = clamp_abs(a + b, limit)
    o2[0] = s2 * clamp_abs(a - b, limit)

cdef inline double dswerve_drive_factor(const dswerve_t* g, Py_ssize_t n,
                                        const double* v, Py_ssize_t vstride,
                                        const double* w, double limit) noexcept nogil:
    # The largest k in [0, 1] with 0.5·|R_A·w_i| + k·0.5·|kv·v_i| <= limit for every pod.
    # A pod whose steering alone exceeds the limit forces k = 0. A NaN anywhere returns
    # 1 (no scaling), as a NaN wheel speed disables WPILib's desaturation.
    cdef Py_ssize_t i
    cdef double k = 1.0, a, b
    for i in range(n):
        a = fabs(0.5 * g.ra * w[i])
        b = fabs(0.5 * g.kv * v[i * vstride])
        if a != a or b != b:
            return 1.0
        if a + b > limit:
            if a >= limit:
                k = 0.0
            elif (limit - a) / b < k:
                k = (limit - a) / b
    return k
