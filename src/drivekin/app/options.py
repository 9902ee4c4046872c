"""Argument types and checks shared by the demo's command line (:mod:`drivekin.app.cli`)
and the replay's (:mod:`drivekin.app.replay_cli`)."""
from __future__ import annotations

import argparse
import importlib.util
import math
import os


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
