"""The drivetrain contract's base class (declared in drivetrain.pxd): the centre-of-rotation
rule written once, defaults for what most drivetrains do not need, and map bodies that
keep a subclass that does not override them from computing.
"""

# Hand-written stub for the private compiled module drivekin._core.drivetrain
# (_core/drivetrain.pyx). The docstrings are written from the compiled module's
# ``__doc__`` (the .pyx docstrings) by scripts/stub_docstrings.py: edit them in the .pyx,
# rebuild and rerun the script. tests/api/test_stubs.py checks that they match and that
# no public name is missing on either side.
#
# Drivetrain is the runtime base class of the four kinematics classes
# (SwerveDriveKinematics, MecanumDriveKinematics, DifferentialDriveKinematics,
# DeadWheelKinematics). Its contract is C-level only (cdef methods, drivetrain.pxd): it
# has no Python-visible members, so the stub declares none.

from typing_extensions import disjoint_base

@disjoint_base
class Drivetrain: ...
