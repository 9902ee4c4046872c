"""Helpers for error messages (only called on error paths, so plain Python)."""
from __future__ import annotations


def clip(text: str, n: int = 60) -> str:
    """``repr(text)``, shortened to about ``n`` characters (names and schema text come
    from the file and may be huge)."""
    return repr(text) if len(text) <= n else repr(text[:n]) + f"... ({len(text)} characters)"


def cut(text: str, n: int = 60) -> str:
    """``text`` as it is, shortened to about ``n`` characters."""
    return text if len(text) <= n else text[:n] + f"... ({len(text)} characters)"


def type_name(obj: object, expected: type | None = None) -> str:
    """Name ``type(obj)`` for an error message.

    Builtins and drivekin's own classes are named bare; anything else carries its module,
    so a robotpy ``wpimath.geometry._geometry.Translation2d`` passed where drivekin's
    Translation2d belongs is not reported as "got Translation2d". A robotpy-wpimath
    object that :mod:`drivekin.interop` converts also gets the call that converts it
    (``fromWpimath``, or ``fromWpimath3d`` for a 3-D one where the 2-D value belongs) —
    when ``expected`` is given, only a call that gives an ``expected`` (a robotpy Pose2d
    where a Rotation2d belongs gets no hint).
    """
    t = type(obj)
    module = getattr(t, "__module__", None) or ""
    name = getattr(t, "__qualname__", t.__name__)
    if module == "builtins" or module == "drivekin" or module.startswith("drivekin."):
        return name
    return f"{module}.{name}{_robotpy_hint(obj, expected)}"


def _robotpy_hint(obj: object, expected: type | None) -> str:
    found = [(function, result) for function, result in _robotpy_conversions(obj)
             if expected is None or issubclass(result, expected)]
    if not found:
        return ""
    function = found[0][0]
    if function == "fromWpimath3d":
        return (" (a robotpy-wpimath 3-D object: convert its 2-D part with "
                "drivekin.interop.fromWpimath3d(value))")
    return " (a robotpy-wpimath object: convert it with drivekin.interop.fromWpimath(value))"


def _robotpy_conversions(obj: object) -> list[tuple[str, type]]:
    """The drivekin.interop functions that convert ``obj`` and the drivekin class each
    returns: interop's own tables, searched as interop searches them."""
    modules = ((getattr(k, "__module__", None) or "") for k in type(obj).__mro__)
    if not any(m == "wpimath" or m.startswith("wpimath.") for m in modules):
        return []          # not robotpy's: never import anything on this error path
    try:
        from drivekin import interop

        return interop._conversions(obj)
    except Exception:      # robotpy-wpimath missing or broken: a message without a hint
        return []


def wrong_type(obj: object, expected: type, name: str) -> TypeError:
    """The TypeError for the argument ``name`` that is not an ``expected`` (None
    included): the one message of drivekin's typed parameters (``_core/args.pxd``)."""
    return TypeError(f"{name} must be a {expected.__name__}, got {type_name(obj, expected)}")


def refuse_delete(obj: object, name: str) -> None:
    """Raise the AttributeError for ``del obj.name`` on a value class (for a property
    without a deleter Cython raises an opaque ``NotImplementedError('__del__')``)."""
    if hasattr(type(obj), name):
        raise AttributeError(f"{type(obj).__name__}.{name} cannot be deleted")
    raise AttributeError(f"{type(obj).__name__!r} object has no attribute {name!r}")
