"""The reproducers of the memory-safety issue (#6) that concern the value, kinematics and
odometry classes, each pinned to its correct outcome. Cases that crashed the interpreter
run in a subprocess, so a regression fails the test instead of killing the runner.
"""
from __future__ import annotations

import copy
import pickle
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

from drivekin import (
    ChassisVelocities,
    DifferentialDriveKinematics,
    MecanumDriveKinematics,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Transform2d,
    Translation2d,
)
from drivekin.geometry import _rotation_from_cos_sin

T = Translation2d


def kin4():
    return SwerveDriveKinematics(T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.3))


def run_isolated(body: str, prelude: str = "") -> str:
    """Run ``prelude`` then ``body`` in a fresh interpreter; fail on a crash; return its
    stdout."""
    code = "import gc\nfrom drivekin import *\n" + prelude + textwrap.dedent(body)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, f"exit {proc.returncode}\n{proc.stdout}\n{proc.stderr}"
    return proc.stdout


# A chain of garbage cycles whose finalizer empties the caller's list at the fuse-th
# collection; gc.set_threshold(1) makes every container allocation inside the call collect.
BOMB = """
def armed(victim, fuse):
    class Bomb:
        def __init__(self):
            self.me = self
        def __del__(self):
            if fuse == 1:
                victim.clear()
            else:
                armed(victim, fuse - 1)
    Bomb()

def call_armed(victim, fuse, call):
    gc.collect()
    gc.disable()
    armed(victim, fuse)
    gc.set_threshold(1)
    gc.enable()
    try:
        return call()
    finally:
        gc.set_threshold(700)
        gc.collect()
"""


@pytest.mark.parametrize("n", [4, 40])
def test_1_desaturate_reads_the_list_before_allocating(n):
    out = run_isolated(prelude=BOMB, body=f"""
        desat = SwerveDriveKinematics.desaturateWheelVelocities
        for fuse in (1, 2, 3):
            states = [SwerveModuleVelocity(3.0 * i, Rotation2d(i)) for i in range({n})]
            want = [(s.velocity, s.angle.getRadians()) for s in desat(list(states), 4.0)]
            got = call_armed(states, fuse, lambda: desat(states, 4.0))
            assert [(s.velocity, s.angle.getRadians()) for s in got] == want, got
            print(len(states))
    """)
    assert "0" in out.split(), "the finalizer never ran during a call"


@pytest.mark.parametrize("n", [4, 40])
def test_2_interpolate_holds_its_items(n):
    out = run_isolated(prelude=BOMB, body=f"""
        import math
        kin = SwerveDriveKinematics([Translation2d(math.cos(i), math.sin(i)) for i in range({n})])
        for fuse in (1, 2, 3):
            start = [SwerveModulePosition(i, Rotation2d(0.1 * i)) for i in range({n})]
            end = [SwerveModulePosition(2 * i, Rotation2d(0.2 * i)) for i in range({n})]
            want = kin.interpolate(list(start), list(end), 0.5)
            got = call_armed(start, fuse, lambda: kin.interpolate(start, end, 0.5))
            assert got == want
            print(len(start))
    """)
    assert "0" in out.split(), "the finalizer never ran during a call"


def test_5_nearest_rejects_none():
    with pytest.raises(TypeError, match="Pose2d.*NoneType"):
        Pose2d().nearest([Pose2d(1e308, 1e308, Rotation2d()), None])


def test_6_out_is_validated_before_the_scratch_is_filled():
    kin = kin4()
    objs = [SwerveModuleVelocity() for _ in range(4)]

    class Out:
        def __iter__(self):
            kin.toSwerveModuleVelocities(ChassisVelocities(9.0, -9.0, 9.0))   # re-entrant
            return iter(objs)

    kin.toSwerveModuleVelocitiesInto(ChassisVelocities(1.0, 0.0, 0.0), Out())
    assert [(o.velocity, o.angle.getRadians()) for o in objs] == [(1.0, 0.0)] * 4


def test_6_two_threads_share_a_kinematics_object():
    kin = kin4()
    commands = [ChassisVelocities(1.0, 0.0, 0.0), ChassisVelocities(0.0, 2.0, 1.0)]
    want = [[(m.velocity, m.angle.getRadians()) for m in kin4().toSwerveModuleVelocities(c)]
            for c in commands]
    wrong = []

    class Yielding:
        # Iterating it gives the other thread the GIL in the middle of the call.
        def __init__(self, items):
            self.items = items

        def __iter__(self):
            time.sleep(0)
            return iter(self.items)

    def worker(k):
        out = [SwerveModuleVelocity() for _ in range(4)]
        for _ in range(200):
            kin.toSwerveModuleVelocitiesInto(commands[k], Yielding(out))
            got = [(m.velocity, m.angle.getRadians()) for m in out]
            if got != want[k]:
                wrong.append(got)

    threads = [threading.Thread(target=worker, args=(k,)) for k in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert wrong == []


def test_7_a_failed_into_call_keeps_heading_memory():
    kin = kin4()
    with pytest.raises(TypeError, match="float64"):
        kin.toSwerveModuleVelocitiesInto(ChassisVelocities(0.0, 1.0, 0.0),
                                         np.zeros((4, 2), dtype=np.float32))
    assert [m.angle.getRadians() for m in kin.toSwerveModuleVelocities(ChassisVelocities())] \
        == [0.0] * 4


@pytest.mark.parametrize("clone", [copy.copy, copy.deepcopy,
                                   lambda k: pickle.loads(pickle.dumps(k))])
def test_8_copies_keep_heading_memory(clone):
    kin = kin4()
    kin.toSwerveModuleVelocities(ChassisVelocities(0.0, 1.0, 0.5), T(0.1, -0.2))
    twin = clone(kin)
    for cv in (ChassisVelocities(), ChassisVelocities(0.3, 0.0, 1.0), ChassisVelocities()):
        assert twin.toSwerveModuleVelocities(cv) == kin.toSwerveModuleVelocities(cv)


def test_9_a_failed_odometry_init_leaves_an_object_that_refuses_to_compute():
    odo = SwerveDriveOdometry.__new__(SwerveDriveOdometry)
    with pytest.raises(ValueError, match="expected 4"):
        odo.__init__(kin4(), Rotation2d(), [SwerveModulePosition()] * 2)
    with pytest.raises(RuntimeError, match="__init__"):
        odo.update(Rotation2d(), [SwerveModulePosition()] * 4)
    with pytest.raises(RuntimeError, match="__init__"):
        odo.getPose()
    odo.__init__(kin4(), Rotation2d(), [SwerveModulePosition()] * 4)   # may try again
    assert odo.update(Rotation2d(), [SwerveModulePosition()] * 4) == Pose2d()
    with pytest.raises(TypeError, match="already initialised"):
        odo.__init__(kin4(), Rotation2d(), [SwerveModulePosition()] * 4)


@pytest.mark.parametrize("value, args", [
    (Rotation2d.kZero, (1.0,)), (Translation2d(1.0, 2.0), (3.0, 4.0)),
    (Pose2d(), (1.0, 2.0, Rotation2d(1.0))), (Transform2d.kZero, (1.0, 2.0, Rotation2d())),
])
def test_10_immutables_refuse_reinit(value, args):
    before = repr(value)
    with pytest.raises(TypeError, match="immutable"):
        value.__init__(*args)
    assert repr(value) == before


def test_10_kinematics_refuse_reinit_and_stay_whole():
    diff = DifferentialDriveKinematics(0.5)
    with pytest.raises(TypeError, match="already initialised"):
        diff.__init__(2.0)
    assert diff.trackwidth == 0.5
    mec = MecanumDriveKinematics(T(1, 1), T(1, -1), T(-1, 1), T(-1, -1))
    with pytest.raises(TypeError, match="already initialised"):
        mec.__init__(T(2, 2), T(2, -2), T(-2, 2), T(-2, -2))
    assert mec.getFrontLeft() == T(1, 1)
    with pytest.raises(TypeError, match="already initialised"):
        kin4().__init__(T(1, 1), T(2, 2))


@pytest.mark.parametrize("cls", [SwerveDriveKinematics, MecanumDriveKinematics,
                                 DifferentialDriveKinematics])
def test_10_bare_kinematics_refuse_to_compute(cls):
    kin = cls.__new__(cls)
    with pytest.raises(RuntimeError, match="__init__"):
        kin.toWheelVelocities(ChassisVelocities(1.0, 0.0, 0.0))


def test_10_failed_mecanum_reinit_via_new_leaves_nothing_half_built():
    mec = MecanumDriveKinematics.__new__(MecanumDriveKinematics)
    with pytest.raises(ValueError, match="finite"):
        mec.__init__(T(1, 1), T(1, -1), T(-1, 1), T(float("nan"), -1))
    with pytest.raises(RuntimeError, match="__init__"):
        mec.toWheelVelocities(ChassisVelocities(1.0, 0.0, 0.0))


def test_11_unpickling_cannot_build_a_non_unit_rotation():
    with pytest.raises(ValueError, match="unit"):
        _rotation_from_cos_sin(2.0, 0.0)
    nan = Rotation2d(float("nan"))
    assert repr(pickle.loads(pickle.dumps(nan))) == repr(nan)
    r = Rotation2d(0.7)
    assert pickle.loads(pickle.dumps(r)).getCos() == r.getCos()


def test_11_bare_new_gives_valid_values():
    assert Rotation2d.__new__(Rotation2d).getCos() == 1.0
    assert Pose2d.__new__(Pose2d) == Pose2d()


def test_17_buffer_where_an_array_is_accepted():
    with pytest.raises(TypeError, match="memoryview"):
        kin4().toChassisVelocities(memoryview(np.zeros((4, 2))))


def test_18_deleting_a_field_is_an_attribute_error():
    with pytest.raises(AttributeError, match="cannot be deleted"):
        del ChassisVelocities().vx


def test_19_vector_constructor_takes_one_argument():
    with pytest.raises(TypeError, match="one argument"):
        Translation2d(np.array([1.0, 2.0]), 99)


def test_20_foreign_classes_are_named_with_their_module():
    wpigeo = pytest.importorskip("wpimath.geometry")
    with pytest.raises(TypeError, match=r"got wpimath\.geometry\.\S*Translation2d"):
        SwerveDriveKinematics(wpigeo.Translation2d(), wpigeo.Translation2d())


def test_20_documented_keywords():
    assert Rotation2d(value=1.0) == Rotation2d(1.0)
    assert Pose2d(translation=T(1, 2), rotation=Rotation2d(0.5)) == Pose2d(1, 2, Rotation2d(0.5))
    assert Pose2d(x=1, y=2, rotation=Rotation2d(0.5)) == Pose2d(1, 2, Rotation2d(0.5))
    with pytest.raises(TypeError, match="both by position and by keyword"):
        Pose2d(T(1, 2), translation=T(1, 2))


def test_reentrant_init_from_an_iterable_is_refused_without_replacing_state():
    # Reading a generic iterable runs Python code; a nested __init__ completing there must
    # not be overwritten (and its memory leaked) when the outer one resumes.
    kin = SwerveDriveKinematics.__new__(SwerveDriveKinematics)

    def modules():
        kin.__init__(T(1, 1), T(-1, -1))
        yield from (T(2, 2), T(-2, -2), T(3, 3))

    with pytest.raises(TypeError, match="already initialised"):
        kin.__init__(modules())
    assert kin.getModules() == (T(1, 1), T(-1, -1))

    odo = SwerveDriveOdometry.__new__(SwerveDriveOdometry)
    two = SwerveDriveKinematics(T(1, 1), T(-1, -1))

    def positions():
        odo.__init__(two, Rotation2d(), [SwerveModulePosition()] * 2)
        yield from (SwerveModulePosition(1.0), SwerveModulePosition(1.0))

    with pytest.raises(TypeError, match="already initialised"):
        odo.__init__(two, Rotation2d(), positions())
    # The nested call's baseline (0 m) stands: a 1 m reading moves the robot 1 m.
    assert odo.update(Rotation2d(), [SwerveModulePosition(1.0)] * 2).getX() == pytest.approx(1.0)
