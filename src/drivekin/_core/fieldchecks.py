"""Checks for the fields of an options dataclass (:class:`drivekin.replay.ReplayConfig`):
each takes the field's label and a value and raises TypeError for a value of the wrong
kind, ValueError for one of the right kind that is out of range or unknown, naming what
is expected. A dataclass lists one check per field in a table and runs it on every
assignment, so a bad value fails where it is given, not later as a silent default.
"""
from __future__ import annotations

import numbers
from typing import Any, Callable

import numpy as np

from drivekin._core.errors import cut, type_name

Check = Callable[[str, Any], None]


def _kind(value: Any) -> str:
    return type_name(value)


def _shown(value: Any) -> str:
    return cut(repr(value))


def choice(*allowed: str | None) -> Check:
    """One of ``allowed`` (None among them when the field may be unset)."""
    shown = ", ".join(repr(a) for a in allowed)

    def check(label: str, value: Any) -> None:
        if value is not None and not isinstance(value, str):
            raise TypeError(f"{label} must be one of {shown}, got {_kind(value)}")
        if value not in allowed:
            raise ValueError(f"{label} must be one of {shown}, got {_shown(value)}")
    return check


def entry_name(label: str, value: Any) -> None:
    """An entry name (str) or None."""
    if value is not None and not isinstance(value, str):
        raise TypeError(f"{label} must be an entry name (str) or None, got {_kind(value)}")
    if value == "":
        raise ValueError(f"{label} must be an entry name, not empty (None: found by type)")


def texts(label: str, value: Any) -> None:
    """A non-empty list of non-empty strings, or None."""
    if value is None:
        return
    if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) for v in value):
        raise TypeError(f"{label} must be a list of str or None, got {_kind(value)}")
    if not value or not all(value):
        raise ValueError(f"{label} must be at least one non-empty string (None: not used)")


def flag(label: str, value: Any) -> None:
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{label} must be True or False, got {_kind(value)}")


def _numbers(label: str, value: Any, what: str) -> np.ndarray:
    """``value`` as float64 numbers (TypeError for text, None and other objects)."""
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{label} must be {what}, got {_kind(value)}")
    try:
        return np.asarray(value, dtype=np.float64)
    except TypeError:
        raise TypeError(f"{label} must be {what}, got {_kind(value)}") from None
    except ValueError:          # ragged lists, text among the numbers
        raise ValueError(f"{label} must be {what}, got {_shown(value)}") from None


def positive(optional: bool) -> Check:
    """A finite number greater than 0 (or None when ``optional``)."""
    what = "a finite number greater than 0" + (" or None" if optional else "")

    def check(label: str, value: Any) -> None:
        if value is None and optional:
            return
        if not isinstance(value, numbers.Real) or isinstance(value, bool):
            raise TypeError(f"{label} must be {what}, got {_kind(value)}")
        if not (0.0 < float(value) < float("inf")):
            raise ValueError(f"{label} must be {what}, got {_shown(value)}")
    return check


def scales(label: str, value: Any) -> None:
    """A finite number greater than 0, or a non-empty list of them."""
    what = "a finite number greater than 0, or a list of them"
    a = _numbers(label, value, what)
    if a.ndim > 1 or a.size == 0:
        raise ValueError(f"{label} must be {what}, got an array of shape {a.shape}")
    if not (np.isfinite(a).all() and (a > 0).all()):
        raise ValueError(f"{label} must be {what}, got {_shown(value)}")


def finite_list(label: str, value: Any) -> None:
    """None, or a list of finite numbers."""
    if value is None:
        return
    what = "None or a list of finite numbers"
    a = _numbers(label, value, what)
    if a.ndim != 1:
        raise ValueError(f"{label} must be {what}, got an array of shape {a.shape}")
    if not np.isfinite(a).all():
        raise ValueError(f"{label} must be {what}, got {_shown(value)}")


_POINT_FIELDS = {2: "(x, y)", 3: "(x, y, deg)"}


def points(n: int) -> Check:
    """None, or a non-empty list of ``n``-tuples of finite numbers."""
    what = f"None or a list of {_POINT_FIELDS[n]} tuples of finite numbers"

    def check(label: str, value: Any) -> None:
        if value is None:
            return
        a = _numbers(label, value, what)
        if a.ndim != 2 or a.shape[0] == 0 or a.shape[1] != n:
            raise ValueError(f"{label} must be {what}, got an array of shape {a.shape}")
        if not np.isfinite(a).all():
            raise ValueError(f"{label} must be {what}, got {_shown(value)}")
    return check
