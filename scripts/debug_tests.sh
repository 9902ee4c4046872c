#!/usr/bin/env bash
# Build drivekin with Cython's bounds, wraparound and initialized checks on
# (DRIVEKIN_CYTHON_DEBUG=1, see setup.py) in a scratch copy of SRC_DIR (default: this
# repository) and run its whole test suite. Extra arguments go to pytest.
#   usage: scripts/debug_tests.sh [SRC_DIR [PYTEST_ARGS...]]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/_scratch.sh"
scratch_copy "${1:-$here/..}"
shift || true

scratch_build DRIVEKIN_CYTHON_DEBUG=1
run_env=(PYTHONPATH="$work/src${PYTHONPATH:+:$PYTHONPATH}")
check_import "${run_env[@]}"

t0=$SECONDS
status=0
(cd "$work" && env "${run_env[@]}" "$PYTHON" -m pytest -p no:cacheprovider "$@") || status=$?
echo "tests on the debug build: $((SECONDS - t0)) s, pytest exit status $status"
exit "$status"
