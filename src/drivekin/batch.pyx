"""Whole recordings at once: numpy stacks through the same kernels as the per-call API.

Shapes follow one convention ("single or stacked", as in scipy.spatial.transform): an
argument that is one value per call in the per-call API is either that value's array
(shape ``S``) or a stack of N of them (shape ``(N,) + S``), and results have the matching
form. The value arrays are

===========================  ==========  =============================================
value                        shape S     columns
===========================  ==========  =============================================
chassis vector / pose        (3,)        ``[vx m/s, vy m/s, omega rad/s]``,
                                         ``[x m, y m, θ rad]``, ``[dx m, dy m, dθ rad]``
swerve modules (M modules)   (M, 2)      ``[velocity m/s or distance m, angle rad]``
wheels (mecanum, diff, dead) (W,)        one value per wheel, the per-call order
angle / time step            ()          rad / s (a float, or an (N,) stack)
===========================  ==========  =============================================

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
"""
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from libc.math cimport atan2, cos, sin
cimport numpy as cnp

import numpy as np

from drivekin._types cimport pose2_t, rot2_t, twist2_t, vec2_t, vec3_t
from drivekin._kernels cimport (chassis_discretize, deadwheel_reading, deadwheel_solve,
                                forward_solve, mat_vec, pose, rot_neg, rot_rad, swerve_ik,
                                transform_log, twist_exp, vec, vec_rotate)
from drivekin.geometry cimport Translation2d
from drivekin.kinematics cimport SwerveDriveKinematics
from drivekin.mecanum cimport MecanumDriveKinematics
from drivekin.differential cimport DifferentialDriveKinematics
from drivekin.deadwheel cimport DeadWheelKinematics
from drivekin.odometry cimport (DeadWheelOdometry, DifferentialDriveOdometry,
                                MecanumDriveOdometry, SwerveDriveOdometry,
                                TwoDeadWheelOdometry, _Odometry)
from drivekin._errors import type_name

cnp.import_array()

__all__ = ["discretize", "exp", "log", "replay", "toChassisVelocities", "toFieldRelative",
           "toRobotRelative", "toSwerveModuleVelocities", "toWheelVelocities"]


# ---------------------------------------------------------------------------------------
# Argument handling. Each helper returns the validated array (the caller keeps it, so its
# data stays alive) and the data pointer; nothing is converted or copied.

cdef class _Stack:
    """One validated float64 argument: ``n`` samples of ``width`` doubles at ``data``."""
    cdef object array
    cdef double* data
    cdef Py_ssize_t n, width
    cdef bint single


cdef str _shape_text(tuple inner):
    return "(" + ", ".join([str(d) for d in inner]) + ("," if len(inner) == 1 else "") + ")"


cdef _Stack _stack(object x, tuple inner, str name, bint single_ok=True):
    """Validate ``x`` as one value of shape ``inner`` or an (N,) + inner stack."""
    cdef _Stack s = _Stack.__new__(_Stack)
    cdef cnp.ndarray a
    cdef tuple shape
    cdef Py_ssize_t d
    if not cnp.PyArray_Check(x):
        raise TypeError(f"{name} must be a float64 numpy array, got {type_name(x)}")
    a = <cnp.ndarray>x
    if cnp.PyArray_TYPE(a) != cnp.NPY_DOUBLE or not cnp.PyArray_ISNOTSWAPPED(a):
        raise TypeError(f"{name} must have dtype float64 (native byte order), got {a.dtype}")
    shape = (<object>a).shape
    if single_ok and shape == inner:
        s.single, s.n = True, 1
    elif len(shape) == len(inner) + 1 and shape[1:] == inner:
        s.single, s.n = False, shape[0]
    else:
        want = _shape_text(("N",) + inner)
        if single_ok:
            want = f"{_shape_text(inner)} or {want}"
        raise ValueError(f"{name} must have shape {want}, got {shape}")
    if not cnp.PyArray_IS_C_CONTIGUOUS(a) or not cnp.PyArray_ISALIGNED(a):
        raise ValueError(f"{name} must be C-contiguous and aligned "
                         "(np.ascontiguousarray makes a copy that is)")
    s.width = 1
    for d in inner:
        s.width *= d
    s.array = a
    s.data = <double*>cnp.PyArray_DATA(a)
    return s


cdef _Stack _per_sample(object x, Py_ssize_t n, bint single, str name):
    """One number per sample: a float (the same for every sample) or, beside a stack of
    n values, an (n,) float64 array. Always returned as n values."""
    cdef _Stack s
    if cnp.PyArray_Check(x):
        s = _stack(x, (), name)
        if s.single or single or s.n != n:
            raise ValueError(f"{name} must be a float" + ("" if single else
                             f" or have shape ({n},) to match the other argument") +
                             f", got an array of shape {x.shape}")
        return s
    if not isinstance(x, (float, int)) or isinstance(x, bool):
        raise TypeError(f"{name} must be a float or a float64 array, got {type_name(x)}")
    return _stack(np.full(n, float(x)), (), name, False)


cdef _Stack _result(object out, Py_ssize_t n, bint single, tuple inner, tuple inputs,
                    str name):
    """``out`` validated for the result's shape, or a new array."""
    cdef tuple shape = inner if single else (n,) + inner
    cdef _Stack s
    cdef _Stack i
    if out is None:
        out = np.empty(shape)
    else:
        if not cnp.PyArray_Check(out):
            raise TypeError(f"out must be a float64 numpy array, got {type_name(out)}")
        if out.shape != shape:
            raise ValueError(f"out must have shape {shape} for this {name}, got {out.shape}")
        if not cnp.PyArray_ISWRITEABLE(<cnp.ndarray>out):
            raise ValueError("out must be writeable")
        for i in inputs:
            if np.may_share_memory(out, i.array):
                raise ValueError("out must not overlap an input array")
    s = _stack(out, inner, "out")
    return s


cdef double* _scratch(Py_ssize_t count) except NULL:
    cdef double* p = <double*>PyMem_Malloc(sizeof(double) * (count if count > 0 else 1))
    if p == NULL:
        raise MemoryError()
    return p


cdef inline void store_pose(double* o, pose2_t p) noexcept nogil:
    o[0] = p.t.x
    o[1] = p.t.y
    o[2] = atan2(p.r.s, p.r.c)


cdef int _ready(object k, tuple types, str call) except -1:
    """Check that ``k`` is a complete object of one of ``types`` (exact types)."""
    cdef type kind = type(k)
    if kind is SwerveDriveKinematics and kind in types:
        (<SwerveDriveKinematics>k)._ready()
    elif kind is MecanumDriveKinematics and kind in types:
        (<MecanumDriveKinematics>k)._ready()
    elif kind is DifferentialDriveKinematics and kind in types:
        (<DifferentialDriveKinematics>k)._ready()
    elif kind is DeadWheelKinematics and kind in types:
        (<DeadWheelKinematics>k)._ready()
    elif kind in types and issubclass(kind, _Odometry):
        if not (<_Odometry>k).ready:
            raise RuntimeError(f"{kind.__name__}.__init__ has not completed")
    else:
        raise TypeError(f"{call} takes a drivekin " + ", ".join([t.__name__ for t in types]) +
                        f" as its first argument, got {type_name(k)}")
    return 0


# ---------------------------------------------------------------------------------------
# Inverse kinematics

def toSwerveModuleVelocities(SwerveDriveKinematics kinematics not None, chassisVelocities,
                             centerOfRotation=None, out=None):
    """Module velocities ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]`` for chassis velocities
    ``(3,)`` / ``(N, 3)`` (robot-relative), about ``centerOfRotation`` (a Translation2d,
    m; default the robot centre). The heading memory is used and left as N
    :meth:`SwerveDriveKinematics.toSwerveModuleVelocities` calls would leave it."""
    cdef SwerveDriveKinematics k = kinematics
    kinematics._ready()
    cdef _Stack v = _stack(chassisVelocities, (3,), "chassisVelocities")
    cdef vec2_t cor = vec(0.0, 0.0)
    if centerOfRotation is not None:
        if not isinstance(centerOfRotation, Translation2d):
            raise TypeError("centerOfRotation must be a drivekin Translation2d, got "
                            f"{type_name(centerOfRotation)}")
        cor = (<Translation2d>centerOfRotation).v
    cdef _Stack o = _result(out, v.n, v.single, (k.n, 2), (v,), "chassisVelocities")
    cdef Py_ssize_t n = k.n, i, j, count = v.n
    # Private copies of the rows and the headings: another thread's call cannot change
    # them under the loop, and the headings are written back once at the end.
    cdef double* buf = _scratch(7 * n)
    cdef double* rx = buf
    cdef double* ry = buf + n
    cdef double* hc = buf + 2 * n
    cdef double* hs = buf + 3 * n
    cdef double* sp = buf + 4 * n
    cdef double* oc = buf + 5 * n
    cdef double* os = buf + 6 * n
    cdef const double* x
    cdef double* y
    k._set_cor(cor)
    for j in range(n):
        rx[j] = k.rx[j]
        ry[j] = k.ry[j]
        hc[j] = k.hc[j]
        hs[j] = k.hs[j]
    with nogil:
        for i in range(count):
            x = v.data + 3 * i
            y = o.data + 2 * n * i
            swerve_ik(n, rx, ry, x[0], x[1], x[2], hc, hs, sp, oc, os)
            for j in range(n):
                y[2 * j] = sp[j]
                y[2 * j + 1] = atan2(os[j], oc[j])
    for j in range(n):
        k.hc[j] = hc[j]
        k.hs[j] = hs[j]
    PyMem_Free(buf)
    return o.array


def toWheelVelocities(kinematics, chassisVelocities, centerOfRotation=None, out=None):
    """Wheel velocities ``(W,)`` / ``(N, W)`` (m/s) for chassis velocities ``(3,)`` /
    ``(N, 3)``: mecanum (W = 4, about ``centerOfRotation``), differential (W = 2,
    ``[left, right]``) or dead-wheel (W = the wheel count; surface velocities)."""
    _ready(kinematics, (MecanumDriveKinematics, DifferentialDriveKinematics,
                        DeadWheelKinematics), "toWheelVelocities")
    cdef _Stack v = _stack(chassisVelocities, (3,), "chassisVelocities")
    cdef Py_ssize_t i, j, w, count = v.n
    cdef double m[12]
    cdef double half
    cdef const double* x
    cdef double* y
    cdef double* rows
    cdef _Stack o
    cdef DeadWheelKinematics dk
    if type(kinematics) is MecanumDriveKinematics:
        if centerOfRotation is None:
            centerOfRotation = Translation2d()
        elif not isinstance(centerOfRotation, Translation2d):
            raise TypeError("centerOfRotation must be a drivekin Translation2d, got "
                            f"{type_name(centerOfRotation)}")
        o = _result(out, count, v.single, (4,), (v,), "chassisVelocities")
        (<MecanumDriveKinematics>kinematics)._set_cor((<Translation2d>centerOfRotation).v)
        m = (<MecanumDriveKinematics>kinematics).m
        with nogil:
            for i in range(count):
                mat_vec(4, 3, m, v.data + 3 * i, o.data + 4 * i)
        return o.array
    if centerOfRotation is not None:
        raise TypeError(f"{type(kinematics).__name__} has no centre of rotation argument")
    if type(kinematics) is DifferentialDriveKinematics:
        o = _result(out, count, v.single, (2,), (v,), "chassisVelocities")
        half = (<DifferentialDriveKinematics>kinematics)._trackwidth / 2.0
        with nogil:
            for i in range(count):
                x = v.data + 3 * i
                o.data[2 * i] = x[0] - half * x[2]
                o.data[2 * i + 1] = x[0] + half * x[2]
        return o.array
    dk = <DeadWheelKinematics>kinematics
    w = dk.n
    o = _result(out, count, v.single, (w,), (v,), "chassisVelocities")
    rows = _scratch(3 * w)
    for j in range(3 * w):
        rows[j] = dk.m[j]
    with nogil:
        for i in range(count):
            x = v.data + 3 * i
            y = o.data + w * i
            for j in range(w):
                y[j] = deadwheel_reading(rows + 3 * j, x[0], x[1], x[2])
    PyMem_Free(rows)
    return o.array


# ---------------------------------------------------------------------------------------
# Forward kinematics

def toChassisVelocities(kinematics, wheelVelocities, gyroRates=None, out=None):
    """Chassis velocities ``(3,)`` / ``(N, 3)`` ``[vx, vy, omega]`` from swerve module
    velocities ``(M, 2)`` / ``(N, M, 2)`` ``[m/s, rad]``, or wheel velocities ``(W,)`` /
    ``(N, W)`` of a mecanum, differential or dead-wheel drive. ``gyroRates`` (rad/s, a
    float or ``(N,)``) is the dead-wheel form's optional gyro."""
    _ready(kinematics, (SwerveDriveKinematics, MecanumDriveKinematics,
                        DifferentialDriveKinematics, DeadWheelKinematics),
           "toChassisVelocities")
    cdef Py_ssize_t i, j, n, count
    cdef _Stack w, o, g
    cdef double* buf
    cdef double* f
    cdef double tw
    cdef const double* x
    cdef DeadWheelKinematics dk
    cdef SwerveDriveKinematics sk
    cdef bint gyro = gyroRates is not None
    if gyro and type(kinematics) is not DeadWheelKinematics:
        raise TypeError("gyroRates is only for DeadWheelKinematics")
    if type(kinematics) is SwerveDriveKinematics:
        sk = <SwerveDriveKinematics>kinematics
        n = sk.n
        w = _stack(wheelVelocities, (n, 2), "moduleVelocities")
        count = w.n
        o = _result(out, count, w.single, (3,), (w,), "moduleVelocities")
        buf = _scratch(3 * n + 6 * n)
        f = buf + 3 * n
        for j in range(6 * n):
            f[j] = sk.f1[j]
        with nogil:
            for i in range(count):
                x = w.data + 2 * n * i
                for j in range(n):
                    buf[j] = x[2 * j]
                    buf[n + j] = cos(x[2 * j + 1])
                    buf[2 * n + j] = sin(x[2 * j + 1])
                forward_solve(3, n, f, buf, buf + n, buf + 2 * n, o.data + 3 * i)
        PyMem_Free(buf)
        return o.array
    if type(kinematics) is MecanumDriveKinematics:
        w = _stack(wheelVelocities, (4,), "wheelVelocities")
        o = _result(out, w.n, w.single, (3,), (w,), "wheelVelocities")
        f = (<MecanumDriveKinematics>kinematics).f
        count = w.n
        with nogil:
            for i in range(count):
                mat_vec(3, 4, f, w.data + 4 * i, o.data + 3 * i)
        return o.array
    if type(kinematics) is DifferentialDriveKinematics:
        w = _stack(wheelVelocities, (2,), "wheelVelocities")
        o = _result(out, w.n, w.single, (3,), (w,), "wheelVelocities")
        tw = (<DifferentialDriveKinematics>kinematics)._trackwidth
        count = w.n
        with nogil:
            for i in range(count):
                x = w.data + 2 * i
                o.data[3 * i] = (x[0] + x[1]) / 2.0
                o.data[3 * i + 1] = 0.0
                o.data[3 * i + 2] = (x[1] - x[0]) / tw
        return o.array
    dk = <DeadWheelKinematics>kinematics
    n = dk.n
    w = _stack(wheelVelocities, (n,), "wheelVelocities")
    count = w.n
    if gyro:
        g = _per_sample(gyroRates, count, w.single, "gyroRates")
    else:
        if not dk.heading:
            dk._need_heading("toChassisVelocities")
        g = _per_sample(0.0, count, w.single, "gyroRates")
    o = _result(out, count, w.single, (3,), (w, g), "wheelVelocities")
    buf = _scratch(6 * n + 2)
    for j in range(3 * n):
        buf[j] = dk.p3[j]
    for j in range(2 * n):
        buf[3 * n + j] = dk.p2[j]
    buf[5 * n] = dk.g[0]
    buf[5 * n + 1] = dk.g[1]
    with nogil:
        for i in range(count):
            deadwheel_solve(n, buf, buf + 3 * n, buf + 5 * n, w.data + n * i, gyro, g.data[i],
                            o.data + 3 * i)
    PyMem_Free(buf)
    return o.array


# ---------------------------------------------------------------------------------------
# Chassis vectors and geometry

def discretize(chassisVelocities, dt, out=None):
    """:meth:`ChassisVelocities.discretize` for ``(3,)`` / ``(N, 3)`` velocities; ``dt`` (s)
    is a float or an ``(N,)`` stack."""
    cdef _Stack v = _stack(chassisVelocities, (3,), "chassisVelocities")
    cdef _Stack t = _per_sample(dt, v.n, v.single, "dt")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v, t), "chassisVelocities")
    cdef Py_ssize_t i, count = v.n
    cdef const double* x
    cdef vec3_t d
    with nogil:
        for i in range(count):
            x = v.data + 3 * i
            d = chassis_discretize(x[0], x[1], x[2], t.data[i])
            o.data[3 * i] = d.x
            o.data[3 * i + 1] = d.y
            o.data[3 * i + 2] = d.z
    return o.array


cdef object _rotate(object vectors, object robotAngles, object out, bint to_robot):
    cdef _Stack v = _stack(vectors, (3,), "chassis vectors")
    cdef _Stack a = _per_sample(robotAngles, v.n, v.single, "robotAngles")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v, a), "chassis vectors")
    cdef Py_ssize_t i, count = v.n
    cdef const double* x
    cdef rot2_t r
    cdef vec2_t t
    with nogil:
        for i in range(count):
            x = v.data + 3 * i
            r = rot_rad(a.data[i])
            if to_robot:
                r = rot_neg(r)
            t = vec_rotate(vec(x[0], x[1]), r)
            o.data[3 * i] = t.x
            o.data[3 * i + 1] = t.y
            o.data[3 * i + 2] = x[2]
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


def exp(twists, out=None):
    """:meth:`Twist2d.exp` for ``(3,)`` / ``(N, 3)`` twists ``[dx m, dy m, dθ rad]``: the
    transforms ``[x m, y m, θ rad]``."""
    cdef _Stack v = _stack(twists, (3,), "twists")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v,), "twists")
    cdef Py_ssize_t i, count = v.n
    cdef const double* x
    with nogil:
        for i in range(count):
            x = v.data + 3 * i
            store_pose(o.data + 3 * i, twist_exp(x[0], x[1], x[2]))
    return o.array


def log(transforms, out=None):
    """:meth:`Transform2d.log` for ``(3,)`` / ``(N, 3)`` transforms ``[x m, y m, θ rad]``:
    the twists ``[dx m, dy m, dθ rad]``."""
    cdef _Stack v = _stack(transforms, (3,), "transforms")
    cdef _Stack o = _result(out, v.n, v.single, (3,), (v,), "transforms")
    cdef Py_ssize_t i, count = v.n
    cdef const double* x
    cdef twist2_t tw
    with nogil:
        for i in range(count):
            x = v.data + 3 * i
            tw = transform_log(pose(vec(x[0], x[1]), rot_rad(x[2])))
            o.data[3 * i] = tw.dx
            o.data[3 * i + 1] = tw.dy
            o.data[3 * i + 2] = tw.dtheta
    return o.array


# ---------------------------------------------------------------------------------------
# Odometry replay

def replay(odometry, gyroAngles, positions, out=None):
    """Run ``odometry.update`` for N samples; return the poses ``(N, 3)`` ``[x m, y m,
    θ rad]`` after each, leaving the odometry at the last one.

    ``gyroAngles`` is ``(N,)`` (rad; None for a DeadWheelOdometry built without a gyro);
    ``positions`` is what ``update`` reads, stacked: SwerveDriveOdometry ``(N, M, 2)``
    ``[distance m, angle rad]``; MecanumDriveOdometry ``(N, 4)``; DifferentialDriveOdometry
    ``(N, 2)`` ``[left, right]``; TwoDeadWheelOdometry ``(N, 2)`` ``[xWheelPos,
    yWheelPos]``; DeadWheelOdometry ``(N, W)`` (m throughout)."""
    cdef type kind = type(odometry)
    cdef tuple inner
    cdef bint needs_gyro = True
    _ready(odometry, (SwerveDriveOdometry, MecanumDriveOdometry, DifferentialDriveOdometry,
                      TwoDeadWheelOdometry, DeadWheelOdometry), "replay")
    if kind is SwerveDriveOdometry:
        inner = ((<SwerveDriveOdometry>odometry).kin.n, 2)
    elif kind is MecanumDriveOdometry:
        inner = (4,)
    elif kind is DeadWheelOdometry:
        inner = ((<DeadWheelOdometry>odometry).kin.n,)
        needs_gyro = (<DeadWheelOdometry>odometry).gyro
    else:
        inner = (2,)
    cdef _Stack p = _stack(positions, inner, "positions", False)
    cdef _Stack g
    if needs_gyro:
        if gyroAngles is None:
            raise TypeError("gyroAngles must be a float64 array of shape (N,), got None")
        g = _stack(gyroAngles, (), "gyroAngles", False)
        if g.n != p.n:
            raise ValueError(f"gyroAngles has {g.n} samples but positions has {p.n}")
    elif gyroAngles is not None:
        raise ValueError("this DeadWheelOdometry was constructed without a gyro, so "
                         "gyroAngles must be None")
    else:
        g = _per_sample(0.0, p.n, False, "gyroAngles")
    cdef _Stack o = _result(out, p.n, False, (3,), (p, g), "replay")
    _replay(odometry, kind, p, g, o)
    return o.array


cdef int _replay(object odometry, type kind, _Stack p, _Stack g, _Stack o) except -1:
    cdef Py_ssize_t i, j, count = p.n, n = p.width
    cdef const double* x
    cdef double* buf = _scratch(3 * n)
    cdef SwerveDriveOdometry so
    cdef MecanumDriveOdometry mo
    cdef DifferentialDriveOdometry do
    cdef TwoDeadWheelOdometry to
    cdef DeadWheelOdometry wo
    if kind is SwerveDriveOdometry:
        so = odometry
        n = so.kin.n
        with nogil:
            for i in range(count):
                x = p.data + 2 * n * i
                for j in range(n):
                    buf[j] = x[2 * j]
                    buf[n + j] = cos(x[2 * j + 1])
                    buf[2 * n + j] = sin(x[2 * j + 1])
                so._advance(buf, buf + n, buf + 2 * n, rot_rad(g.data[i]))
                store_pose(o.data + 3 * i, so.pose)
    elif kind is MecanumDriveOdometry:
        mo = odometry
        with nogil:
            for i in range(count):
                mo._advance(p.data + 4 * i, rot_rad(g.data[i]))
                store_pose(o.data + 3 * i, mo.pose)
    elif kind is DifferentialDriveOdometry:
        do = odometry
        with nogil:
            for i in range(count):
                do._advance(p.data[2 * i], p.data[2 * i + 1], rot_rad(g.data[i]))
                store_pose(o.data + 3 * i, do.pose)
    elif kind is TwoDeadWheelOdometry:
        to = odometry
        with nogil:
            for i in range(count):
                to._advance(p.data[2 * i], p.data[2 * i + 1], rot_rad(g.data[i]))
                store_pose(o.data + 3 * i, to.pose)
    else:
        wo = odometry
        with nogil:
            for i in range(count):
                for j in range(n):
                    buf[j] = p.data[n * i + j]
                wo._advance(buf, rot_rad(g.data[i]))
                store_pose(o.data + 3 * i, wo.pose)
    PyMem_Free(buf)
    return 0
