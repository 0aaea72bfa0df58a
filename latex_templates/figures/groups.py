"""An Assur group drawn on its own: its links bold, the pairs by which it attaches drawn as free
elements (hinges or slider guides) with the letters of the points; a joint of its links by which a
later group attaches (not a pair of this group) is drawn as a hinge with its letter too."""
from __future__ import annotations

import numpy as np

from reportgen.geometry import vec2
from reportgen.tolerances import ABS_ZERO
from matplotlib.patches import Circle, Polygon

from .labels import place_text
from .mechanism import world_points
from .keyed import keyed_plot
from reportgen.read_trace import MASS_FIELDS


@keyed_plot(MASS_FIELDS)
def group_figure(linkage, q: np.ndarray, group, w_cm: float = 7.5):
    from . import new_figure
    pts = world_points(linkage, q)
    names = sorted({p for k in group.links for p in linkage.bodies[k].points})
    xy = np.array([pts[n] for n in names])
    L = max(float(np.ptp(xy[:, 0])), float(np.ptp(xy[:, 1])), ABS_ZERO)
    span = np.ptp(xy, axis=0) + ABS_ZERO
    h_cm = min(7.0, max(3.5, w_cm * span[1] / span[0] + 1.0))
    fig = new_figure(w_cm, h_cm)
    ax = fig.add_axes([0.02, 0.02, 0.96, 0.96])
    r = 0.025 * L
    pad = 0.15 * L
    ax.set_xlim(xy[:, 0].min() - pad, xy[:, 0].max() + pad)
    ax.set_ylim(xy[:, 1].min() - pad, xy[:, 1].max() + pad)
    ax.set_aspect("equal")
    centre = xy.mean(axis=0)
    numbers: list = []                # (link, candidates, what it names, a block?), placed last
    letters: dict[str, np.ndarray] = {}
    for k in group.links:
        b = linkage.bodies[k]
        p = np.array([pts[n] for n in b.points])
        if len(b.points) == 3:
            ax.add_patch(Polygon(p, closed=True, facecolor="0.9", edgecolor="black", lw=1.5))
        elif len(b.points) == 2:
            ax.plot(p[:, 0], p[:, 1], "k-", lw=1.6)
        if len(b.points) >= 2:
            d = p[1] - p[0]
            nrm = np.array([-d[1], d[0]]) / (np.hypot(*d) or 1.0)
            numbers.append((k, [p[0] + d * t + side * nrm * f * L for f in (0.07, 0.11)
                                for t in (0.5, 0.3, 0.7, 0.2, 0.8) for side in (1.0, -1.0)],
                            [tuple(x) for x in p], False))
    for pr in group.pairs:
        if pr.kind == "R":
            p = pts[pr.point]
            ax.add_patch(Circle(vec2(p), r, facecolor="white", edgecolor="black", lw=1.0, zorder=5))
            letters.setdefault(pr.point, p)
        else:
            s = linkage.slides[pr.slide]
            p = pts[s.point]
            ang = q[s.guide, 2] if s.guide else 0.0
            d = np.array([np.cos(ang) * s.line_dir[0] - np.sin(ang) * s.line_dir[1],
                          np.sin(ang) * s.line_dir[0] + np.cos(ang) * s.line_dir[1]])
            n = np.array([-d[1], d[0]])
            w, h = 0.12 * L, 0.06 * L
            corners = np.array([p - d * w / 2 - n * h / 2, p + d * w / 2 - n * h / 2,
                                p + d * w / 2 + n * h / 2, p - d * w / 2 + n * h / 2])
            ax.add_patch(Polygon(corners, closed=True, facecolor="white", edgecolor="black", lw=1.2, zorder=4))
            g0, g1 = p - d * 0.2 * L - n * h / 2, p + d * 0.2 * L - n * h / 2
            ax.plot([g0[0], g1[0]], [g0[1], g1[1]], "k-", lw=0.8)
            letters.setdefault(s.point, p)
            if len(linkage.bodies[s.link].points) == 1 and s.link in group.links:     # the block's number
                numbers.insert(0, (s.link, [p + n * (h / 2 + 0.06 * L), p - n * (h / 2 + 0.09 * L),
                                         p + d * (w / 2 + 0.06 * L), p - d * (w / 2 + 0.06 * L)],
                                [tuple(c) for c in corners], True))
    # every other joint of the structure on the group's links (D of a rocker C-B-D whose D drives
    # the next group, issue 12): its hinge and letter, as the scheme draws it
    # (another named point of its links, not a joint: its letter only)
    joined = {j.name for j in linkage.joints}
    for name in names:
        if name not in letters:
            p = pts[name]
            if name in joined:
                ax.add_patch(Circle(vec2(p), r, facecolor="white", edgecolor="black", lw=1.0, zorder=5))
            letters[name] = p
    taken: list = []
    for name, p in letters.items():                  # one letter a point, away from the group's middle
        u = p - centre
        u = u / (np.hypot(*u) or 1.0)
        cands = [p + v * 0.07 * L for v in (u, np.array([-u[1], u[0]]), np.array([u[1], -u[0]]), -u)]
        cands += [p + v * 0.11 * L for v in (u, np.array([-u[1], u[0]]), np.array([u[1], -u[0]]))]
        place_text(ax, cands, name, [tuple(p)], taken, fontsize=10, style="italic", ha="center", va="center",
                   zorder=7)
    joints = [np.asarray(p) for p in letters.values()]
    for k, cands, named, block in numbers:
        # a link's number away from the pairs (their letters, a block's own number sit there)
        if not block:
            cands = [c for c in cands if all(np.hypot(*(c - j)) > 0.12 * L for j in joints)] or cands
        place_text(ax, cands, str(k), named, taken, grow=2.0, fontsize=9, ha="center", va="center", zorder=7,
                   bbox=dict(boxstyle="circle,pad=0.15", fc="white", ec="black", lw=0.5))
    ax.set_aspect("equal")
    ax.axis("off")
    return fig
