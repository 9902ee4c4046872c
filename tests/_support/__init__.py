"""Helpers shared by several test modules (not tests: pytest collects nothing here).

* ``strategies``: hypothesis strategies, tolerances and reference models;
* ``alloc``: the allocation harness;
* ``wpilib_port``: kEpsilon, JUnit-style ``assert_close``, WPILib's (±12, ±12) test robot,
  and the accuracy tests' trajectory generator and ``java.util.Random``;
* ``wpilog_logs``: .wpilog files written by robotpy-wpiutil (needs it installed).

Import them as ``from tests._support import strategies as S`` or
``from tests._support.wpilib_port import assert_close``.
"""
