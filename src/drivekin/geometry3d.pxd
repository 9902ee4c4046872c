# Immutable 3-D geometry value types. Each holds one C struct by value; other modules
# cimport these declarations and build results with the inline factories below, which
# skip __init__ and draw from the freelists.
cimport cython
from drivekin._core.types cimport pose3_t, quat_t, twist3_t, vec3_t


@cython.final
cdef class Quaternion:
    cdef quat_t q                # not normalised
    cdef bint frozen             # set once constructed: __init__ may not run again

@cython.final
cdef class Rotation3d:
    cdef quat_t q                # unit quaternion
    cdef bint frozen

@cython.final
cdef class Translation3d:
    cdef vec3_t v                # m
    cdef bint frozen

cdef class _Frame3d:
    cdef pose3_t p
    cdef bint frozen
    cdef _Frame3d _new(self, pose3_t p)

@cython.final
cdef class Pose3d(_Frame3d):
    pass

@cython.final
cdef class Transform3d(_Frame3d):
    pass

@cython.final
cdef class Twist3d:
    cdef twist3_t t              # mutable, as WPILib's public fields

@cython.final
cdef class CoordinateAxis:
    cdef vec3_t v                # unit vector
    cdef bint frozen

@cython.final
cdef class CoordinateSystem:
    cdef quat_t q                # the rotation whose matrix has the axes as columns
    cdef tuple axes              # (positive_x, positive_y, positive_z): CoordinateAxis
    cdef bint frozen


cdef inline Quaternion new_quaternion(quat_t q):
    cdef Quaternion o = Quaternion.__new__(Quaternion)
    o.q = q
    o.frozen = True
    return o

cdef inline Rotation3d new_rotation3d(quat_t q):
    # q must be a unit quaternion (or NaN): callers normalise.
    cdef Rotation3d o = Rotation3d.__new__(Rotation3d)
    o.q = q
    o.frozen = True
    return o

cdef inline Translation3d new_translation3d(vec3_t v):
    cdef Translation3d o = Translation3d.__new__(Translation3d)
    o.v = v
    o.frozen = True
    return o

cdef inline Pose3d new_pose3d(pose3_t p):
    cdef Pose3d o = Pose3d.__new__(Pose3d)
    o.p = p
    o.frozen = True
    return o

cdef inline Transform3d new_transform3d(pose3_t p):
    cdef Transform3d o = Transform3d.__new__(Transform3d)
    o.p = p
    o.frozen = True
    return o

cdef inline Twist3d new_twist3d(twist3_t t):
    cdef Twist3d o = Twist3d.__new__(Twist3d)
    o.t = t
    return o
