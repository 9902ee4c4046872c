"""Argument types and checks shared by the demo's command line (:mod:`drivekin.app.cli`)
and the replay's (:mod:`drivekin.app.replay_cli`)."""
from __future__ import annotations

import argparse
import importlib.util
import math
import os
import sys
from typing import NoReturn, TextIO

from drivekin._core.display import escape, escape_lines


class Parser(argparse.ArgumentParser):
    """argparse's parser, its error line escaped (it may quote what the user typed)."""

    def error(self, message: str) -> NoReturn:
        super().error(escape(message))


def emit(text: str, file: TextIO | None = None) -> None:
    """Print ``text`` (a report, a listing, an error line) with every line escaped: the
    command lines print nothing from a log or the user any other way, so no entry name
    can send control characters to the terminal."""
    print(escape_lines(text), file=sys.stdout if file is None else file, flush=True)


def attach_negative_values(parser: argparse.ArgumentParser, argv: list[str]) -> list[str]:
    """``--steer-offsets -0.573,1.2`` (as calibrate prints it) and ``--module -0.3,0.3``:
    argparse takes a value starting with '-' for an option unless it is one plain
    negative number, so a value that starts like a negative number (``-`` and a digit or
    a point) following an option that takes a value is attached to it
    (``--steer-offsets=-0.573,1.2``) before parsing."""
    takes_value = {s for a in parser._actions if a.nargs is None for s in a.option_strings}
    out: list[str] = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if (a in takes_value and i + 1 < len(argv) and argv[i + 1][:1] == "-"
                and argv[i + 1][1:2] in set("0123456789.")):
            out.append(f"{a}={argv[i + 1]}")
            i += 2
            continue
        out.append(a)
        i += 1
    return out


def docs_url() -> str:
    """Where the documentation site is: the installed distribution's Documentation URL
    (pyproject.toml, [project.urls]), or the docs/ folder of a source tree."""
    from importlib import metadata
    try:
        for entry in metadata.metadata("drivekin").get_all("Project-URL") or ():
            label, _, url = entry.partition(",")
            if label.strip().lower() == "documentation":
                return url.strip()
    except metadata.PackageNotFoundError:
        pass
    return "docs/README.md in drivekin's source"


def number_option(low: float, high: float, unit: str, low_inclusive: bool):
    """An argparse ``type`` accepting a decimal number in the given range.

    It raises only ArgumentTypeError, whose message argparse prints as is (any other
    exception would make argparse name this function in the error)."""
    expected = (f"a number from {low:g} to {high:g} {unit}" if low_inclusive else
                f"a number greater than {low:g} and at most {high:g} {unit}")

    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not ((low <= value if low_inclusive else low < value) and value <= high):
            shown = text if len(text) <= 32 else text[:29] + "..."
            raise argparse.ArgumentTypeError(f"expected {expected}, got {shown!r}")
        return value

    return parse


def new_file(option: str):
    """An argparse ``type`` for an output file: its directory must exist."""
    def parse(text: str) -> str:
        shown = text if len(text) <= 60 else text[:57] + "..."
        if not text or text.endswith(os.sep) or os.path.isdir(text):
            raise argparse.ArgumentTypeError(f"expected a file name, got {shown!r}")
        folder = os.path.dirname(text) or "."
        if not os.path.isdir(folder):
            raise argparse.ArgumentTypeError(f"the folder of {shown!r} does not exist")
        return text
    return parse


def need_extras(parser, log: bool, plot: bool, log_option: str, plot_option: str) -> None:
    """Refuse options whose optional dependency is missing before any work is done."""
    if log and importlib.util.find_spec("wpiutil") is None:
        parser.error(f'{log_option} needs robotpy-wpiutil: pip install "drivekin[log]"')
    if plot and importlib.util.find_spec("matplotlib") is None:
        parser.error(f'{plot_option} needs matplotlib: pip install "drivekin[plot]"')
