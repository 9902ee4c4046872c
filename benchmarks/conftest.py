"""pytest-benchmark fixtures for drivekin vs robotpy-wpimath.

The robot is the 4-module square layout (modules at (±0.3, ±0.3) m), built once per
session in robotpy (``rp``) and in drivekin (``dk``); inputs are the fixed values of
``_common.INPUTS``, and every robotpy argument object (ChassisSpeeds, module states,
Rotation2d, Pose2d, Twist2d) is prebuilt, as in shared/reference/perf-floor.md.

Each benchmark body runs its statement ``_common.INNER`` (100) times in a local loop, so
pytest-benchmark's times are per 100 calls (``extra_info["inner_loop"]``);
``python benchmarks/ratio_table.py --from-json FILE`` converts them to ns/call.
"""
from __future__ import annotations

import pytest

from _common import (INNER, INPUTS, build_drivekin, build_drivekin_geometry, build_robotpy,
                     compile_body, kinematics_available)
from registry import baseline_of, evaluate, reference_value, values_agree

KINEMATICS = kinematics_available()


@pytest.fixture(scope="session")
def inputs():
    return INPUTS


@pytest.fixture(scope="session")
def rp():
    """robotpy-wpimath objects: SwerveDrive4Kinematics, ChassisSpeeds, 4 states, ..."""
    return build_robotpy()


@pytest.fixture(scope="session")
def dk():
    """drivekin objects (geometry only while drivekin.kinematics is not built)."""
    return build_drivekin() if KINEMATICS else build_drivekin_geometry()


def _require(op):
    if op.needs_kinematics and not KINEMATICS:
        pytest.skip("drivekin.kinematics is not built")


@pytest.fixture
def bench_op(benchmark, rp, dk):
    """``bench_op(op, variant)``: benchmark one registry case, grouped by operation."""

    def run(op, variant):
        _require(op)
        case = op.variants()[variant]
        body = compile_body(case.stmt, case.setup(rp, dk), INNER)
        body()  # warm the freelists / heading memory before pytest-benchmark starts
        benchmark.group = op.title
        benchmark.extra_info.update(operation=op.key, variant=variant, stmt=case.stmt,
                                    inner_loop=INNER)
        benchmark(body)

    return run


@pytest.fixture
def check_op(rp, dk):
    """``check_op(op)``: every variant produces the robotpy baseline's numbers (for a
    drivekin-only operation: its ``expected`` numbers, else its façade's)."""
    def run(op):
        _require(op)
        baseline_of(op)                      # a baseline must name a registered case
        ref = reference_value(op, rp, dk)
        for name, case in op.variants().items():
            got = evaluate(case, case.setup(rp, dk))
            assert values_agree(ref, got), f"{op.key} {name}: {got} != reference {ref}"

    return run
