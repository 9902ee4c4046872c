# Immutable 2-D geometry value types. Each holds one C struct by value; other modules
# cimport these declarations and build results with the inline factories below, which
# skip __init__ and draw from the freelists.
cimport cython
from drivekin._core.types cimport pose2_t, rot2_t, twist2_t, vec2_t


@cython.final
cdef class Translation2d:
    cdef vec2_t v
    cdef bint frozen             # set once constructed: __init__ may not run again

@cython.final
cdef class Rotation2d:
    cdef rot2_t r
    cdef bint frozen

cdef class _Frame2d:
    cdef pose2_t p
    cdef bint frozen
    cdef _Frame2d _new(self, pose2_t p)

@cython.final
cdef class Pose2d(_Frame2d):
    pass

@cython.final
cdef class Transform2d(_Frame2d):
    pass

@cython.final
cdef class Twist2d:
    cdef twist2_t t


cdef inline Translation2d new_translation(vec2_t v):
    cdef Translation2d o = Translation2d.__new__(Translation2d)
    o.v = v
    o.frozen = True
    return o

cdef inline Rotation2d new_rotation(rot2_t r):
    cdef Rotation2d o = Rotation2d.__new__(Rotation2d)
    o.r = r
    o.frozen = True
    return o

cdef inline Pose2d new_pose(pose2_t p):
    cdef Pose2d o = Pose2d.__new__(Pose2d)
    o.p = p
    o.frozen = True
    return o

cdef inline Transform2d new_transform(pose2_t p):
    cdef Transform2d o = Transform2d.__new__(Transform2d)
    o.p = p
    o.frozen = True
    return o

cdef inline Twist2d new_twist(double dx, double dy, double dtheta):
    cdef Twist2d o = Twist2d.__new__(Twist2d)
    o.t.dx = dx
    o.t.dy = dy
    o.t.dtheta = dtheta
    return o
