"""Matplotlib figures of the note (vector PDF). Import matplotlib lazily, with the Agg backend and a
style that matches the note (Liberation Serif, the text font; decimal comma on the axes)."""
from __future__ import annotations

import re
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

from reportgen.numbers import significant  # noqa: E402

from .mathtext_cache import share_parses  # noqa: E402

share_parses()   # a formula parsed once per process, not once per renderer (same bytes)

STYLE: dict[Any, Any] = {
    # a list: matplotlib falls back to the next family for a glyph the first lacks (₁ in "О₁")
    "font.family": ["Liberation Serif", "DejaVu Serif"],
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


_SUB = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
_SUP = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789")


def math_name(name: str) -> str:
    """A point name typed by a student, for a matplotlib label, printed as typed: ``О₁`` → ``$О_{1}$``
    (subscript and superscript digits as such). A name with other characters than letters, digits,
    primes and spaces stays plain text (its ``$`` escaped), which matplotlib prints as is."""
    if not re.fullmatch(r"[\w'′ ₀-₉⁰¹²³⁴-⁹]+", name) or "_" in name:
        return name.replace("$", r"\$")
    out = []
    for run in re.findall(r"[₀-₉]+|[⁰¹²³⁴-⁹]+|[^₀-₉⁰¹²³⁴-⁹]+", name):
        if run[0] in "₀₁₂₃₄₅₆₇₈₉":
            out.append("_{" + run.translate(_SUB) + "}")
        elif run[0] in "⁰¹²³⁴⁵⁶⁷⁸⁹":
            out.append("^{" + run.translate(_SUP) + "}")
        else:
            out.append(run.replace(" ", r"\ ").replace("′", "'"))
    return "$" + "".join(out) + "$"


def comma(x: float, _pos=None, mark: str | None = None) -> str:
    """Tick label with the language's decimal mark (comma for ru/uk) and a true minus."""
    from ..parts import decimal_mark
    return significant(x, 6, mark=mark or decimal_mark()).replace("-", "\u2212")


def new_figure(w_cm: float = 16.0, h_cm: float = 10.0):
    plt.rcParams.update(STYLE)
    fig = plt.figure(figsize=(w_cm / 2.54, h_cm / 2.54))
    return fig


def comma_axes(ax) -> None:
    """Tick labels with the decimal mark of the note being made (fixed now: figures are saved later)."""
    from ..parts import decimal_mark
    mark = decimal_mark()
    formatter = FuncFormatter(lambda x, pos=None: comma(x, pos, mark))
    ax.xaxis.set_major_formatter(formatter)
    ax.yaxis.set_major_formatter(formatter)
