"""Shared behaviour of the mecanum and differential wheel value classes."""

# Hand-written stub for the private compiled module drivekin._core.wheels
# (_core/wheels.pyx). The docstrings are written from the compiled module's ``__doc__``
# (the .pyx docstrings) by scripts/stub_docstrings.py: edit them in the .pyx, rebuild and
# rerun the script. tests/api/test_stubs.py checks that they match and that no public
# name is missing on either side.
#
# _WheelValues is the private base of the wheel-value classes of drivekin.differential,
# drivekin.mecanum and drivekin.diffswerve; its members are typed with Self, so they
# keep each subclass's precise types.

from collections.abc import Iterator

from typing_extensions import Self, disjoint_base

@disjoint_base
class _WheelValues:
    """Per-wheel values with component-wise arithmetic (operators + - * / and unary -)."""

    def plus(self, other: Self) -> Self:
        """Return the wheel-by-wheel sum."""

    def minus(self, other: Self) -> Self:
        """Return the wheel-by-wheel difference."""

    def unaryMinus(self) -> Self:
        """Return every wheel negated."""

    def times(self, scalar: float) -> Self:
        """Return every wheel multiplied by ``scalar``."""

    def div(self, scalar: float) -> Self:
        """Return every wheel divided by ``scalar`` (no zero guard, as in WPILib)."""

    def __add__(self, other: Self, /) -> Self: ...
    def __sub__(self, other: Self, /) -> Self: ...
    def __neg__(self) -> Self: ...
    def __mul__(self, other: float, /) -> Self: ...
    def __rmul__(self, other: float, /) -> Self: ...
    def __truediv__(self, other: float, /) -> Self: ...
    def __iter__(self) -> Iterator[float]: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    unary_minus = unaryMinus

def set_type_attr(cls: type, name: str, value: object) -> None:
    """Put ``value`` into the dictionary of the extension type ``cls`` under ``name`` (what
    Python code cannot assign on a static type): the 2026 names of _core.renames."""
