"""drivekin's test suite. A package, so that test modules import the shared helpers as
``tests._support`` (and each other by full name) without anything editing ``sys.path``:
pytest's default ``prepend`` import mode puts the directory above ``tests/`` (the
repository root) on ``sys.path``. The layout is described in ``tests/README.md``."""
