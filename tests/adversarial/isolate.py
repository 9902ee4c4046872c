"""Run adversarial case groups in child processes, so a crash or hang fails only the
case that caused it.

Parent side: :func:`results` runs every case of a group (once per pytest session) and
returns {case id: None if it passed, else a message}. The child (this file run as a
script) prints ``START <i>`` before case ``i`` and a JSON result after it; when the child
dies or a case exceeds ``CASE_TIMEOUT``, the open case is recorded as crashed/hung (with
the signal and the end of stderr) and a new child resumes after it.
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
CASE_TIMEOUT = 20.0
_cache: dict[str, dict[str, str | None]] = {}


def results(group: str, ids: list[str]) -> dict[str, str | None]:
    if group not in _cache:
        _cache[group] = _run(group, ids)
    return _cache[group]


def _run(group, ids):
    out: dict[str, str | None] = {}
    start = 0
    while start < len(ids):
        with tempfile.TemporaryFile("w+") as so, tempfile.TemporaryFile("w+") as se:
            env = dict(os.environ, PYTHONFAULTHANDLER="1")
            proc = subprocess.Popen([sys.executable, __file__, group, str(start)],
                                    stdout=so, stderr=se, env=env, cwd=HERE)
            current, began = None, time.monotonic()
            while True:
                try:
                    proc.wait(timeout=0.05)
                    break
                except subprocess.TimeoutExpired:
                    pass
                so.seek(0)
                lines = so.read().splitlines()
                starts = [ln for ln in lines if ln.startswith("START ")]
                if starts and starts[-1] != current:
                    current, began = starts[-1], time.monotonic()
                if time.monotonic() - began > CASE_TIMEOUT:
                    proc.kill()
                    proc.wait()
                    break
            so.seek(0)
            se.seek(0)
            lines, err = so.read().splitlines(), se.read()
        last = None
        for ln in lines:
            if ln.startswith("START "):
                last = int(ln.split()[1])
            elif ln.startswith("RESULT "):
                i, msg = json.loads(ln[7:])
                out[ids[i]] = msg
                last = None
        if proc.returncode == 0 and last is None:
            break
        if last is None:  # died before/after a case: blame the next unfinished one
            done = [i for i, c in enumerate(ids) if c in out]
            last = (max(done) + 1) if done else start
            if last >= len(ids):
                break
        rc = proc.returncode
        how = (f"hung for more than {CASE_TIMEOUT:.0f} s" if rc == -signal.SIGKILL
               else f"crashed the interpreter (signal {signal.Signals(-rc).name})" if rc < 0
               else f"killed the interpreter (exit status {rc})")
        out[ids[last]] = f"{how}; stderr ends:\n{_tail(err)}"
        start = last + 1
    for c in ids:
        out.setdefault(c, "not run: the child process stopped before reaching it")
    return out


def _tail(text, n=12):
    return "\n".join(text.strip().splitlines()[-n:])


def _child(group, start):
    sys.path.insert(0, HERE)
    sys.path.insert(0, os.path.dirname(HERE))
    import cases

    ids = list(cases.GROUPS[group]().items())
    for i in range(start, len(ids)):
        print(f"START {i}", flush=True)
        try:
            ids[i][1]()
            msg = None
        except BaseException as e:  # any failure is the case's result
            msg = f"{type(e).__name__}: {e}"
            if not isinstance(e, AssertionError):
                msg += "\n" + "".join(traceback.format_exception(e)[-4:])
        print("RESULT " + json.dumps([i, msg]), flush=True)


if __name__ == "__main__":
    _child(sys.argv[1], int(sys.argv[2]))
