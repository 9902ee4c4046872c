#!/usr/bin/env bash
# Build drivekin with AddressSanitizer (gcc) in a scratch copy of SRC_DIR (default: this
# repository) and run the memory-safety selection of its tests (tests/README.md; pytest's
# --memory-safety) under ASan. Extra arguments go to pytest instead
# (`scripts/asan.sh . tests` for the whole suite).
# Exit status is non-zero on any test failure and on any ASan report, including reports
# from subprocesses the tests start (they inherit the environment below).
#   usage: scripts/asan.sh [SRC_DIR [PYTEST_ARGS...]]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/_scratch.sh"
scratch_copy "${1:-$here/..}"
shift || true

args=("$@")
((${#args[@]})) || args=(--memory-safety)

step "AddressSanitizer build"
flags="-fsanitize=address -fno-omit-frame-pointer -g"   # frame pointers: usable stacks
scratch_build CFLAGS="$flags" LDFLAGS="-fsanitize=address"
for so in "$work"/src/drivekin/*.so "$work"/src/drivekin/_core/*.so; do  # a build that ignored CFLAGS would prove nothing
    nm -D "$so" | grep __asan_init >/dev/null || { echo "$so is not instrumented" >&2; exit 1; }
done

runtime=$(gcc -print-file-name=libasan.so)
[ -f "$runtime" ] || { echo "gcc has no ASan runtime (libasan.so)" >&2; exit 1; }
cxxruntime=$(gcc -print-file-name=libstdc++.so.6)
[ -f "$cxxruntime" ] || { echo "gcc has no libstdc++.so.6" >&2; exit 1; }
mkdir "$work/asan-reports"
# PYTHONMALLOC=malloc: every Python object gets its own malloc block, so ASan sees
#   overflows and use-after-free of objects (pymalloc would hide them inside its arenas).
# LD_PRELOAD: python itself is not instrumented; the ASan runtime must be loaded first
#   to intercept malloc/free from the start. libstdc++ is preloaded after it so that
#   ASan's __cxa_throw interceptor finds the real function: otherwise the first C++
#   exception thrown inside robotpy-wpimath (e.g. the IndexError that ends iterating a
#   wpimath Translation2d) aborts with "CHECK failed: ... real___cxa_throw".
# ASAN_OPTIONS:
#   detect_leaks=0            CPython does not free everything at exit, so LeakSanitizer
#                             would fail every process; scripts/leakcheck.py covers leaks.
#   abort_on_error=1          end a reporting process with SIGABRT, not exit(1), so a report in
#                             a subprocess cannot pass for an ordinary error exit (ASan
#                             stops at the first report either way).
#   allocator_may_return_null=1  huge requests return NULL and Python raises MemoryError as
#                             it does without ASan, instead of an allocation-size report.
#   log_path                  every process writes its report to a file here, so a report
#                             in a subprocess fails the run even if its test ignored it.
# DRIVEKIN_ASAN=1: a test that cannot run under ASan may skip itself on it, saying why
#   (none needs to today).
run_env=(
    PYTHONPATH="$work/src${PYTHONPATH:+:$PYTHONPATH}"
    PYTHONMALLOC=malloc
    LD_PRELOAD="$runtime $cxxruntime"
    ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:allocator_may_return_null=1:log_path=$work/asan-reports/asan"
    DRIVEKIN_ASAN=1
)
check_import "${run_env[@]}"

step "tests under AddressSanitizer (${args[*]})"
status=0
(cd "$work" && env "${run_env[@]}" "$PYTHON" -m pytest -p no:cacheprovider "${args[@]}") || status=$?
step ""
echo "tests under ASan: pytest exit status $status"

if compgen -G "$work/asan-reports/*" >/dev/null; then
    for f in "$work"/asan-reports/*; do echo "=== $f"; cat "$f"; done
    echo "AddressSanitizer reported errors (above)" >&2
    exit 1
fi
exit "$status"
