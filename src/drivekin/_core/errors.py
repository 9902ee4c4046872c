"""Helpers for error messages (only called on error paths, so plain Python)."""


def type_name(obj: object) -> str:
    """Name ``type(obj)`` for an error message.

    Builtins and drivekin's own classes are named bare; anything else carries its module,
    so a robotpy ``wpimath.geometry._geometry.Translation2d`` passed where drivekin's
    Translation2d belongs is not reported as "got Translation2d".
    """
    t = type(obj)
    module = getattr(t, "__module__", None) or ""
    name = getattr(t, "__qualname__", t.__name__)
    if module == "builtins" or module == "drivekin" or module.startswith("drivekin."):
        return name
    return f"{module}.{name}"


def refuse_delete(obj: object, name: str) -> None:
    """Raise the AttributeError for ``del obj.name`` on a value class (for a property
    without a deleter Cython raises an opaque ``NotImplementedError('__del__')``)."""
    if hasattr(type(obj), name):
        raise AttributeError(f"{type(obj).__name__}.{name} cannot be deleted")
    raise AttributeError(f"{type(obj).__name__!r} object has no attribute {name!r}")
