"""Choreo trajectory sampling on C doubles: choreolib Python 2026.0.3's ``sample_at``.

A sample row is the trajectory's columns (drivekin.choreo): swerve ``t x y heading vx vy
omega ax ay alpha fx0..3 fy0..3``, differential ``t x y heading vl vr omega al ar alpha
fl fr``. choreolib's rules: before the first sample or with one sample, the first; after
the last, the last (stored values); otherwise the first sample k at or after t, and unless
k = 0 or the two samples are less than 1 µs apart, the state integrated from sample k − 1
(so a time exactly on a sample is integrated, not read). Swerve integrates constant
accelerations; differential runs wpimath's adaptive Dormand–Prince (RKDP, max error 1e-6)
step for step, its quirks included; forces are linear between the two samples. The red
alliance's flip is 2026's rotation about the field centre.

ChoreoSampler is the base class of drivekin.choreo.ChoreoTrajectory: it owns a C-contiguous
read-only copy of the samples, and every method reads only that copy."""

cimport cython
from libc.math cimport M_PI, cos, pow, sin, sqrt
from libc.string cimport memcpy

import numpy as np

from drivekin._core.kernels cimport rot_rad
from drivekin._core.types cimport pose2_t
from drivekin.chassis cimport new_chassis_velocities
from drivekin.geometry cimport new_pose

cimport numpy as cnp
cnp.import_array()

cdef enum:
    SWERVE_WIDTH = 18
    DIFFERENTIAL_WIDTH = 12
    # A sample interval of a real file takes 1 to 3 RKDP steps; a step count this large
    # means values no robot has (the step size shrinks towards 0 and the loop would run
    # for hours), so the sample is refused instead.
    MAX_RKDP_STEPS = 100000

#: choreolib's 2026 field, length and width in m (choreo/util/field_dimensions.py): the
#: red alliance's flip rotates about its centre.
FIELD_SIZE = (16.541, 8.0692)
cdef double FIELD_LENGTH = FIELD_SIZE[0]
cdef double FIELD_WIDTH = FIELD_SIZE[1]
cdef double RKDP_MAX_ERROR = 1e-6


cdef inline double lerp(double a, double b, double s) noexcept nogil:
    return a + (b - a) * s


cdef void swerve_interpolate(const double* a, const double* b, double t,
                             double* out) noexcept nogil:
    # choreolib's SwerveSample.interpolate, in its order of operations.
    cdef double scale = (t - a[0]) / (b[0] - a[0])
    cdef double tau = t - a[0]
    cdef double tau2 = tau * tau
    cdef int i
    out[0] = t
    out[1] = a[1] + a[4] * tau + 0.5 * a[7] * tau2
    out[2] = a[2] + a[5] * tau + 0.5 * a[8] * tau2
    out[3] = a[3] + a[6] * tau + 0.5 * a[9] * tau2
    out[4] = a[4] + a[7] * tau
    out[5] = a[5] + a[8] * tau
    out[6] = a[6] + a[9] * tau
    out[7] = a[7]
    out[8] = a[8]
    out[9] = a[9]
    for i in range(10, SWERVE_WIDTH):
        out[i] = lerp(a[i], b[i], scale)


cdef inline void differential_derivative(const double* s, const double* u,
                                         double* k) noexcept nogil:
    # state [x, y, θ, vl, vr, ω], input [al, ar, α] (choreolib's f)
    cdef double v = (s[3] + s[4]) / 2
    k[0] = v * cos(s[2])
    k[1] = v * sin(s[2])
    k[2] = s[5]
    k[3] = u[0]
    k[4] = u[1]
    k[5] = u[2]


cdef int rkdp(double* x, const double* u, double dt) noexcept nogil:
    """wpimath's RKDP (frc/system/NumericalIntegration.h) on the 6-state differential
    model, x updated in place; -1 after MAX_RKDP_STEPS tries. As in wpimath, the time
    advanced after an accepted step is the already-updated step size."""
    cdef double a10 = 1.0 / 5.0
    cdef double a20 = 3.0 / 40.0, a21 = 9.0 / 40.0
    cdef double a30 = 44.0 / 45.0, a31 = -56.0 / 15.0, a32 = 32.0 / 9.0
    cdef double a40 = 19372.0 / 6561.0, a41 = -25360.0 / 2187.0, a42 = 64448.0 / 6561.0
    cdef double a43 = -212.0 / 729.0
    cdef double a50 = 9017.0 / 3168.0, a51 = -355.0 / 33.0, a52 = 46732.0 / 5247.0
    cdef double a53 = 49.0 / 176.0, a54 = -5103.0 / 18656.0
    cdef double a60 = 35.0 / 384.0, a61 = 0.0, a62 = 500.0 / 1113.0, a63 = 125.0 / 192.0
    cdef double a64 = -2187.0 / 6784.0, a65 = 11.0 / 84.0
    cdef double e0 = 35.0 / 384.0 - 5179.0 / 57600.0
    cdef double e1 = 0.0 - 0.0
    cdef double e2 = 500.0 / 1113.0 - 7571.0 / 16695.0
    cdef double e3 = 125.0 / 192.0 - 393.0 / 640.0
    cdef double e4 = -2187.0 / 6784.0 - -92097.0 / 339200.0
    cdef double e5 = 11.0 / 84.0 - 187.0 / 2100.0
    cdef double e6 = 0.0 - 1.0 / 40.0
    cdef double k1[6]
    cdef double k2[6]
    cdef double k3[6]
    cdef double k4[6]
    cdef double k5[6]
    cdef double k6[6]
    cdef double k7[6]
    cdef double y[6]
    cdef double nx[6]
    cdef double err, sq, d
    cdef double elapsed = 0.0
    cdef double h = dt
    cdef int i
    cdef long tries = 0
    while elapsed < dt:
        while True:
            tries += 1
            if tries > MAX_RKDP_STEPS:
                return -1
            if dt - elapsed < h:
                h = dt - elapsed
            differential_derivative(x, u, k1)
            for i in range(6):
                y[i] = x[i] + h * (a10 * k1[i])
            differential_derivative(y, u, k2)
            for i in range(6):
                y[i] = x[i] + h * (a20 * k1[i] + a21 * k2[i])
            differential_derivative(y, u, k3)
            for i in range(6):
                y[i] = x[i] + h * (a30 * k1[i] + a31 * k2[i] + a32 * k3[i])
            differential_derivative(y, u, k4)
            for i in range(6):
                y[i] = x[i] + h * (a40 * k1[i] + a41 * k2[i] + a42 * k3[i] + a43 * k4[i])
            differential_derivative(y, u, k5)
            for i in range(6):
                y[i] = x[i] + h * (a50 * k1[i] + a51 * k2[i] + a52 * k3[i] + a53 * k4[i]
                                   + a54 * k5[i])
            differential_derivative(y, u, k6)
            for i in range(6):
                nx[i] = x[i] + h * (a60 * k1[i] + a61 * k2[i] + a62 * k3[i] + a63 * k4[i]
                                    + a64 * k5[i] + a65 * k6[i])
            differential_derivative(nx, u, k7)
            sq = 0.0
            for i in range(6):
                d = h * (e0 * k1[i] + e1 * k2[i] + e2 * k3[i] + e3 * k4[i] + e4 * k5[i]
                         + e5 * k6[i] + e6 * k7[i])
                sq += d * d
            err = sqrt(sq)
            if err == 0.0:
                h = dt - elapsed
            else:
                h *= 0.9 * pow(RKDP_MAX_ERROR / err, 1.0 / 5.0)
            if not err > RKDP_MAX_ERROR:
                break
        elapsed += h
        memcpy(x, nx, 6 * sizeof(double))
    return 0


cdef int differential_interpolate(const double* a, const double* b, double t,
                                  double* out) noexcept nogil:
    # choreolib's DifferentialSample.interpolate.
    cdef double scale = (t - a[0]) / (b[0] - a[0])
    cdef double x[6]
    memcpy(x, a + 1, 6 * sizeof(double))
    if rkdp(x, a + 7, t - a[0]) != 0:
        return -1
    out[0] = t
    memcpy(out + 1, x, 6 * sizeof(double))
    out[7] = a[7]
    out[8] = a[8]
    out[9] = a[9]
    out[10] = lerp(a[10], b[10], scale)
    out[11] = lerp(a[11], b[11], scale)
    return 0


cdef int sample(const double* d, Py_ssize_t n, Py_ssize_t w, double t, bint flip,
                double* out) noexcept nogil:
    """The row choreolib's sample_at(t, flip) gives, into out (w doubles); -1 when the
    differential integrator gives up (out then undefined)."""
    cdef Py_ssize_t lo = 0, hi = n - 1, mid, i
    cdef const double* a
    cdef const double* b
    if n == 1 or t < d[0]:
        memcpy(out, d, w * sizeof(double))
    elif t > d[(n - 1) * w]:
        memcpy(out, d + (n - 1) * w, w * sizeof(double))
    else:
        while lo != hi:
            mid = (lo + hi) // 2
            if d[mid * w] < t:
                lo = mid + 1
            else:
                hi = mid
        if lo == 0:
            memcpy(out, d, w * sizeof(double))
        else:
            a = d + (lo - 1) * w
            b = d + lo * w
            if b[0] - a[0] < 1e-6:
                memcpy(out, b, w * sizeof(double))
            elif w == SWERVE_WIDTH:
                swerve_interpolate(a, b, t, out)
            elif differential_interpolate(a, b, t, out) != 0:
                return -1
    if flip:
        # 2026: rotated about the field centre. Differential velocities are along the
        # robot and keep their sign; swerve's field-frame vectors and forces turn over.
        out[1] = FIELD_LENGTH - out[1]
        out[2] = FIELD_WIDTH - out[2]
        out[3] = M_PI + out[3]
        if w == SWERVE_WIDTH:
            out[4] = -out[4]
            out[5] = -out[5]
            out[7] = -out[7]
            out[8] = -out[8]
            for i in range(10, SWERVE_WIDTH):
                out[i] = -out[i]
    return 0


cdef Py_ssize_t sample_many(const double* d, Py_ssize_t n, Py_ssize_t w, const double* t,
                            Py_ssize_t m, bint flip, double* out) noexcept nogil:
    """sample() for m times into m rows; the index of the first time that failed, or -1."""
    cdef Py_ssize_t j
    for j in range(m):
        if sample(d, n, w, t[j], flip, out + j * w) != 0:
            return j
    return -1


@cython.freelist(16)
cdef class _ChoreoSample:
    """A trajectory's state at one time (choreolib's sample fields)."""
    cdef double v[SWERVE_WIDTH]

    @property
    def t(self):
        """Time, s."""
        return self.v[0]

    @property
    def x(self):
        """Field x, m (blue origin)."""
        return self.v[1]

    @property
    def y(self):
        """Field y, m."""
        return self.v[2]

    @property
    def heading(self):
        """Heading, rad (not wrapped)."""
        return self.v[3]

    @property
    def omega(self):
        """Angular velocity, rad/s."""
        return self.v[6]

    @property
    def alpha(self):
        """Angular acceleration, rad/s²."""
        return self.v[9]

    def __reduce__(self):
        cdef bint swerve = type(self) is SwerveSample
        cdef Py_ssize_t i, w = SWERVE_WIDTH if swerve else DIFFERENTIAL_WIDTH
        return _sample_from_values, (swerve, tuple([self.v[i] for i in range(w)]))

    def getPose(self):
        """The pose (x, y, heading) as a drivekin Pose2d."""
        cdef pose2_t p
        p.t.x = self.v[1]
        p.t.y = self.v[2]
        p.r = rot_rad(self.v[3])
        return new_pose(p)


@cython.final
cdef class SwerveSample(_ChoreoSample):
    """SwerveSample: a swerve trajectory's state (choreolib's SwerveSample, ``t`` for its
    timestamp): pose, field-frame velocities and accelerations, module forces (N, field
    frame) in Choreo's order FL, BL, BR, FR."""

    def __init__(self):
        raise TypeError("SwerveSample is made by ChoreoTrajectory.sampleAt, or by "
                        "ChoreoTrajectory.newSample() for sampleInto")

    @property
    def vx(self):
        """Field-frame x velocity, m/s."""
        return self.v[4]

    @property
    def vy(self):
        """Field-frame y velocity, m/s."""
        return self.v[5]

    @property
    def ax(self):
        """Field-frame x acceleration, m/s²."""
        return self.v[7]

    @property
    def ay(self):
        """Field-frame y acceleration, m/s²."""
        return self.v[8]

    @property
    def fx(self):
        """Module forces along field x, N, (FL, BL, BR, FR)."""
        return (self.v[10], self.v[11], self.v[12], self.v[13])

    @property
    def fy(self):
        """Module forces along field y, N, (FL, BL, BR, FR)."""
        return (self.v[14], self.v[15], self.v[16], self.v[17])

    def getChassisVelocities(self):
        """Field-relative (vx, vy, omega) as a ChassisVelocities, as choreolib's
        get_chassis_speeds."""
        return new_chassis_velocities(self.v[4], self.v[5], self.v[6])

    def __repr__(self):
        return (f"SwerveSample(t={self.v[0]!r}, x={self.v[1]!r}, y={self.v[2]!r}, "
                f"heading={self.v[3]!r}, vx={self.v[4]!r}, vy={self.v[5]!r}, "
                f"omega={self.v[6]!r})")


@cython.final
cdef class DifferentialSample(_ChoreoSample):
    """DifferentialSample: a differential trajectory's state (choreolib's
    DifferentialSample, ``t`` for its timestamp): pose, wheel velocities and
    accelerations, wheel forces (N) left and right."""

    def __init__(self):
        raise TypeError("DifferentialSample is made by ChoreoTrajectory.sampleAt, or by "
                        "ChoreoTrajectory.newSample() for sampleInto")

    @property
    def vl(self):
        """Left wheel velocity, m/s."""
        return self.v[4]

    @property
    def vr(self):
        """Right wheel velocity, m/s."""
        return self.v[5]

    @property
    def al(self):
        """Left wheel acceleration, m/s²."""
        return self.v[7]

    @property
    def ar(self):
        """Right wheel acceleration, m/s²."""
        return self.v[8]

    @property
    def fl(self):
        """Left wheel force, N."""
        return self.v[10]

    @property
    def fr(self):
        """Right wheel force, N."""
        return self.v[11]

    def getChassisVelocities(self):
        """((vl + vr) / 2, 0, omega) as a ChassisVelocities, as choreolib's
        get_chassis_speeds (choreolib calls it field-relative; its vx is along the
        robot's heading, so it is the robot-relative velocity)."""
        return new_chassis_velocities((self.v[4] + self.v[5]) / 2.0, 0.0, self.v[6])

    def __repr__(self):
        return (f"DifferentialSample(t={self.v[0]!r}, x={self.v[1]!r}, y={self.v[2]!r}, "
                f"heading={self.v[3]!r}, vl={self.v[4]!r}, vr={self.v[5]!r}, "
                f"omega={self.v[6]!r})")


def _sample_from_values(bint swerve, values):
    """The sample a pickle holds: a SwerveSample (18 floats) or DifferentialSample (12) in
    the trajectory's column order."""
    cdef Py_ssize_t i, w = SWERVE_WIDTH if swerve else DIFFERENTIAL_WIDTH
    cdef double buf[SWERVE_WIDTH]
    if type(values) is not tuple or len(<tuple>values) != w:
        got = (f"{len(<tuple>values)} values" if type(values) is tuple
               else type(values).__name__)
        raise ValueError(f"a pickled {'Swerve' if swerve else 'Differential'}Sample holds a "
                         f"tuple of {w} floats, got {got}")
    for i in range(w):
        buf[i] = (<tuple>values)[i]
    cdef _ChoreoSample s = (SwerveSample.__new__(SwerveSample) if swerve
                            else DifferentialSample.__new__(DifferentialSample))
    memcpy(s.v, buf, w * sizeof(double))
    return s


cdef class ChoreoSampler:
    """The sampling half of ChoreoTrajectory: a C-contiguous read-only copy of the samples
    (bound once by _bind) and the methods that read it."""
    cdef object rows             # the float64 (n, w) array the pointer below reads
    cdef const double* d
    cdef Py_ssize_t n, w

    def _bind(self, samples, bint swerve):
        """Copy ``samples`` (n ≥ 1 rows of 18 (swerve) or 12 columns) into this sampler
        once; returns the read-only copy."""
        cdef cnp.ndarray rows
        if self.d != NULL:
            raise TypeError("a ChoreoTrajectory's samples are bound once")
        w = SWERVE_WIDTH if swerve else DIFFERENTIAL_WIDTH
        rows = np.array(samples, dtype=np.float64, order="C", copy=True)
        if rows.ndim != 2 or rows.shape[0] < 1 or rows.shape[1] != w:
            raise ValueError(f"samples must have shape (n >= 1, {w}), got "
                             f"{np.shape(rows)}")
        rows.flags.writeable = False
        self.rows = rows
        self.n = rows.shape[0]
        self.w = w
        self.d = <const double*>cnp.PyArray_DATA(rows)
        return rows

    cdef int ready(self) except -1:
        if self.d == NULL:
            raise TypeError("this ChoreoTrajectory has no samples: make it with "
                            "drivekin.choreo.load")
        return 0

    cdef _ChoreoSample blank(self):
        if self.w == SWERVE_WIDTH:
            return SwerveSample.__new__(SwerveSample)
        return DifferentialSample.__new__(DifferentialSample)

    def newSample(self):
        """A sample object of this trajectory's kind (its first sample), for
        :meth:`sampleInto`."""
        self.ready()
        cdef _ChoreoSample s = self.blank()
        memcpy(s.v, self.d, self.w * sizeof(double))
        return s

    def sampleAt(self, double t, bint mirrorForRedAlliance=False):
        """sampleAt(t, mirrorForRedAlliance=False)

        The state at time ``t`` (s) by choreolib's ``sample_at`` rules (see the module),
        as a SwerveSample or DifferentialSample; flipped for the red alliance (2026:
        rotated about the field centre) if asked. ``t`` must not be NaN (ValueError)."""
        self.ready()
        if t != t:
            raise ValueError("t must be a time in s, got nan")
        cdef _ChoreoSample s = self.blank()
        if sample(self.d, self.n, self.w, t, mirrorForRedAlliance, s.v) != 0:
            integrator_failed(t)
        return s

    def sampleInto(self, double t, out, bint mirrorForRedAlliance=False):
        """sampleInto(t, out, mirrorForRedAlliance=False)

        :meth:`sampleAt` written into ``out`` (a sample of this trajectory's kind, from
        :meth:`newSample`) without allocating; returns ``out``. On an error ``out`` is
        unchanged."""
        cdef double buf[SWERVE_WIDTH]
        self.ready()
        if t != t:
            raise ValueError("t must be a time in s, got nan")
        kind = SwerveSample if self.w == SWERVE_WIDTH else DifferentialSample
        if type(out) is not kind:
            raise TypeError(f"out must be a {kind.__name__} (trajectory.newSample()), got "
                            f"{type(out).__name__}")
        if sample(self.d, self.n, self.w, t, mirrorForRedAlliance, buf) != 0:
            integrator_failed(t)
        memcpy((<_ChoreoSample>out).v, buf, self.w * sizeof(double))
        return out

    def sampleAtMany(self, times, bint mirrorForRedAlliance=False):
        """sampleAtMany(times, mirrorForRedAlliance=False)

        :meth:`sampleAt` at every time of the 1-D ``times`` (s, none NaN): float64 rows
        (len(times), len(columns)) in ``columns`` order, computed without the GIL."""
        self.ready()
        cdef cnp.ndarray ts = np.array(times, dtype=np.float64, order="C", copy=True)
        if ts.ndim != 1:
            raise ValueError(f"times must be 1-D, got shape {np.shape(ts)}")
        if np.isnan(ts).any():
            raise ValueError("times must be times in s, got nan")
        cdef Py_ssize_t m = ts.shape[0]
        cdef cnp.ndarray out = np.empty((m, self.w), dtype=np.float64)
        cdef const double* tp = <const double*>cnp.PyArray_DATA(ts)
        cdef double* op = <double*>cnp.PyArray_DATA(out)
        cdef Py_ssize_t failed
        with nogil:
            failed = sample_many(self.d, self.n, self.w, tp, m, mirrorForRedAlliance, op)
        if failed >= 0:
            integrator_failed(tp[failed])
        return out


cdef integrator_failed(double t):
    raise ValueError(f"sampling at t = {t!r} s: the differential integrator (RKDP) needs "
                     f"more than {MAX_RKDP_STEPS} steps between two samples; the "
                     f"trajectory's velocities or accelerations are not a robot's")
