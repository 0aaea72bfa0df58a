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


def _drawn_lines(ax: Any) -> list:
    """The axes' lines and patch outlines as display-space polylines (arrays of points)."""
    import numpy as np
    out = []
    for ln in ax.lines:
        xy = np.column_stack([np.asarray(ln.get_xdata(), float), np.asarray(ln.get_ydata(), float)])
        if len(xy) >= 2:
            out.append(ax.transData.transform(xy))
    for p in ax.patches:
        path = p.get_path().transformed(p.get_transform())
        for poly in path.to_polygons(closed_only=False):
            if len(poly) >= 2:
                out.append(np.asarray(poly))
    return out


def _crossings(bb: Any, lines: list) -> int:
    from shapely.geometry import LineString, box
    b = box(bb.x0, bb.y0, bb.x1, bb.y1)
    return sum(1 for ln in lines if LineString(ln).intersects(b))


def place_text(ax: Any, candidates: Sequence[Any], s: str, named: Sequence[Any],
               taken: list, grow: float = 1.0, **kw: Any) -> Any:
    """``s`` at the first of ``candidates`` (data coordinates) whose extent overlaps none of ``taken``
    (display boxes, extended by the new one) and crosses no drawn line; else at the one that
    overlaps no text and crosses fewest lines (else the first); ``named``: what it labels. The axes'
    limits and aspect must be final (the extents are the renderer's)."""
    renderer = ax.figure.canvas.get_renderer()
    ax.apply_aspect()
    lines = _drawn_lines(ax)
    t = ax.text(candidates[0][0], candidates[0][1], s, **kw)
    best = None
    for rank, c in enumerate(candidates):
        t.set_position((c[0], c[1]))
        bb = t.get_window_extent(renderer).expanded(grow, grow)
        score = (sum(1 for o in taken if bb.overlaps(o)), _crossings(bb, lines), rank)
        if best is None or score < best[0]:
            best = (score, c, bb)
        if score[:2] == (0, 0):
            break
    assert best is not None
    t.set_position((best[1][0], best[1][1]))
    taken.append(best[2])
    return names(t, *named)
