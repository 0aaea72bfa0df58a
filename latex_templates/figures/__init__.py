"""Matplotlib figures of the note (vector PDF). Import matplotlib lazily, with the Agg backend and a
style that matches the note (Liberation Serif, the text font; decimal comma on the axes)."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

from reportgen.numbers import significant  # noqa: E402

STYLE = {
    "font.family": "serif",
    "font.serif": ["Liberation Serif", "Times New Roman", "DejaVu Serif"],
    "font.size": 10,
    "mathtext.fontset": "stix",
    "figure.max_open_warning": 0,      # a note holds ~30 figures until NoteBuilder saves (and closes) them
    "axes.grid": True,
    "grid.linewidth": 0.3,
    "grid.alpha": 0.5,
    "axes.linewidth": 0.6,
    "lines.linewidth": 1.2,
    "axes.formatter.use_locale": False,
    "pdf.fonttype": 42,
    "svg.hashsalt": "reportgen",
}


def comma(x: float, _pos=None) -> str:
    """Tick label with a decimal comma and a true minus."""
    return significant(x, 6).replace("-", "\u2212")


COMMA = FuncFormatter(comma)


def new_figure(w_cm: float = 16.0, h_cm: float = 10.0):
    plt.rcParams.update(STYLE)
    fig = plt.figure(figsize=(w_cm / 2.54, h_cm / 2.54))
    return fig


def comma_axes(ax) -> None:
    ax.xaxis.set_major_formatter(COMMA)
    ax.yaxis.set_major_formatter(COMMA)
