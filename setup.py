"""Extension list and Cython directives; all static metadata lives in pyproject.toml.

Environment switches:
  DRIVEKIN_CYTHON_DEBUG=1  turn bounds/wraparound checks back on (debug CI job)
  DRIVEKIN_CYTHON_TRACE=1  add line tracing and the annotated HTML
"""
import os

import numpy
from Cython.Build import cythonize
from setuptools import Extension, setup

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
}
macros = [("NPY_NO_DEPRECATED_API", "NPY_1_7_API_VERSION")]
if trace:
    directives["linetrace"] = True
    macros.append(("CYTHON_TRACE_NOGIL", "1"))

# -fno-math-errno lets gcc inline sqrt; no -ffast-math, because NaN/inf must propagate
# exactly as in WPILib.
compile_args = ["-O3", "-fno-math-errno"] if os.name != "nt" else []

modules = ["geometry", "kinematics", "_wheels", "differential", "mecanum", "deadwheel",
           "diffswerve", "odometry", "estimator", "batch", "_alloccount"]
extensions = [
    Extension(
        f"drivekin.{name}",
        [f"src/drivekin/{name}.pyx"],
        include_dirs=[numpy.get_include()],
        define_macros=macros,
        extra_compile_args=compile_args,
    )
    for name in modules
]

setup(
    ext_modules=cythonize(
        extensions,
        compiler_directives=directives,
        include_path=["src"],
        annotate=trace,
    )
)
