# Shared by asan.sh and debug_tests.sh (sourced, not run): copy a drivekin tree to a
# scratch directory and build it in place there, so the caller's own in-place build
# (its .c and .so files) is never touched or shadowed.

PYTHON=${PYTHON:-python}
. "$here/_steps.sh"

# scratch_copy SRC: sets $work to a fresh copy of SRC's sources (no VCS, no build
# products, no virtual environments), removed again when the calling script exits
# unless KEEP_SCRATCH=1 (to rerun a failing test against the same build).
scratch_copy() {
    local src
    src=$(cd "$1" && pwd)
    [ -f "$src/setup.py" ] && [ -d "$src/tests" ] || { echo "$src: not a drivekin tree" >&2; exit 2; }
    work=$(mktemp -d "${TMPDIR:-/tmp}/drivekin-scratch.XXXXXX")
    [ "${KEEP_SCRATCH:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
    tar -C "$src" --exclude=.git --exclude=build --exclude='*.so' --exclude='*.c' \
        --exclude='*venv' --exclude=__pycache__ --exclude='.*cache' --exclude=.hypothesis \
        --exclude=.benchmarks --exclude='*.egg-info' -cf - . | tar -C "$work" -xf -
    echo "scratch copy of $src: $work"
}

# scratch_build [ENV=VALUE ...]: build the extensions in place in $work with the given
# environment.
scratch_build() {
    (cd "$work" && env "$@" "$PYTHON" setup.py -q build_ext --inplace -j2 >"$work/build.log" 2>&1) \
        || { cat "$work/build.log" >&2; echo "build failed" >&2; exit 1; }
}

# check_import [ENV=VALUE ...]: the tests will import drivekin from $work/src, not from an
# installed copy (an installed drivekin must not silently take the scratch build's place).
check_import() {
    local where
    where=$(cd "$work" && env "$@" "$PYTHON" -c 'import drivekin.geometry as g; print(g.__file__)')
    case $where in "$work/src/"*) ;; *) echo "drivekin imported from $where, not $work/src" >&2; exit 1;; esac
}
