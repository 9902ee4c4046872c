"""N-module swerve kinematics (WPILib 2027). The swerve module values it takes and returns
are :mod:`drivekin.swervemodule`'s, importable from here too.

Units: m, m/s, m/s², rad, rad/s, rad/s², s. Robot frame: x forward, y left, CCW positive.

Every hot operation has two forms: an object-returning façade with WPILib's name, and an
allocation-free ``...Into`` / ``...InPlace`` form that writes into caller-owned objects or
numpy buffers. Kinematics objects carry heading memory and are not thread-safe (as in
WPILib); every method runs with the GIL held, so a call is never interleaved."""
from drivekin._core.drivetrain cimport Drivetrain
cimport numpy as cnp
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from cpython.ref cimport PyObject
from cpython.sequence cimport PySequence_Fast_GET_SIZE, PySequence_Fast_ITEMS
from cpython.list cimport PyList_CheckExact
from cpython.tuple cimport PyTuple_CheckExact
from libc.math cimport INFINITY, fabs, isfinite
from drivekin._core.dkmath cimport atan2_n, sincos_n
from libc.string cimport memcpy

import numpy as np

from drivekin._core.types cimport desat_t, rot2_t, vec2_t, vec3_t
from drivekin._core.args cimport as_fast, check_type, exact_type, float64_data, snapshot
from drivekin._core.kernels cimport (
    chassis_discretize, desaturate_factors, desaturated_discretize_scale, forward_solve,
    forward_solve_many, jmax, max_abs, swerve_ik, swerve_ik_accel, vec, vec_eq,
)
from drivekin.swervemodule cimport (SwerveModuleAcceleration, SwerveModulePosition,
                                    SwerveModuleVelocity, _ModuleVector, new_modules)
from drivekin.geometry cimport Rotation2d, Translation2d, Twist2d, new_rotation, new_twist
from drivekin.chassis cimport (ChassisAccelerations, ChassisVelocities, check_discretize_fits,
                              new_chassis_velocities)
from drivekin._core.drivetrain import pseudo_inverse
from drivekin._core.errors import type_name

cnp.import_array()

# An import statement does not bind a name this module cimports, so the module values are
# bound through the module dict: their names stay importable from here.
from drivekin import swervemodule as _swervemodule
globals().update({name: getattr(_swervemodule, name) for name in _swervemodule.__all__})

__all__ = ["SwerveDriveKinematics", "SwerveModuleAcceleration", "SwerveModulePosition",
           "SwerveModuleVelocity"]

cdef Translation2d ORIGIN = Translation2d()
# Module counts up to this are handled in stack memory by the static desaturation façade.
cdef enum:
    STACK_MODULES = 16


# ---------------------------------------------------------------------------------------
# Argument helpers of the swerve classes

cdef object varargs(object first, tuple more, type cls):
    """WPILib methods take Java varargs: accept f(a, b, c) or f([a, b, c]). Taking the
    first argument by name keeps the common one-sequence call free of tuple packing."""
    if not more and type(first) is not cls:
        return first
    return (first,) + more


cdef inline _ModuleVector item(PyObject** items, Py_ssize_t i, type cls, str what):
    if not exact_type(items[i], <PyObject*>cls):
        raise TypeError(f"{what}[{i}] must be a {cls.__name__}, "
                        f"got {type_name(<object>items[i])}")
    return <_ModuleVector>items[i]


# Results are stored in two steps: the destination is built (swervemodule's new_modules)
# or validated first (which may allocate or run Python code), then the kernel runs and
# store_modules copies its output with nothing in between that could run a finalizer,
# another thread or a re-entrant call on the shared scratch, and nothing changes if the
# destination is rejected.

cdef object out_modules(object out, Py_ssize_t n, type cls, str what, double** data):
    """Validate a caller's ``out``: return the list/tuple of its n ``cls`` objects, or None
    with ``data[0]`` pointing at the memory of an (n, 2) float64 array."""
    cdef Py_ssize_t i
    cdef object fast
    data[0] = NULL
    if not (PyTuple_CheckExact(out) or PyList_CheckExact(out)) and cnp.PyArray_Check(out):
        data[0] = float64_data(out, n, 2, True, what)
        return None
    fast = as_fast(out, what)
    if PySequence_Fast_GET_SIZE(fast) != n:
        raise ValueError(f"{what} must hold {n} {cls.__name__} objects, "
                         f"got {PySequence_Fast_GET_SIZE(fast)}")
    for i in range(n):
        item(PySequence_Fast_ITEMS(fast), i, cls, what)
    return fast


cdef void store_rows(double* d, Py_ssize_t n, const double* m, const double* c,
                    const double* s, double* a) noexcept nogil:
    """Copy n (scalar, cos, sin) into the [scalar, angle] rows of an (n, 2) array, the
    angles a vector at a time (the same bits as one atan2 per module) through ``a``
    (scratch for n)."""
    cdef Py_ssize_t i
    atan2_n(n, s, c, a)
    for i in range(n):
        d[2 * i] = m[i]
        d[2 * i + 1] = a[i]


cdef void store_modules(object fast, Py_ssize_t n, const double* m, const double* c,
                        const double* s) noexcept:
    """Copy n (scalar, cos, sin) into the module objects out_modules/new_modules
    returned (an array's rows are store_rows')."""
    cdef Py_ssize_t i
    cdef PyObject** items
    items = PySequence_Fast_ITEMS(fast)
    for i in range(n):
        (<_ModuleVector>items[i]).m = m[i]
        (<_ModuleVector>items[i]).a.c = c[i]
        (<_ModuleVector>items[i]).a.s = s[i]


# ---------------------------------------------------------------------------------------
cdef class SwerveDriveKinematics(Drivetrain):
    """``SwerveDriveKinematics(*module_translations)``

    Kinematics of a swerve drive with N ≥ 2 modules at the given robot-relative
    positions (Translation2d, m), in the order used by every method. Pass the
    translations as separate arguments or as one sequence.

    Inverse kinematics remembers each module's last heading: when the commanded chassis
    velocity is exactly zero, or a module's own speed is at most 1e-6 m/s, the module keeps
    its previous angle instead of snapping to 0. The heading memory lives in this object.
    The forward (pseudo-inverse) matrices are computed once for a centre of rotation at
    the robot origin and never change; a ``center_of_rotation`` passed to inverse
    kinematics only moves the inverse rows, and stays in effect until a different one is
    passed (compared within 1e-9 m).
    """

    def __cinit__(self, *module_translations):
        self.buf = NULL

    cdef int _refuse_reinit(self) except -1:
        if self.buf != NULL:
            raise TypeError("SwerveDriveKinematics is already initialised: __init__ cannot "
                            "be called again")
        return 0

    def __init__(self, *module_translations):
        self._refuse_reinit()
        if not module_translations:
            raise ValueError("a swerve drive needs at least 2 modules, got 0")
        mods = snapshot(varargs(module_translations[0], module_translations[1:],
                                Translation2d),
                        "SwerveDriveKinematics() takes Translation2d module positions or one "
                        "sequence of them; the argument")
        cdef Py_ssize_t n = len(mods), i, k
        if n < 2:
            raise ValueError(f"a swerve drive needs at least 2 modules, got {n}")
        for i, t in enumerate(mods):
            if not isinstance(t, Translation2d):
                raise TypeError(f"module {i} must be a Translation2d, got {type_name(t)}")
            if not (isfinite((<Translation2d>t).v.x) and isfinite((<Translation2d>t).v.y)):
                raise ValueError(f"module {i} position must be finite (m), got {t!r}")
        # Forward kinematics is the least-squares inverse of the inverse-kinematics
        # matrices at CoR = 0 (WPILib Java's EJML pinv, rank-deficient layouts included),
        # drivekin's own (the same bits on every platform), built once.
        # Everything that can fail runs before the object is touched.
        xs = np.array([(<Translation2d>t).v.x for t in mods])
        ys = np.array([(<Translation2d>t).v.y for t in mods])
        m1 = np.zeros((2 * n, 3))
        m1[0::2, 0] = 1.0
        m1[1::2, 1] = 1.0
        m1[0::2, 2] = -ys
        m1[1::2, 2] = xs
        m2 = np.zeros((2 * n, 4))
        m2[0::2, 0] = 1.0
        m2[1::2, 1] = 1.0
        m2[0::2, 2] = -xs
        m2[0::2, 3] = -ys
        m2[1::2, 2] = -ys
        m2[1::2, 3] = xs
        cdef double[:, ::1] p1 = pseudo_inverse(m1)
        cdef double[:, ::1] p2 = pseudo_inverse(m2)
        # Reading a generic iterable above ran Python code, which may have initialised
        # this object meanwhile; committing now would leak and replace that state.
        self._refuse_reinit()
        # 10 arrays of n (positions, CoR rows, headings, scratch) + f1 (3 x 2n) + f2 (4 x 2n)
        cdef double* buf = <double*>PyMem_Malloc(sizeof(double) * (10 * n + 6 * n + 8 * n))
        if buf == NULL:
            raise MemoryError()
        self.n = n
        self.nwheels = n
        self.steered = True
        self.centered = True
        self.modules = mods
        self.mx = buf
        self.my = self.mx + n
        self.rx = self.my + n
        self.ry = self.rx + n
        self.hc = self.ry + n
        self.hs = self.hc + n
        self.s0 = self.hs + n
        self.s1 = self.s0 + n
        self.s2 = self.s1 + n
        self.s3 = self.s2 + n
        self.f1 = self.s3 + n            # 3 x 2n
        self.f2 = self.f1 + 6 * n        # 4 x 2n
        for i in range(n):
            self.mx[i] = xs[i]
            self.my[i] = ys[i]
            self.rx[i] = self.mx[i]
            self.ry[i] = self.my[i]
            self.hc[i] = 1.0
            self.hs[i] = 0.0
        self.cor = vec(0.0, 0.0)
        for i in range(2 * n):
            for k in range(3):
                self.f1[k * 2 * n + i] = p1[k, i]
            for k in range(4):
                self.f2[k * 2 * n + i] = p2[k, i]
        # Set last: a non-NULL buf is what every method checks before computing.
        self.buf = buf

    def __dealloc__(self):
        PyMem_Free(self.buf)

    cdef int _ready(self) except -1:
        if self.buf == NULL:
            raise RuntimeError("SwerveDriveKinematics.__init__ has not completed")
        return 0

    def __reduce__(self):
        # Heading memory is state (it decides the angles at zero velocity): a copy or an
        # unpickled object must behave exactly like the original. The centre of rotation
        # is only a cache of rows, rebuilt from each call's argument.
        self._ready()
        cdef rot2_t h
        cdef Py_ssize_t i
        headings = []
        for i in range(self.n):
            h.c = self.hc[i]
            h.s = self.hs[i]
            headings.append(new_rotation(h))
        return (SwerveDriveKinematics, self.modules, tuple(headings))

    def __setstate__(self, state):
        """Restore the heading memory (N Rotation2d; used by copy and pickle)."""
        if type(state) is not tuple:
            raise TypeError(f"SwerveDriveKinematics state must be a tuple of Rotation2d, "
                            f"got {type_name(state)}")
        self.resetHeadings(state)

    def __repr__(self):
        if self.buf == NULL:
            return "<uninitialised SwerveDriveKinematics>"
        return f"SwerveDriveKinematics({', '.join(repr(m) for m in self.modules)})"

    def getModules(self):
        """Return the module positions (tuple of Translation2d, m), constructor order."""
        self._ready()
        return self.modules

    def getNumModules(self):
        """Return the number of modules N."""
        self._ready()
        return self.n

    def resetHeadings(self, module_headings, *more):
        """Replace the remembered module headings (N Rotation2d, as arguments or one
        sequence); used when the chassis velocity is zero or a module is on the CoR."""
        self._ready()
        cdef object fast = as_fast(varargs(module_headings, more, Rotation2d),
                                   "module_headings")
        cdef Py_ssize_t i, k = PySequence_Fast_GET_SIZE(fast)
        if k != self.n:
            raise ValueError(f"expected {self.n} module headings (one per module), got {k}")
        cdef PyObject** items = PySequence_Fast_ITEMS(fast)
        for i in range(k):
            if not exact_type(items[i], <PyObject*>Rotation2d):
                raise TypeError(f"module_headings[{i}] must be a Rotation2d, "
                                f"got {type_name(<object>items[i])}")
        for i in range(k):
            self.hc[i] = (<Rotation2d>items[i]).r.c
            self.hs[i] = (<Rotation2d>items[i]).r.s

    cdef void _set_cor(self, vec2_t cor) noexcept:
        cdef Py_ssize_t i
        if not vec_eq(cor, self.cor):
            for i in range(self.n):
                self.rx[i] = self.mx[i] - cor.x
                self.ry[i] = self.my[i] - cor.y
            self.cor = cor

    # -----------------------------------------------------------------------------------
    # The drivetrain contract (drivekin._core.drivetrain): a steered drivetrain of n modules

    cdef Py_ssize_t _params(self, double* params, bint forward, bint accel) noexcept:
        # Inverse: the CoR rows and the heading memory (rx, ry, hc, hs: adjacent in buf);
        # forward: the pseudo-inverse.
        cdef Py_ssize_t count = ((8 if accel else 6) if forward else 4) * self.n
        if params != NULL:
            memcpy(params, (self.f2 if accel else self.f1) if forward else self.rx,
                   sizeof(double) * count)
        return count

    cdef void _inverse_many(self, Py_ssize_t k, const double* chassis, const double* omega,
                            bint accel, double* params,
                            double* m, double* c, double* s) noexcept nogil:
        cdef Py_ssize_t i, n = self.n
        cdef const double* x
        for i in range(k):
            x = chassis + 3 * i
            if accel:
                swerve_ik_accel(n, params, params + n, x[0], x[1], omega[i], x[2], m + n * i,
                                c + n * i, s + n * i)
            else:
                swerve_ik(n, params, params + n, x[0], x[1], x[2], params + 2 * n,
                          params + 3 * n, m + n * i, c + n * i, s + n * i)

    cdef void _inverse_done(self, const double* params, bint accel) noexcept:
        # The velocity map leaves the heading memory as that many calls would.
        if not accel:
            memcpy(self.hc, params + 2 * self.n, sizeof(double) * 2 * self.n)

    cdef void _forward_many(self, Py_ssize_t k, const double* m, const double* c,
                            const double* s, const double* gyro, bint accel,
                            const double* params, double* out) noexcept nogil:
        cdef Py_ssize_t i, j, n = self.n
        cdef double r[4]
        for i in range(k):
            j = n * i
            if accel:
                # The solve's third row (the ω² estimate) is discarded.
                forward_solve(4, n, params, m + j, c + j, s + j, r)
                out[3 * i] = r[0]
                out[3 * i + 1] = r[1]
                out[3 * i + 2] = r[3]
            else:
                forward_solve(3, n, params, m + j, c + j, s + j, out + 3 * i)

    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil:
        # The velocity pseudo-inverse's rows, without the dθ row when it is known; the
        # loop over samples innermost, so it vectorises.
        forward_solve_many(2 if dth != NULL else 3, self.n, k, self.f1, d, c, s, out)

    cdef void _twist(self, const double* d, const double* c, const double* s,
                     const double* dth, double* out) noexcept nogil:
        # forward_solve: the cheaper form of the same sums for one sample.
        if dth != NULL:
            forward_solve(2, self.n, self.f1, d, c, s, out)
        else:
            forward_solve(3, self.n, self.f1, d, c, s, out)

    cdef int _ik(self, ChassisVelocities cv, Translation2d cor) except -1:
        # Exact zero returns the remembered headings without looking at the CoR.
        if not (cv.v.x == 0.0 and cv.v.y == 0.0 and cv.v.z == 0.0):
            self._set_cor(cor.v)
        swerve_ik(self.n, self.rx, self.ry, cv.v.x, cv.v.y, cv.v.z, self.hc, self.hs,
                  self.s0, self.s1, self.s2)
        return 0

    def toSwerveModuleVelocities(self, chassis_velocities: ChassisVelocities,
                                 center_of_rotation: Translation2d = ORIGIN):
        """Return the N module velocities (tuple of SwerveModuleVelocity) that produce
        ``chassis_velocities`` (robot-relative, m/s and rad/s), rotating about
        ``center_of_rotation`` (robot frame, m). Module speeds are ≥ 0; the angles follow
        the heading-memory rules in the class docstring. Not desaturated."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        check_type(center_of_rotation, Translation2d, "center_of_rotation")
        self._ready()
        cdef object t = new_modules(self.n, SwerveModuleVelocity)
        self._ik(<ChassisVelocities>chassis_velocities, <Translation2d>center_of_rotation)
        store_modules(t, self.n, self.s0, self.s1, self.s2)
        return t

    def toWheelVelocities(self, chassis_velocities: ChassisVelocities):
        """Same as :meth:`toSwerveModuleVelocities` about the robot origin."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        self._ready()
        cdef object t = new_modules(self.n, SwerveModuleVelocity)
        self._ik(<ChassisVelocities>chassis_velocities, ORIGIN)
        store_modules(t, self.n, self.s0, self.s1, self.s2)
        return t

    def toSwerveModuleVelocitiesInto(self, chassis_velocities: ChassisVelocities, out,
                                     center_of_rotation: Translation2d = ORIGIN):
        """Allocation-free :meth:`toSwerveModuleVelocities`.

        ``out`` is either a list/tuple of N SwerveModuleVelocity objects, updated in place,
        or a float64 C-contiguous writeable numpy array of shape (N, 2) that receives
        ``[velocity m/s, angle rad]`` per module. Returns None."""
        cdef double* d
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        check_type(center_of_rotation, Translation2d, "center_of_rotation")
        self._ready()
        cdef object fast = out_modules(out, self.n, SwerveModuleVelocity, "out", &d)
        self._ik(<ChassisVelocities>chassis_velocities, <Translation2d>center_of_rotation)
        if d == NULL:
            store_modules(fast, self.n, self.s0, self.s1, self.s2)
        else:
            store_rows(d, self.n, self.s0, self.s1, self.s2, self.s3)

    cdef int _read(self, object states, type cls, str what) except -1:
        """Load N (scalar, cos, sin) from objects or an (N, 2) array into the scratch."""
        cdef Py_ssize_t i, n = self.n
        cdef const double* d
        cdef _ModuleVector o
        cdef object fast
        cdef PyObject** items
        self._ready()
        if not (PyTuple_CheckExact(states) or PyList_CheckExact(states)) and cnp.PyArray_Check(states):
            d = float64_data(states, n, 2, False, what)
            for i in range(n):
                self.s0[i] = d[2 * i]
                self.s3[i] = d[2 * i + 1]
            sincos_n(n, self.s3, self.s2, self.s1)
            return 0
        fast = as_fast(states, what)
        if PySequence_Fast_GET_SIZE(fast) != n:
            raise ValueError(f"expected {n} {cls.__name__} objects (one per module), "
                             f"got {PySequence_Fast_GET_SIZE(fast)}")
        items = PySequence_Fast_ITEMS(fast)
        for i in range(n):
            if not exact_type(items[i], <PyObject*>cls):
                item(items, i, cls, what)       # raises the TypeError
            self.s0[i] = (<_ModuleVector>items[i]).m
            self.s1[i] = (<_ModuleVector>items[i]).a.c
            self.s2[i] = (<_ModuleVector>items[i]).a.s
        return 0

    def desaturatedDiscretize(self, chassis_velocities: ChassisVelocities, double dt,
                              double attainable_max_module_velocity):
        """Return ``discretize(k·v, dt)`` for the largest k in [0, 1] at which no module
        (about the robot origin) goes faster than ``attainable_max_module_velocity`` (m/s).

        ``v`` is the robot-relative ``chassis_velocities`` (m/s, rad/s) and ``dt`` the loop
        period (s, > 0). Unlike ``discretize`` followed by
        :meth:`desaturateWheelVelocities`, which scales the modules after the discretize
        correction and so turns the direction of travel by (k − 1)·ω·dt/2 (the skew
        WPILib's ``discretize`` documentation warns about), the robot moves exactly in
        the commanded direction, and unlike desaturating before discretizing, no module
        ends above the limit. k is exact to 1e-14 relative; with no saturation the result
        is ``chassis_velocities.discretize(dt)``. Every input must be finite (the limit
        may be +inf) and the limit ≥ 0; with no limit, a result beyond the largest double
        is a ValueError."""
        cdef vec3_t d
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        self._desaturated_discretize((<ChassisVelocities>chassis_velocities).v, dt,
                                     attainable_max_module_velocity, &d)
        return new_chassis_velocities(d.x, d.y, d.z)

    def desaturatedDiscretizeInto(self, chassis_velocities: ChassisVelocities, double dt,
                                  double attainable_max_module_velocity,
                                  out: ChassisVelocities):
        """Allocation-free :meth:`desaturatedDiscretize`: the result goes into ``out``
        (which may be ``chassis_velocities``). Returns None."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        check_type(out, ChassisVelocities, "out")
        self._desaturated_discretize((<ChassisVelocities>chassis_velocities).v, dt,
                                     attainable_max_module_velocity,
                                     &(<ChassisVelocities>out).v)

    cdef int _desaturated_discretize(self, vec3_t v, double dt, double limit,
                                     vec3_t* out) except -1:
        check_desaturated_discretize(v, dt, limit)
        self._ready()
        cdef double k = desaturated_discretize_scale(self.n, self.mx, self.my, v.x, v.y,
                                                     v.z, dt, limit)
        out[0] = chassis_discretize(k * v.x, k * v.y, k * v.z, dt)
        return 0

    def toChassisVelocities(self, module_velocities, *more):
        """Return the least-squares ChassisVelocities (robot-relative) for N measured
        module velocities (SwerveModuleVelocity, as arguments or one sequence, or an (N, 2)
        float64 array ``[velocity m/s, angle rad]``)."""
        cdef double r[3]
        self._read(varargs(module_velocities, more, SwerveModuleVelocity),
                   SwerveModuleVelocity, "module_velocities")
        forward_solve(3, self.n, self.f1, self.s0, self.s1, self.s2, r)
        return new_chassis_velocities(r[0], r[1], r[2])

    def toChassisVelocitiesInto(self, module_velocities, out: ChassisVelocities):
        """Allocation-free :meth:`toChassisVelocities`: ``module_velocities`` is a sequence
        of N SwerveModuleVelocity or an (N, 2) float64 array ``[velocity m/s, angle rad]``;
        the result is written into ``out``. Returns None."""
        check_type(out, ChassisVelocities, "out")
        self._read(module_velocities, SwerveModuleVelocity, "module_velocities")
        forward_solve(3, self.n, self.f1, self.s0, self.s1, self.s2,
                      &(<ChassisVelocities>out).v.x)

    def toTwist2d(self, module_deltas, *more):
        """toTwist2d(*module_deltas) or toTwist2d(start, end)

        Return the Twist2d (m, rad) of the robot for N module position deltas
        (SwerveModulePosition: distance driven since the last update and the current
        angle; or an (N, 2) float64 array ``[distance m, angle rad]``). With two sequences
        ``start`` and ``end``, the deltas are
        ``end.distance − start.distance`` at the **end** angle, as in WPILib."""
        cdef double r[3]
        if len(more) == 1 and type(module_deltas) is not SwerveModulePosition:
            self._deltas(module_deltas, more[0])
        else:
            self._read(varargs(module_deltas, more, SwerveModulePosition),
                       SwerveModulePosition, "module_deltas")
        forward_solve(3, self.n, self.f1, self.s0, self.s1, self.s2, r)
        return new_twist(r[0], r[1], r[2])

    cdef int _deltas(self, object start, object end) except -1:
        self._ready()
        cdef object fs = as_fast(start, "start"), fe = as_fast(end, "end")
        cdef Py_ssize_t i, k = PySequence_Fast_GET_SIZE(fs)
        if PySequence_Fast_GET_SIZE(fe) != k:
            raise ValueError(f"Inconsistent number of modules: start has {k}, "
                             f"end has {PySequence_Fast_GET_SIZE(fe)}")
        if k != self.n:
            raise ValueError(f"expected {self.n} SwerveModulePosition objects (one per module), "
                             f"got {k}")
        cdef PyObject** a = PySequence_Fast_ITEMS(fs)
        cdef PyObject** b = PySequence_Fast_ITEMS(fe)
        cdef _ModuleVector p, q
        for i in range(k):
            p = item(a, i, SwerveModulePosition, "start")
            q = item(b, i, SwerveModulePosition, "end")
            self.s0[i] = q.m - p.m
            self.s1[i] = q.a.c
            self.s2[i] = q.a.s
        return 0

    def toTwist2dInto(self, module_deltas, out: Twist2d):
        """Allocation-free :meth:`toTwist2d` for N deltas (SwerveModulePosition objects or an
        (N, 2) float64 array ``[distance m, angle rad]``), written into ``out``."""
        check_type(out, Twist2d, "out")
        self._read(module_deltas, SwerveModulePosition, "module_deltas")
        forward_solve(3, self.n, self.f1, self.s0, self.s1, self.s2, &(<Twist2d>out).t.dx)

    def interpolate(self, start, end, double t):
        """Return per-module ``SwerveModulePosition.interpolate`` (t not clamped)."""
        self._ready()
        # Tuples hold their items, so the results' allocations (and any finalizer they
        # trigger) cannot free an item under us.
        cdef tuple fs = snapshot(start, "start")
        cdef tuple fe = snapshot(end, "end")
        cdef Py_ssize_t i, k = len(fs)
        if len(fe) != k:
            raise ValueError(f"Inconsistent number of modules: start has {k}, end has {len(fe)}")
        for i in range(k):
            item(PySequence_Fast_ITEMS(fs), i, SwerveModulePosition, "start")
            item(PySequence_Fast_ITEMS(fe), i, SwerveModulePosition, "end")
        return tuple([(<SwerveModulePosition>fs[i]).interpolate(fe[i], t) for i in range(k)])

    def copy(self, positions):
        """Return independent copies of the module positions (tuple)."""
        self._ready()
        cdef tuple ps = snapshot(positions, "positions")
        cdef Py_ssize_t i
        for i in range(len(ps)):
            item(PySequence_Fast_ITEMS(ps), i, SwerveModulePosition, "positions")
        return tuple([(<SwerveModulePosition>p).copy() for p in ps])

    def copyInto(self, positions, output):
        """Copy each position's fields into the matching object of ``output``."""
        self._ready()
        cdef object fs = as_fast(positions, "positions"), fo = as_fast(output, "output")
        cdef Py_ssize_t i, k = PySequence_Fast_GET_SIZE(fs)
        if PySequence_Fast_GET_SIZE(fo) != k:
            raise ValueError(f"Inconsistent number of modules: positions has {k}, "
                             f"output has {PySequence_Fast_GET_SIZE(fo)}")
        cdef PyObject** a = PySequence_Fast_ITEMS(fs)
        cdef PyObject** b = PySequence_Fast_ITEMS(fo)
        for i in range(k):
            item(a, i, SwerveModulePosition, "positions")
            item(b, i, SwerveModulePosition, "output")
        for i in range(k):
            (<_ModuleVector>b[i]).m = (<_ModuleVector>a[i]).m
            (<_ModuleVector>b[i]).a = (<_ModuleVector>a[i]).a

    def toSwerveModuleAccelerations(self, chassis_accelerations: ChassisAccelerations,
                                    double angular_velocity=0.0,
                                    center_of_rotation: Translation2d = ORIGIN):
        """Return the N module accelerations (SwerveModuleAcceleration: magnitude m/s² and
        direction) for ``chassis_accelerations`` while turning at ``angular_velocity``
        rad/s about ``center_of_rotation`` (m): a_i = a + α × r_i − ω² r_i.

        WPILib's rules are kept: an exactly zero ``chassis_accelerations`` gives all-zero
        results even when ``angular_velocity`` ≠ 0, and a module whose acceleration is at
        most 1e-6 gets angle 0 (there is no heading memory for accelerations)."""
        check_type(chassis_accelerations, ChassisAccelerations, "chassis_accelerations")
        check_type(center_of_rotation, Translation2d, "center_of_rotation")
        cdef ChassisAccelerations ca = <ChassisAccelerations>chassis_accelerations
        self._ready()
        cdef object t = new_modules(self.n, SwerveModuleAcceleration)
        if not (ca.v.x == 0.0 and ca.v.y == 0.0 and ca.v.z == 0.0):
            self._set_cor((<Translation2d>center_of_rotation).v)
        swerve_ik_accel(self.n, self.rx, self.ry, ca.v.x, ca.v.y, angular_velocity, ca.v.z,
                        self.s0, self.s1, self.s2)
        store_modules(t, self.n, self.s0, self.s1, self.s2)
        return t

    def toWheelAccelerations(self, chassis_accelerations: ChassisAccelerations):
        """Same as :meth:`toSwerveModuleAccelerations` with zero angular velocity about
        the robot origin."""
        check_type(chassis_accelerations, ChassisAccelerations, "chassis_accelerations")
        return self.toSwerveModuleAccelerations(chassis_accelerations, 0.0, ORIGIN)

    def toChassisAccelerations(self, module_accelerations, *more):
        """Return the least-squares ChassisAccelerations for N module accelerations
        (as arguments or one sequence, or an (N, 2) float64 array ``[m/s², angle rad]``).
        The ω² estimate of the solve is discarded."""
        cdef double r[4]
        self._read(varargs(module_accelerations, more, SwerveModuleAcceleration),
                   SwerveModuleAcceleration, "module_accelerations")
        forward_solve(4, self.n, self.f2, self.s0, self.s1, self.s2, r)
        return ChassisAccelerations(r[0], r[1], r[3])

    @staticmethod
    def desaturateWheelVelocities(module_velocities, attainable_max_velocity,
                                  attainable_max_module_velocity=None,
                                  attainable_max_robot_translation_velocity=None,
                                  attainable_max_robot_rotation_velocity=None):
        """desaturateWheelVelocities(module_velocities, attainable_max_velocity) or
        desaturateWheelVelocities(module_velocities, desired_chassis_velocity,
        attainable_max_module_velocity, attainable_max_robot_translation_velocity,
        attainable_max_robot_rotation_velocity)

        Return new module velocities (tuple) scaled down so no wheel exceeds its limit,
        keeping their ratios and angles. The one-limit form scales only when the fastest
        wheel is above ``attainable_max_velocity`` (m/s). The five-argument form also
        scales by how hard the driver asks (``desired_chassis_velocity`` against the
        translational m/s and rotational rad/s limits), so it can slow unsaturated wheels;
        it leaves the velocities unchanged if either chassis limit or every wheel speed is
        zero. The input is not modified (2027). In the five-argument form the second
        parameter is the desired ChassisVelocities, passed by position (its keyword is the
        two-argument form's ``attainable_max_velocity``)."""
        cdef desat_t p
        cdef double stack[3 * STACK_MODULES]
        cdef double* buf = stack
        cdef double div, mul
        cdef Py_ssize_t i, n
        cdef PyObject** items
        cdef object t
        parse_desat(attainable_max_velocity, attainable_max_module_velocity,
                    attainable_max_robot_translation_velocity,
                    attainable_max_robot_rotation_velocity, &p)
        cdef object fast = as_fast(module_velocities, "module_velocities")
        n = PySequence_Fast_GET_SIZE(fast)
        if n > STACK_MODULES:
            buf = <double*>PyMem_Malloc(sizeof(double) * 3 * n)
            if buf == NULL:
                raise MemoryError()
        try:
            # The caller's list is read completely before the result tuple is allocated:
            # that allocation can run the cyclic GC, whose finalizers may mutate the list.
            desaturate_factors(read_velocities(PySequence_Fast_ITEMS(fast), n, buf),
                               &p, &div, &mul)
            t = new_modules(n, SwerveModuleVelocity)
            items = PySequence_Fast_ITEMS(t)
            for i in range(n):
                (<_ModuleVector>items[i]).m = buf[3 * i] / div * mul
                (<_ModuleVector>items[i]).a.c = buf[3 * i + 1]
                (<_ModuleVector>items[i]).a.s = buf[3 * i + 2]
        finally:
            if buf != stack:
                PyMem_Free(buf)
        return t

    @staticmethod
    def desaturateWheelVelocitiesInPlace(module_velocities, attainable_max_velocity,
                                         attainable_max_module_velocity=None,
                                         attainable_max_robot_translation_velocity=None,
                                         attainable_max_robot_rotation_velocity=None):
        """Allocation-free :meth:`desaturateWheelVelocities` (same two forms) that rescales
        the caller's N SwerveModuleVelocity objects, or column 0 of an (N, 2) float64
        array ``[velocity m/s, angle rad]``, in place. Returns None."""
        cdef Py_ssize_t i, n
        cdef double* d
        cdef double div, mul
        cdef desat_t p
        parse_desat(attainable_max_velocity, attainable_max_module_velocity,
                    attainable_max_robot_translation_velocity,
                    attainable_max_robot_rotation_velocity, &p)
        cdef object fast
        cdef PyObject** items
        if not (PyTuple_CheckExact(module_velocities) or PyList_CheckExact(module_velocities)) \
                and cnp.PyArray_Check(module_velocities):
            d = float64_data(module_velocities, -1, 2, True, "module_velocities")
            n = cnp.PyArray_DIM(<cnp.ndarray>module_velocities, 0)
            desaturate_factors(max_abs(n, d, 2), &p, &div, &mul)
            for i in range(n):
                d[2 * i] = d[2 * i] / div * mul
            return
        fast = as_fast(module_velocities, "module_velocities")
        n = PySequence_Fast_GET_SIZE(fast)
        items = PySequence_Fast_ITEMS(fast)
        # Check and read, decide, write: nothing here allocates or runs Python code.
        desat_objects(items, n, &p, &div, &mul)
        for i in range(n):
            (<_ModuleVector>items[i]).m = (<_ModuleVector>items[i]).m / div * mul


# ---------------------------------------------------------------------------------------
# Desaturation: parse the two Java overloads once, then one kernel decides the factors.

cdef int check_desaturated_discretize(vec3_t v, double dt, double limit) except -1:
    # Shared by the per-call, allocation-free and batch forms.
    # The messages name no keyword: batch's spelling of the parameters differs.
    if not (isfinite(v.x) and isfinite(v.y) and isfinite(v.z)):
        raise ValueError(f"the chassis velocities must be finite, got ({v.x!r}, {v.y!r}, "
                         f"{v.z!r})")
    if not (isfinite(dt) and dt > 0.0):
        raise ValueError(f"dt must be a finite number of seconds > 0, got {dt!r}")
    if not (limit >= 0.0):
        raise ValueError(f"the module velocity limit must be >= 0 m/s (inf for no limit), "
                         f"got {limit!r}")
    if limit == INFINITY:       # no scaling: the plain discretize, which may not fit
        check_discretize_fits(v, dt)
    return 0


cdef int parse_desat(object first, object mm, object mt, object mr,
                     desat_t* p) except -1:                          # OUT p
    if type(first) is not ChassisVelocities:
        if mm is not None or mt is not None or mr is not None:
            raise TypeError("the five-argument desaturateWheelVelocities form takes a "
                            f"ChassisVelocities second, got {type_name(first)}")
        p.five = False
        p.max_speed = first
        return 0
    if mm is None or mt is None or mr is None:
        raise TypeError("desaturateWheelVelocities(module_velocities, desired_chassis_velocity, "
                        "attainable_max_module_velocity, "
                        "attainable_max_robot_translation_velocity, "
                        "attainable_max_robot_rotation_velocity) needs all three limits")
    p.five = True
    p.desired = (<ChassisVelocities>first).v
    p.max_module = mm
    p.max_trans = mt
    p.max_rot = mr
    return 0


cdef double read_velocities(PyObject** items, Py_ssize_t n, double* buf) except -1.0:
    """Check n SwerveModuleVelocity, copy (velocity, cos, sin) to buf (stride 3) and
    return the largest |velocity| (Java Math.max semantics: NaN wins)."""
    cdef Py_ssize_t i
    cdef double r = 0.0
    for i in range(n):
        if not exact_type(items[i], <PyObject*>SwerveModuleVelocity):
            item(items, i, SwerveModuleVelocity, "module_velocities")  # raises the TypeError
        buf[3 * i] = (<_ModuleVector>items[i]).m
        buf[3 * i + 1] = (<_ModuleVector>items[i]).a.c
        buf[3 * i + 2] = (<_ModuleVector>items[i]).a.s
        r = jmax(r, fabs(buf[3 * i]))
    return r


cdef int desat_objects(PyObject** items, Py_ssize_t n, const desat_t* p,
                       double* div, double* mul) except -1:
    """The in-place form of read_velocities (no copy: nothing allocates before the
    write-back) followed by the factors v' = v / div * mul."""
    cdef Py_ssize_t i
    cdef double r = 0.0
    for i in range(n):
        if not exact_type(items[i], <PyObject*>SwerveModuleVelocity):
            item(items, i, SwerveModuleVelocity, "module_velocities")  # raises the TypeError
        r = jmax(r, fabs((<_ModuleVector>items[i]).m))
    desaturate_factors(r, p, div, mul)
    return 0

