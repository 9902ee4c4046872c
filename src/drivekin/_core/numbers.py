"""The rule for a ``double`` argument of drivekin's Python-written façade, as Cython's
``double`` parameters apply it: anything with ``__float__`` or ``__index__`` (ints,
floats, numpy scalars), never text, which ``float()`` would parse."""
from __future__ import annotations

from drivekin._core.errors import type_name


def as_double(value: object, expected: str) -> float:
    """``value`` as a float. TypeError ``"<expected>, got <type>"`` for anything else; an
    int beyond the largest double is a ValueError (``float()`` would raise
    OverflowError)."""
    if type(value) is float:
        return value
    cls = type(value)
    if isinstance(value, (str, bytes, bytearray)) or not (
            hasattr(cls, "__float__") or hasattr(cls, "__index__")):
        raise TypeError(f"{expected}, got {type_name(value)}")
    try:
        return float(value)  # type: ignore[arg-type]
    except OverflowError:
        raise ValueError(f"{expected}; the {type_name(value)} given is beyond the largest "
                         "double") from None
