#!/usr/bin/env bash
# Build drivekin with DRIVEKIN_SIMD=1 (drivekin.batch on glibc's libmvec, see setup.py) in a
# scratch copy of SRC_DIR (default: this repository) and run the batch tests against it:
# tests/behaviour/test_batch_simd.py (every SIMD-affected batch function against the
# per-call API, within the documented bound) and the parts of tests/behaviour/test_batch.py
# that do not compare transcendental results bit for bit (argument rules, out=, refusals).
# Extra arguments go to pytest.
#   usage: scripts/simd_tests.sh [SRC_DIR [PYTEST_ARGS...]]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/_scratch.sh"
scratch_copy "${1:-$here/..}"
shift || true

scratch_build DRIVEKIN_SIMD=1
so=$(ls "$work"/src/drivekin/batch.*.so)
# A build that ignored the switch would prove nothing.
nm -D "$so" | grep -q _ZGVdN4vv_atan2 || { echo "$so does not call libmvec" >&2; exit 1; }
run_env=(PYTHONPATH="$work/src${PYTHONPATH:+:$PYTHONPATH}")
check_import "${run_env[@]}"
(cd "$work" && env "${run_env[@]}" "$PYTHON" -c 'import drivekin.batch as b; assert b.SIMD') \
    || { echo "drivekin.batch.SIMD is false in the SIMD build" >&2; exit 1; }

t0=$SECONDS
status=0
(cd "$work" && env "${run_env[@]}" "$PYTHON" -m pytest -p no:cacheprovider \
    tests/behaviour/test_batch_simd.py tests/behaviour/test_batch.py -k "simd or bad_arguments or out_is or refusals or empty or wheel_inverse or desaturation" \
    "$@") || status=$?
echo "batch tests on the SIMD build: $((SECONDS - t0)) s, pytest exit status $status"
exit "$status"
