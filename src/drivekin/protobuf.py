"""WPILib protobuf serialization for drivekin's value types and kinematics classes, with
the WPILib 2027 message names and schemas (``package wpi.proto``).

Needs the optional ``protobuf`` package (``pip install "drivekin[protobuf]"``, protobuf
>= 4.22). It is imported on first use, never by ``import drivekin``;
:func:`getTypeName` and :func:`getTypeString` work without it.

The bytes are what WPILib 2027 Java/C++ sends to NetworkTables and DataLog for the same
values under the type string ``proto:wpi.proto.<Message>``. A publisher must also send
the schema: each ``.proto`` file's serialized ``FileDescriptorProto``, dependencies first,
under the name ``proto:<file name>`` with type ``proto:FileDescriptorProto``
(:data:`SCHEMA_TYPE`) — :func:`forEachDescriptor` yields exactly those. The three files::

    wpimath/protobuf/geometry2d.proto   ProtobufTranslation2d {double x = 1; double y = 2}
                                        ProtobufRotation2d {double value = 1}
                                        ProtobufPose2d, ProtobufTransform2d
                                          {ProtobufTranslation2d translation = 1;
                                           ProtobufRotation2d rotation = 2}
                                        ProtobufTwist2d {double dx = 1; dy = 2; dtheta = 3}
    wpimath/protobuf/geometry3d.proto   ProtobufTranslation3d {double x = 1; y = 2; z = 3}
                                        ProtobufQuaternion {double w = 1; x = 2; y = 3;
                                                            z = 4}
                                        ProtobufRotation3d {ProtobufQuaternion q = 1}
                                        ProtobufPose3d, ProtobufTransform3d
                                          {ProtobufTranslation3d translation = 1;
                                           ProtobufRotation3d rotation = 2}
                                        ProtobufTwist3d {double dx = 1; dy = 2; dz = 3;
                                                         rx = 4; ry = 5; rz = 6}
    wpimath/protobuf/kinematics.proto   (imports geometry2d.proto)
      ProtobufChassisVelocities {double vx = 1; vy = 2; omega = 3}
      ProtobufChassisAccelerations {double ax = 1; ay = 2; alpha = 3}
      ProtobufSwerveModuleVelocity {double velocity = 1; ProtobufRotation2d angle = 2}
      ProtobufSwerveModulePosition {double distance = 1; ProtobufRotation2d angle = 2}
      ProtobufSwerveModuleAcceleration {double acceleration = 1; ProtobufRotation2d angle = 2}
      ProtobufMecanumDriveWheelVelocities, ...Positions, ...Accelerations
        {double front_left = 1; front_right = 2; rear_left = 3; rear_right = 4}
      ProtobufDifferentialDriveWheelVelocities, ...Positions, ...Accelerations
        {double left = 1; right = 2}
      ProtobufDifferentialDriveKinematics {double trackwidth = 1}
      ProtobufMecanumDriveKinematics {ProtobufTranslation2d front_left = 1; front_right = 2;
                                      rear_left = 3; rear_right = 4}
      ProtobufSwerveDriveKinematics {repeated ProtobufTranslation2d modules = 1}

(2026 WPILib named four of them ``ProtobufChassisSpeeds``, ``ProtobufSwerveModuleState``
``{double speed = 1; ...}``, ``ProtobufMecanumDriveWheelSpeeds`` and
``ProtobufDifferentialDriveWheelSpeeds``; the field numbers, and so the bytes, are the
same.)

As in the struct format (:mod:`drivekin.wpistruct`), a Rotation2d is sent as its
:meth:`~drivekin.Rotation2d.getRadians` — the wrapped value in [−π, π] — and read back
with ``Rotation2d(value)``; a Rotation3d is sent as its stored quaternion and read back
with ``Rotation3d(Quaternion(w, x, y, z))``, which normalises it as WPILib does (a
missing ``q`` is the zero quaternion, which gives the identity). Encoding follows
proto3: a double field equal to +0.0 is left out (−0.0 is written), nested messages are
always written, even when all their fields are zero; a field or nested message missing
from the input reads as 0, and unknown fields are skipped, as in every protobuf decoder.
The descriptors equal what ``protoc`` produces from WPILib's ``.proto`` files without
their ``option java_*`` lines. Only the kinematics geometry is serialized: an unpacked
SwerveDriveKinematics starts with fresh heading memory.

Functions: :func:`getTypeName`, :func:`getTypeString`, :func:`getMessageClass`,
:func:`forEachDescriptor` (describe a type, from the class or an instance);
:func:`pack`, :func:`unpack`. :data:`PROTOBUF_TYPES` lists the supported classes.

Errors: unsupported objects or classes raise TypeError; bytes that are not a valid
message raise ValueError naming the message; so do values the drivekin constructors
reject (a trackwidth that is not positive and finite, fewer than two swerve modules,
NaN/inf module positions), exactly as :func:`drivekin.wpistruct.unpack` does for the
same values. :func:`unpack` takes any C-contiguous bytes-like object of plain bytes or
numbers (bytes, bytearray, memoryview, numeric numpy arrays); buffers of Python objects
are refused with TypeError.

Example::

    >>> from drivekin import ChassisVelocities
    >>> from drivekin import protobuf
    >>> data = protobuf.pack(ChassisVelocities(1.0, 2.0, 3.0))
    >>> data.hex()
    '09000000000000f03f110000000000000040190000000000000840'
    >>> protobuf.getTypeString(ChassisVelocities)
    'proto:wpi.proto.ProtobufChassisVelocities'
    >>> protobuf.unpack(ChassisVelocities, data) == ChassisVelocities(1.0, 2.0, 3.0)
    True
"""
from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any, TypeVar, Union

from drivekin._core import catalog
from drivekin._core import buffers
from drivekin._core.catalog import GEOMETRY2D_FILE, GEOMETRY3D_FILE, KINEMATICS_FILE
# ProtobufValue: any object this module can pack (the catalog's union of its classes).
from drivekin._core.catalog import SerializableValue as ProtobufValue
from drivekin._core.errors import type_name

__all__ = [
    "GEOMETRY2D_FILE",
    "GEOMETRY3D_FILE",
    "KINEMATICS_FILE",
    "PACKAGE",
    "PROTOBUF_TYPES",
    "ProtobufValue",
    "SCHEMA_TYPE",
    "forEachDescriptor",
    "getMessageClass",
    "getTypeName",
    "getTypeString",
    "pack",
    "unpack",
]

#: Bytes-like input: anything exporting the buffer protocol as C-contiguous memory.
BytesLike = Union[bytes, bytearray, memoryview, Any]

T = TypeVar("T")

#: The protobuf package of every message here.
PACKAGE = "wpi.proto"
# GEOMETRY2D_FILE, GEOMETRY3D_FILE and KINEMATICS_FILE (from the catalog): the file names
# WPILib 2027 gives its descriptors (the schema names are ``"proto:"`` + these).
#: The NetworkTables/DataLog type of a schema entry holding a serialized FileDescriptorProto.
SCHEMA_TYPE = "proto:FileDescriptorProto"

_INSTALL_HINT = 'drivekin.protobuf needs the "protobuf" package (>= 4.22): ' \
                'pip install "drivekin[protobuf]"'


# ---------------------------------------------------------------------------------------
# The schemas, as data: the catalog's messages, by file in WPILib's declaration order.
# A field is (name, number, message type or None for double, repeated). The descriptors
# are built from these tables, so there is no generated code and no .proto file to ship.

# Each file after its dependencies (the descriptor pool takes them in this order).
_DEPENDENCIES: dict[str, tuple[str, ...]] = {GEOMETRY2D_FILE: (), GEOMETRY3D_FILE: (),
                                             KINEMATICS_FILE: (GEOMETRY2D_FILE,)}
_PROTOS = sorted((e.proto for e in catalog.ENTRIES if e.proto is not None),
                 key=lambda p: p.index)
_FIELDS: dict[str, tuple[catalog.Field, ...]] = {p.message: p.fields for p in _PROTOS}
# file name -> (dependencies, [(message, fields), ...])
_FILES: dict[str, tuple[tuple[str, ...], tuple[tuple[str, tuple[catalog.Field, ...]], ...]]] = {
    f: (deps, tuple((p.message, p.fields) for p in _PROTOS if p.file == f))
    for f, deps in _DEPENDENCIES.items()}


# ---------------------------------------------------------------------------------------
# The protobuf runtime, built once on first use.

class _Runtime:
    __slots__ = ("classes", "files", "DecodeError")

    def __init__(self) -> None:
        try:
            from google.protobuf import descriptor_pb2, descriptor_pool, message_factory
            from google.protobuf.message import DecodeError
            get_class = message_factory.GetMessageClass
        except (ImportError, AttributeError) as e:   # AttributeError: protobuf < 4.22
            raise ImportError(_INSTALL_HINT) from e
        # A private pool: WPILib's own generated code (or another library) may have put
        # files of the same names into the default pool.
        pool = descriptor_pool.DescriptorPool()
        d = descriptor_pb2.FieldDescriptorProto
        self.files: dict[str, bytes] = {}
        for fname, (deps, messages) in _FILES.items():
            fdp = descriptor_pb2.FileDescriptorProto(
                name=fname, package=PACKAGE, syntax="proto3", dependency=deps)
            for mname, fields in messages:
                m = fdp.message_type.add(name=mname)
                for name, number, sub, repeated in fields:
                    f = m.field.add(
                        name=name, number=number, json_name=_json_name(name),
                        label=d.LABEL_REPEATED if repeated else d.LABEL_OPTIONAL)
                    if sub is None:
                        f.type = d.TYPE_DOUBLE
                    else:
                        f.type = d.TYPE_MESSAGE
                        f.type_name = f".{PACKAGE}.{sub}"
            pool.Add(fdp)
            self.files[fname] = fdp.SerializeToString()
        self.classes: dict[str, Any] = {
            mname: get_class(pool.FindMessageTypeByName(f"{PACKAGE}.{mname}"))
            for _, messages in _FILES.values() for mname, _ in messages}
        self.DecodeError: type[Exception] = DecodeError


def _json_name(name: str) -> str:
    # protoc's lowerCamelCase json_name ("front_left" -> "frontLeft"), which it records
    # in every descriptor it writes.
    head, *rest = name.split("_")
    return head + "".join(p[:1].upper() + p[1:] for p in rest)


_runtime_lock = threading.Lock()
_runtime_obj: _Runtime | None = None


def _runtime() -> _Runtime:
    global _runtime_obj
    rt = _runtime_obj
    if rt is None:
        with _runtime_lock:      # one pool, so getMessageClass always returns one class
            rt = _runtime_obj
            if rt is None:
                rt = _runtime_obj = _Runtime()
    return rt


# ---------------------------------------------------------------------------------------
# Conversions, from the catalog's wire forms: a message holds the same doubles as the
# struct, in field order, nested messages contributing theirs in place (a repeated field
# takes the rest). Nested messages are passed to the constructor, which marks them
# present even when all their fields are zero. (The recursion follows the schema, whose
# depth is fixed, never the input.)

def _make(M: dict[str, Any], message: str, v: tuple[float, ...], i: int) -> tuple[Any, int]:
    fields: dict[str, Any] = {}
    for name, _, sub, repeated in _FIELDS[message]:
        if sub is None:
            fields[name] = v[i]
            i += 1
        elif repeated:
            items = []
            while i < len(v):
                item, i = _make(M, sub, v, i)
                items.append(item)
            fields[name] = items
        else:
            fields[name], i = _make(M, sub, v, i)
    return M[message](**fields), i


def _read(msg: Any, message: str, out: list[float]) -> None:
    for name, _, sub, repeated in _FIELDS[message]:
        value = getattr(msg, name)
        if sub is None:
            out.append(value)
        elif repeated:
            for item in value:
                _read(item, sub, out)
        else:
            _read(value, sub, out)


class _Spec:
    __slots__ = ("cls", "message", "file", "typeName", "typeString", "flatten", "build")

    def __init__(self, e: catalog.Entry) -> None:
        assert e.proto is not None and e.flatten is not None and e.build is not None
        self.cls, self.message, self.file = e.cls, e.proto.message, e.proto.file
        self.typeName = f"{PACKAGE}.{self.message}"
        self.typeString = "proto:" + self.typeName
        self.flatten = e.flatten
        self.build = _checked(self.typeName, e.build) if e.kind == "kinematics" else e.build

    def make(self, M: dict[str, Any], obj: Any) -> Any:
        return _make(M, self.message, self.flatten(obj), 0)[0]

    def read(self, msg: Any) -> Any:
        values: list[float] = []
        _read(msg, self.message, values)
        return self.build(*values)


def _checked(name: str, build: Callable[..., Any]) -> Callable[..., Any]:
    """Values a kinematics constructor rejects surface as ``ValueError("cannot unpack
    <message>: ...")``."""
    def checked(*v: float) -> Any:
        try:
            return build(*v)
        except ValueError as e:   # includes numpy.linalg.LinAlgError
            raise ValueError(f"cannot unpack {name}: {e}") from e
    return checked


_SPECS: dict[type, _Spec] = {e.cls: _Spec(e) for e in catalog.ENTRIES if e.proto is not None}

#: Every drivekin class this module can serialize.
PROTOBUF_TYPES: tuple[type, ...] = tuple(_SPECS)

_SUPPORTED = ", ".join(c.__name__ for c in PROTOBUF_TYPES)


# ---------------------------------------------------------------------------------------
# Lookup helpers

def _spec_of(x: object) -> _Spec:
    """Spec for a supported class or instance."""
    if isinstance(x, type):
        spec = _SPECS.get(x)
        if spec is None:
            raise TypeError(f"{x.__module__}.{x.__qualname__} has no WPILib protobuf "
                            f"serialization here; supported: {_SUPPORTED}")
        return spec
    spec = _SPECS.get(type(x))
    if spec is None:
        raise TypeError(f"cannot serialize a {type_name(x)} as protobuf; supported "
                        f"drivekin types: {_SUPPORTED}")
    return spec


def _spec_of_class(cls: object, what: str) -> _Spec:
    if not isinstance(cls, type):
        raise TypeError(f"{what}() takes a class as its first argument (e.g. "
                        f"drivekin.Pose2d), got a {type_name(cls)} instance")
    return _spec_of(cls)


# ---------------------------------------------------------------------------------------
# Descriptors

def getTypeName(x: object) -> str:
    """Return the full protobuf message name of a supported class or instance, e.g.
    ``getTypeName(ChassisVelocities)`` → ``"wpi.proto.ProtobufChassisVelocities"``.
    Unsupported types raise TypeError. Does not need the protobuf package."""
    return _spec_of(x).typeName


def getTypeString(x: object) -> str:
    """Return the NetworkTables/DataLog type string ``"proto:" + getTypeName(x)``, e.g.
    ``"proto:wpi.proto.ProtobufChassisVelocities"``. Does not need the protobuf
    package."""
    return _spec_of(x).typeString


def getMessageClass(x: object) -> Any:
    """Return the ``google.protobuf`` message class for a supported class or instance
    (built from this module's descriptors in a private descriptor pool; the same class
    on every call). ``getMessageClass(Pose2d).FromString(pack(pose))`` gives the
    message itself."""
    spec = _spec_of(x)
    return _runtime().classes[spec.message]


def forEachDescriptor(x: object, fn: Callable[[str, bytes], object], *,
                      exists: Callable[[str], object] | None = None) -> None:
    """Call ``fn(name, descriptor)`` for every ``.proto`` file needed to decode ``x``'s
    message, dependencies first: ``name`` is ``"proto:" + file name`` (e.g.
    ``"proto:wpimath/protobuf/geometry2d.proto"``) and ``descriptor`` the file's
    serialized ``google.protobuf.FileDescriptorProto``. Publish each as a schema of type
    :data:`SCHEMA_TYPE` (``proto:FileDescriptorProto``), as WPILib's
    ``addSchema``/``forEachDescriptor`` do.

    ``exists(name)``, if given, is asked first for each file: when it returns true the
    file *and its dependencies* are skipped (WPILib's rule; pass e.g. a
    NetworkTables instance's ``hasSchema``)."""
    spec = _spec_of(x)
    files = _runtime().files
    seen: set[str] = set()

    def visit(fname: str) -> None:
        name = "proto:" + fname
        if name in seen or (exists is not None and exists(name)):
            return
        seen.add(name)
        for dep in _FILES[fname][0]:
            visit(dep)
        fn(name, files[fname])

    visit(spec.file)


# ---------------------------------------------------------------------------------------
# Packing and unpacking

def pack(obj: ProtobufValue) -> bytes:
    """Return the serialized protobuf message of ``obj`` (type
    :func:`getTypeString`). Rotation2d members are written as ``getRadians()``
    (wrapped to [−π, π]), Rotation3d members as their quaternion. Raises TypeError for
    unsupported objects (including classes instead of instances)."""
    spec = _SPECS.get(type(obj))
    if spec is None:
        if isinstance(obj, type):
            raise TypeError(f"cannot serialize the class {obj.__module__}."
                            f"{obj.__qualname__} itself: pass an instance")
        spec = _spec_of(obj)
    data: bytes = spec.make(_runtime().classes, obj).SerializeToString()
    return data


def unpack(cls: type[T], data: BytesLike) -> T:
    """Decode one ``cls`` from the serialized message ``data`` (the whole buffer).
    Returns a new object; Rotation2d members come back as ``Rotation2d(value)``,
    Rotation3d members as ``Rotation3d(Quaternion(w, x, y, z))`` (normalised as WPILib
    does).

    TypeError: ``cls`` is not a supported class or ``data`` is not bytes-like.
    ValueError: ``data`` is not a valid message of that type (truncated or garbage
    bytes), or holds values the drivekin constructor rejects."""
    spec = _spec_of_class(cls, "unpack")
    rt = _runtime()
    if type(data) is not bytes:
        with buffers.view(data) as mv:
            buffers.nbytes(mv)                # C-contiguous, or TypeError
            data = mv.tobytes()                # a copy: the caller may change theirs
    msg = rt.classes[spec.message]()
    try:
        msg.ParseFromString(data)
    except rt.DecodeError as e:
        raise ValueError(f"cannot unpack {spec.typeName}: not a valid message "
                         f"({e})") from None
    obj: T = spec.read(msg)
    return obj
