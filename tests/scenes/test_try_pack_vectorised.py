"""reportgen.scenes.packing.try_pack tests a view's candidates at once (numpy), and pack tests the
cheap conditions before the polygon's, since sheet 1's small plans became a required view (issue 12:
the scale's choice tries every scale and size, in every catalogue language). They must choose
exactly what the loops they replaced chose: those loops are below (the oracles), compared on random
fields, views already placed and requests."""
from __future__ import annotations

import itertools

from hypothesis import given, settings
from hypothesis import strategies as st

from reportgen.errors import BuildError
from reportgen.scenes.boxes import free_field
from reportgen.scenes.packing import (CORNERS, MM_EPS, MM_ROUNDOFF, Rect, Request, _candidates, _corner_target, pack,
                                      try_pack, walls)


def _loop(region, requests, gap, placed):
    """The one-by-one loop try_pack was (the candidates of pack's _candidates, in their order)."""
    bx0, by0, bx1, by1 = region.bounds
    notches = walls(region)
    done, out, eps = list(placed), [], MM_EPS
    for req in requests:
        tx, ty = _corner_target(region, req.preferred)
        fx = {"top-left": 0.0, "bottom-left": 0.0, "top-right": 1.0, "bottom-right": 1.0}.get(req.preferred, 0.5)
        fy = {"top-left": 1.0, "top-right": 1.0, "bottom-left": 0.0, "bottom-right": 0.0}.get(req.preferred, 0.5)
        blocked = [(b.x0, b.y0, b.x1, b.y1) for b in
                   [p.expanded(gap - eps) for p in done] + [n.expanded(-eps) for n in notches]]
        w, h = req.width, req.height
        xs, ys = {bx0, bx1 - w}, {by0, by1 - h}
        for x, y in region.exterior.coords:
            xs.update((x, x - w))
            ys.update((y, y - h))
        for r in done:
            xs.update((r.x1 + gap, r.x0 - gap - w, r.x0, r.x1 - w))
            ys.update((r.y1 + gap, r.y0 - gap - h, r.y0, r.y1 - h))
        best = None
        for cx, cy in itertools.product(sorted(xs), sorted(ys)):
            if cx < bx0 - eps or cy < by0 - eps or cx + w > bx1 + eps or cy + h > by1 + eps:
                continue
            d = (cx + fx * w - tx) ** 2 + (cy + fy * h - ty) ** 2
            if best is not None and d >= best[0] - MM_ROUNDOFF:
                continue
            x1, y1 = cx + w, cy + h
            if any(cx < b2 and b0 < x1 and cy < b3 and b1 < y1 for b0, b1, b2, b3 in blocked):
                continue
            best = (d, cx, cy)
        if best is None:
            return None
        rect = Rect.from_size(best[1], best[2], w, h)
        done.append(rect)
        out.append(rect)
    return out


sizes = st.floats(5.0, 500.0, allow_nan=False)
request = st.builds(Request, st.just("v"), sizes, sizes, st.sampled_from(CORNERS))
spot = st.tuples(st.floats(0.0, 841.0), st.floats(0.0, 594.0), st.floats(5.0, 300.0), st.floats(5.0, 300.0))


@settings(max_examples=300, deadline=None)
@given(st.sampled_from([(841.0, 594.0), (420.0, 297.0)]), st.lists(spot, max_size=4), st.lists(request, min_size=1, max_size=5),
       st.sampled_from([4.0, 10.0]))
def test_the_vectorised_packing_chooses_what_the_loop_chose(sheet, spots, requests, gap):
    region = free_field(*sheet)
    placed = [Rect.from_size(*s) for s in spots]
    assert try_pack(region, requests, gap=gap, placed=placed) == _loop(region, requests, gap, placed)


def test_the_loop_and_the_vectorised_packing_agree_on_a_crowded_sheet():
    """Equal distances (a view flush with both sides of a gap) keep the first candidate, as the loop."""
    region = free_field(841.0, 594.0)
    placed = [Rect(30.0, 300.0, 300.0, 584.0), Rect(400.0, 300.0, 831.0, 584.0)]
    requests = [Request("a", 90.0, 100.0, c) for c in CORNERS] + [Request("b", 100.0, 90.0, "center")]
    assert try_pack(region, requests, placed=placed) == _loop(region, requests, 10.0, placed)


def _pack_loop(region, requests, gap, placed):
    """The loop pack was: the polygon's containment first, then the others, then the distance."""
    done, out = list(placed), []
    grown = region.buffer(MM_EPS)
    for req in requests:
        tx, ty = _corner_target(region, req.preferred)
        best = None
        for cx, cy in _candidates(region, done, req.width, req.height, gap):
            rect = Rect.from_size(cx, cy, req.width, req.height)
            if not grown.contains(rect.polygon()):
                continue
            if any(rect.overlaps(p.expanded(gap - MM_EPS)) for p in done):
                continue
            rx, ry = rect.center if req.preferred == "center" else _corner_target(rect.polygon(), req.preferred)
            d = (rx - tx) ** 2 + (ry - ty) ** 2
            if best is None or d < best[0] - MM_ROUNDOFF:
                best = (d, rect)
        if best is None:
            return None
        done.append(best[1])
        out.append(best[1])
    return out


@settings(max_examples=150, deadline=None)
@given(st.sampled_from([(841.0, 594.0), (420.0, 297.0)]), st.lists(spot, max_size=3), st.lists(request, min_size=1, max_size=3))
def test_pack_chooses_what_its_loop_chose(sheet, spots, requests):
    region = free_field(*sheet)
    placed = [Rect.from_size(*s) for s in spots]
    try:
        got = pack(region, requests, placed=placed)
    except BuildError:
        got = None
    assert got == _pack_loop(region, requests, 10.0, placed)
