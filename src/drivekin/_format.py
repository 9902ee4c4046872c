"""Java-compatible number formatting for ``__str__`` (WPILib's ``toString``).

Java's ``String.format("%.2f", x)`` rounds half-up on the shortest decimal
representation of the double (0.125 -> "0.13", 2.675 -> "2.68"), while Python's
``"%.2f"`` rounds the exact binary value half-even ("0.12", "2.67"). The WPILib
strings are reproduced exactly, so the Java rule is applied here.
"""
from decimal import ROUND_HALF_UP, Decimal

_CENT = Decimal("0.01")


def f2(x: float) -> str:
    """Format ``x`` like Java ``%.2f``."""
    if x != x:
        return "NaN"
    if x in (float("inf"), float("-inf")):
        return "Infinity" if x > 0 else "-Infinity"
    return str(Decimal(repr(float(x))).quantize(_CENT, rounding=ROUND_HALF_UP))
