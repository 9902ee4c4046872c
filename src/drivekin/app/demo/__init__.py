"""The ``python -m drivekin`` demo: a simulated 50 Hz drivetrain control loop on the
allocation-free path (the command line itself is in ``drivekin/app/cli.py``).

The demo drives a swerve, mecanum or differential robot (``--drivetrain``) through a
scripted joystick sequence for a few minutes of robot time and reports how long each
20 ms control step took and whether the loop allocated memory. One step is exactly what a
robot program does every 20 ms; for the default four-module swerve robot::

    joystick script  -> ChassisVelocities (field-relative, one mutable object)
    toRobotRelativeInto(gyro, cv)              field-relative -> robot-relative
    cv.discretizeInto(0.02, cv)                remove the translate-while-turning drift
    kin.toSwerveModuleVelocitiesInto(cv, targets)        inverse kinematics, in place
    SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(targets, max_speed)
    module response model                      optimize(InPlace), rate-limited steering,
                                               cosineScale(InPlace), lagged wheel, encoders
    kin.toChassisVelocitiesInto(states, cv2)   simulated gyro: heading += omega * dt
    pose = odometry.update(gyro, positions)    SwerveDriveOdometry; Pose2d from a freelist

Mecanum: the same first two lines, then ``toWheelVelocitiesInto`` → ``desaturateInPlace``
on a MecanumDriveWheelVelocities → first-order lag per wheel → wheel distances in one
mutable MecanumDriveWheelPositions → ``MecanumDriveOdometry.update(gyro, positions)``.
Differential (arcade drive): the forward and rotation sticks as robot-relative vx and
omega, the sideways stick unused → ``toWheelVelocitiesInto`` → ``desaturateInPlace`` →
lag per side → ``DifferentialDriveOdometry.update(gyro, left, right)``. In all three the
simulated gyro is the true heading: the wheel model's forward kinematics
(``toChassisVelocitiesInto`` of the measured wheel velocities) integrated over each step.
Differential swerve (``--drivetrain diffswerve``, see :class:`DiffSwerveDrive`): the swerve
chain up to inverse kinematics, then per pod a steering rate towards the optimized target,
``desaturateModuleVelocitiesInPlace`` (one factor for all wheels, at a motor limit equal to
``--max-speed`` of pure driving), ``toMotorVelocitiesInto`` → ``desaturateMotorVelocitiesInPlace``,
lagged motors driving a simulated differential, and ``toModulePositionInto`` from the
integrated motor positions as the odometry input; a second odometry fed with the
simulated pods' own positions gives the truth the report compares with.

Measurement, in two passes over identical fresh simulations (so the poses must agree):

1. *Timing pass*, tracemalloc off: ``time.perf_counter_ns()`` around every step; the loop
   runs flat out (no sleeping), the 20 ms period is only the budget the latencies are
   compared with. The two clock reads (~0.1 µs) are included in each sample.
2. *Allocation pass*, tracemalloc on (it slows every allocation down, so it must not
   distort the timings): traced bytes are read once before the loop, the peak is reset,
   and after the loop the peak and current traced bytes are compared with the start;
   ``sys.getallocatedblocks()`` before and after gives the net change in live blocks.
   Around the loop, ``drivekin._core.alloccount.AllocationCounter`` hooks CPython's RAW, MEM
   and OBJ allocator domains and counts every malloc/calloc/realloc call: 0 calls means
   the steady-state loop is served entirely by freelists (floats, drivekin value
   objects) and preallocated objects. The tracemalloc figures are a second opinion.

Before each pass: ``gc.collect()``, then the measured simulation is built, then a
throw-away simulation runs one full script cycle as warm-up (caches, specialised
bytecode) and is freed, refilling the freelists (see :func:`prepared_simulation`).

``--drivetrain deadwheel`` runs the mecanum robot with wheel slip and localizes it twice,
by its drive encoders and by three dead wheels (Road Runner's standard layout, encoder
ticks and noise), reporting both odometries' errors against the simulated truth (see
:class:`DeadWheelDrive`).

``--vision`` (swerve) wears the wheels so that the odometry drifts and adds a simulated
camera whose delayed, noisy AprilTag poses go to a SwerveDrivePoseEstimator; both
estimates are compared with the truth (see :class:`VisionSwerveDrive`).

``--setpoint-generator`` (swerve, also with ``--vision``) replaces discretize, inverse
kinematics and desaturation with a :class:`~drivekin.SwerveSetpointGenerator` in its default
mode: ``generateSetpointInto(setpoint, command, 0.02, setpoint, 12.0)`` updates one setpoint in
place each step, and its module velocities are copied into the module targets. The report
adds the generator's time per call (pass 1) and the steps it limited (see
:class:`SwerveDrive`).

Only the standard library and drivekin are used. Drivetrains plug in through
:data:`DRIVETRAINS`: a :class:`Drivetrain` subclass with ``pose``, ``distance``,
``describe()``, ``step(command)`` and optionally ``results()``.
"""
from drivekin.app.demo.drivetrains import DRIVETRAINS, SETPOINT_DRIVETRAINS, VISION_DRIVETRAINS
from drivekin.app.demo.measure import run
from drivekin.app.demo.report import header, table
from drivekin.app.demo.script import DT

__all__ = ["DRIVETRAINS", "DT", "SETPOINT_DRIVETRAINS", "VISION_DRIVETRAINS", "header", "run",
           "table"]
