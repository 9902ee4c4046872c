"""The swerve setpoint generator's kernel: PathPlannerLib's algorithm (after Team 254's)
in its order of operations, on C doubles, and the C state it runs on (declared in
setpointkernel.pxd). drivekin.setpoint's per-call methods and
drivekin.batch.generateSetpoints both run ``generate`` on a SetpointKernel's buffers.

Angles go through drivekin's Rotation2d arithmetic (WPILib's), so the branches
PathPlannerLib takes on angle comparisons come out the same."""
from libc.float cimport DBL_MAX
from libc.math cimport M_PI, fabs, isfinite, isnan, sqrt
from drivekin._core.dkmath cimport hypot
from libc.string cimport memcpy
from cpython.mem cimport PyMem_Free

from drivekin._core.dkmath cimport atan2, sincos
from drivekin._core.kernels cimport (chassis_discretize, desaturated_discretize_scale,
                                     forward_solve, jmax, jmin, rot_cs, rot_minus, rot_neg,
                                     rot_plus, rot_rad, rot_radians, rot_xy, swerve_ik,
                                     wheels_desaturate)
from drivekin._core.types cimport rot2_t, vec3_t
from drivekin.motor cimport motor_current

# PathPlannerLib's tolerance for "zero" speeds and velocities (issue #957 raised it from 1e-8).
cdef double EPS = 1e-6
# The per-step arguments' bounds (check_step): far beyond any robot and loop, and small
# enough that velocity × dt, their squares and Δvelocity / dt stay finite (a 1.7e308 s dt
# or 1e308 m/s gave NaN and inf).
cdef double LARGEST = 1e100      # |velocity|, m/s and rad/s
cdef double MIN_DT = 1e-9        # s
cdef double MAX_DT = 1e6         # s

# Rotation2d(π), as PathPlannerLib adds it (cos π, sin π: not exactly (−1, 0)).
cdef rot2_t HALF_TURN = rot_rad(M_PI)


cdef inline bint eps_eq(double a, double b) noexcept nogil:
    return a - EPS <= b and a + EPS >= b


cdef inline bint eps_zero(vec3_t v) noexcept nogil:
    return eps_eq(v.x, 0.0) and eps_eq(v.y, 0.0) and eps_eq(v.z, 0.0)


cdef inline bint flips(rot2_t r) noexcept nogil:
    # Reaching the rotation is faster by turning the other way and driving backwards.
    return fabs(rot_radians(r)) > M_PI / 2.0


cdef inline double signum(double x) noexcept nogil:
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else 0.0)


cdef inline double steering_max_s(double x0, double y0, double t0, double x1, double y1,
                                  double t1, double max_step) noexcept nogil:
    # The s in [0, 1] at which the velocity interpolated from (x0, y0) to (x1, y1) has
    # turned max_step from heading t0: rotate both so that the target heading is +x; the
    # y components are proportional to the distances to the crossing.
    cdef double diff, target, sn, cs, h0, h1
    if t1 - t0 > M_PI:
        t1 -= 2.0 * M_PI
    elif t1 - t0 < -M_PI:
        t1 += 2.0 * M_PI
    diff = t1 - t0
    if fabs(diff) <= max_step:
        return 1.0
    target = t0 + (max_step if diff >= 0.0 else -max_step)
    cdef rot2_t r = rot_rad(-target)
    sn = r.s
    cs = r.c
    h0 = sn * x0 + cs * y0
    h1 = sn * x1 + cs * y1
    return h0 / (h0 - h1)


cdef inline bint valid_s(double s) noexcept nogil:
    return isfinite(s) and s >= 0.0 and s <= 1.0


cdef inline double drive_max_s(double x0, double y0, double x1, double y1,
                               double max_step) noexcept nogil:
    # The first s in [0, 1] at which |p0 + s (p1 − p0)| = |p0| ± max_step (a quadratic in
    # s); 1 when the whole segment is within the step.
    cdef double l0 = x0 * x0 + y0 * y0, l1 = x1 * x1 + y1 * y1
    cdef double r0 = sqrt(l0), diff = sqrt(l1) - r0, target, p, a, b, c, root, s
    if fabs(diff) <= max_step:
        return 1.0
    target = r0 + (max_step if diff >= 0.0 else -max_step)
    p = x0 * x1 + y0 * y1
    a = l0 + l1 - 2.0 * p
    b = 2.0 * (p - l0)
    c = l0 - target * target
    root = sqrt(b * b - 4.0 * a * c)
    if a != 0.0:
        s = (-b + root) / (2.0 * a)
        if valid_s(s):
            return s
        s = (-b - root) / (2.0 * a)
        if valid_s(s):
            return s
    return 1.0


cdef inline double band_exit(double x0, double y0, double x1, double y1, double up,
                             double down) noexcept nogil:
    # The first s in [0, 1] at which |p0 + s (p1 − p0)| leaves [|p0| − down, |p0| + up]
    # (1 if it never does). PathPlannerLib's root (drive_max_s) only looks for the bound on
    # the side of |p1|, so a speed that dips through the lower bound on the way to a faster
    # end goes unseen, and another module's limit can stop the step inside the dip; and
    # its l0 + l1 − 2p cancels for a short step at speed (a 1e-8 m/s step near 4.3 m/s
    # came out 0: no limit). Here a = |Δ|² and b = 2 p0·Δ come from the difference, the
    # constant terms from |p0| and the steps, and the roots from the cancellation-free
    # form of the quadratic formula.
    cdef double dx = x1 - x0, dy = y1 - y0
    cdef double a = dx * dx + dy * dy, b = 2.0 * (x0 * dx + y0 * dy)
    cdef double r0 = sqrt(x0 * x0 + y0 * y0), s = 1.0, c, disc, q, lo, hi
    if not a > 0.0:
        return 1.0
    # Leaving above: a s² + b s − up (2|p0| + up) = 0 has one positive root.
    c = -up * (2.0 * r0 + up)
    disc = b * b - 4.0 * a * c
    q = -0.5 * (b + (sqrt(disc) if b >= 0.0 else -sqrt(disc)))
    hi = jmax(q / a, c / q) if q != 0.0 else sqrt(-c / a)
    if hi < s:
        s = hi
    # Leaving below (only where |p0| > down): c > 0, real roots only when heading inwards.
    if r0 > down:
        c = down * (2.0 * r0 - down)
        disc = b * b - 4.0 * a * c
        if disc >= 0.0 and b < 0.0:
            q = -0.5 * (b - sqrt(disc))
            lo = jmin(q / a, c / q)
            if 0.0 <= lo < s:
                s = lo
    return jmax(s, 0.0)


cdef inline vec3_t wpilib_discretize(double vx, double vy, double omega,
                                    double dt) noexcept nogil:
    # ChassisSpeeds.discretize in WPILib 2026's own arithmetic (Pose2d.log's cos θ − 1,
    # which cancels for small θ): drivekin's discretize is exact where this is not (up to
    # ~1e-10 m/s apart here), and the compatibility mode reproduces PathPlannerLib's
    # arithmetic (its bits, but for drivekin's own sin and cos, an ulp from libm's at most).
    cdef double c, s, m, theta, h, k, cmo, rc, rs, x, y
    cdef vec3_t out
    sincos(omega * dt, &s, &c)
    m = hypot(c, s)
    if m > 1e-6:
        c = c / m
        s = s / m
    else:
        c = 1.0
        s = 0.0
    theta = atan2(s, c)
    h = theta / 2.0
    cmo = c - 1.0
    if fabs(cmo) < 1e-9:
        k = 1.0 - 1.0 / 12.0 * theta * theta
    else:
        k = -(h * s) / cmo
    m = hypot(k, -h)
    rc = k / m
    rs = -h / m
    x = vx * dt
    y = vy * dt
    m = hypot(k, h)
    out.x = (x * rc - y * rs) * m / dt
    out.y = (x * rs + y * rc) * m / dt
    out.z = theta / dt
    return out


cdef inline vec3_t module_force(const generator_t* g, Py_ssize_t m, double v, double c,
                                double s, double tq_f, double tq_r,
                                bint accelerating) noexcept nogil:
    # PathPlannerLib's wheel force of module m (previous speed v, angle (c, s)) with its
    # accelerating (motor torque tq_f less the friction) or braking (tq_r plus it) torque,
    # and (z) its torque about the robot's centre.
    cdef rot2_t fa = rot_cs(c, s)
    cdef double tq, k, f
    cdef vec3_t out
    if accelerating:
        tq = tq_f - g.torque_loss
        k = 1.0
        if v < 0.0:
            fa = rot_plus(fa, HALF_TURN)
    else:
        tq = tq_r + g.torque_loss
        k = -1.0
        if v > 0.0:
            fa = rot_plus(fa, HALF_TURN)
    tq = jmin(tq, g.max_torque_friction)
    f = tq / g.radius
    out.x = f * k * fa.c
    out.y = f * k * fa.s
    out.z = 0.0
    if not eps_eq(0.0, hypot(out.x, out.y)):
        out.z = f * g.pd[m] * rot_minus(rot_xy(out.x, out.y), rot_cs(g.lc[m], g.ls[m])).s
    return out


cdef inline vec3_t chassis_acceleration(const generator_t* g, const limits_t* lim,
                                        double fx, double fy, double torque) noexcept nogil:
    # a = F / m, alpha = T / MOI, then PathConstraints' acceleration limits.
    cdef vec3_t a
    cdef double norm, k
    a.x = fx / g.mass
    a.y = fy / g.mass
    a.z = torque / g.moi
    if lim != NULL:
        norm = hypot(a.x, a.y)
        if norm > lim.max_a:
            k = lim.max_a / norm
            a.x = a.x * k
            a.y = a.y * k
        a.z = jmax(-lim.max_alpha, jmin(a.z, lim.max_alpha))
    return a


cdef inline double other_step(const generator_t* g, const limits_t* lim, Py_ssize_t m,
                              double v, double c, double s, double tq_f, double tq_r,
                              bint accelerating, double fx, double fy, double torque,
                              double dt) noexcept nogil:
    # Module m's largest speed change in dt with its accelerating (or braking) torque in
    # place of the other in the chassis force (fx, fy) and torque.
    cdef vec3_t own = module_force(g, m, v, c, s, tq_f, tq_r, not accelerating)
    cdef vec3_t alt = module_force(g, m, v, c, s, tq_f, tq_r, accelerating)
    cdef vec3_t a = chassis_acceleration(g, lim, fx - own.x + alt.x, fy - own.y + alt.y,
                                         torque - own.z + alt.z)
    return hypot(a.x - a.z * g.my[m], a.y + a.z * g.mx[m]) * dt


cdef void generate(generator_t* g, const double* prev, vec3_t desired, double dt,
                   double voltage, const limits_t* lim, double* out) noexcept nogil:
    """One setpoint. ``prev`` holds the previous chassis velocities then n speeds, n
    cosines and n sines; ``out`` receives the chassis velocities, the module speeds,
    cosines and sines, then the five feedforward rows. ``lim`` may be NULL."""
    cdef Py_ssize_t n = g.n, m
    cdef const double* psp = prev + 3
    cdef const double* pcs = prev + 3 + n
    cdef const double* psn = prev + 3 + 2 * n
    cdef double* w = g.scratch
    cdef double* dsp = w            # desired module speeds, angles
    cdef double* dc = w + n
    cdef double* ds = w + 2 * n
    cdef double* pvx = w + 3 * n    # previous and desired module velocity vectors
    cdef double* pvy = w + 4 * n
    cdef double* dvx = w + 5 * n
    cdef double* dvy = w + 6 * n
    cdef double* pht = w + 7 * n    # their headings (direction of travel), rad
    cdef double* dht = w + 8 * n
    cdef double* ovr = w + 9 * n    # 1 where the module's angle is set by the steering rule
    cdef double* oc = w + 10 * n
    cdef double* osn = w + 11 * n
    cdef double* acc = w + 12 * n   # module speeds of the chassis acceleration
    cdef double* tc = w + 13 * n
    cdef double* ts = w + 14 * n
    cdef double* wfx = w + 15 * n   # wheel force vectors
    cdef double* wfy = w + 16 * n
    cdef double* acl = w + 17 * n   # 1 where the module takes its accelerating torque
    cdef double* tqf = w + 18 * n   # its accelerating and braking motor torques, N·m
    cdef double* tqr = w + 19 * n
    cdef double* rsp = out + 3      # the result's module speeds, angles
    cdef double* rc = out + 3 + n
    cdef double* rs = out + 3 + 2 * n
    cdef double* ff = out + 3 + 3 * n
    cdef double max_speed, k, norm, dx, dy, dth, min_s, step, s, cur, rcur, tq_f, tq_r
    cdef double fcx, fcy, torque, x1, y1, fx, fy, tq, wd, applied, f, up, down
    cdef double r3[3]
    cdef vec3_t d, ret, fo, ca
    cdef rot2_t ph, dh, a
    cdef bint steer = True, all_flip, accelerating
    cdef int attempt

    if isnan(voltage):
        voltage = 12.0
    else:
        voltage = jmax(voltage, g.brownout)
    max_speed = g.vmax * jmin(1.0, voltage / 12.0)

    for attempt in range(2):
        d = desired
        if attempt == 1:
            # Every module would turn more than 90°: stop first, then flip in place.
            d.x = 0.0
            d.y = 0.0
            d.z = 0.0
        if lim != NULL:
            norm = hypot(d.x, d.y)
            if norm > lim.max_v:
                k = lim.max_v / norm
                d.x = d.x * k
                d.y = d.y * k
            d.z = jmax(-lim.max_w, jmin(d.z, lim.max_w))
        if g.compat:
            swerve_ik(n, g.mx, g.my, d.x, d.y, d.z, g.hc, g.hs, dsp, dc, ds)
            wheels_desaturate(n, dsp, max_speed, dsp)
            forward_solve(3, n, g.f1, dsp, dc, ds, r3)
            d.x = r3[0]
            d.y = r3[1]
            d.z = r3[2]
        else:
            k = desaturated_discretize_scale(n, g.mx, g.my, d.x, d.y, d.z, dt, max_speed)
            d = chassis_discretize(k * d.x, k * d.y, k * d.z, dt)
            swerve_ik(n, g.mx, g.my, d.x, d.y, d.z, g.hc, g.hs, dsp, dc, ds)

        steer = not eps_zero(d)
        if not steer:
            for m in range(n):
                dc[m] = pcs[m]
                ds[m] = psn[m]
                dsp[m] = 0.0
        all_flip = True
        for m in range(n):
            pvx[m] = pcs[m] * psp[m]
            pvy[m] = psn[m] * psp[m]
            ph = rot_cs(pcs[m], psn[m])
            if psp[m] < 0.0:
                ph = rot_plus(ph, HALF_TURN)
            dvx[m] = dc[m] * dsp[m]
            dvy[m] = ds[m] * dsp[m]
            dh = rot_cs(dc[m], ds[m])
            if dsp[m] < 0.0:
                dh = rot_plus(dh, HALF_TURN)
            pht[m] = rot_radians(ph)
            dht[m] = rot_radians(dh)
            if all_flip and fabs(rot_radians(rot_plus(rot_neg(ph), dh))) < M_PI / 2.0:
                all_flip = False
        ret.x = prev[0]
        ret.y = prev[1]
        ret.z = prev[2]
        if attempt == 1 or not (all_flip and not eps_zero(ret) and not eps_zero(d)):
            break

    dx = d.x - prev[0]
    dy = d.y - prev[1]
    dth = d.z - prev[2]
    min_s = 1.0

    # Steering: a stopped module turns in place (holding the robot still until it is
    # within a step of its goal); a moving one limits s to where its heading has turned
    # one step, which friction may shorten (the wheel must not slide sideways).
    for m in range(n):
        ovr[m] = 0.0
        if not steer:
            ovr[m] = 1.0
            oc[m] = pcs[m]
            osn[m] = psn[m]
            continue
        step = dt * g.max_steer
        if eps_eq(psp[m], 0.0):
            ovr[m] = 1.0
            if eps_eq(dsp[m], 0.0):
                oc[m] = pcs[m]
                osn[m] = psn[m]
                continue
            a = rot_plus(rot_neg(rot_cs(pcs[m], psn[m])), rot_cs(dc[m], ds[m]))
            if flips(a):
                a = rot_plus(a, HALF_TURN)
            if fabs(rot_radians(a)) / step <= 1.0:
                oc[m] = dc[m]
                osn[m] = ds[m]
            else:
                a = rot_plus(rot_cs(pcs[m], psn[m]), rot_rad(signum(rot_radians(a)) * step))
                oc[m] = a.c
                osn[m] = a.s
                min_s = 0.0
            continue
        if min_s == 0.0:
            continue
        step = jmin(step, (dt * g.friction_force) / ((g.mass / n) * fabs(psp[m])))
        s = steering_max_s(pvx[m], pvy[m], pht[m], dvx[m], dvy[m], dht[m], step)
        min_s = jmin(min_s, s)

    # Drive torque: what each motor can give at its present speed on this voltage, less
    # (accelerating) or plus (braking) the module's friction, capped by wheel slip; the
    # forces give the chassis acceleration, and that each module's largest speed step.
    # PathPlannerLib picks each module's torque by its desired speed (signed, once
    # optimised); the default mode keeps both torques (tqf, tqr), so that a module can
    # take its accelerating step up and its braking step down whatever the desired speed
    # says (a module turned by more than 90° speeds up though its optimised desired speed
    # is below its previous one).
    fcx = 0.0
    fcy = 0.0
    torque = 0.0
    for m in range(n):
        f = fabs(psp[m] / g.radius)
        cur = jmax(jmin(motor_current(g.kv, g.r, f, voltage), g.current_limit), 0.0)
        rcur = jmax(jmin(fabs(motor_current(g.kv, g.r, f, -voltage)), g.current_limit), 0.0)
        tq_f = cur * g.kt
        tq_r = rcur * g.kt
        # The desired speed once optimised against the previous angle (turn ≤ 90°).
        s = dsp[m]
        if fabs(rot_radians(rot_minus(rot_cs(dc[m], ds[m]), rot_cs(pcs[m], psn[m])))
                * (180.0 / M_PI)) > 90.0:
            s = -s
        accelerating = (eps_eq(psp[m], 0.0) or (psp[m] > 0.0 and s >= psp[m])
                        or (psp[m] < 0.0 and s <= psp[m]))
        fo = module_force(g, m, psp[m], pcs[m], psn[m], tq_f, tq_r, accelerating)
        fcx = fcx + fo.x
        fcy = fcy + fo.y
        torque = torque + fo.z
        acl[m] = 1.0 if accelerating else 0.0
        tqf[m] = tq_f
        tqr[m] = tq_r
    ca = chassis_acceleration(g, lim, fcx, fcy, torque)
    # A velocity conversion, as in PathPlannerLib: it updates the heading memory.
    swerve_ik(n, g.mx, g.my, ca.x, ca.y, ca.z, g.hc, g.hs, acc, tc, ts)

    # Drive: search the segment the limits so far left, [prev, prev + min_s·Δ]. Its root
    # is relative to that segment, so the step is min_s·s (Team 254); PathPlannerLib takes
    # s itself. The default mode takes the first point where the module's speed leaves the
    # band [|v0| − braking step, |v0| + accelerating step] (band_exit): the step of its
    # torque above, the other from the chassis acceleration with its other torque
    # (other_step).
    for m in range(n):
        if min_s == 0.0:
            break
        step = fabs(acc[m] * dt)
        if min_s == 1.0:
            x1 = dvx[m]
            y1 = dvy[m]
        else:
            x1 = (dvx[m] - pvx[m]) * min_s + pvx[m]
            y1 = (dvy[m] - pvy[m]) * min_s + pvy[m]
        if g.compat:
            min_s = jmin(min_s, drive_max_s(pvx[m], pvy[m], x1, y1, step))
        else:
            # The other torque's step matters only where its bound can be crossed: below
            # for a module whose speed starts falling, above for one that ends faster.
            up = step
            down = step
            if acl[m] != 0.0:
                if pvx[m] * (x1 - pvx[m]) + pvy[m] * (y1 - pvy[m]) < 0.0:
                    down = other_step(g, lim, m, psp[m], pcs[m], psn[m], tqf[m], tqr[m],
                                      False, fcx, fcy, torque, dt)
            elif x1 * x1 + y1 * y1 > pvx[m] * pvx[m] + pvy[m] * pvy[m]:
                up = other_step(g, lim, m, psp[m], pcs[m], psn[m], tqf[m], tqr[m], True,
                                fcx, fcy, torque, dt)
            min_s = jmin(min_s, min_s * band_exit(pvx[m], pvy[m], x1, y1, up, down))

    ret.x = prev[0] + min_s * dx
    ret.y = prev[1] + min_s * dy
    ret.z = prev[2] + min_s * dth
    if g.compat:
        ret = wpilib_discretize(ret.x, ret.y, ret.z, dt)
    out[0] = ret.x
    out[1] = ret.y
    out[2] = ret.z

    # Feedforwards: the force and torque that make this step's acceleration, shared out
    # over the wheels.
    fx = (ret.x - prev[0]) / dt * g.mass / n
    fy = (ret.y - prev[1]) / dt * g.mass / n
    tq = (ret.z - prev[2]) / dt * g.moi / n
    for m in range(n):
        wfx[m] = fx + g.kx[m] * tq
        wfy[m] = fy + g.ky[m] * tq
    swerve_ik(n, g.mx, g.my, ret.x, ret.y, ret.z, g.hc, g.hs, rsp, rc, rs)
    for m in range(n):
        wd = hypot(wfx[m], wfy[m])
        applied = 0.0
        if wd > 1e-6:
            applied = wd * rot_minus(rot_xy(wfx[m], wfy[m]), rot_cs(rc[m], rs[m])).c
        cur = applied * g.radius / g.kt
        if ovr[m] != 0.0:
            if flips(rot_plus(rot_neg(rot_cs(rc[m], rs[m])), rot_cs(oc[m], osn[m]))):
                rsp[m] = -rsp[m]
                applied = -applied
                cur = -cur
            rc[m] = oc[m]
            rs[m] = osn[m]
        if flips(rot_plus(rot_neg(rot_cs(pcs[m], psn[m])), rot_cs(rc[m], rs[m]))):
            a = rot_plus(rot_cs(rc[m], rs[m]), HALF_TURN)
            rc[m] = a.c
            rs[m] = a.s
            rsp[m] = -rsp[m]
            applied = -applied
            cur = -cur
        ff[m] = (rsp[m] - psp[m]) / dt
        ff[n + m] = applied
        ff[2 * n + m] = cur
        ff[3 * n + m] = wfx[m]
        ff[4 * n + m] = wfy[m]


cdef str where(Py_ssize_t sample):
    # The batch form's messages name the sample (built only for a message).
    return "" if sample < 0 else f"sample {sample}: "


cdef int check_step(vec3_t want, double dt, double voltage, Py_ssize_t sample) except -1:
    """The per-step arguments: desired velocities of at most LARGEST, dt from MIN_DT to
    MAX_DT, a finite voltage or NaN (``sample`` ≥ 0 names the batch form's sample in the
    message). Within these bounds (and the previous setpoint's, _load) the kernel's
    products and quotients of them stay finite."""
    if not (fabs(want.x) <= LARGEST and fabs(want.y) <= LARGEST and fabs(want.z) <= LARGEST):
        raise ValueError(f"{where(sample)}desiredRobotRelativeVelocities must be finite and "
                         f"at most {LARGEST:g} (m/s, rad/s) in magnitude, got "
                         f"({want.x!r}, {want.y!r}, {want.z!r})")
    if not (MIN_DT <= dt <= MAX_DT):
        raise ValueError(f"{where(sample)}dt must be a loop period from {MIN_DT:g} to "
                         f"{MAX_DT:g} s, got {dt!r}")
    if not (isnan(voltage) or isfinite(voltage)):
        raise ValueError(f"{where(sample)}inputVoltage must be a finite voltage in V (NaN for "
                         f"12 V), got {voltage!r}")
    return 0


cdef void keep_headings(SetpointKernel k) noexcept:
    memcpy(k.saved, k.g.hc, sizeof(double) * k.g.n)
    memcpy(k.saved + k.g.n, k.g.hs, sizeof(double) * k.g.n)


cdef int check_output(SetpointKernel k, Py_ssize_t sample) except -1:
    """Refuse a setpoint that is not finite, or whose velocities the next call would refuse
    as its previous setpoint (beyond LARGEST): within check_step's bounds only a robot
    whose own numbers are extreme gets there (module positions of 1e300 m). The heading
    memory is left as keep_headings found it."""
    cdef Py_ssize_t i, n = k.g.n
    cdef bint bad = False
    for i in range(3 + n):
        bad |= not fabs(k.out[i]) <= LARGEST
    for i in range(3 + n, 3 + 8 * n):
        bad |= not fabs(k.out[i]) <= DBL_MAX
    if not bad:
        return 0
    memcpy(k.g.hc, k.saved, sizeof(double) * n)
    memcpy(k.g.hs, k.saved + n, sizeof(double) * n)
    raise ValueError(f"{where(sample)}the setpoint overflowed: the generator's config holds "
                     f"numbers too extreme for its model (module positions, wheel radius, top "
                     f"speed, the motor's constants) at these velocities")

cdef class SetpointKernel:
    """The generator's C state (setpointkernel.pxd): the robot's constants, the buffer
    that holds per-module constants, scratch, the previous setpoint and the output, which
    it frees. drivekin.setpoint.SwerveSetpointGenerator fills it and reads the previous
    setpoint and the constraints into it (_load)."""

    def __dealloc__(self):
        PyMem_Free(self.buf)

    cdef int _load(self, object prevSetpoint, object constraints,
                   limits_t* lim) except -1:
        raise TypeError(f"{type(self).__name__} is not a SwerveSetpointGenerator")
