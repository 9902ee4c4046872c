"""The rule for bytes-like arguments of the serializers (drivekin.wpistruct and
drivekin.protobuf): plain data only, viewed for as long as it is used."""
from __future__ import annotations

import re


def nbytes(mv: memoryview) -> int:
    if not mv.c_contiguous:
        raise TypeError("the buffer must be C-contiguous")
    return mv.nbytes


# Item formats of buffers whose memory is plain bytes or numbers (optionally with a
# byte-order prefix; "Zd" etc. are numpy's complex types, "5s" fixed-size bytes). Anything
# else is refused: object arrays ("O") hold PyObject pointers that raw doubles must never
# overwrite or be read from, and pointer ("P", "&d"), structured ("T{...}") or text formats
# are not plain data either.
PLAIN_FORMAT = re.compile(r"[@=<>!]?(?:[bBchHiIlLqQnNefdg?]|Z[fdg]|\d*s)")


def view(data: object) -> memoryview:
    """A memoryview of ``data`` after checking it holds plain bytes or numbers.

    Callers keep the view (``with``) for as long as they use its memory: while it is
    held the exporter cannot resize or free the memory (a bytearray refuses to resize, a
    released memoryview stays alive underneath). Validate every other argument, which
    may run Python code (``__index__``), before taking the view."""
    try:
        mv = memoryview(data)  # type: ignore[arg-type]
    except TypeError:
        raise TypeError(f"expected a bytes-like object (bytes, bytearray, memoryview), "
                        f"got {type(data).__name__}") from None
    fmt = mv.format
    if PLAIN_FORMAT.fullmatch(fmt) is None:
        mv.release()
        what = "object (dtype=object)" if fmt.lstrip("@=<>!") == "O" else repr(fmt)
        raise TypeError(f"expected a buffer of plain bytes or numbers (bytes, bytearray, "
                        f"a numeric numpy array, ...), got {type(data).__name__} with "
                        f"item format {what}")
    return mv
