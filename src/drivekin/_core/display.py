"""Text from a log made safe to print: entry names are whatever bytes a robot program
wrote, and a name carrying ESC, BEL, CR, a C1 control or a bidirectional override
(U+202E) would move the cursor, retitle or clear the terminal, or reorder the line it is
printed on.

:func:`escape` replaces each such character by the escape Python's ``repr`` writes for it
(``\\x1b``, ``\\r``, ``\\u202e``), so an escaped name reads like a ``{name!r}`` in an error
message; visible text, non-ASCII letters included (``é``, ``日本``), is left as it is, and
so is the backslash (the result is for reading, not for parsing back). Escaping twice
changes nothing. Where it is applied: every :class:`~drivekin.datalog.DataLogError`
message at construction, the replay report's entry names, and, as the last line of
defence, every line the command lines print (:func:`escape_lines`).
"""
from __future__ import annotations

# C0 controls and DEL, the C1 controls (U+0080-U+009F: CSI, OSC, NEL ...), the line and
# paragraph separators, and the bidirectional formatting characters (ALM, LRM, RLM, the
# embeddings and overrides U+202A-U+202E, the isolates U+2066-U+2069).
_CONTROLS = ([*range(0x00, 0x20), *range(0x7F, 0xA0), 0x061C, 0x200E, 0x200F,
              *range(0x2028, 0x202F), *range(0x2066, 0x206A)])
_TABLE = {c: repr(chr(c))[1:-1] for c in _CONTROLS}


def escape(text: str) -> str:
    """``text`` with every control, line-separator and bidi-formatting character written
    as its Python escape (a newline too: the result is one line)."""
    return text.translate(_TABLE)


def escape_lines(text: str) -> str:
    """``text`` with each of its lines escaped (the newlines between them kept)."""
    return "\n".join(escape(line) for line in text.split("\n"))
