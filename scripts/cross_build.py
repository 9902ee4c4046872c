"""Compile drivekin's extension modules for an interpreter that cannot run the build.

scripts/wheels.sh uses this for CPython 3.14 (x86_64 and aarch64), which this machine
runs only inside Debian root filesystems. The extension list, Cython directives and
compiler and linker flags are setup.py's own (``extensions(...)``, imported, not
copied); only the driver differs: a given C compiler, the target's Python headers and
numpy's headers from the target's numpy wheel. Cython's C output does not depend on the
interpreter that generates it (it tests PY_VERSION_HEX when compiled), so the host's
Cython writes it.

    python scripts/cross_build.py --cc aarch64-linux-gnu-gcc --machine aarch64 \\
        --python-include ROOTFS/usr/include/python3.14 \\
        --pyconfig-include ROOTFS/usr/include/aarch64-linux-gnu/python3.14 \\
        --numpy-include DIR --suffix .cpython-314-aarch64-linux-gnu.so --out DIR

writes ``DIR/drivekin/<module><suffix>`` for every extension module.
"""
from __future__ import annotations

import argparse
import importlib.util
import os
import shlex
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# What CPython's own sysconfig passes for an extension on Linux (CCSHARED, OPT without -g
# and the warnings): position-independent code, wrapping signed overflow as CPython is
# built, assertions off.
BASE_CFLAGS = ["-fPIC", "-fwrapv", "-fno-strict-overflow", "-DNDEBUG", "-pthread"]


def load_setup():
    spec = importlib.util.spec_from_file_location("drivekin_setup", ROOT / "setup.py")
    module = importlib.util.module_from_spec(spec)
    cwd = os.getcwd()
    os.chdir(ROOT)                  # setup.py's paths are relative to the checkout
    try:
        spec.loader.exec_module(module)
    finally:
        os.chdir(cwd)
    return module


def run(cmd):
    result = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"failed: {shlex.join(cmd)}\n{result.stdout}{result.stderr}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cc", required=True, help="the target's C compiler")
    parser.add_argument("--machine", required=True, help="target machine (uname -m)")
    parser.add_argument("--python-include", required=True, help="dir with Python.h")
    parser.add_argument("--pyconfig-include", required=True,
                        help="dir with the target's own pyconfig.h (Debian: multiarch)")
    parser.add_argument("--numpy-include", required=True, help="numpy/_core/include")
    parser.add_argument("--suffix", required=True, help="extension suffix, e.g. "
                        ".cpython-314-aarch64-linux-gnu.so")
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    args.out = args.out.resolve()

    setup = load_setup()
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        exts = setup.extensions(args.numpy_include, "linux", args.machine)
    finally:
        os.chdir(cwd)

    with tempfile.TemporaryDirectory() as tmp:
        # Debian's python3.14/pyconfig.h includes <MULTIARCH/python3.14/pyconfig.h>: give
        # it only that directory, not the root filesystem's /usr/include, whose C library
        # headers are newer than the cross compiler's (and would raise the manylinux tag).
        multiarch = Path(tmp, "include", f"{args.machine}-linux-gnu", "python3.14")
        multiarch.parent.mkdir(parents=True)
        multiarch.symlink_to(Path(args.pyconfig_include).resolve())

        def build(ext):
            includes = [f"-I{d}" for d in [*ext.include_dirs, args.python_include,
                                           Path(tmp, "include"), ROOT / "src"]]
            macros = [f"-D{k}" if v is None else f"-D{k}={v}" for k, v in ext.define_macros]
            objects = []
            for source in ext.sources:
                obj = str(Path(tmp, ext.name + "-" + Path(source).stem + ".o"))
                run([args.cc, *BASE_CFLAGS, *ext.extra_compile_args, *macros, *includes,
                     "-c", source, "-o", obj])
                objects.append(obj)
            target = args.out.joinpath(*ext.name.split(".")).with_name(
                ext.name.split(".")[-1] + args.suffix)
            target.parent.mkdir(parents=True, exist_ok=True)
            run([args.cc, "-shared", "-pthread", *objects, *ext.extra_link_args,
                 *[f"-l{lib}" for lib in ext.libraries], "-o", str(target)])
            return target

        with ThreadPoolExecutor(args.jobs) as pool:
            for target in pool.map(build, exts):
                print(target.relative_to(args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
