"""Zero level lines of a function sampled on a rectangular grid (marching squares).

Plain linear interpolation along cell edges; cells touching a NaN are skipped; the ambiguous
saddle cells are resolved by the mean of the four corners. The segments are chained into
polylines by the grid edges they share, so each returned polyline is a connected curve.
"""
from __future__ import annotations

import numpy as np

from ..geometry import readonly


def zero_lines(xs: np.ndarray, ys: np.ndarray, f: np.ndarray) -> tuple[np.ndarray, ...]:
    """Polylines (each an (n, 2) read-only array of (x, y)) where f = 0; f[i, j] = f(xs[i], ys[j])."""
    f = np.asarray(f, dtype=float)
    nx, ny = f.shape
    pos = f >= 0.0

    def point(edge):
        (i0, j0), (i1, j1) = edge
        f0, f1 = f[i0, j0], f[i1, j1]
        t = f0 / (f0 - f1)
        return (xs[i0] + t * (xs[i1] - xs[i0]), ys[j0] + t * (ys[j1] - ys[j0]))

    segments: list[tuple[tuple, tuple]] = []
    for i in range(nx - 1):
        for j in range(ny - 1):
            corners = ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1))
            vals = [f[c] for c in corners]
            if any(np.isnan(v) for v in vals):
                continue
            signs = [pos[c] for c in corners]
            if all(signs) or not any(signs):
                continue
            edges = [(corners[k], corners[(k + 1) % 4]) for k in range(4)]
            crossing = [e for e, k in zip(edges, range(4)) if signs[k] != signs[(k + 1) % 4]]
            if len(crossing) == 2:
                segments.append((crossing[0], crossing[1]))
            else:  # saddle: pair the edges so that the centre's sign separates them
                centre_pos = np.mean(vals) >= 0.0
                if centre_pos == signs[0]:  # corners 1 and 3 are cut off
                    segments += [(crossing[0], crossing[1]), (crossing[2], crossing[3])]
                else:  # corners 0 and 2 are cut off
                    segments += [(crossing[0], crossing[3]), (crossing[1], crossing[2])]

    def key(edge):
        return tuple(sorted(edge))

    by_edge: dict[tuple, list[int]] = {}
    for n, (e0, e1) in enumerate(segments):
        by_edge.setdefault(key(e0), []).append(n)
        by_edge.setdefault(key(e1), []).append(n)
    used = [False] * len(segments)
    lines = []
    for start in range(len(segments)):
        if used[start]:
            continue
        used[start] = True
        chain = [segments[start][0], segments[start][1]]
        for direction in (1, -1):
            while True:
                end = chain[-1] if direction == 1 else chain[0]
                nxt = [n for n in by_edge[key(end)] if not used[n]]
                if not nxt:
                    break
                n = nxt[0]
                used[n] = True
                e0, e1 = segments[n]
                other = e1 if key(e0) == key(end) else e0
                if direction == 1:
                    chain.append(other)
                else:
                    chain.insert(0, other)
        arr = readonly([point(e) for e in chain])
        lines.append(arr)
    return tuple(lines)
