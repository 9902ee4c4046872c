"""The adversarial cases of cases.py, one pytest test each. Every group runs in a child
process (isolate.py): a crash or hang fails the case that caused it, not the run."""
from __future__ import annotations

import pytest

from tests.safety.adversarial import cases, isolate

GROUP_IDS = {g: list(make()) for g, make in cases.GROUPS.items()}


def _params():
    for g, ids in GROUP_IDS.items():
        for c in ids:
            yield pytest.param(g, c, id=f"{g}: {c}")


@pytest.mark.parametrize("group, case", list(_params()))
def test_case(group, case):
    msg = isolate.results(group, GROUP_IDS[group])[case]
    assert msg is None, msg
