#!/usr/bin/env bash
# Line coverage of the compiled modules under the whole test suite and under the
# memory-safety selection (pytest --memory-safety, tests/README.md), which must be within
# one percentage point of each other. Builds SRC_DIR (default: this repository) with line
# tracing (DRIVEKIN_CYTHON_TRACE=1) in a scratch copy, runs each test folder under
# coverage.py with Cython's plugin into its own data file, and lets
# scripts/selection_coverage.py compare the union of every folder with the union of the
# selection's. Needs coverage>=7.10 besides the build requirements and the test extra;
# about 15 minutes on 2 cores (tracing makes the suite several times slower, and tests
# that count allocations or time themselves fail under it: only the lines they reach
# matter here). Two cuts keep it that short without changing a line reached: the mpmath
# accuracy checks take a two-hundredth of their points (the trig itself is C, which the
# plugin does not trace), and calibrate's interval-coverage tests, which repeat
# test_recovers_the_true_parameters' fits forty times a case and alone take over 15
# minutes under tracing, are left out.
#   usage: scripts/selection_coverage.sh [SRC_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/_scratch.sh"
scratch_copy "${1:-$here/..}"

step "line-tracing build"
scratch_build DRIVEKIN_CYTHON_TRACE=1
run_env=(PYTHONPATH="$work/src${PYTHONPATH:+:$PYTHONPATH}")
check_import "${run_env[@]}"
cat >"$work/coverage.ini" <<EOF
[run]
plugins = Cython.Coverage
source = $work/src/drivekin
patch = subprocess
parallel = true
EOF
mkdir "$work/coverage"
for folder in "$work"/tests/*/; do
    folder=$(basename "$folder")
    [[ $folder == _* || $folder == data ]] && continue
    step "tests/$folder under coverage"
    (cd "$work" && env "${run_env[@]}" COVERAGE_RCFILE="$work/coverage.ini" \
        COVERAGE_FILE="$work/coverage/$folder" DRIVEKIN_TRIG_FRACTION=200 "$PYTHON" -m coverage \
        run -m pytest -q -p no:cacheprovider -k "not intervals_cover" "tests/$folder" \
        >"$work/coverage/$folder.log" 2>&1) \
        || echo "(some tests of tests/$folder fail under tracing; their lines still count)"
done
step ""
(cd "$work" && "$PYTHON" "$here/selection_coverage.py" "$work")
