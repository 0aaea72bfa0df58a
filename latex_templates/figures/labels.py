"""What a label of a note figure names: ``names(text, p, …)`` keeps the points (data coordinates) of
the entity a text labels on the matplotlib Text (``reportgen_names``: one point, or the points of a
line), so that tests/labels can read every label's window extent back and check that it stays near
what it names (:data:`reportgen.tolerances.LABEL_NEAR_MM`). Nothing is measured at build time."""
from __future__ import annotations

from typing import Any, Sequence


def names(text: Any, *points: Sequence[float]) -> Any:
    """Record on the matplotlib ``text`` the points (data coordinates) of what it names; returns it."""
    text.reportgen_names = tuple((float(p[0]), float(p[1])) for p in points)
    return text


def place_text(ax: Any, candidates: Sequence[Sequence[float]], s: str, named: Sequence[Sequence[float]],
               taken: list, grow: float = 1.0, **kw: Any) -> Any:
    """``s`` at the first of ``candidates`` (data coordinates) whose extent overlaps none of ``taken``
    (display boxes, extended by the new one), else at the first; ``named``: what it labels. The
    axes' limits and aspect must be final (the extents are the renderer's)."""
    renderer = ax.figure.canvas.get_renderer()
    ax.apply_aspect()
    t = ax.text(candidates[0][0], candidates[0][1], s, **kw)
    chosen = None
    for c in candidates:
        t.set_position((c[0], c[1]))
        bb = t.get_window_extent(renderer).expanded(grow, grow)
        if not any(bb.overlaps(o) for o in taken):
            chosen = bb
            break
    if chosen is None:
        t.set_position((candidates[0][0], candidates[0][1]))
        chosen = t.get_window_extent(renderer).expanded(grow, grow)
    taken.append(chosen)
    return names(t, *named)
