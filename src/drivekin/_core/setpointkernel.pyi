"""The swerve setpoint generator's kernel: PathPlannerLib's algorithm (after Team 254's)
in its order of operations, on C doubles, and the C state it runs on (declared in
setpointkernel.pxd). drivekin.setpoint's per-call methods and
drivekin.batch.generateSetpoints both run ``generate`` on a SetpointKernel's buffers.

Angles go through drivekin's Rotation2d arithmetic (WPILib's), so the branches
PathPlannerLib takes on angle comparisons come out the same."""

# Hand-written stub for the private compiled module drivekin._core.setpointkernel
# (_core/setpointkernel.pyx). The docstrings are written from the compiled module's
# ``__doc__`` (the .pyx docstrings) by scripts/stub_docstrings.py: edit them in the .pyx,
# rebuild and rerun the script. tests/api/test_stubs.py checks that they match and that
# no public name is missing on either side.
#
# SetpointKernel is the runtime base class of SwerveSetpointGenerator. Its contract is
# C-level only (C fields and a cdef method, setpointkernel.pxd): it has no Python-visible
# members, so the stub declares none.

from typing_extensions import disjoint_base

@disjoint_base
class SetpointKernel:
    """The generator's C state (setpointkernel.pxd): the robot's constants, the buffer
    that holds per-module constants, scratch, the previous setpoint and the output, which
    it frees. drivekin.setpoint.SwerveSetpointGenerator fills it and reads the previous
    setpoint and the constraints into it (_load)."""
