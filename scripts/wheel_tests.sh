#!/usr/bin/env bash
# Install every wheel that scripts/wheels.sh wrote into wheelhouse/ into a fresh
# environment of its own interpreter, with --only-binary :all: and no compiler on PATH,
# and run the tests against the installed wheel (DRIVEKIN_TEST_INSTALLED=1: the session
# fails if drivekin would come from the source tree; the tests run from a copy of the
# checkout without src/). Two parts, each its own argument (default: both, in turn);
# .ci/run runs them side by side, each on one core:
#
#   native          robotpy sync: `pip download` exactly as `robotpy sync` runs it picks
#                   the aarch64 wheel (tests/integration/test_wheelhouse.py);
#                   cp310-cp313 x86_64, on this machine: install, import every compiled
#                   module, the WPILib reference cases (the mpmath trig accuracy check at a
#                   two-hundredth of its points: these wheels compile the same C with the
#                   same gcc and flags as the builds that run it whole);
#                   cp314 x86_64, in the Debian forky amd64 root filesystem: the whole suite.
#   emulated        cp314 aarch64, in the arm64 root filesystem under qemu-user emulating
#                   SystemCore's Cortex-A76 (scripts/_sysroot.sh says why that matters):
#                   EMULATED_TESTS below: the trig corpus hash and batch bit-identity, the
#                   reference, allocation and property suites (the robotpy-wpimath
#                   differential tests among them). The API, behaviour, integration and
#                   safety suites test Python-level behaviour the x86_64 runs already cover.
#                   DRIVEKIN_SKIP_EMULATED=1 skips it, for quick runs by hand.
#   usage: scripts/wheel_tests.sh [native] [emulated]
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

EMULATED_TESTS=(tests/reference tests/allocation tests/properties tests/behaviour/test_batch.py
                tests/behaviour/test_batch3d.py)
NATIVE_TESTS=(tests/reference)
parts=("$@")
((${#parts[@]})) || parts=(native emulated)
for part in "${parts[@]}"; do
    case $part in native|emulated) ;; *) echo "unknown part $part (native, emulated)" >&2; exit 2;; esac
done
# What the installed wheels' tests need beyond drivekin (the test extra, for the whole
# suite; the subsets need fewer: mpmath for the reference suite's accuracy checks).
SUBSET_DEPS=(pytest hypothesis mpmath)
VERSION=$(ls "$OUT"/drivekin-*.tar.gz | sed 's/.*drivekin-\(.*\)\.tar\.gz/\1/')


# The tests and everything they read, without src/ (so only an installed drivekin can
# be imported).
copy_tests() {
    rm -rf "$1" && mkdir -p "$1"
    git ls-files -z --cached --others --exclude-standard | grep -zv '^src/' \
        | tar --null -T - -cf - | tar -xf - -C "$1"
}

run_native() {
    # Every compiled module of the installed wheel imports (not only those the tests use).
    cat >"$WORK/import_all.py" <<'PY'
import importlib, pathlib, drivekin
root = pathlib.Path(drivekin.__file__).parent
names = sorted("drivekin." + ".".join(p.relative_to(root).parts).split(".cpython")[0]
               for p in root.rglob("*.so"))
assert len(names) >= 16, names
for name in names:
    importlib.import_module(name)
print(f"{len(names)} compiled modules import")
PY
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
            python '$WORK/import_all.py' &&
            DRIVEKIN_TRIG_FRACTION=200 python -m pytest -q -p no:cacheprovider ${NATIVE_TESTS[*]}")
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
}

run_emulated() {
    if [[ ${DRIVEKIN_SKIP_EMULATED:-0} == 1 ]]; then
        step "aarch64 wheel under qemu-user: skipped (DRIVEKIN_SKIP_EMULATED=1)"
        return 0
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
            ${SUBSET_DEPS[*]} robotpy-wpimath==2026.2.2 robotpy-wpiutil==2026.2.2 &&
        cd /src && python -m pytest -q -p no:cacheprovider ${EMULATED_TESTS[*]}"
}

for part in "${parts[@]}"; do "run_$part"; done
step ""
