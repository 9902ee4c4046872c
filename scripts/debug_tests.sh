#!/usr/bin/env bash
# Build drivekin with Cython's bounds, wraparound and initialized checks on
# (DRIVEKIN_CYTHON_DEBUG=1, see setup.py) in a scratch copy of SRC_DIR (default: this
# repository) and run the memory-safety selection of its tests (tests/README.md; pytest's
# --memory-safety). Extra arguments go to pytest instead
# (`scripts/debug_tests.sh . tests` for the whole suite).
#   usage: scripts/debug_tests.sh [SRC_DIR [PYTEST_ARGS...]]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/_scratch.sh"
scratch_copy "${1:-$here/..}"
shift || true

args=("$@")
((${#args[@]})) || args=(--memory-safety)

step "Cython debug build"
scratch_build DRIVEKIN_CYTHON_DEBUG=1
run_env=(PYTHONPATH="$work/src${PYTHONPATH:+:$PYTHONPATH}")
check_import "${run_env[@]}"

step "tests on the Cython debug build (${args[*]})"
status=0
(cd "$work" && env "${run_env[@]}" "$PYTHON" -m pytest -p no:cacheprovider "${args[@]}") || status=$?
step ""
echo "tests on the debug build: pytest exit status $status"
exit "$status"
