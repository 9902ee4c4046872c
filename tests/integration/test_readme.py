"""Every Python example in the README runs as written."""
import pathlib
import re

import pytest

README = pathlib.Path(__file__).resolve().parents[2] / "README.md"  # tests/integration/ -> root
BLOCKS = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S) \
    if README.exists() else []


def test_readme_has_examples():
    if not README.exists():
        pytest.skip("README.md is not next to the tests (installed from an sdist?)")
    assert len(BLOCKS) >= 4


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_example_runs(code):
    namespace: dict = {}
    exec(compile(code, str(README), "exec"), namespace)
    if "periodic" in namespace:                      # the allocation-free loop example
        from drivekin import Rotation2d
        pose = namespace["periodic"](0.5, 0.2, 0.1, Rotation2d(0.3))
        assert type(pose).__name__ == "Pose2d"
