"""An entry's metadata read as JSON, safely: the one place drivekin parses metadata.

Metadata is whatever string a robot program wrote. ``json.loads`` recurses once per
nesting level, so ``[[[[...]]]]`` 2,000 deep (4 KiB) ends in ``RecursionError``; it is
also unbounded in size. :func:`parse` therefore takes only a JSON object under
:data:`MAX_LENGTH` characters whose brackets nest at most :data:`MAX_DEPTH` deep, measured
first by one linear scan that skips strings, and returns None for anything else (metadata
is a hint, never required).
"""
from __future__ import annotations

import json
from typing import Any

MAX_LENGTH = 4096       # characters: WPILib's own metadata ({"source": ...}) is far shorter
MAX_DEPTH = 16          # nested objects and arrays (a unit needs one)


def depth(text: str) -> int:
    """How deep the brackets of ``text`` nest outside its JSON strings (linear, no
    recursion; unbalanced text is measured as far as it goes)."""
    deepest = level = 0
    in_string = escaped = False
    for c in text:
        if in_string:
            if escaped:
                escaped = False
            elif c == "\\":
                escaped = True
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
        elif c in "[{":
            level += 1
            deepest = max(deepest, level)
        elif c in "]}":
            level -= 1
    return deepest


def parse(text: str) -> dict[str, Any] | None:
    """The JSON object ``text`` holds, or None: not JSON, not an object, longer than
    MAX_LENGTH or nested deeper than MAX_DEPTH."""
    if not text or len(text) >= MAX_LENGTH or not text.lstrip().startswith("{"):
        return None
    if depth(text) > MAX_DEPTH:
        return None
    try:
        value = json.loads(text)
    except ValueError:
        return None
    return value if isinstance(value, dict) else None
