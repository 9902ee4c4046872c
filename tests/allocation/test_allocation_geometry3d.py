"""The hot 3-D geometry calls allocate nothing in steady state: Pose3d composition
(``transformBy``, ``plus``, ``+``), ``relativeTo``, ``Twist3d.exp``, ``Transform3d.log``
and a pose update loop built from them draw their results from freelists (method:
``tests/_support/alloc.py``)."""
from __future__ import annotations

import pytest

from drivekin import Pose3d, Rotation3d, Transform3d, Translation3d, Twist3d
from tests._support.alloc import assert_allocation_free


class _Box:
    __slots__ = ("pose", "twist")


def _pose():
    return Pose3d(1.0, 2.0, 0.5, Rotation3d(0.1, -0.2, 0.3))


def _transform():
    return Transform3d(Translation3d(0.05, -0.01, 0.002), Rotation3d(0.001, 0.002, -0.003))


@pytest.mark.parametrize("call", ["transformBy", "plus", "add"])
def test_pose_composition(call):
    box = _Box()
    box.pose = _pose()
    t = _transform()
    if call == "add":
        def step():
            box.pose = box.pose + t
    else:
        method = getattr(Pose3d, call)

        def step():
            box.pose = method(box.pose, t)

    assert_allocation_free(step)
    assert box.pose.getX() != 1.0        # the loop moved the pose


def test_relative_to_and_minus():
    p, q = _pose(), Pose3d(-0.5, 0.25, 1.0, Rotation3d(0.3, 0.1, -1.2))
    assert_allocation_free(lambda: p.relativeTo(q))
    assert_allocation_free(lambda: p - q)


def test_twist_exp_and_transform_log():
    tw = Twist3d(0.5, 0.1, 0.2, 0.01, 0.02, 0.03)
    t = _transform()
    assert_allocation_free(tw.exp)
    assert_allocation_free(t.log)


def test_odometry_style_update():
    """A 3-D odometry step: pose ← pose + twist.exp(), and the twist back from the poses."""
    box = _Box()
    box.pose = _pose()
    box.twist = Twist3d(0.02, 0.001, 0.0, 0.0005, -0.0002, 0.003)

    def step():
        old = box.pose
        box.pose = old.plus(box.twist.exp())
        box.twist = box.pose.minus(old).log()

    assert_allocation_free(step)
