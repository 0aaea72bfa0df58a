"""The kinematic scheme of the linkage in matplotlib: bars, triangular links, hinges, fixed pivots
with hatching, sliders on their guides, point labels and link numbers."""
from __future__ import annotations

import math

import numpy as np

from reportgen.geometry import vec2
from matplotlib.patches import Circle, Polygon, Rectangle
from matplotlib.transforms import Affine2D

from reportgen.kinematics.constraints import rot

from .labels import place_text
from reportgen.linkage import Linkage
from reportgen.tolerances import ABS_ROUNDOFF, ABS_ZERO, TINY
from .keyed import keyed_plot
from reportgen.read_trace import MASS_FIELDS


def world_points(linkage: Linkage, q: np.ndarray) -> dict[str, np.ndarray]:
    """Positions of every point at one position (q: (bodies, 3))."""
    out: dict[str, np.ndarray] = {}
    for k, b in linkage.bodies.items():
        for name, p in b.local.items():
            if k == 0:
                out.setdefault(name, np.asarray(p, float))
            elif name not in out or k != 0:
                out[name] = q[k, :2] + rot(np.array([q[k, 2]]), p)[0]
    return out


def size_of(pts: dict[str, np.ndarray]) -> float:
    arr = np.array(list(pts.values()))
    return float(max(np.ptp(arr[:, 0]), np.ptp(arr[:, 1]), ABS_ZERO))


def draw_mechanism(ax, linkage: Linkage, q: np.ndarray, *, labels: bool = True, numbers: bool = True,
                   color: str = "black", lw: float = 1.6, alpha: float = 1.0, guides: bool = True,
                   size: float | None = None) -> None:
    """Draw the mechanism at one position on ``ax`` (equal aspect)."""
    pts = world_points(linkage, q)
    L = size if size is not None else size_of(pts)
    r_hinge = 0.012 * L
    ax.set_aspect("equal")
    pending: list = []          # link numbers: placed after the letters, where they overlap none
    blocks: dict[str, list] = {}  # a slider's point → its block's outline (what its letter names)
    # links
    for k, b in sorted(linkage.bodies.items()):
        if k == 0:
            continue
        names = b.points
        xy = np.array([pts[n] for n in names])
        if len(names) == 3:
            ax.add_patch(Polygon(xy, closed=True, facecolor="0.9" if alpha == 1 else "none", edgecolor=color,
                                 lw=lw, alpha=alpha, zorder=2))
        elif len(names) == 2:
            ax.plot(xy[:, 0], xy[:, 1], color=color, lw=lw, alpha=alpha, zorder=2, solid_capstyle="round")
        if numbers and alpha == 1 and len(names) >= 2:
            c = xy.mean(axis=0)
            d = xy[1] - xy[0]
            n = np.array([-d[1], d[0]]) / (np.hypot(*d) + TINY)
            cands = [c + n * f * L for f in (0.035, -0.035, 0.06, -0.06)] + \
                [xy[0] + d * t + n * f * L for t in (0.3, 0.7, 0.2, 0.8) for f in (0.035, -0.035, 0.06, -0.06)]
            # away from the points (their letters, a block and its number sit there)
            cands = [x for x in cands if min(np.hypot(*(x - q)) for q in pts.values()) > 0.07 * L] or cands
            pending.append((str(k), cands, [tuple(x) for x in xy]))
    # sliders and guides
    for s in linkage.slides:
        k = s.link
        b = linkage.bodies[k]
        guide_dir = _guide_dir(q, s)
        gang = math.degrees(math.atan2(guide_dir[1], guide_dir[0]))
        p = pts[s.point]
        if len(b.points) == 1:
            w, h = 0.09 * L, 0.05 * L
            rect = Rectangle((-w / 2, -h / 2), w, h, facecolor="white", edgecolor=color, lw=lw, alpha=alpha, zorder=4)
            rect.set_transform(Affine2D().rotate_deg(gang).translate(p[0], p[1]) + ax.transData)
            ax.add_patch(rect)
            nrm = np.array([-guide_dir[1], guide_dir[0]])
            blocks[s.point] = [tuple(p + guide_dir * sx * w / 2 + nrm * sy * h / 2)
                               for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1), (-1, -1))]
            if numbers and alpha == 1:
                cands = [p + v * f * L for f in (0.07, 0.1) for v in (nrm, -nrm, guide_dir, -guide_dir)]
                pending.insert(0, (str(k), cands, blocks[s.point]))       # a block's number first
        if guides and s.guide == 0:
            a = np.asarray(s.line_point)
            t = np.dot(p - a, guide_dir)
            ends = [a + (t - 0.25 * L) * guide_dir, a + (t + 0.25 * L) * guide_dir]
            normal = np.array([-guide_dir[1], guide_dir[0]])
            # the guide under the block on the side its links do not come from, so that the guide
            # and its hatching never cross them (issue 12, fig. 1.1)
            towards = sum((pts[n] - p for bk, bb in linkage.bodies.items() if bk != 0 and s.point in bb.points
                           for n in bb.points if n != s.point), np.zeros(2))
            if np.hypot(*towards) < ABS_ROUNDOFF:
                towards = np.array(list(pts.values())).mean(axis=0) - p
            if np.dot(towards, normal) > 0:
                normal = -normal
            _hatch_line(ax, ends[0], ends[1], normal, 0.03 * L, color, alpha, offset=0.025 * L + 0.0)
    # hinges and fixed pivots
    for j in linkage.joints:
        p = pts[j.name]
        if 0 in j.bodies:
            _fixed_pivot(ax, p, 0.05 * L, color, alpha)
        ax.add_patch(Circle(vec2(p), r_hinge, facecolor="white", edgecolor=color, lw=1.0, alpha=alpha, zorder=5))
    taken: list = []
    if labels and alpha == 1:
        centre = np.array(list(pts.values())).mean(axis=0)
        for name, p in pts.items():
            d = p - centre
            n = np.hypot(*d)
            d = d / n if n > 0 else np.array([0.0, 1.0])
            on_slider = any(sl.point == name and len(linkage.bodies[sl.link].points) == 1 for sl in linkage.slides)
            f = 0.075 if on_slider else 0.045
            side = np.array([-d[1], d[0]])
            cands = [p + v * f * L for v in (d, d + side, d - side, side, -side, -d)] + \
                [p + v * 1.6 * f * L for v in (d, side, -side)]
            if on_slider:         # beside the block along its guide first: above it is the guide's side
                g = next(_guide_dir(q, sl) for sl in linkage.slides if sl.point == name)
                cands = [p + g * 0.085 * L, p - g * 0.085 * L] + cands
            place_text(ax, cands, name, blocks.get(name, [tuple(p)]), taken, fontsize=10, ha="center", va="center",
                       style="italic", zorder=7)
    for text, cands, named in pending:
        place_text(ax, cands, text, named, taken, grow=2.0, fontsize=9, ha="center", va="center", color=color,
                   bbox=dict(boxstyle="circle,pad=0.15", fc="white", ec=color, lw=0.5), zorder=6)


def _guide_dir(q: np.ndarray, s) -> np.ndarray:
    """The unit direction of slide ``s``'s guide at position ``q``."""
    return rot(np.array([q[s.guide, 2]]), s.line_dir)[0] if s.guide else np.asarray(s.line_dir, float)


def _fixed_pivot(ax, p, s, color, alpha) -> None:
    tri = np.array([p, p + [-0.6 * s, -s], p + [0.6 * s, -s]])
    ax.add_patch(Polygon(tri, closed=True, facecolor="none", edgecolor=color, lw=0.8, alpha=alpha, zorder=3))
    _hatch_line(ax, p + [-0.9 * s, -s], p + [0.9 * s, -s], np.array([0.0, -1.0]), 0.5 * s, color, alpha)


def _hatch_line(ax, a, b, normal, depth, color, alpha, offset: float = 0.0) -> None:
    a, b = np.asarray(a, float) + normal * offset, np.asarray(b, float) + normal * offset
    ax.plot([a[0], b[0]], [a[1], b[1]], color=color, lw=0.8, alpha=alpha, zorder=1)
    n = 7
    d = b - a
    for i in range(n + 1):
        p = a + d * i / n
        q = p + normal * depth + d / n * 0.8
        ax.plot([p[0], q[0]], [p[1], q[1]], color=color, lw=0.5, alpha=alpha, zorder=1)


@keyed_plot(MASS_FIELDS)
def scheme_figure(linkage: Linkage, q: np.ndarray, w_cm: float = 15.0):
    """A figure of the scheme at one position, axes in metres hidden."""
    from . import new_figure
    pts = world_points(linkage, q)
    arr = np.array(list(pts.values()))
    span = np.ptp(arr, axis=0) + ABS_ZERO
    h_cm = min(12.0, max(5.0, w_cm * span[1] / span[0] + 2.0))
    fig = new_figure(w_cm, h_cm)
    ax = fig.add_axes([0.02, 0.02, 0.96, 0.96])
    L = size_of(pts)
    ax.set_xlim(arr[:, 0].min() - 0.12 * L, arr[:, 0].max() + 0.12 * L)     # before the labels:
    ax.set_ylim(arr[:, 1].min() - 0.12 * L, arr[:, 1].max() + 0.12 * L)     # they are placed by extents
    draw_mechanism(ax, linkage, q)
    ax.axis("off")
    return fig
