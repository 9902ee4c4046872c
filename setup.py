"""Extension list and Cython directives; all static metadata lives in pyproject.toml.

Environment switches:
  DRIVEKIN_CYTHON_DEBUG=1  turn bounds/wraparound checks back on (debug CI job)
  DRIVEKIN_CYTHON_TRACE=1  add line tracing and the annotated HTML
"""
import os
import platform
import sys

import numpy
from Cython.Build import cythonize
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

debug = os.environ.get("DRIVEKIN_CYTHON_DEBUG") == "1"
trace = os.environ.get("DRIVEKIN_CYTHON_TRACE") == "1"

directives = {
    "language_level": 3,
    "boundscheck": debug,
    "wraparound": debug,
    "initializedcheck": debug,
    "nonecheck": False,
    "cdivision": True,
    "embedsignature": True,
    # Every value class defines __reduce__; the rest (kinematics caches, odometry) are
    # not meant to be pickled, so Cython need not generate pickling helpers.
    "auto_pickle": False,
    # Plain method descriptors instead of cyfunctions: CPython calls them through its
    # specialised fast path, about 85 instructions (~5 ns) less per call (benchmarks/).
    "binding": False,
    # Annotations are documentation only: a public parameter of a drivekin class is
    # annotated (``pose: Pose2d``) for the embedded signature and checked by drivekin
    # itself (_core/args.pxd, check_type), whose TypeError says how to convert a robotpy
    # object; typing it would bring back Cython's own test and message.
    "annotation_typing": False,
}
macros = [("NPY_NO_DEPRECATED_API", "NPY_1_7_API_VERSION")]
if trace:
    directives["linetrace"] = True
    macros.append(("CYTHON_TRACE_NOGIL", "1"))

# -fno-math-errno lets gcc inline sqrt. -fno-trapping-math lets it turn a selection after a
# comparison (Rotation2d's "shorter than 1e-6 gives the identity") into a blend, so loops
# over rotations vectorise; Python runs with floating-point traps off, and every value is
# computed as before. No -ffast-math, because NaN/inf must propagate exactly as in WPILib.
# -ffp-contract=off: where the target has fused multiply-add (aarch64, and x86_64 with
# -mfma), gcc and clang would otherwise fuse a*b + c in some loops and not in others, so
# the batch module would no longer give the per-call kernels' bits (seen on aarch64: one
# ulp in test_batch's bit-identity tests), nor would aarch64 give x86_64's; drivekin's own
# sin, cos and atan2 (_core/dkmath.h) rely on it for the same bits on every platform.
compile_args = (["-O3", "-fno-math-errno", "-fno-trapping-math", "-ffp-contract=off"]
                if os.name != "nt" else [])

modules = ["geometry", "geometry3d", "chassis", "swervemodule", "swerve", "_core.wheels", "_core.drivetrain",
           "differential", "mecanum", "deadwheel", "diffswerve", "odometry", "estimator", "odometry3d",
           "estimator3d", "_core.stacks", "_core.batch3d", "batch",
           "_core.alloccount", "_core.wpilog", "motor", "robotconfig", "_core.setpointkernel",
           "setpoint", "_core.choreokernel"]


def link_args(system=sys.platform, machine=platform.machine()):
    """Linker arguments for a target. Linux aarch64: LOAD segments aligned to 16 KiB, the
    page size of SystemCore's kernel (and of other 16 KiB-page arm64 kernels), which
    cannot map a library aligned to 4 KiB; GNU ld's aarch64 default is 64 KiB, but
    other linkers (lld: 4 KiB) differ, so it is said explicitly."""
    if system.startswith("linux") and machine in ("aarch64", "arm64"):
        return ["-Wl,-z,max-page-size=16384"]
    return []


def extensions(numpy_include=None, system=sys.platform, machine=platform.machine()):
    """The extension modules, cythonized; numpy_include, system and machine name the
    target (scripts/cross_build.py builds the same list for another interpreter)."""
    return cythonize(
        [
            Extension(
                f"drivekin.{name}",
                [f"src/drivekin/{name.replace('.', '/')}.pyx"],
                **{
                    # src/drivekin for "_core/*.h", which modules in _core include too.
                    "include_dirs": [numpy_include or numpy.get_include(), "src/drivekin"],
                    "define_macros": macros,
                    "extra_compile_args": compile_args,
                    "extra_link_args": link_args(system, machine),
                },
            )
            for name in modules
        ],
        compiler_directives=directives,
        include_path=["src"],
        annotate=trace,
        # Cython translates the modules in parallel too, as build_ext compiles them (below).
        nthreads=os.cpu_count() or 1,
    )


# setuptools runs this file as __main__ (pip, build, cibuildwheel, setup.py commands);
# scripts/cross_build.py imports it for the extension list.
if __name__ == "__main__":
    class BuildExt(build_ext):
        """Cythonizes when the extensions are built, not whenever setup.py runs: writing
        the sdist or the metadata (pip asks for it before every build) needs only the
        module names, and translating every module took a minute there."""

        def finalize_options(self):
            self.distribution.ext_modules = extensions()
            super().finalize_options()

    setup(ext_modules=[Extension(f"drivekin.{name}", []) for name in modules],
          cmdclass={"build_ext": BuildExt},
          # Compile the modules in parallel (pip and cibuildwheel pass no -j).
          options={"build_ext": {"parallel": os.cpu_count() or 1}})
