#!/usr/bin/env bash
# Install every wheel that scripts/wheels.sh wrote into wheelhouse/ into a fresh
# environment of its own interpreter, with --only-binary :all: and no compiler on PATH,
# and run the tests against the installed wheel (DRIVEKIN_TEST_INSTALLED=1: the session
# fails if drivekin would come from the source tree; the tests run from a copy of the
# checkout without src/):
#
#   robotpy sync    `pip download` exactly as `robotpy sync` runs it picks the aarch64 wheel
#                   (tests/integration/test_wheelhouse.py)
#   cp310-cp313     x86_64, on this machine: the WPILib reference cases and the
#                   allocation tests
#   cp314 x86_64    in the Debian forky amd64 root filesystem: the whole suite
#   cp314 aarch64   in the arm64 root filesystem under qemu-user, emulating SystemCore's
#                   Cortex-A76 (scripts/_sysroot.sh says why that matters): EMULATED_TESTS
#                   below, everything but the API, integration and safety suites, which
#                   test Python-level behaviour the x86_64 runs already cover (about 10
#                   minutes with the installs; the whole suite took 14 minutes there).
#                   DRIVEKIN_SKIP_EMULATED=1 skips it, for quick runs by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
OUT=$ROOT/wheelhouse
WORK=$(mktemp -d)
. scripts/_sysroot.sh
rootfs_x86_64= rootfs_aarch64=
cleanup() {
    for r in "$rootfs_x86_64" "$rootfs_aarch64"; do [[ -n $r ]] && release_sysroot "$r"; done
    rm -rf "$WORK"
}
trap cleanup EXIT

EMULATED_TESTS=(tests/reference tests/allocation tests/behaviour tests/properties
                tests/integration/test_wpilog_reader.py tests/safety/test_wpilog_hostile.py)
NATIVE_TESTS=(tests/reference tests/allocation)
# What the installed wheels' tests need beyond drivekin (the test extra, for the whole
# suite; the subsets need fewer).
SUBSET_DEPS=(pytest hypothesis)
VERSION=$(ls "$OUT"/drivekin-*.tar.gz | sed 's/.*drivekin-\(.*\)\.tar\.gz/\1/')


# The tests and everything they read, without src/ (so only an installed drivekin can
# be imported).
copy_tests() {
    rm -rf "$1" && mkdir -p "$1"
    git ls-files -z --cached --others --exclude-standard | grep -zv '^src/' \
        | tar --null -T - -cf - | tar -xf - -C "$1"
}

step "robotpy sync resolves the aarch64 wheel"
DRIVEKIN_WHEELHOUSE="$OUT" python -m pytest -q -p no:cacheprovider \
    tests/integration/test_wheelhouse.py

copy_tests "$WORK/tree"
for py in $(native_pythons); do
    tag=$("$py" -c 'import sys; print(f"cp{sys.version_info[0]}{sys.version_info[1]}")')
    step "$tag x86_64 wheel: ${NATIVE_TESTS[*]}"
    "$py" -m venv "$WORK/venv-$tag"
    # No compiler: PATH holds only the venv, and pip may not build anything.
    (cd "$WORK/tree" && env -i HOME="$HOME" PATH="$WORK/venv-$tag/bin" CC=false \
        DRIVEKIN_TEST_INSTALLED=1 /bin/sh -c "
        python -m pip install -q --only-binary :all: --find-links '$OUT' \
            'drivekin==$VERSION' ${SUBSET_DEPS[*]} &&
        python -m pytest -q -p no:cacheprovider ${NATIVE_TESTS[*]}")
done

step "CPython 3.14 x86_64 root filesystem"
rootfs_x86_64=$(ensure_sysroot x86_64)
step "cp314 x86_64 wheel: the whole suite"
copy_tests "$rootfs_x86_64/src"
rm -rf "$rootfs_x86_64/venv" "$rootfs_x86_64/wheelhouse"
cp -r "$OUT" "$rootfs_x86_64/wheelhouse"
IN_SYSROOT_ENV="DRIVEKIN_TEST_INSTALLED=1" in_sysroot "$rootfs_x86_64" sh -c "
    python3.14 -m venv /venv && . /venv/bin/activate &&
    pip install -q --only-binary :all: --find-links /wheelhouse 'drivekin[test]==$VERSION' &&
    cd /src && python -m pytest -q -p no:cacheprovider"

if [[ ${DRIVEKIN_SKIP_EMULATED:-0} == 1 ]]; then
    step "aarch64 wheel under qemu-user: skipped (DRIVEKIN_SKIP_EMULATED=1)"
    step ""
    exit 0
fi
step "CPython 3.14 aarch64 root filesystem"
rootfs_aarch64=$(ensure_sysroot aarch64)
step "cp314 aarch64 wheel under qemu-user: ${EMULATED_TESTS[*]}"
copy_tests "$rootfs_aarch64/src"
rm -rf "$rootfs_aarch64/venv" "$rootfs_aarch64/wheelhouse"
cp -r "$OUT" "$rootfs_aarch64/wheelhouse"
# DRIVEKIN_EMULATED=1: wall-clock budgets meant for real hardware are not checked.
IN_SYSROOT_ENV="DRIVEKIN_TEST_INSTALLED=1 DRIVEKIN_EMULATED=1" \
    in_sysroot "$rootfs_aarch64" sh -c "
    uname -m && python3.14 -m venv /venv && . /venv/bin/activate &&
    pip install -q --only-binary :all: --find-links /wheelhouse 'drivekin==$VERSION' \
        ${SUBSET_DEPS[*]} robotpy-wpimath==2026.2.2 robotpy-wpiutil==2026.2.2 mpmath &&
    cd /src && python -m pytest -q -p no:cacheprovider ${EMULATED_TESTS[*]}"
step ""
