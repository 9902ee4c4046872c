"""A LogData reads once: its entry table is built once and each entry's values decoded
once, however often replay and the layouts ask; what it returns is read-only, so no
caller can change what the next one gets."""
from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("wpiutil")

from drivekin import datalog, replay                          # noqa: E402
from tests._support import wpilog_logs as W                    # noqa: E402


@pytest.fixture(scope="module")
def match_log(tmp_path_factory):
    path = tmp_path_factory.mktemp("once") / "match.wpilog"
    W.write_match_log(path, W.simulate_match(6.0))
    return path


def test_a_replay_builds_the_entry_table_once_and_decodes_each_entry_once(match_log):
    log = datalog.read(match_log)
    result = replay.replayLog(log, replay.ReplayConfig(modules=list(W.MODULES)))
    assert result.entries["positions"] == "/Drive/ModulePositions"
    assert log._stats["entry_table"] == 1
    decodes = {k: n for k, n in log._stats.items() if k != "entry_table"}
    assert ("values", "/Drive/ModulePositions") in decodes
    assert all(n == 1 for n in decodes.values()), decodes
    # A second replay of the same LogData reads nothing again.
    before = dict(log._stats)
    replay.replayLog(log, replay.ReplayConfig(modules=list(W.MODULES)))
    assert dict(log._stats) == before


def test_returned_arrays_are_read_only_and_shared(match_log):
    log = datalog.read(match_log)
    t, v = log.values("/Drive/ModulePositions")
    for a in (t, v):
        with pytest.raises(ValueError, match="read-only"):
            a[0] = 0
    t2, v2 = log.values("/Drive/ModulePositions")
    assert t2 is t and v2 is v
    # ragged= changes the result, so it is part of the key
    assert log.values("/Drive/ModulePositions", ragged="drop")[1] is not v
    assert np.array_equal(log.values("/Drive/ModulePositions", ragged="drop")[1], v)
    # entries is a new dict each time, over one table
    e1, e2 = log.entries, log.entries
    assert e1 == e2 and e1 is not e2
    e1.clear()
    assert log.entries == e2 and log._stats["entry_table"] == 1


def test_a_failed_decode_is_kept_and_raised_again(match_log):
    log = datalog.read(match_log)
    name = next(n for n, e in log.entries.items() if e.type == "structschema")
    for _ in range(3):
        with pytest.raises(datalog.DataLogError, match="is not numeric"):
            log.values(name)
    assert log._stats["values", name] == 1
