"""Hostile inputs at drivekin's pure-Python edges (issue 6): ``wpistruct`` buffers and
module counts, ``str()`` formatting, and the ``python -m drivekin`` command line.

Cases that crashed 0.1.0 (raw doubles written over an object array's pointers) run in a
subprocess, so a crash fails the test instead of killing the runner.
"""
from __future__ import annotations

import array
import ctypes
import decimal
import gc
import math
import os
import subprocess
import sys
import textwrap
import tracemalloc

import numpy as np
import pytest

import drivekin
from drivekin import (
    ChassisVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    Translation2d,
    Twist2d,
    wpistruct,
)

_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(drivekin.__file__)))


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        p for p in (_PACKAGE_ROOT, env.get("PYTHONPATH", "")) if p)
    return env


def _python(*args: str, timeout: float = 60) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, *args], env=_env(), capture_output=True,
                          text=True, encoding="utf-8", timeout=timeout)


# ---------------------------------------------------------------------------------------
# wpistruct: buffers must hold plain bytes or numbers (defects 3 and 4)

POSE = Pose2d(1.0, 2.0, Rotation2d(0.5))

# Buffers whose memory is not plain data; each must be refused by every entry point.
NON_DATA_BUFFERS = {
    "object ndarray": lambda: np.array([1.0, 2.0, 3.0], dtype=object),
    "empty object ndarray": lambda: np.empty(3, dtype=object),
    "structured ndarray": lambda: np.zeros(3, dtype=[("a", "f8")]),
    "unicode ndarray": lambda: np.zeros(3, dtype="U2"),
    # "w" (UCS-4) replaces the deprecated "u" from Python 3.13
    "unicode array.array": lambda: array.array("w" if sys.version_info >= (3, 13) else "u",
                                               "x" * 12),
    "ctypes pointer array": lambda: (ctypes.c_void_p * 3)(),
}


@pytest.mark.parametrize("make", NON_DATA_BUFFERS.values(), ids=NON_DATA_BUFFERS)
def test_every_buffer_entry_point_refuses_non_data_formats(make):
    calls = {
        "packInto": lambda b: wpistruct.packInto(POSE, b),
        "packInto offset": lambda b: wpistruct.packInto(POSE, b, 0),
        "unpack": lambda b: wpistruct.unpack(Pose2d, b),
        "unpack offset": lambda b: wpistruct.unpack(Pose2d, b, 0),
        "unpack swerve": lambda b: wpistruct.unpack(SwerveDriveKinematics, b),
        "unpackFrom": lambda b: wpistruct.unpackFrom(Pose2d, b),
        "unpackArray": lambda b: wpistruct.unpackArray(Pose2d, b),
    }
    for name, call in calls.items():
        buf = make()
        if name.startswith("packInto") and getattr(buf, "dtype", None) == object:
            continue          # would crash the runner on a regression: see the next test
        before = bytes(memoryview(buf).cast("B")) if not isinstance(buf, np.ndarray) \
            or buf.dtype != object else buf.tolist()
        with pytest.raises(TypeError, match="plain bytes or numbers") as info:
            call(buf)
        assert "item format" in str(info.value), name
        after = bytes(memoryview(buf).cast("B")) if not isinstance(buf, np.ndarray) \
            or buf.dtype != object else buf.tolist()
        assert after == before, name                          # nothing written


def test_unpack_object_array_names_dtype_object():
    # 0.1.0 read the object pointers as doubles: Pose2d(6.9e-310, ...).
    with pytest.raises(TypeError, match=r"dtype=object"):
        wpistruct.unpack(Pose2d, np.array([1.0, 2.0, 3.0], dtype=object))
    with pytest.raises(TypeError, match=r"dtype=object"):
        wpistruct.unpackArray(Pose2d, np.array([1.0, 2.0, 3.0], dtype=object))


def test_pack_into_object_array_leaves_it_usable():
    # 0.1.0 wrote raw doubles over the object pointers: SIGSEGV when the array was used.
    result = _python("-c", textwrap.dedent("""
        import gc
        import numpy as np
        from drivekin import Pose2d, Rotation2d, wpistruct
        for arr in (np.empty(3, dtype=object), np.array([1.0, "a", None], dtype=object)):
            before = arr.tolist()
            for args in ((), (0,)):
                try:
                    wpistruct.packInto(Pose2d(1e300, 2.0, Rotation2d(0.5)), arr, *args)
                except TypeError as e:
                    print("TypeError", "dtype=object" in str(e))
                assert arr.tolist() == before
        del arr
        gc.collect()
        print("alive")
    """))
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == ["TypeError True"] * 4 + ["alive"]


@pytest.mark.parametrize("dtype", ["f8", ">f8", "u1", "i1", "i4", "f4", "c16", "?", "S8"])
def test_plain_numeric_buffers_still_work(dtype):
    itemsize = np.dtype(dtype).itemsize
    buf = np.zeros(48 // itemsize, dtype=dtype)
    wpistruct.packInto(POSE, buf, 8)
    assert buf.tobytes()[8:32] == wpistruct.pack(POSE)
    assert wpistruct.unpackFrom(Pose2d, buf, 8) == POSE
    for typed in (array.array("d", [1.0, 2.0, 0.5]), (ctypes.c_double * 3)(1.0, 2.0, 0.5),
                  (ctypes.c_char * 24)()):
        wpistruct.packInto(POSE, typed)
        assert wpistruct.unpack(Pose2d, typed) == POSE


class _Clears:
    """An ``__index__`` that empties a bytearray, as a hostile callback would."""

    def __init__(self, buf: bytearray, value: int) -> None:
        self.buf, self.value = buf, value

    def __index__(self) -> int:
        self.buf.clear()
        return self.value


def test_arguments_are_read_before_the_buffer_is_viewed():
    # The buffer is viewed (and so locked against resizing) only after every argument that
    # can run Python code has been read: a callback that empties the buffer sees it
    # unlocked, and the call then reports the real (empty) size. On 0.1.0 unpack() read
    # numModules inside the view: BufferError from the callback.
    k = SwerveDriveKinematics([Translation2d(1.0, 0.0), Translation2d(-1.0, 0.0)])
    buf = bytearray(wpistruct.pack(k))
    with pytest.raises(ValueError, match="is 32 bytes, got 0"):
        wpistruct.unpack(SwerveDriveKinematics, buf, numModules=_Clears(buf, 2))
    buf = bytearray(wpistruct.pack(k))
    with pytest.raises(ValueError, match="only 0 available"):
        wpistruct.unpackFrom(SwerveDriveKinematics, buf, numModules=_Clears(buf, 2))
    buf = bytearray(wpistruct.pack(POSE))
    with pytest.raises(ValueError, match="got 0"):
        wpistruct.unpack(Pose2d, buf, _Clears(buf, 0))
    buf = bytearray(24)
    with pytest.raises(ValueError, match="the buffer has 0"):
        wpistruct.packInto(POSE, buf, _Clears(buf, 0))
    assert buf == bytearray()
    buf.extend(b"\0")                         # and no export is left behind


def test_buffer_is_held_for_the_whole_call():
    # A memoryview released by its owner during the call stays valid underneath ours.
    data = bytearray(wpistruct.pack(POSE))
    view = memoryview(data)
    assert wpistruct.unpack(Pose2d, view) == POSE
    view.release()
    data.extend(b"\0")                        # not left locked


# ---------------------------------------------------------------------------------------
# wpistruct: module counts (defects 13 and 15)

# (getattr: the module must still collect against 0.1.0, which lacked the constant.)
HUGE_COUNTS = [10**18, 2**63, 10**100, 10**5000,
               getattr(wpistruct, "MAX_SWERVE_MODULES", sys.maxsize // 16) + 1]


@pytest.mark.parametrize("n", HUGE_COUNTS, ids=["1e18", "2**63", "1e100", "1e5000", "max+1"])
def test_huge_module_counts_are_value_errors(n):
    # 0.1.0: struct.error from building a struct of 2·N doubles.
    calls = (lambda: wpistruct.getSize(SwerveDriveKinematics, numModules=n),
             lambda: wpistruct.getTypeName(SwerveDriveKinematics, numModules=n),
             lambda: wpistruct.getSchema(SwerveDriveKinematics, numModules=n),
             lambda: wpistruct.unpack(SwerveDriveKinematics, b"", numModules=n),
             lambda: wpistruct.unpackFrom(SwerveDriveKinematics, b"", numModules=n),
             lambda: wpistruct.unpackArray(SwerveDriveKinematics, b"", numModules=n),
             lambda: wpistruct.forEachNested(SwerveDriveKinematics, lambda t, s: None,
                                             numModules=n))
    for call in calls:
        with pytest.raises(ValueError, match=r"numModules <= \d+ "):
            call()


@pytest.mark.parametrize("n", [-(10**18), -(10**5000), 1, 0], ids=["-1e18", "-1e5000", "1", "0"])
def test_small_and_negative_module_counts_are_value_errors(n):
    for call in (lambda: wpistruct.getSize(SwerveDriveKinematics, numModules=n),
                 lambda: wpistruct.unpackArray(SwerveDriveKinematics, b"", numModules=n)):
        with pytest.raises(ValueError, match="numModules >= 2"):
            call()


@pytest.mark.parametrize("bad", [2.0, "4", [4], np.float64(4.0), True])
def test_non_int_module_counts_are_type_errors(bad):
    with pytest.raises(TypeError, match="numModules must be an int"):
        wpistruct.getSize(SwerveDriveKinematics, numModules=bad)


def test_largest_module_count_is_described_without_building_anything():
    n = wpistruct.MAX_SWERVE_MODULES
    assert wpistruct.getSize(SwerveDriveKinematics, numModules=n) == 16 * n
    assert wpistruct.unpackArray(SwerveDriveKinematics, b"", numModules=n) == []
    with pytest.raises(ValueError, match=f"is {16 * n} bytes, got 0"):
        wpistruct.unpack(SwerveDriveKinematics, b"", numModules=n)
    with pytest.raises(ValueError, match="numModules=3 does not match"):
        wpistruct.getSize(SwerveDriveKinematics(
            [Translation2d(1.0, 0.0), Translation2d(-1.0, 0.0)]), numModules=3)
    with pytest.raises(ValueError, match="numModules=a huge number does not match"):
        wpistruct.getSize(SwerveDriveKinematics(
            [Translation2d(1.0, 0.0), Translation2d(-1.0, 0.0)]), numModules=10**5000)


def test_spec_cache_does_not_keep_memory_per_module_count():
    # 0.1.0 kept one spec per count forever: +126 MiB for 100k counts (~1.3 KiB each).
    get = wpistruct.getTypeName
    for n in range(2, 200):                   # warm up: the cache's own fixed footprint
        get(SwerveDriveKinematics, numModules=n)
    gc.collect()
    # 100k counts, counted in live blocks (0.1.0: several blocks per count) ...
    blocks = sys.getallocatedblocks()
    for n in range(1000, 101_000):
        get(SwerveDriveKinematics, numModules=n)
    gc.collect()
    assert sys.getallocatedblocks() - blocks < 1000
    # ... and 10k in bytes (tracemalloc slows each spec down ~8x, hence fewer).
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        for n in range(200_000, 210_000):
            get(SwerveDriveKinematics, numModules=n)
        gc.collect()
        grown = tracemalloc.get_traced_memory()[0] - start
    finally:
        tracemalloc.stop()
    assert grown < 64 * 1024, f"{grown} bytes kept for 10k distinct module counts"
    assert get(SwerveDriveKinematics, numModules=4) == "SwerveDriveKinematics__4"


# ---------------------------------------------------------------------------------------
# str(): Java %.2f, independent of the decimal context (defect 14)

# Expected strings came from String.format("%.2f", x) on OpenJDK 17 (17.0.15), run on this
# project's machine. For |x| >= 1e16 JDK 17 sometimes prints non-shortest digits (1e23 ->
# "99999999999999990000000.00"); drivekin, like JDK 21+, uses the shortest repr, so only
# large values where both agree are listed.
JAVA_17 = [
    (1e26, "100000000000000000000000000.00"),
    (-1e26, "-100000000000000000000000000.00"),
    (1e22, "10000000000000000000000.00"),
    (1.7976931348623157e308,
     "17976931348623157" + "0" * 292 + ".00"),
    (-1.7976931348623157e308,
     "-17976931348623157" + "0" * 292 + ".00"),
    (5e-324, "0.00"),
    (-0.0, "-0.00"),
    (0.0, "0.00"),
    (0.005, "0.01"),
    (0.015, "0.02"),
    (1.005, "1.01"),
    (123456789.125, "123456789.13"),
    (0.125, "0.13"),
    (2.675, "2.68"),
    (-0.125, "-0.13"),
    (-2.675, "-2.68"),
    (-0.001, "-0.00"),
    (-0.005, "-0.01"),
    (9.995, "10.00"),
    (99.995, "100.00"),
    (0.045, "0.05"),
    (1e-5, "0.00"),
    (4.35, "4.35"),
    (8.345, "8.35"),
    (1234.5678, "1234.57"),
    (0.994999, "0.99"),
    (0.995, "1.00"),
    (1e15 + 0.125, "1000000000000000.10"),
    (0.0025, "0.00"),
]


@pytest.mark.parametrize("x, java", JAVA_17, ids=[repr(x) for x, _ in JAVA_17])
def test_str_matches_java(x, java):
    assert str(Translation2d(x, 0.0)) == f"Translation2d(X: {java}, Y: 0.00)"
    assert str(ChassisVelocities(0.0, 0.0, x)) == \
        f"ChassisVelocities(Vx: 0.00 m/s, Vy: 0.00 m/s, Omega: {java} rad/s)"


def test_str_of_non_finite_values():
    assert str(Twist2d(math.nan, math.inf, -math.inf)) == \
        "Twist2d(dX: NaN, dY: Infinity, dTheta: -Infinity)"


def _hostile_contexts():
    low = decimal.Context(prec=1)
    # Every signal, named: iterating a context's signal dict raises ValueError on the
    # CPython 3.14.8 that Debian ships (seen under scripts/wheel_tests.sh).
    signals = [decimal.Clamped, decimal.DivisionByZero, decimal.Inexact, decimal.Overflow,
               decimal.Rounded, decimal.Subnormal, decimal.Underflow,
               decimal.InvalidOperation, decimal.FloatOperation]
    trapping = decimal.Context(prec=3, traps=signals)
    tiny = decimal.Context(prec=28, Emax=2, Emin=-2)
    down = decimal.Context(rounding=decimal.ROUND_DOWN)
    return [low, trapping, tiny, down]


@pytest.mark.parametrize("ctx", _hostile_contexts(), ids=["prec1", "traps", "Emax", "down"])
def test_str_ignores_the_callers_decimal_context(ctx):
    # 0.1.0 quantized in the caller's context: InvalidOperation (or other rounding).
    with decimal.localcontext(ctx):
        for x, java in JAVA_17:
            assert str(ChassisVelocities(x, 0.0, 0.0)).startswith(
                f"ChassisVelocities(Vx: {java} m/s")


def test_str_ignores_a_modified_default_context():
    # A process-wide DefaultContext change (before drivekin is imported) must not matter.
    result = _python("-c", textwrap.dedent("""
        import decimal
        decimal.DefaultContext.prec = 2
        decimal.DefaultContext.traps[decimal.Inexact] = True
        decimal.setcontext(decimal.Context())
        from drivekin import Translation2d
        print(str(Translation2d(123456.125, 1e26)))
    """))
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == \
        "Translation2d(X: 123456.13, Y: 100000000000000000000000000.00)"


# ---------------------------------------------------------------------------------------
# python -m drivekin: bad options (defect 16)

BAD_OPTIONS = [
    ("--seconds", "1e12"), ("--seconds", "abc"), ("--seconds", "nan"),
    ("--seconds", "inf"), ("--seconds", "-1"), ("--seconds", "0"), ("--seconds", "0.001"),
    ("--seconds", "3600.5"), ("--seconds", "9" * 400),
    ("--max-speed", "1e300"), ("--max-speed", "0"), ("--max-speed", "NaN"),
    ("--max-speed", "x"), ("--max-omega", "-inf"), ("--max-omega", "1e9"),
    ("--max-omega", "infinity"), ("--max-omega", ""),
]


@pytest.mark.parametrize("option, value", BAD_OPTIONS,
                         ids=[f"{o}={v[:12]}" for o, v in BAD_OPTIONS])
def test_bad_numeric_option_is_one_clear_error(option, value):
    # 0.1.0: --seconds 1e12 gave a MemoryError/OverflowError traceback, --seconds abc an
    # error naming the internal _positive_float.
    result = _python("-m", "drivekin", f"{option}={value}", "--json")
    assert result.returncode == 2, result.stderr
    assert result.stdout == ""
    errors = [line for line in result.stderr.splitlines() if "error:" in line]
    assert len(errors) == 1, result.stderr
    assert errors[0].startswith(f"python -m drivekin: error: argument {option}: expected "
                                f"a number "), errors[0]
    assert "Traceback" not in result.stderr
    assert "_float" not in result.stderr and "_number" not in result.stderr
    assert all(line.startswith(("usage:", " ", "python -m drivekin: error:"))
               for line in result.stderr.splitlines()), result.stderr


def test_option_bounds_are_inclusive_where_documented():
    result = _python("-m", "drivekin", "--seconds=0.02", "--max-speed=30",
                     "--max-omega=100", "--json")
    assert result.returncode == 0, result.stderr
    assert '"steps": 1' in result.stdout


# ---------------------------------------------------------------------------------------
# RobotConfig.fromGUISettings: only paths of small regular files, parsed without
# recursing into hostile nesting; every number finite (issue 27)

GUI_SETTINGS = {"holonomicMode": True, "robotMass": 61.0, "robotMOI": 6.2,
                "driveWheelRadius": 0.048, "driveGearing": 5.9, "maxDriveSpeed": 4.7,
                "wheelCOF": 1.3, "driveMotorType": "NEO", "driveCurrentLimit": 50,
                "flModuleX": 0.28, "flModuleY": 0.26, "frModuleX": 0.28, "frModuleY": -0.26,
                "blModuleX": -0.28, "blModuleY": 0.26, "brModuleX": -0.28,
                "brModuleY": -0.26}


def _settings_text(**change) -> str:
    import json
    return json.dumps({**GUI_SETTINGS, **change})


@pytest.mark.parametrize("key, raw", [
    ("robotMass", "1" + "0" * 400),             # float() of it: OverflowError
    ("robotMOI", "1e400"),                      # json gives inf
    ("flModuleX", "-1e400"),
    ("wheelCOF", "NaN"),
    ("maxDriveSpeed", "Infinity"),
])
def test_gui_settings_non_finite_numbers_name_the_field(tmp_path, key, raw):
    p = tmp_path / "settings.json"
    text = _settings_text(**{key: "@"}).replace('"@"', raw)
    p.write_text(text)
    with pytest.raises(ValueError, match=f"'{key}' in .* must be a finite number"):
        drivekin.RobotConfig.fromGUISettings(p)


@pytest.mark.parametrize("depth", [64, 100_000])
def test_gui_settings_deep_nesting_is_refused_before_parsing(tmp_path, depth):
    p = tmp_path / "settings.json"
    p.write_text(_settings_text()[:-1] + ', "x": ' + "[" * depth + "]" * depth + "}")
    with pytest.raises(ValueError, match="nests arrays or objects more than 64 deep"):
        drivekin.RobotConfig.fromGUISettings(p)


def test_gui_settings_nesting_inside_strings_does_not_count(tmp_path):
    # Brackets (and escaped quotes) inside a string value are text, not nesting.
    p = tmp_path / "settings.json"
    p.write_text(_settings_text(notes='\\"[{' * 100))
    assert drivekin.RobotConfig.fromGUISettings(p).massKG == 61.0
    # 64 levels with the settings object itself.
    p.write_text(_settings_text()[:-1] + ', "x": ' + "[" * 63 + "]" * 63 + "}")
    assert drivekin.RobotConfig.fromGUISettings(p).massKG == 61.0


@pytest.mark.parametrize("bad", [0, 1, -1, True, 3.0, b"settings.json", None])
def test_gui_settings_takes_only_paths(bad):
    # An int would be taken as an open file descriptor, read and closed.
    with pytest.raises(TypeError, match="path must be a str or os.PathLike"):
        drivekin.RobotConfig.fromGUISettings(bad)


def test_gui_settings_leaves_file_descriptors_alone(tmp_path):
    r, w = os.pipe()
    try:
        with pytest.raises(TypeError):
            drivekin.RobotConfig.fromGUISettings(r)
        os.fstat(r)                             # still open
    finally:
        os.close(r)
        os.close(w)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_gui_settings_refuses_a_fifo_without_blocking(tmp_path):
    fifo = tmp_path / "settings.json"
    os.mkfifo(fifo)
    # In a child process: a reader that opened the FIFO would wait for a writer for ever.
    r = _python("-c", textwrap.dedent(f"""
        import drivekin
        try:
            drivekin.RobotConfig.fromGUISettings({str(fifo)!r})
        except ValueError as e:
            print(e)
        """), timeout=60)
    assert r.returncode == 0, r.stderr
    assert "is not a regular file" in r.stdout


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_gui_settings_refuses_a_device():
    with pytest.raises(ValueError, match="is not a regular file"):
        drivekin.RobotConfig.fromGUISettings("/dev/zero")


def test_gui_settings_refuses_a_directory(tmp_path):
    with pytest.raises(ValueError, match="is not a regular file"):
        drivekin.RobotConfig.fromGUISettings(tmp_path)


def test_gui_settings_size_bound(tmp_path):
    # 1 MiB is accepted (padding in a string value), one byte more is not; a sparse
    # multi-GB file is refused by its size, before a byte is read.
    p = tmp_path / "settings.json"
    text = _settings_text(pad="")
    p.write_text(text.replace('"pad": ""', '"pad": "' + "x" * (2**20 - len(text)) + '"'))
    assert p.stat().st_size == 2**20
    assert drivekin.RobotConfig.fromGUISettings(p).massKG == 61.0
    with open(p, "ab") as f:
        f.write(b" ")
    with pytest.raises(ValueError, match="1048577 bytes, more than the 1048576"):
        drivekin.RobotConfig.fromGUISettings(p)
    huge = tmp_path / "huge.json"
    with open(huge, "wb") as f:
        f.truncate(5 * 2**30)
    tracemalloc.start()
    try:
        with pytest.raises(ValueError, match="more than the 1048576"):
            drivekin.RobotConfig.fromGUISettings(huge)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 2**20
