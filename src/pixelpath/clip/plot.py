"""Pictures of clipping: a trace stage by stage, and zero-width bridges beside the pieces.

matplotlib is an optional extra (``pip install 'pixelpath[plot]'``); it is imported only here,
when a picture is asked for. Files are written atomically (temporary file, then rename).
"""

from __future__ import annotations

import io
import os
import warnings
from pathlib import Path

import numpy as np

from pixelpath.clip.sutherland_hodgman import (
    ClipTrace,
    ZeroWidthBridgeWarning,
    sutherland_hodgman,
    zero_width_bridges,
)
from pixelpath.clip.weiler_atherton import weiler_atherton
from pixelpath.clip.window import Rect, as_window
from pixelpath.io.images import write_bytes

__all__ = ["plot_bridges", "plot_trace"]

SUBJECT_STYLE = {"color": "tab:blue", "alpha": 0.25}
WINDOW_STYLE = {"color": "black", "linestyle": "--", "linewidth": 1.0}
RESULT_STYLE = {"color": "tab:orange", "alpha": 0.6}


def plot_trace(trace: ClipTrace, path: str | os.PathLike) -> Path:
    """Draw the subject and window, then each stage's output, side by side, into a PNG.

    Parameters
    ----------
    trace : ClipTrace
        From ``sutherland_hodgman(subject, window, trace=True)``.
    path : str or path-like
        The PNG file to write.

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ImportError
        When matplotlib is not installed.

    Examples
    --------
    >>> from pixelpath.clip import Rect, sutherland_hodgman
    >>> from pixelpath.clip.plot import plot_trace
    >>> _, trace = sutherland_hodgman([(1, 1), (9, 1), (9, 7), (1, 7)], Rect(2, 2, 8, 6),
    ...                               trace=True)
    >>> plot_trace(trace, "stages.png")  # doctest: +SKIP
    PosixPath('stages.png')
    """
    plt = _pyplot()
    window = trace.window.vertices
    subject = trace.stages[0].input
    panels = len(trace.stages) + 1
    fig, axes = plt.subplots(1, panels, figsize=(2.4 * panels, 2.6), sharex=True, sharey=True)
    _fill(axes[0], subject, **SUBJECT_STYLE)
    _outline(axes[0], window, **WINDOW_STYLE)
    axes[0].set_title("subject and window", fontsize=9)
    for ax, stage in zip(axes[1:], trace.stages, strict=True):
        _fill(ax, subject, color="lightgray", alpha=0.4)
        _outline(ax, window, **WINDOW_STYLE)
        _fill(ax, stage.output, **RESULT_STYLE)
        ax.plot(*stage.output.T, "o", color="tab:red", markersize=3)
        ax.set_title(f"after {stage.boundary}", fontsize=9)
    return _save(fig, axes, path)


def plot_bridges(subject: np.ndarray, window: object, path: str | os.PathLike) -> Path:
    """Draw Sutherland-Hodgman's result, bridges in red, beside Weiler-Atherton's pieces.

    Parameters
    ----------
    subject : (N, 2) array_like
        A simple polygon, typically concave.
    window : Rect or (K, 2) array_like
        The window; when it is concave Sutherland-Hodgman does not apply and only
        Weiler-Atherton's pieces are drawn.
    path : str or path-like
        The PNG file to write.

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ImportError
        When matplotlib is not installed.

    Examples
    --------
    >>> from pixelpath.clip import Rect
    >>> from pixelpath.clip.plot import plot_bridges
    >>> notched = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 4), (4, 4), (4, 2), (0, 2)]
    >>> plot_bridges(notched, Rect(-1, -1, 3, 7), "bridges.png")  # doctest: +SKIP
    PosixPath('bridges.png')
    """
    plt = _pyplot()
    subject = np.asarray(subject, dtype=np.float64)
    pieces = weiler_atherton(subject, window)
    try:
        convex = as_window(window)
    except ValueError:  # a concave window: Sutherland-Hodgman does not apply
        convex = None
    outline = np.asarray(window.vertices if isinstance(window, Rect) else window, dtype=float)
    panels = 1 if convex is None else 2
    fig, axes = plt.subplots(1, panels, figsize=(3.0 * panels, 3.0), sharex=True, sharey=True,
                             squeeze=False)
    axes = axes[0]
    for ax in axes:
        _fill(ax, subject, color="lightgray", alpha=0.4)
        _outline(ax, outline, **WINDOW_STYLE)
    if convex is not None:
        _draw_bridged(axes[0], subject, convex)
    colours = ("tab:green", "tab:purple", "tab:cyan")
    for k, piece in enumerate(pieces):
        _fill(axes[-1], piece, color=colours[k % len(colours)], alpha=0.6)
    noun = "piece" if len(pieces) == 1 else "pieces"
    axes[-1].set_title(f"weiler_atherton: {len(pieces)} {noun}", fontsize=9)
    return _save(fig, axes, path)


def _draw_bridged(ax, subject: np.ndarray, window) -> None:
    """Sutherland-Hodgman's single polygon, its zero-width bridges in red."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ZeroWidthBridgeWarning)
        clipped = sutherland_hodgman(subject, window)
    _fill(ax, clipped, **RESULT_STYLE)
    if len(clipped):
        _outline(ax, clipped, color="tab:orange", linewidth=1.0)
    for bridge in zero_width_bridges(clipped, window) if len(clipped) else ():
        ax.plot(*bridge.T, color="tab:red", linewidth=3, label="zero-width bridge")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="lower right", fontsize=7)
    ax.set_title("sutherland_hodgman: one polygon", fontsize=9)


def _pyplot():
    try:
        import matplotlib
    except ImportError as exc:
        raise ImportError(
            "drawing clipping pictures needs matplotlib: pip install 'pixelpath[plot]'"
        ) from exc
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _fill(ax, points: np.ndarray, **style) -> None:
    if len(points):
        ax.fill(*np.asarray(points).T, **style)


def _outline(ax, points: np.ndarray, **style) -> None:
    closed = np.vstack([points, points[:1]])
    ax.plot(*closed.T, **style)


def _save(fig, axes, path: str | os.PathLike) -> Path:
    import matplotlib.pyplot as plt

    for ax in np.ravel(axes):
        ax.set_aspect("equal")
        ax.tick_params(labelsize=7)
    fig.tight_layout()
    png = io.BytesIO()
    try:
        fig.savefig(png, format="png", dpi=100)
    finally:
        plt.close(fig)
    write_bytes(path, png.getvalue())
    return Path(path)
