# drivekin.batch's 3-D forms; batch.pyx documents them and dispatches to them by the
# arrays' shapes. Rows: poses and transforms [x, y, z m, qw, qx, qy, qz], twists
# [dx, dy, dz m, rx, ry, rz rad], gyro readings [w, x, y, z].
from drivekin.odometry3d cimport _Odometry3d

cdef object exp3(object twists, object out)
cdef object log3(object transforms, object out)
# a.transformBy(b), or with ``relative`` a.relativeTo(b); either may be a single row.
cdef object compose3(object a, object b, object out, bint relative, str name_a, str name_b)
cdef object replay3(_Odometry3d odometry, object gyro, object positions, object out)
