"""Whole recordings at once: numpy stacks through the same kernels as the per-call API.

Shapes follow one convention ("single or stacked", as in scipy.spatial.transform): an
argument that is one value per call in the per-call API is either that value's array
(shape ``S``) or a stack of N of them (shape ``(N,) + S``), and results have the matching
form. The value arrays are

==============================  ==========  =============================================
value                           shape S     columns
==============================  ==========  =============================================
chassis vector / pose           (3,)        ``[vx m/s, vy m/s, omega rad/s]``,
                                            ``[x m, y m, θ rad]``, ``[dx m, dy m, dθ rad]``
3-D pose / transform            (7,)        ``[x m, y m, z m, qw, qx, qy, qz]``
3-D twist                       (6,)        ``[dx m, dy m, dz m, rx rad, ry rad, rz rad]``
3-D gyro reading                (4,)        ``[w, x, y, z]`` (a Rotation3d's quaternion)
swerve modules (M modules)      (M, 2)      ``[velocity m/s or distance m, angle rad]``
wheels (mecanum, diff, dead)    (W,)        one value per wheel, the per-call order
angle / time step               ()          rad / s (a float, or an (N,) stack)
==============================  ==========  =============================================

A 3-D row is read as the per-call constructors read it: ``[x, y, z, qw, qx, qy, qz]`` is
``Pose3d(Translation3d(x, y, z), Rotation3d(Quaternion(qw, qx, qy, qz)))`` (the
quaternion normalised as that constructor and WPILib's struct unpacking do; a zero one is
the identity), a gyro row ``Rotation3d(Quaternion(w, x, y, z))``. Results hold the
getters' values (``getX()``, ..., ``getRotation().getQuaternion()``), so a result read
back as a row is normalised again, which may move a component by an ulp.

Every array must be a float64, native-endian, C-contiguous numpy array (the rule of the
per-call buffers; ``np.ascontiguousarray(x, dtype=np.float64)`` makes one). ``out=``, when
given, must have exactly the result's shape, be writeable and not overlap an input; it
is filled and returned. Angles in results are ``Rotation2d.getRadians()`` values, wrapped to
(−π, π].

Results are bit-identical to the per-call methods called in a loop, including their
state: swerve inverse kinematics reads and leaves the heading memory as N calls would,
and :func:`replay` leaves the odometry at the last sample. The loops run without the GIL;
do not use the same kinematics or odometry object from another thread meanwhile (memory
stays safe, but the interleaving is unspecified).

Every sine, cosine and atan2 comes from drivekin's own functions (``_core/dkmath.h``,
at most 1 ulp from the exact value), here vectorised by the compiler: ``SIMD`` names the
instruction set in use, the best the CPU has, chosen at import: ``"AVX-512"`` or
``"AVX2"`` (x86_64 CPUs that have them), ``"SSE2"`` (other x86_64), ``"NEON"``
(aarch64). The vector and scalar forms perform the same operations in the same order, so
results are the same bits whichever is in use, on every supported platform
(docs/DESIGN.md, "One trig"). The 3-D forms run the per-call kernels sample by sample,
with the scalar forms (a 3-D replay's module angles excepted).
"""
from cpython.mem cimport PyMem_Free
from drivekin._core.dkmath cimport atan2, atan2_n, sincos, sincos_n, trig_isa, trig_use
from libc.string cimport memcpy, memset
cimport numpy as cnp

import numpy as np

from drivekin._core.types cimport desat_t, pose2_t, rot2_t, twist2_t, vec2_t, vec3_t
from drivekin._core.stacks cimport (CHUNK, _Stack, _pair, _per_sample, _result, _rows,
                                    _scratch, _stack, chunk_len, sample_shape,
                                    wheel_major)
from drivekin._core.kernels cimport (chassis_discretize, chassis_discretize_cs,
                                     desaturate_factors, desaturated_discretize_scale,
                                     gyro_turn,
                                     max_abs, odometry_motion, pose, pose_relative_to,
                                     pose_transform_by,
                                     rot_cs, rot_neg, transform_log_angle, twist_exp_cs,
                                     vec, vec_rotate, wheels_desaturate)
from drivekin.geometry cimport Translation2d
from drivekin._core.drivetrain cimport Drivetrain
from drivekin.odometry cimport _Odometry
from drivekin.odometry3d cimport _Odometry3d
from drivekin._core.batch3d cimport compose3, exp3, log3, replay3
from drivekin.swerve cimport SwerveDriveKinematics, check_desaturated_discretize
from drivekin.chassis cimport check_discretize_fits, discretize_is_large
from drivekin._core.setpointkernel cimport (SetpointKernel, check_output, check_step,
                                            generate, keep_headings, limits_t)
from drivekin._core.errors import type_name

cnp.import_array()

SIMD = trig_isa().decode()


def _use_isa(str name):
    """Test hook: run the array trig on instruction set ``name`` ("SSE2", "AVX2", ...);
    returns the one in use before. ValueError if this build or CPU cannot."""
    global SIMD
    cdef str before = SIMD
    if trig_use(name.encode()) != 0:
        raise ValueError(f"instruction set {name!r} is not available here (in use: {before})")
    SIMD = trig_isa().decode()
    return before


def _isas():
    """Test hook: the instruction sets :func:`_use_isa` accepts with this build and CPU."""
    cdef str before = SIMD
    found = tuple(n for n in ("SSE2", "AVX2", "AVX-512", "NEON", "scalar")
                  if trig_use(n.encode()) == 0)
    trig_use(before.encode())
    return found


def _trig(str fn, a, b=None, bint scalar=False):
    """Test hook: ``fn`` ("sincos" or "atan2") of float64 arrays through the array path
    (or, with ``scalar``, the per-call path, one element at a time); sincos returns
    (sin, cos)."""
    cdef _Stack x = _stack(a, (), "a", False)
    cdef _Stack y = None if b is None else _stack(b, (), "b", False)
    cdef Py_ssize_t i, n = x.n
    cdef cnp.ndarray r1 = np.empty(n), r2 = np.empty(n)
    cdef double* o1 = <double*>cnp.PyArray_DATA(r1)
    cdef double* o2 = <double*>cnp.PyArray_DATA(r2)
    if fn == "sincos" and y is None:
        with nogil:
            if scalar:
                for i in range(n):
                    sincos(x.data[i], &o1[i], &o2[i])
            else:
                sincos_n(n, x.data, o1, o2)
        return r1, r2
    if fn == "atan2" and y is not None and y.n == n:
        with nogil:
            if scalar:
                for i in range(n):
                    o1[i] = atan2(x.data[i], y.data[i])
            else:
                atan2_n(n, x.data, y.data, o1)
        return r1
    raise ValueError("_trig takes ('sincos', x) or ('atan2', y, x) with arrays of one length")


__all__ = ["desaturate", "desaturateWheelVelocities", "desaturatedDiscretize", "discretize",
           "exp", "generateSetpoints", "log", "relativeTo", "replay", "toChassisAccelerations",
           "toChassisVelocities", "toFieldRelative", "toRobotRelative",
           "toSwerveModuleAccelerations", "toSwerveModuleVelocities", "toWheelAccelerations",
           "toWheelVelocities", "transformBy"]


# ---------------------------------------------------------------------------------------
# Chunk helpers

cdef inline void keep_pose(Py_ssize_t i, double* px, double* py, double* pc, double* ps,
                           pose2_t p) noexcept nogil:
    # The pose of sample i of a chunk, its heading's atan2 left for store_poses.
    px[i] = p.t.x
    py[i] = p.t.y
    pc[i] = p.r.c
    ps[i] = p.r.s


cdef inline void store_poses(Py_ssize_t k, double* o, const double* px, const double* py,
                             const double* pc, const double* ps, double* heading) noexcept nogil:
    # k poses as [x, y, atan2(s, c)] rows.
    cdef Py_ssize_t i
    atan2_n(k, ps, pc, heading)
    for i in range(k):
        o[3 * i] = px[i]
        o[3 * i + 1] = py[i]
        o[3 * i + 2] = heading[i]


cdef Drivetrain _drivetrain(object k, str call, bint steered_only=False):
    """``k`` as the drivetrain contract, checked complete (and steered, for the module
    functions)."""
    if not isinstance(k, Drivetrain) or (steered_only and not (<Drivetrain>k).steered):
        from drivekin._core.catalog import names
        raise TypeError(f"{call} takes a drivekin "
                        + names("steered" if steered_only else "drivetrain")
                        + f" as its first argument, got {type_name(k)}")
    (<Drivetrain>k)._ready()
    return <Drivetrain>k


# ---------------------------------------------------------------------------------------
# Inverse kinematics

cdef object _inverse(Drivetrain k, object chassis, object omega, object centerOfRotation,
                     object out, bint accel, str name):
    """Wheel samples for a chassis stack through the drivetrain contract: module
    ``[magnitude, rad]`` pairs (steered; velocities use and leave the heading memory,
    accelerations take ``omega``, the angular velocity) or wheel values."""
    cdef _Stack v = _stack(chassis, (3,), name)
    if centerOfRotation is not None and not isinstance(centerOfRotation, Translation2d):
        raise TypeError("centerOfRotation must be a drivekin Translation2d, got "
                        f"{type_name(centerOfRotation)}")
    cdef _Stack w = _per_sample(omega, v.n, v.single, "angularVelocity") if k.steered else None
    cdef _Stack o = _result(out, v.n, v.single, sample_shape(k.nwheels, k.steered),
                            (v, w) if k.steered else (v,), name)
    cdef Py_ssize_t n = k.nwheels, i, i0, ch, j, kk, count = v.n, m = CHUNK * n
    k._center(centerOfRotation)
    # Private copies of the parameters: another thread's call cannot change them under the
    # loop; the heading memory is written back once at the end (_inverse_done).
    cdef Py_ssize_t size = k._params(NULL, False, accel)
    cdef double* buf = _scratch(size + (4 * m if k.steered else 0))
    cdef double* mag = buf + size           # a chunk's module magnitudes, cos, sin, angles
    cdef double* oc = mag + m
    cdef double* os = oc + m
    cdef double* ang = os + m
    cdef double* y
    k._params(buf, False, accel)
    with nogil:
        if not k.steered:
            k._inverse_many(count, v.data, NULL, accel, buf, o.data, NULL, NULL)
        else:
            for ch in range((count + CHUNK - 1) // CHUNK):
                i0 = ch * CHUNK
                kk = chunk_len(i0, count)
                k._inverse_many(kk, v.data + 3 * i0, w.data + i0, accel, buf, mag, oc, os)
                atan2_n(kk * n, os, oc, ang)
                y = o.data + 2 * n * i0
                for j in range(kk * n):
                    y[2 * j] = mag[j]
                    y[2 * j + 1] = ang[j]
    k._inverse_done(buf, accel)
    PyMem_Free(buf)
    return o.array


def toSwerveModuleVelocities(kinematics, chassisVelocities, centerOfRotation=None,
                             out=None):
    """Module velocities ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]`` for chassis velocities
    ``(3,)`` / ``(N, 3)`` (robot-relative), about ``centerOfRotation`` (a Translation2d,
    m; default the robot centre). The heading memory is used and left as N
    :meth:`SwerveDriveKinematics.toSwerveModuleVelocities` calls would leave it."""
    return _inverse(_drivetrain(kinematics, "toSwerveModuleVelocities", True),
                    chassisVelocities, 0.0, centerOfRotation, out, False, "chassisVelocities")


def toSwerveModuleAccelerations(kinematics, chassisAccelerations, angularVelocity=0.0,
                                centerOfRotation=None, out=None):
    """Module accelerations ``(M, 2)`` / ``(N, M, 2)`` ``[m/s², rad]`` for chassis
    accelerations ``(3,)`` / ``(N, 3)`` ``[ax, ay, alpha]`` while turning at
    ``angularVelocity`` (rad/s; a float or ``(N,)``), as
    :meth:`SwerveDriveKinematics.toSwerveModuleAccelerations`."""
    return _inverse(_drivetrain(kinematics, "toSwerveModuleAccelerations", True),
                    chassisAccelerations, angularVelocity, centerOfRotation, out, True,
                    "chassisAccelerations")


def toWheelVelocities(kinematics, chassisVelocities, centerOfRotation=None, out=None):
    """Wheel velocities for chassis velocities ``(3,)`` / ``(N, 3)``: mecanum ``(4,)`` /
    ``(N, 4)`` (about ``centerOfRotation``), differential ``(N, 2)`` ``[left, right]``,
    dead-wheel ``(N, W)`` (surface velocities), all m/s; a SwerveDriveKinematics gives
    :func:`toSwerveModuleVelocities`."""
    return _inverse(_drivetrain(kinematics, "toWheelVelocities"), chassisVelocities, 0.0,
                    centerOfRotation, out, False, "chassisVelocities")


def toWheelAccelerations(kinematics, chassisAccelerations, centerOfRotation=None, out=None):
    """Wheel accelerations (m/s²) for chassis accelerations ``(3,)`` / ``(N, 3)``, shaped
    as :func:`toWheelVelocities`; a SwerveDriveKinematics gives
    :func:`toSwerveModuleAccelerations` with zero angular velocity."""
    return _inverse(_drivetrain(kinematics, "toWheelAccelerations"), chassisAccelerations,
                    0.0, centerOfRotation, out, True, "chassisAccelerations")


# ---------------------------------------------------------------------------------------
# Forward kinematics

cdef object _forward(Drivetrain k, object wheels, object gyro_arg, object out,
                     bint accel, str name, str gyro_name):
    cdef Py_ssize_t i0, ch, j, kk, n = k.nwheels, m = CHUNK * n, count
    cdef _Stack g = None
    cdef bint gyro = gyro_arg is not None
    cdef const double* x
    if gyro and not k.gyro_forward:
        raise TypeError(f"{gyro_name} is not taken by a {type(k).__name__}: only dead "
                        "wheels fit the heading change to a gyro")
    cdef _Stack w = _stack(wheels, sample_shape(n, k.steered), name)
    count = w.n
    if k.gyro_forward:
        k._forward_check(gyro, accel)
        if gyro:
            g = _per_sample(gyro_arg, count, w.single, gyro_name)
    cdef _Stack o = _result(out, count, w.single, (3,), (w,) if g is None else (w, g), name)
    cdef Py_ssize_t size = k._params(NULL, True, accel)
    cdef double* buf = _scratch(size + (4 * m if k.steered else 0))
    cdef double* mag = buf + size           # a chunk's magnitudes, angles, cos, sin
    cdef double* ang = mag + m
    cdef double* c = ang + m
    cdef double* s = c + m
    k._params(buf, True, accel)
    with nogil:
        if not k.steered:
            k._forward_many(count, w.data, NULL, NULL, NULL if g is None else g.data, accel,
                            buf, o.data)
        else:
            for ch in range((count + CHUNK - 1) // CHUNK):
                i0 = ch * CHUNK
                kk = chunk_len(i0, count)
                x = w.data + 2 * n * i0
                for j in range(kk * n):
                    mag[j] = x[2 * j]
                    ang[j] = x[2 * j + 1]
                sincos_n(kk * n, ang, s, c)
                k._forward_many(kk, mag, c, s, NULL, accel, buf, o.data + 3 * i0)
    PyMem_Free(buf)
    return o.array


def toChassisVelocities(kinematics, wheelVelocities, gyroRates=None, out=None):
    """Chassis velocities ``(3,)`` / ``(N, 3)`` ``[vx, vy, omega]`` from swerve module
    velocities ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]``, or wheel velocities ``(W,)`` /
    ``(N, W)`` of a mecanum, differential or dead-wheel drive. ``gyroRates`` (rad/s, a
    float or ``(N,)``) is the dead-wheel form's optional gyro."""
    return _forward(_drivetrain(kinematics, "toChassisVelocities"), wheelVelocities,
                    gyroRates, out, False, "wheelVelocities", "gyroRates")


def toChassisAccelerations(kinematics, wheelAccelerations, angularAccelerations=None,
                           out=None):
    """Chassis accelerations ``(3,)`` / ``(N, 3)`` ``[ax, ay, alpha]`` from swerve module
    accelerations ``(M, 2)`` / ``(N, M, 2)`` ``[m/s², rad]`` or wheel accelerations;
    ``angularAccelerations`` (rad/s², a float or ``(N,)``) fixes alpha for dead wheels."""
    return _forward(_drivetrain(kinematics, "toChassisAccelerations"), wheelAccelerations,
                    angularAccelerations, out, True, "wheelAccelerations",
                    "angularAccelerations")


# ---------------------------------------------------------------------------------------
# Desaturation

def desaturateWheelVelocities(moduleVelocities, attainableMaxSpeed,
                              attainableMaxModuleSpeed=None,
                              attainableMaxTranslationalSpeed=None,
                              attainableMaxRotationalVelocity=None, out=None):
    """:meth:`SwerveDriveKinematics.desaturateWheelVelocities` for module velocities
    ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]``, each sample scaled on its own. Either one
    limit ``attainableMaxSpeed`` (m/s), or the desired chassis velocities (``(3,)`` /
    ``(N, 3)``) in its place followed by the three limits (m/s, m/s, rad/s). Angles pass
    through unchanged (as in the per-call (M, 2) array form); ``out=moduleVelocities``
    desaturates in place."""
    cdef _Stack v, c, o
    cdef desat_t p
    cdef bint five = attainableMaxModuleSpeed is not None or \
        attainableMaxTranslationalSpeed is not None or attainableMaxRotationalVelocity is not None
    cdef Py_ssize_t i, j, m, count
    cdef double div, mul
    cdef double* y
    cdef const double* x
    memset(&p, 0, sizeof(p))
    m = _rows(moduleVelocities, 2, "moduleVelocities", "(M, 2) or (N, M, 2)")
    v = _stack(moduleVelocities, (m, 2), "moduleVelocities")
    count = v.n
    p.five = five
    if five:
        if (attainableMaxModuleSpeed is None or attainableMaxTranslationalSpeed is None
                or attainableMaxRotationalVelocity is None):
            raise TypeError("the five-argument form needs all three limits")
        c = _stack(attainableMaxSpeed, (3,), "desiredChassisVelocities")
        if c.single != v.single or c.n != count:
            raise ValueError("desiredChassisVelocities must have one row per sample of "
                             f"moduleVelocities ({'(3,)' if v.single else f'({count}, 3)'}), "
                             f"got {attainableMaxSpeed.shape}")
        p.max_module = attainableMaxModuleSpeed
        p.max_trans = attainableMaxTranslationalSpeed
        p.max_rot = attainableMaxRotationalVelocity
        inputs = (v, c)
    else:
        c = v
        p.max_speed = attainableMaxSpeed
        inputs = (v,)
    # In place is safe: each sample's speeds are all read before any is written. The
    # chassis rows are read sample by sample, so they must not share memory with it.
    if out is moduleVelocities:
        if five and np.may_share_memory(v.array, c.array):
            raise ValueError("out must not overlap an input array other than "
                             "moduleVelocities (desiredChassisVelocities shares its memory)")
        o = v
    else:
        o = _result(out, count, v.single, (m, 2), inputs, "moduleVelocities")
    with nogil:
        for i in range(count):
            x = v.data + 2 * m * i
            y = o.data + 2 * m * i
            if five:
                p.desired.x = c.data[3 * i]
                p.desired.y = c.data[3 * i + 1]
                p.desired.z = c.data[3 * i + 2]
            desaturate_factors(max_abs(m, x, 2), &p, &div, &mul)
            for j in range(m):
                y[2 * j] = x[2 * j] / div * mul
                y[2 * j + 1] = x[2 * j + 1]
    return o.array


def desaturate(wheelVelocities, double attainableMaxSpeed, out=None):
    """:meth:`MecanumDriveWheelVelocities.desaturate` (W = 4) and the differential one
    (W = 2) for wheel velocities ``(W,)`` / ``(N, W)`` (m/s), each sample scaled on its own;
    ``out=wheelVelocities`` desaturates in place."""
    cdef Py_ssize_t i, w = _rows(wheelVelocities, 0, "wheelVelocities", "(W,) or (N, W)")
    if w != 2 and w != 4:
        raise ValueError("wheelVelocities must hold 4 (mecanum) or 2 (differential) wheels "
                         f"per sample, got shape {wheelVelocities.shape}")
    cdef _Stack v = _stack(wheelVelocities, (w,), "wheelVelocities")
    cdef _Stack o = v if out is wheelVelocities else _result(out, v.n, v.single, (w,), (v,),
                                                             "wheelVelocities")
    cdef Py_ssize_t count = v.n
    with nogil:
        for i in range(count):
            wheels_desaturate(w, v.data + w * i, attainableMaxSpeed, o.data + w * i)
    return o.array


# ---------------------------------------------------------------------------------------
# Chassis vectors and geometry

def discretize(chassisVelocities, dt, out=None):
    """:meth:`ChassisVelocities.discretize` for ``(3,)`` / ``(N, 3)`` velocities; ``dt`` (s)
    is a float or an ``(N,)`` stack."""
    cdef _Stack v = _stack(chassisVelocities, (3,), "chassisVelocities")
    cdef _Stack t = _per_sample(dt, v.n, v.single, "dt")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v, t), "chassisVelocities")
    cdef Py_ssize_t i, i0, ch, kk, count = v.n
    cdef const double* x
    cdef vec3_t d
    cdef double th[CHUNK]
    cdef double c[CHUNK]
    cdef double s[CHUNK]
    for i in range(count):
        x = v.data + 3 * i
        if discretize_is_large(x[0], x[1], x[2]):
            d.x, d.y, d.z = x[0], x[1], x[2]
            try:
                check_discretize_fits(d, t.data[i])
            except ValueError as e:
                raise ValueError(f"sample {i}: {e}") from None
    with nogil:
        for ch in range((count + CHUNK - 1) // CHUNK):
            i0 = ch * CHUNK
            kk = chunk_len(i0, count)
            for i in range(kk):
                th[i] = v.data[3 * (i0 + i) + 2] * t.data[i0 + i]
            sincos_n(kk, th, s, c)
            for i in range(kk):
                x = v.data + 3 * (i0 + i)
                d = chassis_discretize_cs(x[0], x[1], x[2], t.data[i0 + i], th[i], c[i], s[i])
                o.data[3 * (i0 + i)] = d.x
                o.data[3 * (i0 + i) + 1] = d.y
                o.data[3 * (i0 + i) + 2] = d.z
    return o.array


def desaturatedDiscretize(kinematics, chassisVelocities, dt, double attainableMaxModuleVelocity,
                          out=None):
    """:meth:`SwerveDriveKinematics.desaturatedDiscretize` for ``(3,)`` / ``(N, 3)``
    velocities; ``dt`` (s) is a float or an ``(N,)`` stack. Every sample is checked
    before any is written."""
    if type(kinematics) is not SwerveDriveKinematics:
        raise TypeError(f"desaturatedDiscretize takes a SwerveDriveKinematics as its first "
                        f"argument, got {type_name(kinematics)}")
    cdef SwerveDriveKinematics k = <SwerveDriveKinematics>kinematics
    k._ready()
    cdef _Stack v = _stack(chassisVelocities, (3,), "chassisVelocities")
    cdef _Stack t = _per_sample(dt, v.n, v.single, "dt")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v, t), "chassisVelocities")
    cdef Py_ssize_t i, count = v.n
    cdef vec3_t c, d
    cdef double f
    for i in range(count):
        c.x, c.y, c.z = v.data[3 * i], v.data[3 * i + 1], v.data[3 * i + 2]
        try:
            check_desaturated_discretize(c, t.data[i], attainableMaxModuleVelocity)
        except ValueError as e:
            raise ValueError(f"sample {i}: {e}") from None
    with nogil:
        for i in range(count):
            f = desaturated_discretize_scale(k.n, k.mx, k.my, v.data[3 * i],
                                             v.data[3 * i + 1], v.data[3 * i + 2],
                                             t.data[i], attainableMaxModuleVelocity)
            d = chassis_discretize(f * v.data[3 * i], f * v.data[3 * i + 1],
                                   f * v.data[3 * i + 2], t.data[i])
            o.data[3 * i] = d.x
            o.data[3 * i + 1] = d.y
            o.data[3 * i + 2] = d.z
    return o.array


def generateSetpoints(generator, prevSetpoint, desiredVelocities, dt,
                      inputVoltage=float("nan"), constraints=None):
    """:meth:`SwerveSetpointGenerator.generateSetpoint` over a log of commands: from
    ``prevSetpoint``, each row of ``desiredVelocities`` (``(T, 3)`` float64, robot-relative
    vx, vy, ω) is fed the previous row's setpoint. ``dt`` (s) and ``inputVoltage`` (V, NaN
    for 12 V) are floats or ``(T,)`` stacks; ``constraints`` applies to every row.

    Returns ``(velocities, modules, feedforwards)``: ``(T, 3)`` chassis velocities,
    ``(T, N, 2)`` module ``[velocity m/s, angle rad]`` and ``(T, 5, N)`` feedforwards in
    :class:`DriveFeedforwards`' order. The same numbers as T calls, the generator's
    heading memory included (it is left as the last call leaves it). Every input is copied
    before any is checked (a constraints object's getters may run code), every row is
    checked before any is computed, and a refused call leaves the generator as it was;
    the GIL is held (the generator's scratch is shared)."""
    if not isinstance(generator, SetpointKernel):
        raise TypeError(f"generateSetpoints takes a SwerveSetpointGenerator as its first "
                        f"argument, got {type_name(generator)}")
    cdef SetpointKernel g = <SetpointKernel>generator
    # Every input is read into private memory before any is validated: reading the next
    # one (a duck-typed constraints object's getters, a number's conversion) can run Python
    # code that writes into the arrays already read.
    cdef _Stack v = _stack(desiredVelocities, (3,), "desiredVelocities", False)
    cdef Py_ssize_t i, m, count = v.n, n
    cdef double* rows = _scratch(5 * count)       # [vx, vy, ω] × count, dt, voltage
    cdef double* dts = rows + 3 * count
    cdef double* volts = rows + 4 * count
    cdef double* oc
    cdef double* om
    cdef double* of
    cdef double* out
    cdef vec3_t want
    cdef limits_t lim
    cdef _Stack t, u
    cdef int has
    try:
        memcpy(rows, v.data, sizeof(double) * 3 * count)
        t = _per_sample(dt, count, False, "dt")
        memcpy(dts, t.data, sizeof(double) * count)
        u = _per_sample(inputVoltage, count, False, "inputVoltage")
        memcpy(volts, u.data, sizeof(double) * count)
        # The previous setpoint is copied after the constraints' getters have run.
        has = g._load(prevSetpoint, constraints, &lim)
        for i in range(count):
            want.x, want.y, want.z = rows[3 * i], rows[3 * i + 1], rows[3 * i + 2]
            check_step(want, dts[i], volts[i], i)
        n = g.g.n
        chassis = np.empty((count, 3))
        modules = np.empty((count, n, 2))
        feedforwards = np.empty((count, 5, n))
        oc = <double*>cnp.PyArray_DATA(chassis)
        om = <double*>cnp.PyArray_DATA(modules)
        of = <double*>cnp.PyArray_DATA(feedforwards)
        out = g.out
        keep_headings(g)                # a refused row restores the memory of before the call
        for i in range(count):
            want.x, want.y, want.z = rows[3 * i], rows[3 * i + 1], rows[3 * i + 2]
            generate(&g.g, g.prev, want, dts[i], volts[i], &lim if has else NULL, out)
            check_output(g, i)
            memcpy(g.prev, out, sizeof(double) * (3 + 3 * n))
            memcpy(oc + 3 * i, out, sizeof(double) * 3)
            memcpy(of + 5 * n * i, out + 3 + 3 * n, sizeof(double) * 5 * n)
            for m in range(n):
                om[2 * (n * i + m)] = out[3 + m]
                om[2 * (n * i + m) + 1] = atan2(out[3 + 2 * n + m], out[3 + n + m])
    finally:
        PyMem_Free(rows)
    return chassis, modules, feedforwards


cdef object _rotate(object vectors, object robotAngles, object out, bint to_robot):
    cdef _Stack v = _stack(vectors, (3,), "chassis vectors")
    cdef _Stack a = _per_sample(robotAngles, v.n, v.single, "robotAngles")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v, a), "chassis vectors")
    cdef Py_ssize_t i, i0, ch, kk, count = v.n
    cdef const double* x
    cdef rot2_t r
    cdef vec2_t t
    cdef double c[CHUNK]
    cdef double s[CHUNK]
    with nogil:
        for ch in range((count + CHUNK - 1) // CHUNK):
            i0 = ch * CHUNK
            kk = chunk_len(i0, count)
            sincos_n(kk, a.data + i0, s, c)
            for i in range(kk):
                x = v.data + 3 * (i0 + i)
                r = rot_cs(c[i], s[i])
                if to_robot:
                    r = rot_neg(r)
                t = vec_rotate(vec(x[0], x[1]), r)
                o.data[3 * (i0 + i)] = t.x
                o.data[3 * (i0 + i) + 1] = t.y
                o.data[3 * (i0 + i) + 2] = x[2]
    return o.array


def toRobotRelative(chassisVectors, robotAngles, out=None):
    """:meth:`ChassisVelocities.toRobotRelative` (and the ChassisAccelerations one) for
    ``(3,)`` / ``(N, 3)`` field-relative vectors and robot headings ``robotAngles`` (rad;
    a float or ``(N,)``)."""
    return _rotate(chassisVectors, robotAngles, out, True)


def toFieldRelative(chassisVectors, robotAngles, out=None):
    """:meth:`ChassisVelocities.toFieldRelative` for ``(3,)`` / ``(N, 3)`` robot-relative
    vectors and robot headings ``robotAngles`` (rad; a float or ``(N,)``)."""
    return _rotate(chassisVectors, robotAngles, out, False)


cdef bint _rows3d(object x, Py_ssize_t w2, Py_ssize_t w3, str name) except -1:
    """Whether ``x`` holds 3-D rows (a last axis of w3) rather than 2-D ones (w2); an array
    of one or two axes whose last fits neither is refused here, anything else is left to
    the 2-D form's checks."""
    if not cnp.PyArray_Check(x):
        return False
    cdef tuple shape = x.shape
    cdef Py_ssize_t nd = len(shape)
    if nd == 1 or nd == 2:
        if shape[nd - 1] == w3:
            return True
        if shape[nd - 1] != w2:
            raise ValueError(f"{name} must have shape ({w2},) or (N, {w2}) (2-D), or "
                             f"({w3},) or (N, {w3}) (3-D), got {shape}")
    return False


cdef object _compose(object a, object b, object out, bint relative, str name_a, str name_b):
    # Pose2d.transformBy / relativeTo of [x, y, θ] rows, either of them single.
    cdef _Stack sa, sb
    sa, sb = _pair(a, b, (3,), name_a, name_b)
    cdef Py_ssize_t i, i0, ch, kk, count = sb.n if sa.single else sa.n
    cdef Py_ssize_t da = 0 if sa.single else 3, db = 0 if sb.single else 3
    cdef _Stack o = _result(out, count, sa.single and sb.single, (3,), (sa, sb), name_a)
    cdef const double* x
    cdef const double* y
    cdef pose2_t p, q
    cdef double buf[10 * CHUNK]     # each side's θ, sin, cos; then the poses (x, y, cos, sin)
    cdef double* ta = buf
    cdef double* tb = buf + CHUNK
    cdef double* sa_ = buf + 2 * CHUNK
    cdef double* ca = buf + 3 * CHUNK
    cdef double* sb_ = buf + 4 * CHUNK
    cdef double* cb = buf + 5 * CHUNK
    cdef double* px = buf + 6 * CHUNK
    cdef double* py = buf + 7 * CHUNK
    cdef double* pc = buf + 8 * CHUNK
    cdef double* ps = buf + 9 * CHUNK
    with nogil:
        for ch in range((count + CHUNK - 1) // CHUNK):
            i0 = ch * CHUNK
            kk = chunk_len(i0, count)
            for i in range(kk):
                ta[i] = sa.data[da * (i0 + i) + 2]
                tb[i] = sb.data[db * (i0 + i) + 2]
            sincos_n(kk, ta, sa_, ca)
            sincos_n(kk, tb, sb_, cb)
            for i in range(kk):
                x = sa.data + da * (i0 + i)
                y = sb.data + db * (i0 + i)
                p = pose(vec(x[0], x[1]), rot_cs(ca[i], sa_[i]))
                q = pose(vec(y[0], y[1]), rot_cs(cb[i], sb_[i]))
                keep_pose(i, px, py, pc, ps,
                          pose_relative_to(p, q) if relative else pose_transform_by(p, q))
            store_poses(kk, o.data + 3 * i0, px, py, pc, ps, ta)
    return o.array


def transformBy(poses, transforms, out=None):
    """:meth:`Pose2d.transformBy` for ``(3,)`` / ``(N, 3)`` poses and transforms
    ``[x m, y m, θ rad]``, or :meth:`Pose3d.transformBy` for ``(7,)`` / ``(N, 7)`` ones
    ``[x m, y m, z m, qw, qx, qy, qz]``: each pose moved by its transform. Either argument
    may be a single value, which goes with every sample of the other."""
    if _rows3d(poses, 3, 7, "poses"):
        return compose3(poses, transforms, out, False, "poses", "transforms")
    return _compose(poses, transforms, out, False, "poses", "transforms")


def relativeTo(poses, others, out=None):
    """:meth:`Pose2d.relativeTo` for ``(3,)`` / ``(N, 3)`` poses ``[x m, y m, θ rad]``, or
    :meth:`Pose3d.relativeTo` for ``(7,)`` / ``(N, 7)`` ones: each pose seen from the
    frame of its ``others`` pose. Either argument may be a single value, which goes with
    every sample of the other."""
    if _rows3d(poses, 3, 7, "poses"):
        return compose3(poses, others, out, True, "poses", "others")
    return _compose(poses, others, out, True, "poses", "others")


def exp(twists, out=None):
    """:meth:`Twist2d.exp` for ``(3,)`` / ``(N, 3)`` twists ``[dx m, dy m, dθ rad]``: the
    transforms ``[x m, y m, θ rad]``; :meth:`Twist3d.exp` for ``(6,)`` / ``(N, 6)`` twists
    ``[dx m, dy m, dz m, rx rad, ry rad, rz rad]``: the transforms ``(7,)`` / ``(N, 7)``."""
    if _rows3d(twists, 3, 6, "twists"):
        return exp3(twists, out)
    cdef _Stack v = _stack(twists, (3,), "twists")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v,), "twists")
    cdef Py_ssize_t i, i0, ch, kk, count = v.n
    cdef const double* x
    cdef double buf[7 * CHUNK]             # dθ, sin, cos, then the poses (x, y, cos, sin)
    cdef double* th = buf
    cdef double* s = buf + CHUNK
    cdef double* c = buf + 2 * CHUNK
    cdef double* px = buf + 3 * CHUNK
    cdef double* py = buf + 4 * CHUNK
    cdef double* pc = buf + 5 * CHUNK
    cdef double* ps = buf + 6 * CHUNK
    with nogil:
        for ch in range((count + CHUNK - 1) // CHUNK):
            i0 = ch * CHUNK
            kk = chunk_len(i0, count)
            for i in range(kk):
                th[i] = v.data[3 * (i0 + i) + 2]
            sincos_n(kk, th, s, c)
            for i in range(kk):
                x = v.data + 3 * (i0 + i)
                keep_pose(i, px, py, pc, ps, twist_exp_cs(x[0], x[1], x[2], c[i], s[i]))
            store_poses(kk, o.data + 3 * i0, px, py, pc, ps, th)
    return o.array


def log(transforms, out=None):
    """:meth:`Transform2d.log` for ``(3,)`` / ``(N, 3)`` transforms ``[x m, y m, θ rad]``:
    the twists ``[dx m, dy m, dθ rad]``; :meth:`Transform3d.log` for ``(7,)`` / ``(N, 7)``
    transforms: the twists ``(6,)`` / ``(N, 6)``."""
    if _rows3d(transforms, 3, 7, "transforms"):
        return log3(transforms, out)
    cdef _Stack v = _stack(transforms, (3,), "transforms")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v,), "transforms")
    cdef Py_ssize_t i, i0, ch, kk, count = v.n
    cdef const double* x
    cdef twist2_t tw
    cdef double th[CHUNK]
    cdef double c[CHUNK]
    cdef double s[CHUNK]
    with nogil:
        for ch in range((count + CHUNK - 1) // CHUNK):
            i0 = ch * CHUNK
            kk = chunk_len(i0, count)
            for i in range(kk):
                th[i] = v.data[3 * (i0 + i) + 2]
            sincos_n(kk, th, s, c)
            # The wrapped angle: Transform2d.log takes atan2 of the rotation.
            atan2_n(kk, s, c, th)
            for i in range(kk):
                x = v.data + 3 * (i0 + i)
                tw = transform_log_angle(pose(vec(x[0], x[1]), rot_cs(c[i], s[i])), th[i])
                o.data[3 * (i0 + i)] = tw.dx
                o.data[3 * (i0 + i) + 1] = tw.dy
                o.data[3 * (i0 + i) + 2] = tw.dtheta
    return o.array


# ---------------------------------------------------------------------------------------
# Odometry replay

def replay(odometry, gyroAngles, positions, out=None):
    """Run ``odometry.update`` for N samples; return the poses after each.

    The poses are ``(N, 3)`` ``[x m, y m, θ rad]``, or for a 3-D odometry ``(N, 7)``
    ``[x m, y m, z m, qw, qx, qy, qz]``; the odometry is left at the last one.

    ``gyroAngles`` is ``(N,)`` (rad; None for a DeadWheelOdometry built without a gyro),
    or for a 3-D odometry ``(N, 4)`` quaternions ``[w, x, y, z]`` (each read as
    ``Rotation3d(Quaternion(w, x, y, z))``); ``positions`` is what ``update`` reads,
    stacked: Swerve ``(N, M, 2)`` ``[distance m, angle rad]``; Mecanum ``(N, 4)``;
    Differential ``(N, 2)`` ``[left, right]``; TwoDeadWheel ``(N, 2)`` ``[xWheelPos,
    yWheelPos]``; DeadWheel ``(N, W)`` (m throughout), for the 2-D and 3-D classes
    alike."""
    if isinstance(odometry, _Odometry3d):
        return replay3(<_Odometry3d>odometry, gyroAngles, positions, out)
    if not isinstance(odometry, _Odometry):
        from drivekin._core.catalog import names
        raise TypeError(f"replay takes a drivekin {names('odometry')}, "
                        f"{names('odometry3d')} as its first argument, "
                        f"got {type_name(odometry)}")
    cdef _Odometry odo = <_Odometry>odometry
    if not odo.ready:
        raise RuntimeError(f"{type(odo).__name__}.__init__ has not completed")
    cdef tuple inner = sample_shape(odo.width, odo.steered)
    cdef bint needs_gyro = odo.gyro
    cdef _Stack p = _stack(positions, inner, "positions", False)
    cdef _Stack g
    if needs_gyro:
        if gyroAngles is None:
            raise TypeError("gyroAngles must be a float64 array of shape (N,), got None")
        g = _stack(gyroAngles, (), "gyroAngles", False)
        if g.n != p.n:
            raise ValueError(f"gyroAngles has {g.n} samples but positions has {p.n}")
    elif gyroAngles is not None:
        raise ValueError(f"this {type(odo).__name__} was constructed without a gyro, so "
                         "gyroAngles must be None")
    else:
        g = _per_sample(0.0, p.n, False, "gyroAngles")
    cdef _Stack o = _result(out, p.n, False, (3,), (p, g), "replay")
    _replay(odo, p, g, o)
    return o.array


cdef inline void gyro_turns(Py_ssize_t k, const double* g, rot2_t* prev,   # IN/OUT prev
                            double* gc, double* gs,                           # scratch
                            double* tc, double* ts, double* dth               # OUT
                            ) noexcept nogil:
    # gyro_turn for k samples: each gyro reading's change from the one before (prev before
    # the first; left at the last), as a rotation (tc, ts) and its angle dth. None of it
    # depends on the poses, so it runs ahead of the sequential pose updates, and with each
    # reading's predecessor read from the arrays (gc[i] is the reading before sample i) the
    # loop vectorises. gc and gs hold k + 1 values.
    cdef Py_ssize_t i
    cdef rot2_t d, before
    gc[0] = prev.c
    gs[0] = prev.s
    sincos_n(k, g, gs + 1, gc + 1)
    for i in range(k):
        before = rot_cs(gc[i], gs[i])
        d = gyro_turn(rot_cs(gc[i + 1], gs[i + 1]), &before)
        tc[i] = d.c
        ts[i] = d.s
    prev[0] = rot_cs(gc[k], gs[k])
    atan2_n(k, ts, tc, dth)


cdef int _replay(_Odometry odo, _Stack p, _Stack g, _Stack o) except -1:
    # The odometry step (the drivetrain's motion, the gyro turn, the pose change and its
    # composition, as in update), restaged per chunk as passes over all its samples: the
    # gyro turns; the motions (_Odometry._motions on the chunk's readings laid out
    # wheel-major, a steered drivetrain's with their directions' cos/sin); for
    # dead wheels without a gyro, the cos/sin of the solved dθ; the pose changes; then,
    # the only sequential pass, the compositions; then the headings. Each sample sees
    # exactly the operations of update (tests/behaviour/test_batch.py compares the bits).
    cdef Py_ssize_t i, i0, ch, kk, count = p.n, n = odo.width
    cdef bint gyro = odo.gyro
    cdef double* buf = _scratch(13 * CHUNK + 2 + 4 * CHUNK * n)
    cdef double* gc = buf                   # the gyro's cos and sin (CHUNK + 1 each)
    cdef double* gs = gc + CHUNK + 1
    cdef double* tc = gs + CHUNK + 1        # the heading change: cos, sin, angle
    cdef double* ts = tc + CHUNK
    cdef double* dth = ts + CHUNK
    cdef double* mx = dth + CHUNK           # each sample's motion dx, then dy (kk apart),
    cdef double* my                         # then the wheels' dθ
    cdef double* px = mx + 3 * CHUNK        # the pose changes, then the poses of the chunk
    cdef double* py = px + CHUNK
    cdef double* pc = py + CHUNK
    cdef double* ps = pc + CHUNK
    cdef double* hd = ps + CHUNK
    cdef double* md = hd + CHUNK            # a chunk's wheel distances (steered: and module
    cdef double* ang = md + CHUNK * n       # angles, cos and sin), wheel-major
    cdef double* mc = ang + CHUNK * n
    cdef double* ms = mc + CHUNK * n
    cdef pose2_t step, cur
    with nogil:
        for ch in range((count + CHUNK - 1) // CHUNK):
            i0 = ch * CHUNK
            kk = chunk_len(i0, count)
            my = mx + kk
            if gyro:
                gyro_turns(kk, g.data + i0, &odo.prev_gyro, gc, gs, tc, ts, dth)
            wheel_major(kk, n, p.data + p.width * i0, odo.steered, md, ang)
            if odo.steered:
                sincos_n(kk * n, ang, ms, mc)
                odo._motions(kk, md, mc, ms, dth, mx)
            else:
                odo._motions(kk, md, NULL, NULL, dth, mx)
            if not gyro:
                sincos_n(kk, dth, ts, tc)
            # The pose changes (vectorised), then the compositions, the only sequential part.
            for i in range(kk):
                step = odometry_motion(mx[i], my[i], dth[i], tc[i], ts[i], gyro)
                px[i] = step.t.x
                py[i] = step.t.y
                pc[i] = step.r.c
                ps[i] = step.r.s
            cur = odo.pose                  # a local, which the stores below cannot alias
            for i in range(kk):
                cur = pose_transform_by(cur, pose(vec(px[i], py[i]), rot_cs(pc[i], ps[i])))
                keep_pose(i, px, py, pc, ps, cur)
            odo.pose = cur
            odo.twist.dx = mx[kk - 1]
            odo.twist.dy = my[kk - 1]
            odo.twist.dtheta = dth[kk - 1]
            store_poses(kk, o.data + 3 * i0, px, py, pc, ps, hd)
    PyMem_Free(buf)
    return 0
