"""matplotlib for the PNG plots (the optional ``plot`` extra), imported on first use."""
from __future__ import annotations

from typing import Any


def pyplot() -> Any:
    """matplotlib.pyplot on the headless Agg backend, or ImportError saying how to install it."""
    try:
        import matplotlib
    except ImportError as e:
        raise ImportError('matplotlib is needed to draw the plot: pip install '
                          '"drivekin[plot]"') from e
    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt
    return plt
