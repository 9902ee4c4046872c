"""The drivetrain contract's base class (declared in drivetrain.pxd): the centre-of-rotation
rule written once, defaults for what most drivetrains do not need, and map bodies that
keep a subclass that does not override them from computing; and the pseudo-inverse the
drivetrains build their forward maps with.
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
# has no Python-visible members, so the stub declares none. pseudo_inverse builds their
# forward maps.

import numpy as np
import numpy.typing as npt
from typing_extensions import disjoint_base

@disjoint_base
class Drivetrain: ...

def pseudo_inverse(a: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Return the Moore–Penrose pseudo-inverse of a finite 2-D float64 matrix with at most
    8 columns or rows, computed by drivekin in one fixed order of operations (Householder
    QR), so that it has the same bits on every platform: within about 1e-15 relative of
    the exact one for a well-conditioned matrix. Singular values below 1e-15 of the
    largest are treated as zero, as numpy's ``pinv`` does (the test is on each column's
    part independent of the columns before it)."""
