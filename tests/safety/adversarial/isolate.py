"""Run adversarial case groups in child processes, so a crash or hang fails only the
case that caused it.

Parent side: :func:`results` runs every case of a group (once per pytest session) and
returns {case id: None if it passed, else a message}. The child (this module run as
``python -m tests.safety.adversarial.isolate`` in the directory that holds ``tests/``)
reads the case indices to run from stdin and reports ``START <i>`` before case ``i`` and a
JSON result after it; when the child dies or a case exceeds ``CASE_TIMEOUT``, the open
case is recorded as crashed/hung (with the signal and the end of stderr) and a new child
runs the cases still pending.
"""
from __future__ import annotations

import gc
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import traceback
from pathlib import Path

# The directory that holds the ``tests`` package (three above tests/safety/adversarial/): the
# child runs there, so ``python -m`` finds this module and ``cases`` by their package names.
ROOT = Path(__file__).resolve().parents[3]
CASE_TIMEOUT = 20.0
_cache: dict[str, dict[str, str | None]] = {}


def results(group: str, ids: list[str]) -> dict[str, str | None]:
    if group not in _cache:
        _cache[group] = _run(group, ids)
    return _cache[group]


def _run(group, ids):
    out: dict[str, str | None] = {}
    while len(out) < len(ids):
        pending = [i for i, c in enumerate(ids) if c not in out]
        lines, err, rc = _child_run(group, pending)
        open_case = None
        for ln in lines:
            if ln.startswith("START "):
                open_case = int(ln.split()[1])
            elif ln.startswith("RESULT "):
                i, msg = json.loads(ln[7:])
                out[ids[i]] = msg
                open_case = None
        if rc == 0 and open_case is None:
            for i in pending:
                out.setdefault(ids[i], "not run: the child process skipped it")
            break
        if open_case is None:  # died between cases: blame the first one not reported
            open_case = next((i for i in pending if ids[i] not in out), None)
            if open_case is None:
                break
        how = (f"hung for more than {CASE_TIMEOUT:.0f} s" if rc == -signal.SIGKILL
               else f"crashed the interpreter (signal {signal.Signals(-rc).name})" if rc < 0
               else f"killed the interpreter (exit status {rc})")
        out[ids[open_case]] = f"{how}; stderr ends:\n{_tail(err)}"
    return out


def _child_run(group, indices):
    """Run the cases ``indices`` of ``group`` in one child; (report lines, stderr, rc).
    A case that runs longer than CASE_TIMEOUT gets the child killed. The report goes to
    its own file, so whatever a case prints cannot garble it."""
    with tempfile.NamedTemporaryFile("w+") as rep, tempfile.TemporaryFile("w+") as se:
        env = dict(os.environ, PYTHONFAULTHANDLER="1")
        proc = subprocess.Popen([sys.executable, "-m", __name__, group, rep.name],
                                stdin=subprocess.PIPE, stdout=se, stderr=se, env=env,
                                cwd=ROOT, text=True)
        proc.stdin.write(json.dumps(indices))
        proc.stdin.close()
        current, began = None, time.monotonic()
        while True:
            try:
                proc.wait(timeout=0.05)
                break
            except subprocess.TimeoutExpired:
                pass
            rep.seek(0)
            starts = [ln for ln in rep.read().splitlines() if ln.startswith("START ")]
            if starts and starts[-1] != current:
                current, began = starts[-1], time.monotonic()
            if time.monotonic() - began > CASE_TIMEOUT:
                proc.kill()
                proc.wait()
                break
        rep.seek(0)
        se.seek(0)
        return rep.read().splitlines(), se.read(), proc.returncode


def _tail(text, n=12):
    return "\n".join(text.strip().splitlines()[-n:])


def _child(group, report, indices):
    from tests.safety.adversarial import cases

    ids = list(cases.GROUPS[group]().items())
    gc.collect()
    gc.freeze()  # what exists now is never garbage: keeps the cases' full collections cheap
    for i in indices:
        report.write(f"START {i}\n")
        report.flush()
        try:
            ids[i][1]()
            msg = None
        except BaseException as e:  # any failure is the case's result
            msg = f"{type(e).__name__}: {e}"
            if not isinstance(e, AssertionError):
                msg += "\n" + "".join(traceback.format_exception(e)[-4:])
        report.write("RESULT " + json.dumps([i, msg]) + "\n")
        report.flush()


if __name__ == "__main__":
    with open(sys.argv[2], "a") as rep:
        _child(sys.argv[1], rep, json.loads(sys.stdin.read()))
