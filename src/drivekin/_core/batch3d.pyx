"""drivekin.batch's 3-D forms (declared in batch3d.pxd): the per-call kernels of
_core/kernels3d.pxd, sample by sample, without the GIL.

A row [x, y, z, qw, qx, qy, qz] is read as Pose3d(Translation3d(x, y, z),
Rotation3d(Quaternion(qw, qx, qy, qz))), and a gyro row [w, x, y, z] as
Rotation3d(Quaternion(w, x, y, z)): the quaternion normalised as that constructor does
(so as WPILib's struct unpacking does), each time it is read."""
from cpython.mem cimport PyMem_Free
from drivekin._core.dkmath cimport sincos_n

from drivekin._core.types cimport pose3_t, quat_t, twist3_t
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.kernels3d cimport (pose3, pose3_log, pose3_plus, pose3_relative_to,
                                       q_normalize, quat, rot3_relative_to, rot3_z, twist3,
                                       twist3_exp, vec3)
from drivekin._core.stacks cimport (CHUNK, _Stack, _pair, _result, _scratch, _stack,
                                    chunk_len, sample_shape, wheel_major)
from drivekin.odometry3d cimport _Odometry3d, odometry3d_move


cdef inline pose3_t read_pose(const double* r) noexcept nogil:
    return pose3(vec3(r[0], r[1], r[2]), q_normalize(quat(r[3], r[4], r[5], r[6])))


cdef inline void write_pose(double* o, pose3_t p) noexcept nogil:   # OUT: 7 values
    o[0] = p.t.x
    o[1] = p.t.y
    o[2] = p.t.z
    o[3] = p.q.w
    o[4] = p.q.x
    o[5] = p.q.y
    o[6] = p.q.z


cdef object exp3(object twists, object out):
    cdef _Stack v = _stack(twists, (6,), "twists")
    cdef _Stack o = _result(out, v.n, v.single, (7,), (v,), "twists")
    cdef Py_ssize_t i, count = v.n
    cdef const double* x
    with nogil:
        for i in range(count):
            x = v.data + 6 * i
            write_pose(o.data + 7 * i, twist3_exp(twist3(x[0], x[1], x[2], x[3], x[4], x[5])))
    return o.array


cdef object log3(object transforms, object out):
    cdef _Stack v = _stack(transforms, (7,), "transforms")
    cdef _Stack o = _result(out, v.n, v.single, (6,), (v,), "transforms")
    cdef Py_ssize_t i, count = v.n
    cdef twist3_t t
    cdef double* y
    with nogil:
        for i in range(count):
            t = pose3_log(read_pose(v.data + 7 * i))
            y = o.data + 6 * i
            y[0] = t.dx
            y[1] = t.dy
            y[2] = t.dz
            y[3] = t.rx
            y[4] = t.ry
            y[5] = t.rz
    return o.array


cdef object compose3(object a, object b, object out, bint relative, str name_a, str name_b):
    cdef _Stack sa, sb
    sa, sb = _pair(a, b, (7,), name_a, name_b)
    cdef Py_ssize_t i, count = sb.n if sa.single else sa.n
    cdef Py_ssize_t da = 0 if sa.single else 7, db = 0 if sb.single else 7
    cdef _Stack o = _result(out, count, sa.single and sb.single, (7,), (sa, sb), name_a)
    cdef pose3_t p, q
    with nogil:
        for i in range(count):
            p = read_pose(sa.data + da * i)
            q = read_pose(sb.data + db * i)
            write_pose(o.data + 7 * i, pose3_relative_to(p, q) if relative else pose3_plus(p, q))
    return o.array


cdef object replay3(_Odometry3d odo, object gyro, object positions, object out):
    if not odo.ready:
        raise RuntimeError(f"{type(odo).__name__}.__init__ has not completed")
    cdef _Stack p = _stack(positions, sample_shape(odo.width, odo.kin.steered), "positions",
                           False)
    if gyro is None:
        raise TypeError("gyroAngles must be a float64 array of shape (N, 4) (quaternions "
                        "[w, x, y, z]), got None")
    cdef _Stack g = _stack(gyro, (4,), "gyroAngles", False)
    if g.n != p.n:
        raise ValueError(f"gyroAngles has {g.n} samples but positions has {p.n}")
    cdef _Stack o = _result(out, p.n, False, (7,), (p, g), "replay")
    _replay3(odo, p, g, o)
    return o.array


cdef int _replay3(_Odometry3d odo, _Stack p, _Stack g, _Stack o) except -1:
    # Odometry3d.update (odometry3d.pyx's _move) restaged per chunk: the gyro changes (and
    # their yaw, for dead wheels); the wheel readings laid out wheel-major (a steered
    # drivetrain's with their directions' cos/sin, vectorised) and turned into changes;
    # the drivetrain's (dx, dy) for the chunk (_twists, k samples as k calls); then, in
    # order, each step's move (odometry3d_move, update's own kernel). Each sample sees
    # exactly the operations of update (tests/behaviour/test_batch3d.py compares the bits).
    cdef Drivetrain kin = odo.kin
    cdef Py_ssize_t i, i0, ch, j, kk, count = p.n, n = odo.width
    cdef bint steered = kin.steered, yaw = odo.yaw
    cdef double* buf = _scratch(3 * CHUNK + 4 * CHUNK * n)   # freed below: nothing raises
    cdef quat_t turns[CHUNK]                # each sample's gyro change,
    cdef double dth[CHUNK]                  # and its yaw (0 unless the map takes it)
    cdef double* mxy = buf                  # the motions: dx, then dy, kk apart (3 CHUNK)
    cdef double* md = mxy + 3 * CHUNK       # a chunk's wheel readings, then their changes;
    cdef double* ang = md + CHUNK * n       # steered: module angles, cos and sin
    cdef double* mc = ang + CHUNK * n
    cdef double* ms = mc + CHUNK * n
    cdef double* prev = odo.prev
    cdef const double* x
    cdef double r
    cdef quat_t gq
    cdef quat_t before = odo.prev_gyro
    cdef pose3_t cur = odo.pose
    cdef twist3_t tw = odo.twist
    with nogil:
        for ch in range((count + CHUNK - 1) // CHUNK):
            i0 = ch * CHUNK
            kk = chunk_len(i0, count)
            for i in range(kk):
                x = g.data + 4 * (i0 + i)
                gq = q_normalize(quat(x[0], x[1], x[2], x[3]))
                turns[i] = rot3_relative_to(gq, before)
                before = gq
                dth[i] = rot3_z(turns[i]) if yaw else 0.0
            wheel_major(kk, n, p.data + p.width * i0, steered, md, ang)
            if steered:
                sincos_n(kk * n, ang, ms, mc)
            for j in range(n):
                for i in range(kk):
                    r = md[kk * j + i]
                    md[kk * j + i] = r - prev[j]
                    prev[j] = r
            kin._twists(kk, md, mc if steered else NULL, ms if steered else NULL, dth, mxy)
            for i in range(kk):
                odometry3d_move(&cur, &tw, mxy[i], mxy[kk + i], turns[i])
                write_pose(o.data + 7 * (i0 + i), cur)
        odo.pose = cur
        odo.prev_gyro = before
        odo.twist = tw
    PyMem_Free(buf)
    return 0
