"""Check the release artefacts in a wheelhouse (scripts/wheels.sh runs it).

For every wheel:
- ``twine check --strict`` passes (the sdist too);
- ``auditwheel show`` finds the wheel consistent with every platform tag in its name;
- it holds exactly: one extension module per module of setup.py, built for the wheel's
  interpreter and machine; every Python module and ``.pyi`` stub of ``src/drivekin``;
  ``py.typed``; its metadata. No Cython sources or headers (drivekin documents that it
  ships no ``.pxd``), no C files, objects or build leftovers;
- on aarch64, every LOAD segment of every extension is aligned to at least 16 KiB
  (SystemCore's kernel page size), read with readelf.

    python scripts/check_wheels.py wheelhouse/
"""
from __future__ import annotations

import re
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGE = 16384

# The compiled modules, read from setup.py without running it.
MODULES = re.search(r"^modules = \[(.*?)\]", (ROOT / "setup.py").read_text(),
                    re.S | re.M).group(1)
MODULES = re.findall(r'"([\w.]+)"', MODULES)


def source_files() -> set[str]:
    listed = subprocess.run(["git", "ls-files", "src/drivekin"], cwd=ROOT, check=True,
                            capture_output=True, text=True).stdout.split()
    return {p[len("src/"):] for p in listed if p.endswith((".py", ".pyi", "py.typed"))}


def wheel_tags(name: str) -> tuple[str, str, list[str]]:
    # name-version-python-abi-platform.whl; a platform may be several joined by dots
    _, _, python, abi, platform = name[:-len(".whl")].split("-")
    return python, abi, platform.split(".")


def check_wheel(path: Path, sources: set[str]) -> list[str]:
    errors = []
    python, abi, platforms = wheel_tags(path.name)
    machine = "aarch64" if platforms[0].endswith("aarch64") else "x86_64"
    suffix = f".cpython-{python[2:]}-{machine}-linux-gnu.so"
    with zipfile.ZipFile(path) as z:
        names = {n for n in z.namelist() if not n.endswith("/")}     # not directories
        expected = sources | {f"drivekin/{m.replace('.', '/')}{suffix}" for m in MODULES}
        payload = {n for n in names if ".dist-info/" not in n}
        for n in sorted(expected - payload):
            errors.append(f"missing {n}")
        for n in sorted(payload - expected):
            errors.append(f"unexpected file {n}")
        if machine == "aarch64":
            with tempfile.TemporaryDirectory() as tmp:
                for n in sorted(n for n in names if n.endswith(".so")):
                    so = z.extract(n, tmp)
                    errors += check_alignment(n, so)
    shown = subprocess.run(["auditwheel", "show", str(path)], capture_output=True, text=True)
    text = " ".join(shown.stdout.split())
    if shown.returncode != 0:
        errors.append(f"auditwheel show failed: {shown.stderr.strip()}")
    else:
        consistent = re.search(r'consistent with the following platform tag: "([^"]+)"', text)
        if not consistent:
            errors.append(f"auditwheel show: no platform tag in {text!r}")
        else:
            # The tag auditwheel names is the most compatible one the wheel meets; every
            # tag in the file name must be that one or a newer glibc of the same machine.
            best = consistent.group(1)
            for tag in platforms:
                if not tag_at_least(tag, best):
                    errors.append(f"platform tag {tag} is older than what the wheel "
                                  f"needs ({best})")
    return errors


def glibc(tag: str) -> tuple[int, int, str]:
    legacy = {"manylinux1": (2, 5), "manylinux2010": (2, 12), "manylinux2014": (2, 17)}
    m = re.fullmatch(r"manylinux_(\d+)_(\d+)_(\w+)", tag)
    if m:
        return int(m.group(1)), int(m.group(2)), m.group(3)
    m = re.fullmatch(r"(manylinux\d+)_(\w+)", tag)
    if m and m.group(1) in legacy:
        return (*legacy[m.group(1)], m.group(2))
    raise ValueError(f"not a manylinux tag: {tag}")


def tag_at_least(tag: str, best: str) -> bool:
    *version, machine = glibc(tag)
    *need, need_machine = glibc(best)
    return machine == need_machine and tuple(version) >= tuple(need)


def check_alignment(name: str, so: str) -> list[str]:
    out = subprocess.run(["readelf", "-lW", so], check=True, capture_output=True,
                         text=True).stdout
    aligns = [int(line.split()[-1], 16) for line in out.splitlines()
              if line.split()[:1] == ["LOAD"]]
    if not aligns:
        return [f"{name}: no LOAD segments in readelf -lW"]
    return [f"{name}: LOAD segment aligned to {a:#x}, SystemCore needs {PAGE:#x}"
            for a in aligns if a < PAGE]


def main() -> int:
    house = Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "wheelhouse")
    artefacts = sorted(house.glob("*.whl")) + sorted(house.glob("*.tar.gz"))
    if not any(p.suffix == ".whl" for p in artefacts):
        sys.exit(f"no wheels in {house}")
    twine = subprocess.run([sys.executable, "-m", "twine", "check", "--strict",
                            *map(str, artefacts)], capture_output=True, text=True)
    failed = twine.returncode != 0
    if failed:
        print(twine.stdout + twine.stderr)
    sources = source_files()
    for path in artefacts:
        errors = check_wheel(path, sources) if path.suffix == ".whl" else []
        status = "FAILED" if errors else "ok"
        print(f"{status:6} {path.stat().st_size / 1e6:6.2f} MB  {path.name}")
        for e in errors:
            print(f"         {e}")
        failed |= bool(errors)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
