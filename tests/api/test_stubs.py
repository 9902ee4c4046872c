"""The hand-written type stubs (``src/drivekin/**/<module>.pyi``) against the compiled modules.

Modules are named relative to the package, with dots: ``geometry``, ``_core.wheels``.
A module is public when no part of its name starts with an underscore.

1. Every public compiled module has a stub and every stub a compiled module (a private
   one may have a stub, for the bases it provides; a ``.pyi`` beside a plain ``.py``
   module would shadow it and is refused).
2. Every public name (module level and class level, inherited members included) exists on
   both sides, with the same kind (method, static method, property/attribute, ClassVar
   constant), and a stub property is writable exactly when the runtime one is.
3. Each runtime ``__doc__`` of a public module, class, method and property equals the
   stub docstring (both compared after :func:`inspect.cleandoc`). The ``.pyx``
   docstrings are the source of truth; ``scripts/stub_docstrings.py`` writes the stub
   docstrings from them, and its ``--check`` must find nothing to rewrite.
4. ``python -m mypy.stubtest`` passes with ``stubtest-allowlist.txt`` (skipped without mypy).
5. ``pyproject.toml`` ships the stubs and ``py.typed``.

Cython's ``embedsignature=True`` (setup.py) prepends a signature line to the runtime
docstrings; :func:`runtime_doc` (defined in ``scripts/stub_docstrings.py``, tested here)
removes exactly that line and nothing else, see there.
"""
from __future__ import annotations

import ast
import functools
import importlib
import importlib.machinery
import importlib.util
import inspect
import os
import re
import subprocess
import sys
import types
from dataclasses import dataclass, field
from pathlib import Path

import pytest

import drivekin
from drivekin._core import pynames

PKG_DIR = Path(drivekin.__file__).resolve().parent
REPO = Path(__file__).resolve().parents[2]
ALLOWLIST = Path(__file__).with_name("stubtest-allowlist.txt")
SCRIPT = REPO / "scripts" / "stub_docstrings.py"


# ---------------------------------------------------------------------------------------
# Discovery

def public(name: str) -> bool:
    return not name.startswith("_")


def public_module(dotted: str) -> bool:
    """``geometry`` is public, ``_core.wheels`` (or ``app._x``) is not."""
    return all(public(part) for part in dotted.split("."))


def _dotted(path: Path, stem: str) -> str | None:
    """``_core.wheels`` for ``PKG_DIR/_core/wheels.<suffix>``; None if a part of the name
    is not an identifier (build leftovers)."""
    parts = (*path.parent.relative_to(PKG_DIR).parts, stem)
    return ".".join(parts) if all(p.isidentifier() for p in parts) else None


def compiled_modules(*, private: bool = False) -> list[str]:
    """Public (or all) extension modules of the package, at any depth
    (``drivekin/<name>.<ext-suffix>``, ``drivekin/_core/<name>.<ext-suffix>``)."""
    suffixes = sorted(importlib.machinery.EXTENSION_SUFFIXES, key=len, reverse=True)
    names = set()
    for path in PKG_DIR.rglob("*"):
        for suffix in suffixes:                       # ".cpython-311-...so" before ".so"
            if path.name.endswith(suffix) and path.is_file():
                if (name := _dotted(path, path.name[: -len(suffix)])) is not None:
                    names.add(name)
                break
    return sorted(n for n in names if private or public_module(n))


def stub_files() -> list[str]:
    return sorted(_dotted(p, p.stem) or str(p) for p in PKG_DIR.rglob("*.pyi"))


def stub_path(module: str) -> Path:
    return PKG_DIR.joinpath(*module.split(".")).with_suffix(".pyi")


MODULES = compiled_modules()
# Modules with a stub: the public ones and private ones whose classes the public stubs
# derive from (drivekin._core.wheels, drivekin._core.drivetrain).
STUBBED = stub_files()


def test_modules_discovered():
    # Guards the parametrisation below against an empty or broken discovery (also of the
    # subpackages: the private compiled modules live in drivekin._core).
    assert {"geometry", "chassis", "swerve"} <= set(MODULES), MODULES
    assert {"_core.wheels", "_core.drivetrain"} <= set(compiled_modules(private=True))


def test_every_compiled_module_has_a_stub_and_vice_versa():
    assert sorted(MODULES) == [m for m in stub_files() if public_module(m)]
    # A private module may have a stub (for the bases it provides); it must exist too.
    assert sorted(set(stub_files()) - set(compiled_modules(private=True))) == []


# ---------------------------------------------------------------------------------------
# Stub model parsed with ast

@dataclass
class StubMember:
    kind: str     # "method", "staticmethod", "classmethod", "attribute" or "constant"
    docs: list[str | None] = field(default_factory=list)   # one per overload / definition
    writable: bool = False         # attributes: has a setter or is a plain annotation


@dataclass
class StubClass:
    doc: str | None
    bases: list[str]               # as written: "_Wheel2", "_WheelValues", "wheels._WheelValues"
    members: dict[str, StubMember]


@dataclass
class Stub:
    module: str                    # "geometry", "_core.wheels"
    doc: str | None
    classes: dict[str, StubClass]
    others: set[str]               # public module-level functions, constants, aliases
    functions: dict[str, StubMember]       # module-level functions (kind "function")
    # Names bound to another stub module ("_core.wheels") or to a class of one:
    # from drivekin._core.wheels import _WheelValues
    #     -> {"_WheelValues": ("_core.wheels", "_WheelValues")};
    # from drivekin._core import wheels -> {"wheels": ("_core.wheels", None)};
    # import drivekin._core.wheels as wheels -> {"wheels": ("_core.wheels", None)};
    # import drivekin._core.wheels -> {"drivekin._core.wheels": ("_core.wheels", None)}.
    imports: dict[str, tuple[str, str | None]] = field(default_factory=dict)


def _decorator_names(node: ast.FunctionDef) -> list[str]:
    names = []
    for d in node.decorator_list:
        if isinstance(d, ast.Name):
            names.append(d.id)
        elif isinstance(d, ast.Attribute):
            names.append(d.attr)   # "setter" for @x.setter, "final"/"overload" if qualified
    return names


def _is_classvar(annotation: ast.expr) -> bool:
    target = annotation.value if isinstance(annotation, ast.Subscript) else annotation
    return (isinstance(target, ast.Name) and target.id == "ClassVar") or (
        isinstance(target, ast.Attribute) and target.attr == "ClassVar")


def _parse_class(node: ast.ClassDef) -> StubClass:
    members: dict[str, StubMember] = {}
    for item in node.body:
        if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
            decos = _decorator_names(item)
            doc = ast.get_docstring(item, clean=True)
            if "setter" in decos or "deleter" in decos:
                member = members.setdefault(item.name, StubMember("attribute"))
                member.writable |= "setter" in decos
                assert doc is None, f"{node.name}.{item.name}: put the docstring on the getter"
                continue
            if "property" in decos:
                kind = "attribute"
            elif "staticmethod" in decos:
                kind = "staticmethod"
            elif "classmethod" in decos:
                kind = "classmethod"
            else:
                kind = "method"
            member = members.setdefault(item.name, StubMember(kind))
            assert member.kind == kind, f"{node.name}.{item.name}: mixed kinds in the stub"
            member.docs.append(doc)
        elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
            if _is_classvar(item.annotation):
                members[item.target.id] = StubMember("constant")
            else:
                members[item.target.id] = StubMember("attribute", writable=True)
        elif isinstance(item, ast.Assign):
            # ``radians = getRadians``: robotpy 2027's spelling of a member (its kind).
            alias = (members.get(item.value.id) if isinstance(item.value, ast.Name)
                     else None)
            for target in item.targets:
                if isinstance(target, ast.Name):
                    members[target.id] = StubMember(alias.kind if alias else "constant")
    bases = [ast.unparse(b) for b in node.bases if isinstance(b, (ast.Name, ast.Attribute))]
    return StubClass(ast.get_docstring(node, clean=True), bases, members)


def _package_relative(dotted: str | None, level: int, importer: str) -> str | None:
    """The package-relative name ("_core.wheels", "" for drivekin itself) of the module
    that ``from <dotted> import`` (``level`` dots) in the stub of ``importer`` names, or
    None if it is outside drivekin."""
    if level == 0:
        if dotted == "drivekin":
            return ""
        if not dotted or not dotted.startswith("drivekin."):
            return None
        return dotted[len("drivekin."):]
    package = importer.split(".")[:-1]             # "_core.wheels" -> ["_core"]
    if level - 1 > len(package):
        return None                                # above drivekin
    parts = package[: len(package) - (level - 1)] + (dotted.split(".") if dotted else [])
    return ".".join(parts)


def _stub_module(dotted: str | None, level: int, importer: str) -> str | None:
    """The stub module ("_core.wheels") that ``from <dotted> import`` (``level`` dots) in
    the stub of ``importer`` names, or None if it is not a drivekin module with a stub."""
    name = _package_relative(dotted, level, importer)
    if name and stub_path(name).is_file():
        return name
    return None


@functools.lru_cache(maxsize=None)
def parse_stub(module: str) -> Stub:
    tree = ast.parse(stub_path(module).read_text(encoding="utf-8"))
    classes: dict[str, StubClass] = {}
    others: set[str] = set()
    functions: dict[str, StubMember] = {}
    imports: dict[str, tuple[str, str | None]] = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            classes[node.name] = _parse_class(node)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            others.add(node.name)
            functions.setdefault(node.name, StubMember("function")).docs.append(
                ast.get_docstring(node, clean=True))
        elif isinstance(node, ast.ImportFrom):
            source = _stub_module(node.module, node.level, module)
            package = _package_relative(node.module, node.level, module)
            for alias in node.names:
                if source is not None:
                    imports[alias.asname or alias.name] = (source, alias.name)
                elif package is not None:           # from drivekin._core import wheels
                    sub = f"{package}.{alias.name}" if package else alias.name
                    if stub_path(sub).is_file():
                        imports[alias.asname or alias.name] = (sub, None)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                sub = _stub_module(alias.name, 0, module)
                if sub is not None:                 # the full dotted name without "as"
                    imports[alias.asname or alias.name] = (sub, None)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            others.add(node.target.id)
        elif isinstance(node, ast.Assign):
            others.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return Stub(module, ast.get_docstring(tree, clean=True), classes, others, functions, imports)


def resolve_base(stub: Stub, base: str) -> tuple[Stub, str] | None:
    """The stub and class name of a base class as written in ``stub``: a class of the same
    file, or one of another stub imported by name or reached through an imported module
    (``wheels._WheelValues``, ``drivekin._core.wheels._WheelValues``); None for anything
    else (``object``, typing constructs)."""
    head, _, attr = base.rpartition(".")
    if not head:
        if base in stub.classes:
            return stub, base
        if base in stub.imports:
            module, name = stub.imports[base]
            other = parse_stub(module)
            if name is not None:
                return resolve_base(other, name)
    elif head in stub.imports and stub.imports[head][1] is None:
        return resolve_base(parse_stub(stub.imports[head][0]), attr)
    return None


def stub_class_members(stub: Stub, name: str) -> dict[str, StubMember]:
    """Members of a stub class including those of its stub base classes, in the same file
    or in another stub (drivekin._core.wheels._WheelValues)."""
    cls = stub.classes[name]
    members: dict[str, StubMember] = {}
    for base in reversed(cls.bases):
        found = resolve_base(stub, base)
        assert found is not None or public(base.rpartition(".")[2]), (
            f"{stub.module}.{name}: private base {base} not found in the stubs")
        if found is not None:
            members.update(stub_class_members(*found))
    members.update(cls.members)
    return members


# ---------------------------------------------------------------------------------------
# Runtime model

def runtime_public_names(mod: types.ModuleType) -> set[str]:
    """Public names defined by the module itself (not imports such as ``np`` or ``f2``)."""
    names = set()
    for name, obj in vars(mod).items():
        if not public(name) or isinstance(obj, types.ModuleType):
            continue
        if getattr(obj, "__module__", mod.__name__) != mod.__name__:
            continue
        names.add(name)
    return names


def runtime_class_members(cls: type) -> dict[str, object]:
    """Public members of ``cls`` and of its bases (private bases such as _ChassisVector
    included: their methods are part of the public class's API); raw ``__dict__`` values.
    robotpy-wpimath 2026 names, which only raise (drivekin._core.renames), are not
    members."""
    from drivekin._core.renames import Renamed
    members: dict[str, object] = {}
    for klass in reversed(cls.__mro__[:-1]):          # without object
        if klass.__module__ == "builtins":
            continue                                  # BaseException's, for a warning
        members.update({k: v for k, v in vars(klass).items()
                        if public(k) and not isinstance(v, Renamed)})
    return members


DESCRIPTORS = (property, types.GetSetDescriptorType, types.MemberDescriptorType)


def runtime_kind(raw: object) -> str:
    if isinstance(raw, staticmethod):
        return "staticmethod"
    if isinstance(raw, classmethod):
        return "classmethod"
    if isinstance(raw, DESCRIPTORS):
        return "attribute"
    if callable(raw):
        return "method"
    return "constant"


def public_classes(mod: types.ModuleType) -> list[str]:
    return sorted(n for n in runtime_public_names(mod) if isinstance(getattr(mod, n), type))


# ---------------------------------------------------------------------------------------
# Docstrings: the rule that strips Cython's embedded signature line lives in the script
# that writes the stub docstrings (scripts/stub_docstrings.py), see runtime_doc there.

def _load_script(path: Path) -> types.ModuleType:
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module            # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


stub_docstrings = _load_script(SCRIPT)
runtime_doc = stub_docstrings.runtime_doc
module_embeds_signatures = stub_docstrings.module_embeds_signatures


def _fail_unless_equal(where: str, runtime: str | None, stub: str | None, errors: list[str]):
    if runtime != stub:
        errors.append(f"{where}:\n  runtime: {runtime!r}\n  stub:    {stub!r}")


# ---------------------------------------------------------------------------------------
# 1-2: names and kinds

@pytest.mark.parametrize("module", MODULES)
def test_module_level_names_match(module):
    mod = importlib.import_module(f"drivekin.{module}")
    stub = parse_stub(module)
    stub_names = {n for n in set(stub.classes) | stub.others if public(n)}
    runtime = runtime_public_names(mod)
    assert sorted(runtime - stub_names) == [], "public at runtime but missing from the stub"
    assert sorted(stub_names - runtime) == [], "in the stub but missing at runtime"
    for name in stub.classes:
        if public(name):
            assert isinstance(getattr(mod, name), type), f"{name} is not a class at runtime"


@pytest.mark.parametrize("module", MODULES)
def test_class_members_match(module):
    mod = importlib.import_module(f"drivekin.{module}")
    stub = parse_stub(module)
    errors = []
    for cname in public_classes(mod):
        runtime = runtime_class_members(getattr(mod, cname))
        stubbed = {k: v for k, v in stub_class_members(stub, cname).items() if public(k)}
        for name in sorted(set(runtime) - set(stubbed)):
            errors.append(f"{cname}.{name}: public at runtime, missing from the stub")
        for name in sorted(set(stubbed) - set(runtime)):
            errors.append(f"{cname}.{name}: in the stub, missing at runtime")
        for name in sorted(set(runtime) & set(stubbed)):
            rk, sk = runtime_kind(runtime[name]), stubbed[name].kind
            if rk != sk:
                errors.append(f"{cname}.{name}: runtime {rk}, stub {sk}")
    assert not errors, "\n".join(errors)


@pytest.mark.parametrize("module", STUBBED)
def test_stub_classes_mirror_the_runtime_hierarchy(module):
    """Each stub class that exists at runtime (private bases included) has the runtime
    class's bases, and declares only members that the runtime class defines itself: an
    inherited member is declared once, on the (private) base that defines it, and
    reaches the subclasses through the stub's own inheritance."""
    mod = importlib.import_module(f"drivekin.{module}")
    stub = parse_stub(module)
    errors = []
    for cname, scls in sorted(stub.classes.items()):
        cls = vars(mod).get(cname)
        if not isinstance(cls, type):
            continue                    # a stub-only helper (none today)
        bases = []
        for base in scls.bases:
            found = resolve_base(stub, base)
            bases.append(f"drivekin.{found[0].module}.{found[1]}" if found else base)
        runtime_bases = [b.__qualname__ if b.__module__ == "builtins"
                         else f"{b.__module__}.{b.__qualname__}" for b in cls.__bases__
                         if b is not object]
        if bases != runtime_bases:
            errors.append(f"{cname}: stub bases {bases}, runtime bases {runtime_bases}")
        for name in sorted(scls.members):
            if name not in vars(cls):
                owner = next((k.__qualname__ for k in cls.__mro__ if name in vars(k)), None)
                errors.append(f"{cname}.{name}: declared on {cname} in the stub but defined "
                              f"by {owner} at runtime")
    assert not errors, "\n".join(errors)


def _sample_instances() -> dict[str, object]:
    """One instance per public class with an example in the catalog, for the writability
    check."""
    from drivekin._core import catalog
    return {e.cls.__name__: e.example() for e in catalog.ENTRIES if e.example is not None}


@pytest.mark.parametrize("module", MODULES)
def test_stub_attribute_writability_matches(module):
    """A stub property has a setter (or is a plain annotated attribute) exactly when the
    runtime attribute can be assigned."""
    mod = importlib.import_module(f"drivekin.{module}")
    stub = parse_stub(module)
    samples = _sample_instances()
    errors = []
    for cname in public_classes(mod):
        cls = getattr(mod, cname)
        attrs = {n: m for n, m in stub_class_members(stub, cname).items()
                 if public(n) and m.kind == "attribute"}
        if not attrs:
            continue
        obj = samples[cname] if cname in samples else cls()   # else add a sample above
        for name, member in sorted(attrs.items()):
            try:
                setattr(obj, name, getattr(obj, name))
                writable = True
            except AttributeError:
                writable = False
            if writable != member.writable:
                errors.append(f"{cname}.{name}: runtime writable={writable}, "
                              f"stub writable={member.writable}")
    assert not errors, "\n".join(errors)


# ---------------------------------------------------------------------------------------
# 3: docstrings

def _fake_function(qualname: str, doc: str | None):
    def f():
        pass
    f.__qualname__ = qualname
    f.__doc__ = doc
    return f


def _fake_class(doc: str, *, own_init: bool) -> type:
    namespace: dict[str, object] = {"__doc__": doc}
    if own_init:
        namespace["__init__"] = lambda self: None
    return type("K", (), namespace)


@pytest.mark.parametrize("qualname, doc, embeds, expected", [
    ("C.f", "C.f(self, double x)\n\nBody.", True, "Body."),
    ("C.f", "C.f(self) -> int\n\nBody\n    more.", True, "Body\nmore."),
    ("_Base.f", "_Base.f(self, _Base other)\n\nBody.", True, "Body."),
    ("C.f", "C.f(self)", True, None),                        # no source docstring
    ("C.g", "g(*a) or g(s, e)\n\nBody.", False, "g(*a) or g(s, e)\n\nBody."),
    ("C.g", "C.g(self, first, *more)\n\ng(*a) or g(s, e)\n\nBody.", True,
     "g(*a) or g(s, e)\n\nBody."),
])
def test_function_signature_line_is_stripped_exactly(qualname, doc, embeds, expected):
    assert runtime_doc(_fake_function(qualname, doc), kind="function", embeds=embeds) == expected


def test_function_without_embedded_signature_is_an_error_when_the_module_embeds():
    with pytest.raises(AssertionError, match="embedded signature missing"):
        runtime_doc(_fake_function("C.f", "Body."), kind="function", embeds=True)


@pytest.mark.parametrize("doc, own_init, embeds, expected", [
    ("K(a=None)\n\nK() or K(a)\n\nBody.", True, True, "K() or K(a)\n\nBody."),
    ("K(*m)\n\nK(*m)\n\nBody.", True, True, "K(*m)\n\nBody."),     # identical lines
    ("K(x=0.0)\n\n    Body.\n    ", False, True, "K(x=0.0)\n\nBody."),  # inherited __init__
    ("K(*m)\n\nBody.", True, False, "K(*m)\n\nBody."),                # built without it
])
def test_class_signature_line_is_stripped_exactly(doc, own_init, embeds, expected):
    cls = _fake_class(doc, own_init=own_init)
    assert runtime_doc(cls, kind="class", embeds=embeds) == expected


def test_cython_attribute_type_doc_counts_as_missing():
    class Attr:
        __doc__ = "dx: 'double'"
    assert runtime_doc(Attr(), kind="attribute", embeds=True) is None


def test_signature_stripping_on_the_real_modules():
    import drivekin.geometry as geometry
    import drivekin.swerve as swerve
    from drivekin.swerve import SwerveDriveKinematics

    assert module_embeds_signatures(geometry) and module_embeds_signatures(swerve)
    # The source's own first line is the signature again, as a literal: only the
    # embedded line goes.
    raw = SwerveDriveKinematics.__doc__
    first, blank, second = raw.split("\n")[:3]
    assert first == "SwerveDriveKinematics(*module_translations)" and blank == ""
    assert second == f"``{first}``"
    cleaned = runtime_doc(SwerveDriveKinematics, kind="class", embeds=True)
    assert cleaned == inspect.cleandoc(raw.split("\n", 2)[2])
    assert cleaned.startswith(second + "\n")


@pytest.mark.parametrize("module", STUBBED)
def test_docstrings_match(module):
    mod = importlib.import_module(f"drivekin.{module}")
    stub = parse_stub(module)
    embeds = module_embeds_signatures(mod)
    errors: list[str] = []
    _fail_unless_equal(f"module {module}", runtime_doc(mod, kind="module", embeds=embeds),
                       stub.doc, errors)
    for cname in public_classes(mod):
        cls = getattr(mod, cname)
        _fail_unless_equal(cname, runtime_doc(cls, kind="class", embeds=embeds),
                           stub.classes[cname].doc, errors)
        runtime = runtime_class_members(cls)
        spellings = pynames.spellings(cls)
        for name, member in sorted(stub_class_members(stub, cname).items()):
            if not public(name) or name not in runtime or member.kind == "constant":
                continue        # dunders have no docstrings; constants are instances
            if name in spellings:
                continue        # robotpy 2027's spelling: the Java name's docstring
            distinct = set(d for d in member.docs if d is not None)
            if len(distinct) > 1:
                errors.append(f"{cname}.{name}: overloads carry different docstrings")
                continue
            stub_doc = distinct.pop() if distinct else None
            raw = runtime[name]
            if member.kind == "attribute":
                rt = runtime_doc(raw, kind="attribute", embeds=embeds)
            else:
                rt = runtime_doc(getattr(cls, name), kind="function", embeds=embeds)
            _fail_unless_equal(f"{cname}.{name}", rt, stub_doc, errors)
    for name, member in sorted(stub.functions.items()):
        if public(name) and callable(getattr(mod, name, None)):
            distinct = set(d for d in member.docs if d is not None)
            _fail_unless_equal(f"{module}.{name}", runtime_doc(
                getattr(mod, name), kind="function", embeds=embeds),
                distinct.pop() if len(distinct) == 1 else None, errors)
    assert not errors, "\n".join(errors)


def test_stub_docstrings_are_generated():
    """Every stub docstring is what scripts/stub_docstrings.py writes: a docstring edited in
    a .pyx (and rebuilt) without rerunning the script fails here."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(PKG_DIR.parent)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    proc = subprocess.run(
        [sys.executable, str(SCRIPT), "--check", "--diff", "--package-dir", str(PKG_DIR)],
        env=env, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, (
        "stub docstrings differ from the compiled modules' __doc__: run "
        "`python scripts/stub_docstrings.py` and commit the stubs\n"
        + proc.stdout + proc.stderr)


# ---------------------------------------------------------------------------------------
# 4: stubtest

def test_stubtest(tmp_path):
    pytest.importorskip("mypy.stubtest")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(PKG_DIR.parent)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    env["MYPY_CACHE_DIR"] = str(tmp_path / "mypy_cache")   # keep the work tree clean
    # The robotpy-wpimath 2026 names that only raise (drivekin._core.renames) are in the
    # classes' dictionaries and deliberately not in the stubs: allowed, by their table.
    from drivekin._core.renames import RENAMES
    renamed = tmp_path / "renamed-allowlist.txt"
    renamed.write_text("".join(
        f"{re.escape(getattr(drivekin, cls).__module__)}\\.{cls}\\.{old}\n"
        for cls, names in RENAMES.items() for old in names))
    cmd = [sys.executable, "-m", "mypy.stubtest",
           *(f"drivekin.{m}" for m in STUBBED), "--allowlist", str(ALLOWLIST),
           "--allowlist", str(renamed)]
    proc = subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr


# ---------------------------------------------------------------------------------------
# 5: packaging

def test_pyproject_ships_stubs_and_py_typed():
    tomllib = pytest.importorskip("tomllib")
    pyproject = REPO / "pyproject.toml"
    if not pyproject.exists():
        pytest.skip("not running from a source checkout")
    data = tomllib.loads(pyproject.read_text(encoding="utf-8"))
    package_data = data["tool"]["setuptools"]["package-data"]["drivekin"]
    assert "*.pyi" in package_data and "py.typed" in package_data
    assert (PKG_DIR / "py.typed").is_file()


def test_stub_aliases_are_generated():
    # robotpy 2027's spellings in the stubs are scripts/stub_aliases.py's output.
    done = subprocess.run([sys.executable, str(REPO / "scripts" / "stub_aliases.py"),
                           "--check", "--package-dir", str(PKG_DIR)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
