# Plain C value types shared by every kernel and value class. SI units throughout:
# metres, seconds, radians. Frame: x forward, y left, angles counter-clockwise positive.

cdef struct vec2_t:
    double x                    # m (or m/s, m/s^2 when it holds a velocity/acceleration)
    double y                    # m

cdef struct rot2_t:
    # A rotation is kept as its unit vector, as WPILib 2027 does; the angle is derived.
    double c                    # cos(angle)
    double s                    # sin(angle)

cdef struct pose2_t:
    # Used both for poses and for transforms (same layout, different meaning).
    vec2_t t                    # translation, m
    rot2_t r                    # rotation

cdef struct twist2_t:
    double dx                   # m, along the start frame's x
    double dy                   # m, along the start frame's y
    double dtheta               # rad

cdef struct vec3_t:
    # Chassis-level 3-vector: (vx m/s, vy m/s, omega rad/s) or (ax, ay m/s^2, alpha rad/s^2);
    # in 3-D geometry a translation (m) or a rotation vector (rad).
    double x
    double y
    double z

cdef struct quat_t:
    # A quaternion w + xi + yj + zk; a Rotation3d keeps a unit one, as WPILib does.
    double w
    double x
    double y
    double z

cdef struct pose3_t:
    # Used both for 3-D poses and transforms (same layout, different meaning).
    vec3_t t                    # translation, m
    quat_t q                    # rotation (unit quaternion)

cdef struct twist3_t:
    double dx                   # m, along the start frame's axes
    double dy
    double dz
    double rx                   # rad: the rotation vector, in the start frame
    double ry
    double rz

cdef struct desat_t:
    # Arguments of the two desaturateWheelVelocities overloads.
    bint five                   # True for the five-argument (joystick) form
    double max_speed            # attainableMaxSpeed, m/s (one-limit form)
    vec3_t desired              # desired chassis velocity (vx, vy m/s, omega rad/s)
    double max_module           # attainableMaxModuleSpeed, m/s
    double max_trans            # attainableMaxTranslationalSpeed, m/s
    double max_rot              # attainableMaxRotationalVelocity, rad/s

# A differential swerve pod's gearing (drivekin.diffswerve).
cdef struct dswerve_t:
    double ra                    # azimuth gear ratio R_A, motor turns per pod turn
    double rl                    # wheel gear ratio R_L, motor turns per wheel turn
    double r                     # wheel radius, m
    double kv                    # R_L / r: motor rad per m of wheel travel
    double s2                    # +1, or -1 when motor 2 is mounted reversed
    double ira                   # 1 / R_A, for the inverse map
    double ikv                   # 1 / kv, m of wheel travel per motor rad
