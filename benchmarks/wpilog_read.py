"""Reading a .wpilog file: a Python loop over robotpy-wpiutil's DataLogReader against
drivekin.datalog's native reader (issue 17, item 4).

The log is a 10-minute match of a 4-module swerve robot logged the AdvantageKit way,
written with robotpy-wpiutil's DataLogWriter, records interleaved in time order:

* 250 Hz: ``/Drive/ModulePositions`` (struct:SwerveModulePosition[4]), the gyro's yaw
  (struct:Rotation2d) and yaw rate (double), and per module the drive and turn positions
  (8 doubles);
* 50 Hz: the odometry pose (struct:Pose2d) and the measured module states
  (struct:SwerveModuleState[4]).

That is about 1.7 M records in about 36 MB. In one run it times

(a) a Python loop over ``wpiutil.log.DataLogReader`` that keeps each record's timestamp
    and bytes per entry (what drivekin 0.2.0's reader did, and what a script would do);
(b) ``drivekin.datalog.read(path)`` plus ``.values()`` of every numeric entry (all of
    them here), keeping every array;

as the minimum over ``--repeats`` runs, and measures (b)'s peak memory growth two ways,
each in a fresh subprocess: tracemalloc's peak (Python and numpy allocations; the
read-only memory map of the file is not an allocation) and the growth of the peak
resident memory (VmHWM on Linux, else ru_maxrss), which also counts the file's mapped
pages as they are read.

    python benchmarks/wpilog_read.py              # about a minute
    python benchmarks/wpilog_read.py --quick      # CI smoke run: a 20-second log
"""
from __future__ import annotations

import argparse
import gc
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

MODULES = 4


def write_log(path: str, seconds: float) -> None:
    import wpiutil
    from wpimath.geometry import Pose2d, Rotation2d
    from wpimath.kinematics import SwerveModulePosition, SwerveModuleState
    import wpiutil.wpistruct as ws

    n = int(seconds * 250)
    t = 1_000_000 + 4000 * np.arange(n, dtype=np.int64)
    rng = np.random.default_rng(17)
    dist = np.cumsum(rng.uniform(0, 0.02, (n, MODULES)), axis=0)
    angle = np.cumsum(rng.normal(0, 0.01, (n, MODULES)), axis=0)
    yaw = np.cumsum(rng.normal(0, 0.002, n))
    mods = np.stack([dist, angle], axis=-1).astype("<f8")              # (n, 4, 2)
    log = wpiutil.DataLogWriter(path, '{"producer":"drivekin benchmark"}')
    log.addStructSchema(SwerveModulePosition, 1)
    log.addStructSchema(SwerveModuleState, 1)
    log.addStructSchema(Pose2d, 1)
    e_mods = log.start("/Drive/ModulePositions", "struct:SwerveModulePosition[]", "", 1)
    e_yaw = log.start("/Drive/Gyro/YawPosition", "struct:Rotation2d", "", 1)
    e_rate = log.start("/Drive/Gyro/YawVelocityRadPerSec", "double", "", 1)
    e_mod = [log.start(f"/Drive/Module{j}/{what}", "double", "", 1)
             for j in range(MODULES) for what in ("DrivePositionRad", "TurnPositionRad")]
    e_pose = log.start("/RealOutputs/Odometry/Robot", "struct:Pose2d", "", 1)
    e_states = log.start("/RealOutputs/SwerveStates/Measured", "struct:SwerveModuleState[]",
                         "", 1)
    mods_b = mods.tobytes()
    yaw_b = yaw.astype("<f8").tobytes()
    rate_b = np.gradient(yaw).astype("<f8").tobytes()
    per_mod = mods.reshape(n, 2 * MODULES).astype("<f8").tobytes()
    pose_b = np.column_stack([dist[:, 0], dist[:, 1], yaw]).astype("<f8").tobytes()
    raw = log.appendRaw
    for i in range(n):
        ts = int(t[i])
        raw(e_mods, mods_b[64 * i:64 * i + 64], ts)
        raw(e_yaw, yaw_b[8 * i:8 * i + 8], ts)
        raw(e_rate, rate_b[8 * i:8 * i + 8], ts)
        for k in range(2 * MODULES):
            o = 64 * i + 8 * k
            raw(e_mod[k], per_mod[o:o + 8], ts)
        if i % 5 == 0:
            raw(e_pose, pose_b[24 * i:24 * i + 24], ts)
            raw(e_states, mods_b[64 * i:64 * i + 64], ts)
        if i % 500 == 0:
            log.flush()                     # robotpy's writer blocks past ~1 MiB unflushed
    log.flush()
    log.stop()


def robotpy_loop(path: str) -> int:
    """(a): every data record's timestamp and bytes, per entry, through robotpy."""
    import wpiutil.log as wlog
    names: dict[int, str] = {}
    out: dict[str, tuple[list[int], list[bytes]]] = {}
    for rec in wlog.DataLogReader(path):
        entry = rec.getEntry()
        if entry == 0:
            if rec.isStart():
                s = rec.getStartData()
                names[s.entry] = s.name
                out.setdefault(s.name, ([], []))
            continue
        ts, data = out[names[entry]]
        ts.append(rec.getTimestamp())
        data.append(rec.getRaw())
    return sum(len(v[0]) for v in out.values())


def drivekin_read(path: str) -> tuple[int, list]:
    """(b): read, then the values of every numeric entry (kept)."""
    from drivekin import datalog
    log = datalog.read(path)
    kept = []
    for name, info in log.entries.items():
        if info.type.startswith("struct:") or info.type in ("double", "int64", "boolean"):
            kept.append(log.values(name))
    return sum(len(t) for t, _ in kept), kept


_MEMORY = """
import gc, json, resource, sys, tracemalloc
sys.path.insert(0, {bench!r})
import numpy, drivekin.datalog
from wpilog_read import drivekin_read
how = {how!r}
if how == "tracemalloc":
    drivekin_read({path!r})        # warm: first-use caches (not for ru_maxrss: a peak)
    gc.collect()
    tracemalloc.start()
    result = drivekin_read({path!r})
    print(json.dumps(tracemalloc.get_traced_memory()[1]))
else:
    def peak():
        # VmHWM: this process's peak RSS (ru_maxrss keeps the parent's across exec).
        try:
            with open("/proc/self/status") as f:
                return next(int(ln.split()[1]) for ln in f if ln.startswith("VmHWM:"))
        except OSError:
            return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    before = peak()
    result = drivekin_read({path!r})
    print(json.dumps((peak() - before) * 1024))
"""


def memory(path: str, how: str) -> int:
    code = _MEMORY.format(bench=os.path.dirname(os.path.abspath(__file__)), path=path, how=how)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return int(json.loads(r.stdout.strip().splitlines()[-1]))


def best(fn, path: str, repeats: int) -> tuple[float, object]:
    times, result = [], None
    for _ in range(repeats):
        gc.collect()
        t = time.perf_counter()
        result = fn(path)
        times.append(time.perf_counter() - t)
        del result
        result = None
    return min(times), result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=600.0, help="match length (600)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="a 20-second log, one repeat")
    args = ap.parse_args()
    if args.quick:
        args.seconds, args.repeats = 20.0, 1
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "match.wpilog")
        t = time.perf_counter()
        write_log(path, args.seconds)
        size = os.path.getsize(path)
        n_a = robotpy_loop(path)
        from drivekin import datalog
        assert n_a == sum(i.records for i in datalog.read(path).entries.values())
        n_b = drivekin_read(path)[0]
        print(f"log: {args.seconds:.0f} s, {n_a:,} data records ({n_b:,} numeric), "
              f"{size / 1e6:.1f} MB "
              f"(written in {time.perf_counter() - t:.1f} s)")
        ta, _ = best(robotpy_loop, path, args.repeats)
        tb, _ = best(drivekin_read, path, args.repeats)
        print(f"(a) robotpy DataLogReader loop, bytes + timestamps kept: {ta * 1e3:9.1f} ms")
        print(f"(b) drivekin read + values() of every numeric entry:      {tb * 1e3:9.1f} ms")
        print(f"    (a) / (b) = {ta / tb:.1f}x  (target >= 10x)")
        traced = memory(path, "tracemalloc")
        rss = memory(path, "maxrss")
        print(f"(b) peak memory growth: tracemalloc {traced / 1e6:.1f} MB = "
              f"{traced / size:.2f}x the file; peak RSS {rss / 1e6:.1f} MB = "
              f"{rss / size:.2f}x the file, mapped pages included (target <= 2x)")


if __name__ == "__main__":
    main()
