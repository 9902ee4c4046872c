"""WPILib packed-struct serialization (struct spec v1.0) for drivekin's value types and
kinematics classes, with the WPILib 2027 type names and schemas.

The bytes are what WPILib 2027 Java/C++ writes for the same values to NetworkTables and
DataLog (type string ``struct:<Name>``, arrays ``struct:<Name>[]``):

* members in schema order, **little-endian**, no padding or alignment, nested structs
  inlined; every member of every type here is an 8-byte IEEE-754 ``double``;
* a Rotation2d is packed as its :meth:`~drivekin.Rotation2d.getRadians` — in 2027 the
  wrapped ``atan2`` value in [−π, π], so ``Rotation2d(4.0)`` packs 4 − 2π — and unpacked
  with ``Rotation2d(value)``. (WPILib 2026 and robotpy 2026 pack the constructor value
  unwrapped; both agree for angles already in [−π, π].)
* a Rotation3d is packed as its stored quaternion (w, x, y, z) and unpacked with
  ``Rotation3d(Quaternion(w, x, y, z))``, which normalises it exactly as WPILib does
  (WPILib's C++ ``Quaternion::Normalize``: the same bits as robotpy-wpimath's unpack; a
  zero quaternion gives the identity), except where the squared norm leaves the normal
  doubles: there it scales by an exact power of two first, so the result is still unit. A Quaternion is packed and unpacked as it is.

Types, sizes and schemas (units: m, m/s, m/s², rad, rad/s, rad/s²)::

    type name                            bytes  schema
    Translation2d                          16   double x;double y
    Rotation2d                              8   double value
    Pose2d, Transform2d                    24   Translation2d translation;Rotation2d rotation
    Twist2d                                24   double dx;double dy;double dtheta
    Translation3d                          24   double x;double y;double z
    Quaternion                             32   double w;double x;double y;double z
    Rotation3d                             32   Quaternion q
    Pose3d, Transform3d                    56   Translation3d translation;
                                                Rotation3d rotation
    Twist3d                                48   double dx;double dy;double dz;
                                                double rx;double ry;double rz
    ChassisVelocities                      24   double vx;double vy;double omega
    ChassisAccelerations                   24   double ax;double ay;double alpha
    SwerveModuleVelocity                   16   double velocity;Rotation2d angle
    SwerveModulePosition                   16   double distance;Rotation2d angle
    SwerveModuleAccelerations (sic)        16   double acceleration;Rotation2d angle
    MecanumDriveWheelVelocities,           32   double front_left;double front_right;
      ...Positions, ...Accelerations                double rear_left;double rear_right
    DifferentialDriveWheelVelocities,      16   double left;double right
      ...Positions, ...Accelerations
    DifferentialDriveKinematics             8   double trackwidth
    MecanumDriveKinematics                 64   Translation2d front_left;
                                                Translation2d front_right;
                                                Translation2d rear_left;
                                                Translation2d rear_right
    SwerveDriveKinematics__N             16·N   Translation2d modules[N]

(Schema strings have no spaces after the semicolons.)

Functions: :func:`getTypeName`, :func:`getTypeString`, :func:`getSchema`,
:func:`getSize`, :func:`getNested`, :func:`forEachNested` (describe a type, from the
class or an instance); :func:`pack`, :func:`packInto`, :func:`packArray`;
:func:`unpack`, :func:`unpackFrom`, :func:`unpackArray`. :data:`STRUCT_TYPES` lists the
supported classes.

The class :class:`~drivekin.SwerveModuleAcceleration` is published under the type name
``SwerveModuleAccelerations`` (plural), exactly as WPILib 2027 does.

SwerveDriveKinematics has one struct type per module count N (``SwerveDriveKinematics__4``
for four modules). Functions given an *instance* read N from it; given the *class* they
need ``numModules=N`` — except :func:`unpack`, which infers ``N = (len(data) - offset) //
16`` when ``numModules`` is omitted (the byte count must then be a multiple of 16 and at
least 32, since a swerve drive has N ≥ 2). ``numModules`` must be an int with
2 ≤ N ≤ :data:`MAX_SWERVE_MODULES` (``sys.maxsize // 16``, so that 16·N bytes fit in a
buffer); other values raise ValueError (TypeError if not an int) before anything is
built.

Only the kinematics *geometry* is serialized: a SwerveDriveKinematics' heading memory and
sticky centre of rotation (and a MecanumDriveKinematics' centre of rotation) are not part
of the struct, so an unpacked copy starts fresh, as in WPILib.

Every function taking bytes accepts any C-contiguous bytes-like object whose items are
plain bytes or numbers (bytes, bytearray, memoryview, array.array, numeric numpy arrays,
...); the sizes are byte counts. Buffers of Python objects (``dtype=object`` arrays) or
other non-numeric item formats are refused with TypeError, since their memory holds
object pointers, not data. Wrong types raise TypeError; wrong byte counts and values the drivekin constructors reject (a trackwidth
that is not positive and finite, fewer than two swerve modules, NaN/inf module positions)
raise ValueError. (Apart from N ≥ 2, those checks are drivekin's own: bytes that WPILib
would decode into a degenerate kinematics object are rejected here.)

Example::

    >>> from drivekin import ChassisVelocities
    >>> from drivekin import wpistruct
    >>> data = wpistruct.pack(ChassisVelocities(1.0, 2.0, 3.0))
    >>> data.hex()
    '000000000000f03f00000000000000400000000000000840'
    >>> wpistruct.getTypeString(ChassisVelocities), wpistruct.getSchema(ChassisVelocities)
    ('struct:ChassisVelocities', 'double vx;double vy;double omega')
    >>> wpistruct.unpack(ChassisVelocities, data) == ChassisVelocities(1.0, 2.0, 3.0)
    True
"""
from __future__ import annotations

import functools
import operator
import struct
import sys
from collections.abc import Callable, Iterable
from typing import Any, TypeVar, Union

from drivekin._core import catalog
from drivekin._core import buffers
# StructValue: any object this module can pack (the catalog's union of its classes).
from drivekin._core.catalog import SerializableValue as StructValue
from drivekin._core.errors import type_name

__all__ = [
    "MAX_SWERVE_MODULES",
    "STRUCT_TYPES",
    "StructValue",
    "forEachNested",
    "getNested",
    "getSchema",
    "getSize",
    "getTypeName",
    "getTypeString",
    "pack",
    "packArray",
    "packInto",
    "unpack",
    "unpackArray",
    "unpackFrom",
]

#: Bytes-like input: anything exporting the buffer protocol as C-contiguous memory.
BytesLike = Union[bytes, bytearray, memoryview, Any]

T = TypeVar("T")


class _Spec:
    """Everything known about one struct type (internal).

    ``flatten(obj)`` returns the struct's doubles in wire order; ``build(*values)``
    constructs an object from them.
    """

    __slots__ = ("cls", "name", "typeString", "schema", "size", "count", "struct",
                 "nested", "flatten", "build")

    def __init__(self, cls: type, name: str, schema: str, count: int,
                 nested: tuple[type, ...],
                 flatten: Callable[[Any], tuple[float, ...]],
                 build: Callable[..., Any]) -> None:
        self.cls = cls
        self.name = name
        self.typeString = "struct:" + name
        self.schema = schema
        self.count = count                      # number of doubles
        self.size = 8 * count                   # bytes
        self.struct = struct.Struct("<%dd" % count)
        self.nested = nested
        self.flatten = flatten
        self.build = build


# ---------------------------------------------------------------------------------------
# The specs, from the catalog's wire forms. Every member is a double, so a struct is a
# flat run of little-endian doubles; nested structs contribute their doubles in place.

def _checked(name: str, build: Callable[..., Any]) -> Callable[..., Any]:
    """Wrap a kinematics constructor so that values it rejects (trackwidth <= 0, NaN/inf
    module positions, ...) surface as ``ValueError("cannot unpack <name>: ...")``."""
    def checked(*v: float) -> Any:
        try:
            return build(*v)
        except ValueError as e:   # includes numpy.linalg.LinAlgError
            raise ValueError(f"cannot unpack {name}: {e}") from e
    return checked


def _spec(e: catalog.Entry, name: str, schema: str, count: int) -> _Spec:
    assert e.struct is not None and e.flatten is not None and e.build is not None
    build = _checked(name, e.build) if e.kind == "kinematics" else e.build
    return _Spec(e.cls, name, schema, count, e.struct.nested, e.flatten, build)


_SPECS: dict[type, _Spec] = {}
# Repeated structs (one type per member count): their catalog entries.
_REPEATED: dict[type, catalog.Entry] = {}
for _e in catalog.ENTRIES:
    if _e.struct is None:
        continue
    if _e.struct.repeats is None:
        _SPECS[_e.cls] = _spec(_e, _e.struct.name, _e.struct.schema, _e.struct.count)
    else:
        _REPEATED[_e.cls] = _e
del _e

#: Largest module count a SwerveDriveKinematics struct may declare: its 16·N bytes must
#: fit in one buffer (a Py_ssize_t byte count).
MAX_SWERVE_MODULES = sys.maxsize // 16


def _int_text(n: int) -> str:
    # str() of an int beyond sys.get_int_max_str_digits() raises ValueError itself.
    return str(n) if n.bit_length() <= 128 else ("a huge negative number" if n < 0
                                                  else "a huge number")


def _repeated_spec(cls: type, n: int) -> _Spec:
    # Range checks come before the cache, so no spec is built for a count that cannot be
    # valid, whatever its size.
    st = _REPEATED[cls].struct
    assert st is not None
    if n < st.least:
        raise ValueError(f"a {st.name} struct needs numModules >= {st.least}, "
                         f"got {_int_text(n)}")
    if n > MAX_SWERVE_MODULES:
        raise ValueError(f"a {st.name} struct needs numModules <= "
                         f"{MAX_SWERVE_MODULES} ({8 * st.count}·N bytes must fit in a "
                         f"buffer), got {_int_text(n)}")
    return _cached_repeated_spec(cls, n)


# Bounded: a caller iterating over many module counts must not keep a spec for each.
@functools.lru_cache(maxsize=32)
def _cached_repeated_spec(cls: type, n: int) -> _Spec:
    e = _REPEATED[cls]
    assert e.struct is not None
    return _spec(e, f"{e.struct.name}__{n}", f"{e.struct.schema}[{n}]", e.struct.count * n)


#: Every drivekin class this module can serialize (SwerveDriveKinematics: any N >= 2).
STRUCT_TYPES: tuple[type, ...] = tuple(e.cls for e in catalog.ENTRIES if e.struct)

_SUPPORTED = ", ".join(c.__name__ for c in STRUCT_TYPES)
_REPEATED_NAMES = " and ".join(c.__name__ for c in _REPEATED)


# ---------------------------------------------------------------------------------------
# Lookup helpers

def _num_modules(numModules: object) -> int:
    try:
        n = operator.index(numModules)  # type: ignore[arg-type]
    except TypeError:
        raise TypeError(
            f"numModules must be an int, got {type_name(numModules)}") from None
    if isinstance(numModules, bool):
        raise TypeError("numModules must be an int, got bool")
    return n


def _spec_of(x: object, numModules: int | None = None) -> _Spec:
    """Spec for a supported class or instance (``numModules`` only for the swerve class)."""
    if isinstance(x, type):
        spec = _SPECS.get(x)
        if spec is not None:
            if numModules is not None:
                raise TypeError(f"numModules applies only to {_REPEATED_NAMES}, "
                                f"not {x.__name__}")
            return spec
        if x in _REPEATED:
            if numModules is None:
                raise TypeError(
                    f"the {x.__name__} struct type depends on the module count: "
                    "pass numModules=N or an instance")
            return _repeated_spec(x, _num_modules(numModules))
        raise TypeError(f"{x.__module__}.{x.__qualname__} has no WPILib struct "
                        f"serialization here; supported: {_SUPPORTED}")
    spec = _SPECS.get(type(x))
    if spec is not None:
        if numModules is not None:
            raise TypeError(f"numModules applies only to {_REPEATED_NAMES}, "
                            f"not {type(x).__name__}")
        return spec
    e = _REPEATED.get(type(x))
    if e is not None:
        assert e.struct is not None and e.struct.repeats is not None
        n = e.struct.repeats(x)
        if numModules is not None:
            given = _num_modules(numModules)
            if given != n:
                raise ValueError(f"numModules={_int_text(given)} does not match the "
                                 f"instance's {n} modules")
        return _repeated_spec(type(x), n)
    raise TypeError(f"cannot serialize a {type(x).__module__}.{type(x).__qualname__}; "
                    f"supported drivekin types: {_SUPPORTED}")


def _spec_of_instance(obj: object) -> _Spec:
    spec = _SPECS.get(type(obj))
    if spec is not None:
        return spec
    if isinstance(obj, type):
        raise TypeError(f"cannot serialize the class {obj.__module__}.{obj.__qualname__} "
                        f"itself: pass an instance")
    return _spec_of(obj)


def _spec_of_class(cls: object, numModules: int | None, what: str) -> _Spec:
    if not isinstance(cls, type):
        raise TypeError(f"{what}() takes a class as its first argument (e.g. "
                        f"drivekin.Pose2d), got a {type(cls).__name__} instance")
    return _spec_of(cls, numModules)


def _check_offset(offset: object) -> int:
    try:
        off = operator.index(offset)  # type: ignore[arg-type]
    except TypeError:
        raise TypeError(f"offset must be an int, got {type_name(offset)}") from None
    if off < 0:
        raise ValueError(f"offset must be >= 0, got {off}")
    return off


# ---------------------------------------------------------------------------------------
# Descriptors

def getTypeName(x: object, *, numModules: int | None = None) -> str:
    """Return the WPILib struct type name of a supported class or instance.

    ``getTypeName(ChassisVelocities)`` → ``"ChassisVelocities"``;
    ``getTypeName(SwerveModuleAcceleration)`` → ``"SwerveModuleAccelerations"`` (sic);
    ``getTypeName(kinematics4)`` → ``"SwerveDriveKinematics__4"``;
    ``getTypeName(SwerveDriveKinematics, numModules=4)`` → the same (the class alone is a
    TypeError: its name depends on N). Unsupported types raise TypeError.
    """
    return _spec_of(x, numModules).name


def getTypeString(x: object, *, numModules: int | None = None) -> str:
    """Return the NetworkTables/DataLog type string ``"struct:<Name>"`` (see
    :func:`getTypeName`). An array of the type is published as ``getTypeString(x) + "[]"``.
    """
    return _spec_of(x, numModules).typeString


def getSchema(x: object, *, numModules: int | None = None) -> str:
    """Return the struct schema string, e.g. ``"double velocity;Rotation2d angle"`` or
    ``"Translation2d modules[4]"`` (published under type ``structschema`` as
    ``struct:<Name>``)."""
    return _spec_of(x, numModules).schema


def getSize(x: object, *, numModules: int | None = None) -> int:
    """Return the packed size in bytes (8 per double; 16·N for SwerveDriveKinematics__N)."""
    return _spec_of(x, numModules).size


def getNested(x: object) -> tuple[type, ...]:
    """Return the struct types nested *directly* in this one, in schema order, without
    duplicates: ``(Translation2d, Rotation2d)`` for Pose2d/Transform2d,
    ``(Translation3d, Rotation3d)`` for Pose3d/Transform3d, ``(Quaternion,)`` for
    Rotation3d, ``(Rotation2d,)`` for the swerve module values, ``(Translation2d,)``
    for MecanumDriveKinematics and SwerveDriveKinematics (any N), ``()`` for the
    plain-double types. Their own schemas must be published too; :func:`forEachNested`
    walks the whole tree."""
    e = _REPEATED.get(x if isinstance(x, type) else type(x))
    if e is not None and e.struct is not None:
        return e.struct.nested
    return _spec_of(x).nested


def forEachNested(x: object, fn: Callable[[str, str], object], *,
                  numModules: int | None = None) -> None:
    """Call ``fn(typeString, schema)`` for every struct type needed to decode ``x``:
    nested types first (depth-first, each once), then ``x``'s own type last — the order
    robotpy's ``wpiutil.wpistruct.forEachNested`` uses. Publish each as a
    ``structschema`` to make a log self-describing."""
    seen: set[str] = set()

    def visit(spec: _Spec) -> None:
        for cls in spec.nested:
            visit(_SPECS[cls])
        if spec.typeString not in seen:
            seen.add(spec.typeString)
            fn(spec.typeString, spec.schema)

    visit(_spec_of(x, numModules))


# ---------------------------------------------------------------------------------------
# Packing

def pack(obj: StructValue) -> bytes:
    """Return the packed little-endian bytes of ``obj`` (:func:`getSize` bytes).

    Rotation2d members are written as ``getRadians()`` (wrapped to [−π, π]), Rotation3d
    members as their quaternion. Raises TypeError for unsupported objects (including
    classes instead of instances)."""
    spec = _SPECS.get(type(obj))
    if spec is None:
        spec = _spec_of_instance(obj)
    return spec.struct.pack(*spec.flatten(obj))


def packInto(obj: StructValue, buffer: BytesLike, offset: int = 0) -> None:
    """Write ``pack(obj)`` into the writable ``buffer`` at byte ``offset`` without
    creating a bytes object (e.g. to fill a preallocated log record). ValueError if ``buffer[offset:]`` is shorter than
    :func:`getSize` bytes; TypeError if ``buffer`` is read-only or not bytes-like."""
    spec = _SPECS.get(type(obj))
    if spec is None:
        spec = _spec_of_instance(obj)
    if type(buffer) is bytearray and type(offset) is int and 0 <= offset:
        if len(buffer) - offset < spec.size:     # fast path, same checks as below
            raise ValueError(f"{spec.typeString} needs {spec.size} bytes at offset "
                             f"{offset}, the buffer has {max(len(buffer) - offset, 0)}")
        spec.struct.pack_into(buffer, offset, *spec.flatten(obj))
        return
    off = _check_offset(offset)
    values = spec.flatten(obj)
    with buffers.view(buffer) as mv:
        if mv.readonly:
            raise TypeError(f"packInto() needs a writable buffer, got a read-only "
                            f"{type(buffer).__name__}")
        avail = buffers.nbytes(mv) - off
        if avail < spec.size:
            raise ValueError(f"{spec.typeString} needs {spec.size} bytes at offset {off}, "
                             f"the buffer has {max(avail, 0)}")
        spec.struct.pack_into(mv, off, *values)


def packArray(seq: Iterable[StructValue]) -> bytes:
    """Pack a sequence of objects of one type as the ``struct:<Name>[]`` value: the
    packed elements back to back, no count prefix. An empty sequence packs to ``b""``.
    Mixed element types (or SwerveDriveKinematics with different module counts) raise
    TypeError."""
    # A snapshot in one C call: no finalizer or thread can change it while it is packed.
    items = tuple(seq)
    if not items:
        return b""
    first = items[0]
    spec = _spec_of_instance(first)
    cls = type(first)
    e = _REPEATED.get(cls)
    if e is not None and e.struct is not None and e.struct.repeats is not None:
        counts = {e.struct.repeats(o) for o in items if type(o) is cls}
        if len(counts) > 1:
            raise TypeError(f"packArray() elements must share one struct type; got "
                            f"{cls.__name__} with {sorted(counts)} modules")
    flatten = spec.flatten
    pack_one = spec.struct.pack
    parts = []
    for o in items:
        if type(o) is not cls:
            i = next(j for j, x in enumerate(items) if type(x) is not cls)
            raise TypeError(f"packArray() elements must all be {cls.__name__}; element "
                            f"{i} is {type_name(items[i])}")
        parts.append(pack_one(*flatten(o)))
    return b"".join(parts)


# ---------------------------------------------------------------------------------------
# Unpacking

def unpack(cls: type[T], data: BytesLike, offset: int = 0, *,
           numModules: int | None = None) -> T:
    """Decode one ``cls`` from ``data[offset:]``, which must be exactly
    :func:`getSize` bytes long (as robotpy and WPILib C++ require). Returns a new object;
    Rotation2d members come back as ``Rotation2d(value)``, Rotation3d members as
    ``Rotation3d(Quaternion(w, x, y, z))`` (normalised as WPILib does).

    For ``cls=SwerveDriveKinematics`` the module count N is ``numModules`` if given, else
    inferred as ``(len(data) - offset) // 16`` (the length must be a multiple of 16 and
    at least 32 bytes). To read a struct embedded in a longer buffer use
    :func:`unpackFrom`.

    TypeError: ``cls`` is not a supported class or ``data`` is not bytes-like.
    ValueError: wrong byte count, or values the drivekin constructor rejects.
    """
    if (numModules is None and type(offset) is int and offset == 0
            and (type(data) is bytes or type(data) is bytearray) and type(cls) is type):
        fast = _SPECS.get(cls)                   # fast path, same checks as below
        if fast is not None:
            if len(data) != fast.size:
                raise ValueError(f"{fast.typeString} is {fast.size} bytes, got {len(data)} "
                                 f"(buffer of {len(data)} bytes, offset 0)")
            result: T = fast.build(*fast.struct.unpack(data))
            return result
    # Every argument that may run Python code (numModules.__index__, offset.__index__)
    # is validated before the buffer is viewed.
    spec: _Spec | None = None
    repeated = (_REPEATED.get(cls) if isinstance(cls, type) and numModules is None
                else None)
    if repeated is None:
        spec = _spec_of_class(cls, numModules, "unpack")
    off = _check_offset(offset)
    with buffers.view(data) as mv:
        avail = buffers.nbytes(mv) - off
        if spec is None:
            st = repeated.struct  # type: ignore[union-attr]
            assert st is not None
            member = 8 * st.count
            if avail < member * st.least or avail % member:
                raise ValueError(
                    f"cannot infer the module count of a {st.name} from "
                    f"{max(avail, 0)} bytes: need a multiple of {member} bytes, at least "
                    f"{member * st.least} (N >= {st.least} modules)")
            spec = _repeated_spec(cls, avail // member)
        else:
            if avail != spec.size:
                raise ValueError(f"{spec.typeString} is {spec.size} bytes, got "
                                 f"{max(avail, 0)} (buffer of {buffers.nbytes(mv)} "
                                 f"bytes, offset {off})")
        values = spec.struct.unpack_from(mv, off)
    obj: T = spec.build(*values)
    return obj


def unpackFrom(cls: type[T], data: BytesLike, offset: int = 0, *,
               numModules: int | None = None) -> T:
    """Like :func:`unpack` but reads :func:`getSize` bytes at ``offset`` and ignores any
    bytes after them (``struct.unpack_from`` semantics), for structs embedded in a larger
    buffer. ``SwerveDriveKinematics`` needs ``numModules`` here (nothing to infer it from).
    ValueError if fewer than :func:`getSize` bytes follow ``offset``."""
    spec = _spec_of_class(cls, numModules, "unpackFrom")
    off = _check_offset(offset)
    with buffers.view(data) as mv:
        avail = buffers.nbytes(mv) - off
        if avail < spec.size:
            raise ValueError(f"{spec.typeString} is {spec.size} bytes, only "
                             f"{max(avail, 0)} available at offset {off}")
        values = spec.struct.unpack_from(mv, off)
    obj: T = spec.build(*values)
    return obj


def unpackArray(cls: type[T], data: BytesLike, *,
                numModules: int | None = None) -> list[T]:
    """Decode a ``struct:<Name>[]`` value: ``len(data)`` must be a multiple of
    :func:`getSize` (an empty buffer gives ``[]``). For SwerveDriveKinematics pass
    ``numModules`` (the element size cannot be inferred from an array)."""
    spec = _spec_of_class(cls, numModules, "unpackArray")
    with buffers.view(data) as mv:
        nbytes = buffers.nbytes(mv)
        if nbytes % spec.size:
            raise ValueError(f"a {spec.typeString}[] value must be a multiple of "
                             f"{spec.size} bytes, got {nbytes}")
        rows = list(spec.struct.iter_unpack(mv))   # before the view is released
    build = spec.build
    return [build(*row) for row in rows]
