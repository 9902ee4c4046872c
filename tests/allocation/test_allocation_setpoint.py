"""Allocation tests for the swerve setpoint generator (drivekin.setpoint).

``generateSetpointInto`` makes no allocator calls (traced memory, GC counts and the
malloc counter of tests/_support/alloc.py), with and without constraints, in both modes,
with ``out`` a separate setpoint or ``prevSetpoint`` itself, on commands that keep the
generator's limits active (the kernel's every branch: steering, torque, the all-modules
flip)."""
from __future__ import annotations

import itertools
import math

import pytest

from tests._support.alloc import assert_allocation_free, assert_no_allocations
from drivekin import (
    ChassisVelocities,
    DCMotor,
    DriveFeedforwards,
    ModuleConfig,
    PathConstraints,
    RobotConfig,
    SwerveModuleVelocity,
    SwerveSetpoint,
    SwerveSetpointGenerator,
    Translation2d,
)


def _generator(compatibility, n=4):
    module = ModuleConfig(0.0508, 4.5, 1.2, DCMotor.getKrakenX60(1).withReduction(6.75),
                          60.0, 1)
    offsets = [Translation2d(0.3 * math.cos(2 * math.pi * i / n + 0.4),
                             0.3 * math.sin(2 * math.pi * i / n + 0.4)) for i in range(n)]
    return SwerveSetpointGenerator(RobotConfig(55.0, 5.5, module, offsets), 2 * math.pi,
                                   compatibility=compatibility)


def _zeros(n=4):
    return SwerveSetpoint(ChassisVelocities(), [SwerveModuleVelocity() for _ in range(n)],
                          DriveFeedforwards.zeros(n))


# Forward, sideways-and-turning, then straight back: acceleration, steering limits and the
# "every module flips" stop.
COMMANDS = [ChassisVelocities(4.0, 0.0, 0.0), ChassisVelocities(1.0, 3.0, 4.0),
            ChassisVelocities(-4.0, 0.0, 0.0), ChassisVelocities()]


@pytest.mark.parametrize("compatibility", [None, "pathplanner"])
@pytest.mark.parametrize("constraints", [None, PathConstraints(3.0, 5.0, 4.0, 8.0)],
                         ids=["unconstrained", "constrained"])
def test_generate_setpoint_into(compatibility, constraints):
    gen = _generator(compatibility)
    prev, out = _zeros(), _zeros()
    cycle = itertools.cycle(COMMANDS)

    def loop(it):
        for _ in it:
            cmd = next(cycle)
            gen.generateSetpointInto(prev, cmd, 0.02, out, 11.5, constraints)
            gen.generateSetpointInto(out, cmd, 0.02, prev, 11.5, constraints)

    assert_no_allocations(loop, f"generateSetpointInto({compatibility}, {constraints})")
    # The result is the per-call façade's.
    expect = _generator(compatibility).generateSetpoint(_zeros(), COMMANDS[1], 0.02, 11.5,
                                                       constraints)
    _generator(compatibility).generateSetpointInto(_zeros(), COMMANDS[1], 0.02, out, 11.5,
                                                  constraints)
    assert out == expect


def test_generate_setpoint_into_prev_as_out():
    gen = _generator(None, n=5)
    sp = _zeros(5)
    cmd = ChassisVelocities(2.0, -1.0, 1.5)
    assert_allocation_free(lambda: gen.generateSetpointInto(sp, cmd, 0.02, sp))
    assert sp.robotRelativeVelocities.vx > 0.0
