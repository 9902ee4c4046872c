"""WPILib protobuf serialization for drivekin's value types and kinematics classes, with
the WPILib 2027 message names and schemas (``package wpi.proto``).

Needs the optional ``protobuf`` package (``pip install "drivekin[protobuf]"``, protobuf
>= 4.22). It is imported on first use, never by ``import drivekin``;
:func:`getTypeName` and :func:`getTypeString` work without it.

The bytes are what WPILib 2027 Java/C++ sends to NetworkTables and DataLog for the same
values under the type string ``proto:wpi.proto.<Message>``. A publisher must also send
the schema: each ``.proto`` file's serialized ``FileDescriptorProto``, dependencies first,
under the name ``proto:<file name>`` with type ``proto:FileDescriptorProto``
(:data:`SCHEMA_TYPE`) — :func:`forEachDescriptor` yields exactly those. The two files::

    wpimath/protobuf/geometry2d.proto   ProtobufTranslation2d {double x = 1; double y = 2}
                                        ProtobufRotation2d {double value = 1}
                                        ProtobufPose2d, ProtobufTransform2d
                                          {ProtobufTranslation2d translation = 1;
                                           ProtobufRotation2d rotation = 2}
                                        ProtobufTwist2d {double dx = 1; dy = 2; dtheta = 3}
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
with ``Rotation2d(value)``. Encoding follows proto3: a double field equal to +0.0 is
left out (−0.0 is written), nested messages are always written, even when all their
fields are zero; a field or nested message missing from the input reads as 0, and
unknown fields are skipped, as in every protobuf decoder. The descriptors equal what
``protoc`` produces from WPILib's ``.proto`` files without their ``option java_*``
lines. Only the kinematics geometry is serialized: an unpacked SwerveDriveKinematics
starts with fresh heading memory.

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

from drivekin._core.errors import type_name
from drivekin.differential import (
    DifferentialDriveKinematics,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
)
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d
from drivekin.kinematics import (
    ChassisAccelerations,
    ChassisVelocities,
    SwerveDriveKinematics,
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
)
from drivekin.mecanum import (
    MecanumDriveKinematics,
    MecanumDriveWheelAccelerations,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
)
# The buffer checks are wpistruct's: one rule for which bytes-like inputs are plain data.
from drivekin.wpistruct import _nbytes, _view

__all__ = [
    "GEOMETRY2D_FILE",
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

ProtobufValue = Union[
    Translation2d, Rotation2d, Pose2d, Transform2d, Twist2d,
    ChassisVelocities, ChassisAccelerations,
    SwerveModuleVelocity, SwerveModulePosition, SwerveModuleAcceleration,
    MecanumDriveWheelVelocities, MecanumDriveWheelPositions, MecanumDriveWheelAccelerations,
    DifferentialDriveWheelVelocities, DifferentialDriveWheelPositions,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveKinematics, MecanumDriveKinematics, SwerveDriveKinematics,
]
"""Any object this module can pack (a union of the supported drivekin classes)."""

#: Bytes-like input: anything exporting the buffer protocol as C-contiguous memory.
BytesLike = Union[bytes, bytearray, memoryview, Any]

T = TypeVar("T")

#: The protobuf package of every message here.
PACKAGE = "wpi.proto"
#: File names WPILib 2027 gives its descriptors (the schema names are ``"proto:"`` + these).
GEOMETRY2D_FILE = "wpimath/protobuf/geometry2d.proto"
KINEMATICS_FILE = "wpimath/protobuf/kinematics.proto"
#: The NetworkTables/DataLog type of a schema entry holding a serialized FileDescriptorProto.
SCHEMA_TYPE = "proto:FileDescriptorProto"

_INSTALL_HINT = 'drivekin.protobuf needs the "protobuf" package (>= 4.22): ' \
                'pip install "drivekin[protobuf]"'


# ---------------------------------------------------------------------------------------
# The schemas, as data. A field is (name, number, message type or None for double,
# repeated). The descriptors are built from these tables, so there is no generated code
# and no .proto file to ship.

_Field = tuple[str, int, Union[str, None], bool]


def _doubles(*names: str) -> tuple[_Field, ...]:
    return tuple((n, i, None, False) for i, n in enumerate(names, 1))


def _value_and_angle(name: str) -> tuple[_Field, ...]:
    return ((name, 1, None, False), ("angle", 2, "ProtobufRotation2d", False))


_POSE_FIELDS: tuple[_Field, ...] = (("translation", 1, "ProtobufTranslation2d", False),
                                    ("rotation", 2, "ProtobufRotation2d", False))
_MECANUM = ("front_left", "front_right", "rear_left", "rear_right")

# file name -> (dependencies, [(message, fields), ...]) in WPILib's declaration order.
_FILES: dict[str, tuple[tuple[str, ...], tuple[tuple[str, tuple[_Field, ...]], ...]]] = {
    GEOMETRY2D_FILE: ((), (
        ("ProtobufTranslation2d", _doubles("x", "y")),
        ("ProtobufRotation2d", _doubles("value")),
        ("ProtobufPose2d", _POSE_FIELDS),
        ("ProtobufTransform2d", _POSE_FIELDS),
        ("ProtobufTwist2d", _doubles("dx", "dy", "dtheta")),
    )),
    KINEMATICS_FILE: ((GEOMETRY2D_FILE,), (
        ("ProtobufChassisVelocities", _doubles("vx", "vy", "omega")),
        ("ProtobufChassisAccelerations", _doubles("ax", "ay", "alpha")),
        ("ProtobufDifferentialDriveKinematics", _doubles("trackwidth")),
        ("ProtobufDifferentialDriveWheelVelocities", _doubles("left", "right")),
        ("ProtobufDifferentialDriveWheelAccelerations", _doubles("left", "right")),
        ("ProtobufDifferentialDriveWheelPositions", _doubles("left", "right")),
        ("ProtobufMecanumDriveKinematics",
         tuple((n, i, "ProtobufTranslation2d", False) for i, n in enumerate(_MECANUM, 1))),
        ("ProtobufMecanumDriveWheelPositions", _doubles(*_MECANUM)),
        ("ProtobufMecanumDriveWheelVelocities", _doubles(*_MECANUM)),
        ("ProtobufMecanumDriveWheelAccelerations", _doubles(*_MECANUM)),
        ("ProtobufSwerveDriveKinematics", (("modules", 1, "ProtobufTranslation2d", True),)),
        ("ProtobufSwerveModulePosition", _value_and_angle("distance")),
        ("ProtobufSwerveModuleVelocity", _value_and_angle("velocity")),
        ("ProtobufSwerveModuleAcceleration", _value_and_angle("acceleration")),
    )),
}


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
# Per-type conversions. ``make(M, obj)`` builds the message (``M``: message classes by
# name); ``read(msg)`` builds the drivekin object. Nested messages are passed to the
# constructor, which marks them present even when all their fields are zero.

class _Spec:
    __slots__ = ("cls", "message", "file", "typeName", "typeString", "make", "read")

    def __init__(self, cls: type, message: str, file: str,
                 make: Callable[[dict[str, Any], Any], Any],
                 read: Callable[[Any], Any]) -> None:
        self.cls, self.message, self.file = cls, message, file
        self.typeName = f"{PACKAGE}.{message}"
        self.typeString = "proto:" + self.typeName
        self.make, self.read = make, read


_SPECS: dict[type, _Spec] = {}


def _register(cls: type, message: str, file: str,
              make: Callable[[dict[str, Any], Any], Any], read: Callable[[Any], Any],
              checked: bool = False) -> None:
    if checked:
        read = _checked(f"{PACKAGE}.{message}", read)
    _SPECS[cls] = _Spec(cls, message, file, make, read)


def _checked(name: str, read: Callable[[Any], Any]) -> Callable[[Any], Any]:
    """Values a kinematics constructor rejects surface as ``ValueError("cannot unpack
    <message>: ...")``."""
    def checked(msg: Any) -> Any:
        try:
            return read(msg)
        except ValueError as e:   # includes numpy.linalg.LinAlgError
            raise ValueError(f"cannot unpack {name}: {e}") from e
    return checked


_R = Rotation2d
_T = Translation2d
_G = GEOMETRY2D_FILE
_K = KINEMATICS_FILE


def _tr(M: dict[str, Any], t: Translation2d) -> Any:
    return M["ProtobufTranslation2d"](x=t.getX(), y=t.getY())


def _rot(M: dict[str, Any], r: Rotation2d) -> Any:
    return M["ProtobufRotation2d"](value=r.getRadians())


def _make_pose(message: str) -> Callable[[dict[str, Any], Any], Any]:
    def make(M: dict[str, Any], p: Any) -> Any:
        return M[message](translation=M["ProtobufTranslation2d"](x=p.getX(), y=p.getY()),
                          rotation=_rot(M, p.getRotation()))
    return make


_register(Translation2d, "ProtobufTranslation2d", _G, _tr, lambda m: _T(m.x, m.y))
_register(Rotation2d, "ProtobufRotation2d", _G, _rot, lambda m: _R(m.value))
_register(Pose2d, "ProtobufPose2d", _G, _make_pose("ProtobufPose2d"),
          lambda m: Pose2d(m.translation.x, m.translation.y, _R(m.rotation.value)))
_register(Transform2d, "ProtobufTransform2d", _G, _make_pose("ProtobufTransform2d"),
          lambda m: Transform2d(m.translation.x, m.translation.y, _R(m.rotation.value)))
_register(Twist2d, "ProtobufTwist2d", _G,
          lambda M, t: M["ProtobufTwist2d"](dx=t.dx, dy=t.dy, dtheta=t.dtheta),
          lambda m: Twist2d(m.dx, m.dy, m.dtheta))
_register(ChassisVelocities, "ProtobufChassisVelocities", _K,
          lambda M, c: M["ProtobufChassisVelocities"](vx=c.vx, vy=c.vy, omega=c.omega),
          lambda m: ChassisVelocities(m.vx, m.vy, m.omega))
_register(ChassisAccelerations, "ProtobufChassisAccelerations", _K,
          lambda M, c: M["ProtobufChassisAccelerations"](ax=c.ax, ay=c.ay, alpha=c.alpha),
          lambda m: ChassisAccelerations(m.ax, m.ay, m.alpha))
_register(SwerveModuleVelocity, "ProtobufSwerveModuleVelocity", _K,
          lambda M, s: M["ProtobufSwerveModuleVelocity"](velocity=s.velocity,
                                                         angle=_rot(M, s.angle)),
          lambda m: SwerveModuleVelocity(m.velocity, _R(m.angle.value)))
_register(SwerveModulePosition, "ProtobufSwerveModulePosition", _K,
          lambda M, s: M["ProtobufSwerveModulePosition"](distance=s.distance,
                                                         angle=_rot(M, s.angle)),
          lambda m: SwerveModulePosition(m.distance, _R(m.angle.value)))
_register(SwerveModuleAcceleration, "ProtobufSwerveModuleAcceleration", _K,
          lambda M, s: M["ProtobufSwerveModuleAcceleration"](acceleration=s.acceleration,
                                                             angle=_rot(M, s.angle)),
          lambda m: SwerveModuleAcceleration(m.acceleration, _R(m.angle.value)))


def _wheels(cls: type, kind: str) -> None:
    message = f"Protobuf{cls.__name__}"
    if kind == "mecanum":
        _register(cls, message, _K,
                  lambda M, w: M[message](front_left=w.frontLeft, front_right=w.frontRight,
                                          rear_left=w.rearLeft, rear_right=w.rearRight),
                  lambda m: cls(m.front_left, m.front_right, m.rear_left, m.rear_right))
    else:
        _register(cls, message, _K, lambda M, w: M[message](left=w.left, right=w.right),
                  lambda m: cls(m.left, m.right))


_wcls: type
for _wcls in (MecanumDriveWheelVelocities, MecanumDriveWheelPositions,
              MecanumDriveWheelAccelerations):
    _wheels(_wcls, "mecanum")
for _wcls in (DifferentialDriveWheelVelocities, DifferentialDriveWheelPositions,
              DifferentialDriveWheelAccelerations):
    _wheels(_wcls, "differential")
del _wcls

_register(DifferentialDriveKinematics, "ProtobufDifferentialDriveKinematics", _K,
          lambda M, k: M["ProtobufDifferentialDriveKinematics"](trackwidth=k.trackwidth),
          lambda m: DifferentialDriveKinematics(m.trackwidth), checked=True)
_register(MecanumDriveKinematics, "ProtobufMecanumDriveKinematics", _K,
          lambda M, k: M["ProtobufMecanumDriveKinematics"](
              front_left=_tr(M, k.getFrontLeft()), front_right=_tr(M, k.getFrontRight()),
              rear_left=_tr(M, k.getRearLeft()), rear_right=_tr(M, k.getRearRight())),
          lambda m: MecanumDriveKinematics(
              _T(m.front_left.x, m.front_left.y), _T(m.front_right.x, m.front_right.y),
              _T(m.rear_left.x, m.rear_left.y), _T(m.rear_right.x, m.rear_right.y)),
          checked=True)


def _read_swerve(m: Any) -> SwerveDriveKinematics:
    modules = [_T(t.x, t.y) for t in m.modules]
    if len(modules) < 2:
        raise ValueError(f"a swerve drive needs at least 2 modules, got {len(modules)}")
    return SwerveDriveKinematics(modules)


_register(SwerveDriveKinematics, "ProtobufSwerveDriveKinematics", _K,
          lambda M, k: M["ProtobufSwerveDriveKinematics"](
              modules=[_tr(M, t) for t in k.getModules()]),
          _read_swerve, checked=True)

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
    (wrapped to [−π, π]). Raises TypeError for unsupported objects (including classes
    instead of instances)."""
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
    Returns a new object; Rotation2d members come back as ``Rotation2d(value)``.

    TypeError: ``cls`` is not a supported class or ``data`` is not bytes-like.
    ValueError: ``data`` is not a valid message of that type (truncated or garbage
    bytes), or holds values the drivekin constructor rejects."""
    spec = _spec_of_class(cls, "unpack")
    rt = _runtime()
    if type(data) is not bytes:
        with _view(data) as mv:
            _nbytes(mv)                        # C-contiguous, or TypeError
            data = mv.tobytes()                # a copy: the caller may change theirs
    msg = rt.classes[spec.message]()
    try:
        msg.ParseFromString(data)
    except rt.DecodeError as e:
        raise ValueError(f"cannot unpack {spec.typeName}: not a valid message "
                         f"({e})") from None
    obj: T = spec.read(msg)
    return obj
