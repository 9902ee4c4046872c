"""robotpy 2027's spellings of drivekin's names: one rule and a small table of exceptions.

robotpy 2027 names every wpimath member with semiwrap's snake_case transform of the
**C++** name. Where C++ and Java differ, they differ the same way everywhere: WPILib's C++
value types (geometry, motors, wheel values) name their accessors without ``Get``
(``Radians()``, ``X()``, ``Translation()``, ``NEO()``), while its stateful objects
(kinematics, odometry, estimators, buffers) keep it (``GetPose()``,
``GetEstimatedPosition()``, ``GetModules()``). So the rule, from the Java name and the
catalog's kind of the class, is:

* a member of a ``"value"`` class loses Java's ``get`` prefix;
* then every name is snake_case: a ``k`` before a capital is dropped, words split as
  semiwrap splits them (digits stay on their word: ``toTwist2d`` -> ``to_twist2d``,
  ``getNeo550`` -> ``neo550``), lower-cased, joined with ``_``.

:data:`EXCEPTIONS` holds the members whose C++ name is not the rule's. The snake_case
name is put into the dictionary of the class that defines the Java member (a private base
such as ``_Frame2d`` included) as **the same object** (the method descriptor, static
method or property), so calling through either name costs the same and shows one
docstring. A Java name the class already has in snake_case spelling
(``Pose2d.x``) is left as it is.

robotpy's **class** names that Java does not have are built here too: the fixed-module-
count swerve classes ``SwerveDrive{2,3,4,6}<Kinematics|Odometry|PoseEstimator|...>`` (one
family per catalog class of the swerve drivetrain whose name starts ``SwerveDrive``) and
``TimeInterpolatable<T>Buffer`` (one per interpolatable value class drivekin has, and
``Float``). Calling one builds the drivekin object, checking the module count; its static
methods and constants are reachable through it; ``isinstance`` works.

The few robotpy names with no Java member at all (``x_feet``, ``vx_fps``, ``from_matrix``)
are written out in _core/robotpyextras.py; install() puts them in first.

``tests/api/test_robotpy_names.py`` holds the result against robotpy 2027's own tables
(``tests/data/robotpy2027-names.json``).
"""
from __future__ import annotations

import re
from typing import Any, Callable

#: (class name, Java member name) -> robotpy 2027's name, where the rule does not give it.
EXCEPTIONS: dict[tuple[str, str], str] = {
    # C++ DCMotor::RS775_125: Java adds the maker's name.
    ("DCMotor", "getAndymarkRs775_125"): "rs775_125",
    # C++ TimeInterpolatableBuffer::Sample: the one stateful accessor without Get.
    ("TimeInterpolatableBuffer", "getSample"): "sample",
    # C++ Rotation3d::GetQuaternion: the one value accessor that keeps Get.
    ("Rotation3d", "getQuaternion"): "get_quaternion",
}

_WORD = re.compile(r"[A-Z]+[0-9]*(?=[A-Z][a-z0-9]|_|$)|[A-Z]?[a-z0-9]+|[A-Z]+[0-9]*")
_GETTER = re.compile(r"get(?=[A-Z])")
_K_CONSTANT = re.compile(r"^k(?=[A-Z])")


def snake_case(name: str) -> str:
    """semiwrap's name transform (robotpy's ``name_transform = snake_case``)."""
    return "_".join(w.lower() for w in _WORD.findall(_K_CONSTANT.sub("", name, count=1)))


def python_name(cls_name: str, kind: str, java: str) -> str:
    """robotpy 2027's name of the Java member ``java`` of a class of catalog ``kind``."""
    name = EXCEPTIONS.get((cls_name, java))
    if name is not None:
        return name
    if kind == "value" and _GETTER.match(java):
        java = java[3:]
    return snake_case(java)


def _members(cls: type) -> dict[str, Any]:
    """The public members of ``cls`` as stored in the class dictionaries (nearest first):
    methods, static and class methods, properties. Constants (instances of the class, or
    numbers) have no robotpy 2027 spelling and are left out, as are the 2026 names of
    _core.renames, which raise."""
    from drivekin._core.renames import Renamed
    out: dict[str, Any] = {}
    for klass in cls.__mro__[:-1]:              # object's members are not drivekin's
        for name, raw in vars(klass).items():
            if name.startswith("_") or name in out or isinstance(raw, Renamed):
                continue
            if isinstance(raw, (staticmethod, classmethod, property)) or callable(raw) \
                    or hasattr(type(raw), "__get__") and not isinstance(raw, cls):
                out[name] = raw
    return out


def aliases(cls: type, kind: str) -> dict[str, str]:
    """{robotpy 2027 name: Java name} for the members of ``cls`` whose robotpy name is a
    different spelling (the rule applied to every public member)."""
    out: dict[str, str] = {}
    for java in _members(cls):
        py = python_name(cls.__name__, kind, java)
        if py != java:
            out[py] = java
    return out


def _set(cls: type, name: str, value: Any) -> None:
    from drivekin._core.wheels import set_type_attr
    if cls.__flags__ & (1 << 9):                # Py_TPFLAGS_HEAPTYPE: a Python class
        setattr(cls, name, value)
    else:
        set_type_attr(cls, name, value)


# ---------------------------------------------------------------------------------------
# robotpy's class names

class RobotpyClass(type):
    """The type of robotpy 2027's class names that drivekin builds from one of its own
    classes (``SwerveDrive4Kinematics`` from ``SwerveDriveKinematics``): calling one
    builds the drivekin object, its other attributes are the drivekin class's."""

    _base: type
    _build: Callable[..., Any]
    _accepts: Callable[[Any], bool]

    def __call__(cls, *args: Any, **kwargs: Any) -> Any:
        return cls._build(*args, **kwargs)

    def __getattr__(cls, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(cls._base, name)

    def __instancecheck__(cls, obj: Any) -> bool:
        return isinstance(obj, cls._base) and cls._accepts(obj)

    def __subclasscheck__(cls, sub: type) -> bool:
        return sub is cls

    def __repr__(cls) -> str:
        return f"<class 'drivekin.{cls.__name__}' (drivekin.{cls._base.__name__})>"


def _family_class(name: str, base: type, doc: str, build: Callable[..., Any],
                  accepts: Callable[[Any], bool]) -> type:
    return RobotpyClass(name, (), {
        "__doc__": doc, "__module__": "drivekin", "__qualname__": name,
        "_base": base, "_build": staticmethod(build), "_accepts": staticmethod(accepts)})


def _swerve_count(obj: Any, what: str) -> int:
    from drivekin.swerve import SwerveDriveKinematics
    if not isinstance(obj, SwerveDriveKinematics):
        raise TypeError(f"{what} takes a SwerveDriveKinematics as its first argument, "
                        f"got {type(obj).__name__}")
    return int(obj.getNumModules())


def _swerve_family(base: type, n: int) -> type:
    suffix = base.__name__[len("SwerveDrive"):]
    name = f"SwerveDrive{n}{suffix}"
    kinematics = suffix == "Kinematics"

    def build(*args: Any, **kwargs: Any) -> Any:
        if kinematics:
            obj = base(*args, **kwargs)
            if obj.getNumModules() != n:
                raise TypeError(f"{name} takes {n} module locations (Translation2d), got "
                                f"{obj.getNumModules()}; drivekin.SwerveDriveKinematics "
                                "takes any number")
            return obj
        kin = args[0] if args else kwargs.get("kinematics")
        count = _swerve_count(kin, name)
        if count != n:
            raise TypeError(f"{name} takes a {n}-module kinematics (SwerveDrive{n}"
                            f"Kinematics), got one with {count} modules")
        return base(*args, **kwargs)

    def accepts(obj: Any) -> bool:
        return not kinematics or obj.getNumModules() == n

    doc = (f"robotpy's {name}: drivekin's {base.__name__} with {n} modules. Calling it "
           f"builds a {base.__name__} (checking the module count); its static methods "
           f"are {base.__name__}'s.")
    return _family_class(name, base, doc, build, accepts)


#: robotpy's TimeInterpolatable<T>Buffer element types (``Float`` interpolates floats).
BUFFER_TYPES = ("Pose2d", "Rotation2d", "Translation2d", "Pose3d", "Rotation3d",
                "Translation3d")


def _buffer_family(buffer: Any, element: str, value: Any) -> type:
    name = f"TimeInterpolatable{element}Buffer"

    def build(history_size: float, func: Callable[[Any, Any, float], Any] | None = None
              ) -> Any:
        if func is not None:
            return buffer(func, history_size)
        if value is None:
            return buffer.createDoubleBuffer(history_size)
        return buffer(value.interpolate, history_size)

    what = "floats" if value is None else f"{element} samples"
    doc = (f"robotpy's {name}(history_size, func=None): a drivekin TimeInterpolatableBuffer "
           f"of {what} kept for ``history_size`` s, blended by ``func(start, end, t)`` "
           f"(default: {'linear' if value is None else f'{element}.interpolate'}).")
    return _family_class(name, buffer, doc, build, lambda obj: True)


def class_names(namespace: dict[str, Any]) -> dict[str, type]:
    """robotpy 2027's class names that drivekin builds from its own classes (catalog
    entries), by name."""
    from drivekin._core.catalog import ENTRIES, SWERVE_MODULE_COUNTS as counts
    out: dict[str, type] = {}
    for e in ENTRIES:
        if e.drivetrain == "swerve" and e.cls.__name__.startswith("SwerveDrive"):
            for n in counts:
                c = _swerve_family(e.cls, n)
                out[c.__name__] = c
    buffer = namespace["TimeInterpolatableBuffer"]
    for element in BUFFER_TYPES:
        if element in namespace:
            c = _buffer_family(buffer, element, namespace[element])
            out[c.__name__] = c
    c = _buffer_family(buffer, "Float", None)
    out[c.__name__] = c
    return out


#: What install() added, by the class whose dictionary holds it: class -> {robotpy 2027
#: name: Java name}.
INSTALLED: dict[type, dict[str, str]] = {}


def spellings(cls: type) -> dict[str, str]:
    """{robotpy 2027 name: Java name} of the spellings install() gave ``cls`` and its
    bases: names of members that are already there under their Java name."""
    out: dict[str, str] = {}
    for klass in reversed(cls.__mro__):
        out.update(INSTALLED.get(klass, {}))
    return out


def install(namespace: dict[str, Any]) -> list[str]:
    """Give every catalog class its robotpy 2027 names and put robotpy's class names into
    ``namespace`` (the package's); return the class names added."""
    from drivekin._core.catalog import ENTRIES
    from drivekin._core.robotpyextras import install_extras
    install_extras(namespace)               # the names without a Java member first
    for e in ENTRIES:
        if not e.robotpy_names:
            continue
        members = _members(e.cls)
        for py, java in aliases(e.cls, e.kind).items():
            if py in members:
                continue                        # the class has this spelling already
            # Beside the Java member, on the class that defines it (a private base is
            # shared by classes of one kind, so they agree on the name).
            owner = next(k for k in e.cls.__mro__ if java in vars(k))
            if py not in vars(owner):
                _set(owner, py, members[java])
                INSTALLED.setdefault(owner, {})[py] = java
    classes = class_names(namespace)
    namespace.update(classes)
    return sorted(classes)
