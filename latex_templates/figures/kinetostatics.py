"""Figures of section 2 (kinetostatics, matplotlib): an Assur group or the crank cut out of the
mechanism with every force at its point, a force polygon at μF, Zhukovsky's lever (the velocity plan
turned by −90° with the loads at the image points and their arms), and M_ур over the cycle.

Every geometric number comes from the solver's objects (``reportgen.kinetostatics``); nothing here
computes a force. Arrow lengths on the group diagrams are schematic (a square-root law, so that a
10 N weight stays visible beside a 10 kN resistance); the polygons are drawn at their scale μF."""
from __future__ import annotations

import math

import numpy as np

from reportgen.geometry import vec2
from matplotlib.patches import Circle, FancyArrowPatch, Polygon

from ..parts import active, tr
from reportgen.scenes.forces import force_tex
from reportgen.tolerances import ABS_ZERO, TINY

from . import comma_axes, math_name, new_figure
from .mechanism import world_points

#: Colours: loads, reactions found in this step, reactions known from an earlier step.
LOAD = "black"
FOUND = "tab:red"
KNOWN = "tab:blue"


def mathtext(name: str) -> str:
    """A solver's force name as matplotlib mathtext: ``Fи4′`` → ``$F'_{\\mathrm{и}4}$``."""
    return "$" + active().localize_latex(symbol(name, text="\\mathrm").replace("\\mathrm{", "\\text{")).replace(
        "\\text{", "\\mathrm{") + "$"


def symbol(name: str, text: str = "\\text") -> str:
    """A solver's force or moment name as a math symbol (LaTeX, or mathtext with ``text``
    = "\\mathrm"): :func:`reportgen.scenes.forces.force_tex`."""
    tex = force_tex(name)
    return tex.replace("\\text{", text + "{") if text != "\\text" else tex


def _arrow(ax, tail, head, colour, lw=1.3, ls="-", z=6):
    ax.add_patch(FancyArrowPatch(tuple(tail), tuple(head), arrowstyle="-|>", mutation_scale=10, color=colour,
                                 lw=lw, ls=ls, shrinkA=0, shrinkB=0, zorder=z))


def _label(ax, p, text, colour, placed: list, size: float) -> None:
    p0 = np.asarray(p, float)
    p = p0
    for step in range(1, 4):
        if all(np.hypot(*(p - q)) > 0.06 * size for q in placed):
            break
        for a in range(0, 360, 45):
            cand = p0 + 0.06 * size * step * np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
            if all(np.hypot(*(cand - q)) > 0.06 * size for q in placed):
                p = cand
                break
        else:
            continue
        break
    placed.append(p)
    ax.text(p[0], p[1], text, fontsize=9, color=colour, ha="center", va="center", zorder=8,
            bbox=dict(boxstyle="round,pad=0.05", fc="white", ec="none", alpha=0.8))


def schematic_lengths(mags: list[float], ref: float) -> list[float]:
    """Arrow lengths on a diagram: ref·√(|F|/F_max), at least 0.25·ref."""
    top = max(mags + [TINY])
    return [ref * max(0.25, math.sqrt(m / top)) for m in mags]


def free_body_figure(linkage, q: np.ndarray, links: tuple[int, ...], pairs: list[dict], arrows: list[dict],
                     couples: list[dict], w_cm: float = 14.0):
    """A group (or the crank) cut out: its links, the pairs at which it was cut, and the forces.

    ``pairs``: {"point": xy, "kind": "R"|"P", "name": letter, "guide": unit vector (P)};
    ``arrows``: {"point": xy, "vector": N, "name": solver name, "role": "load"|"found"|"known"};
    ``couples``: {"point": xy, "value": N·m, "name": ...} drawn as curved arrows."""
    pts = world_points(linkage, q)
    names = sorted({p for k in links for p in linkage.bodies[k].points})
    xy = np.array([pts[n] for n in names])
    span = np.ptp(xy, axis=0)
    L = float(max(span.max(), ABS_ZERO))
    ref = 0.32 * L
    lengths = schematic_lengths([float(np.hypot(*a["vector"])) for a in arrows], ref)
    ends = []
    for a, ln in zip(arrows, lengths):
        v = np.asarray(a["vector"], float)
        n = float(np.hypot(*v))
        u = v / n if n > 0 else np.zeros(2)
        ends.append((np.asarray(a["point"], float), np.asarray(a["point"], float) + u * ln))
    allp = np.vstack([xy] + [np.vstack(e) for e in ends]) if ends else xy
    lo, hi = allp.min(0) - 0.1 * L, allp.max(0) + 0.1 * L
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], ABS_ZERO)
    h_cm = min(11.0, max(5.0, w_cm * aspect))
    w_cm = max(5.0, min(w_cm, h_cm / max(aspect, ABS_ZERO)))
    fig = new_figure(w_cm, h_cm)
    ax = fig.add_axes([0.01, 0.01, 0.98, 0.98])
    for k in links:
        b = linkage.bodies[k]
        p = np.array([pts[n] for n in b.points])
        if len(b.points) >= 3:
            ax.add_patch(Polygon(p, closed=True, facecolor="0.92", edgecolor="black", lw=1.6, zorder=2))
        elif len(b.points) == 2:
            ax.plot(p[:, 0], p[:, 1], "k-", lw=2.0, zorder=2)
        c = p.mean(axis=0)
        d = p[-1] - p[0] if len(p) > 1 else np.array([1.0, 0.0])
        nrm = np.array([-d[1], d[0]]) / (np.hypot(*d) + TINY)
        t = c + nrm * 0.06 * L
        ax.text(t[0], t[1], str(k), fontsize=9, ha="center", va="center", zorder=7,
                bbox=dict(boxstyle="circle,pad=0.15", fc="white", ec="black", lw=0.5))
    r = 0.018 * L
    for pr in pairs:
        p = np.asarray(pr["point"], float)
        if pr["kind"] == "P":
            g = np.asarray(pr["guide"], float)
            nv = np.array([-g[1], g[0]])
            w, h = 0.14 * L, 0.07 * L
            box = np.array([p - g * w / 2 - nv * h / 2, p + g * w / 2 - nv * h / 2, p + g * w / 2 + nv * h / 2,
                            p - g * w / 2 + nv * h / 2])
            ax.add_patch(Polygon(box, closed=True, facecolor="white", edgecolor="black", lw=1.3, zorder=4))
            g0, g1 = p - g * 0.22 * L - nv * h / 2, p + g * 0.22 * L - nv * h / 2
            ax.plot([g0[0], g1[0]], [g0[1], g1[1]], color="0.4", lw=0.8, ls="--", zorder=1)
        ax.add_patch(Circle(vec2(p), r, facecolor="white", edgecolor="black", lw=1.0, zorder=5))
    placed: list[np.ndarray] = []
    for n in names:
        p = pts[n]
        c = xy.mean(axis=0)
        d = p - c
        d = d / (np.hypot(*d) + TINY)
        _label(ax, p - d * 0.06 * L + np.array([0.0, 0.04 * L]), math_name(n), "black", placed, L)
    colour = {"load": LOAD, "found": FOUND, "known": KNOWN}
    for a, (tail, head) in zip(arrows, ends):
        col = colour[a["role"]]
        _arrow(ax, tail, head, col)
        d = head - tail
        d = d / (np.hypot(*d) + TINY)
        _label(ax, head + d * 0.05 * L, mathtext(a["name"]), col, placed, L)
    for c in couples:
        p = np.asarray(c["point"], float)
        rr = 0.09 * L
        a0, a1 = (200.0, 520.0) if c["value"] > 0 else (520.0, 200.0)
        t = np.radians(np.linspace(a0, a1, 30)) * 0.75
        arc = p + rr * np.column_stack((np.cos(t), np.sin(t)))
        ax.plot(arc[:-1, 0], arc[:-1, 1], color=LOAD, lw=1.1, zorder=6)
        _arrow(ax, arc[-3], arc[-1], LOAD)
        _label(ax, p + np.array([0.0, rr + 0.05 * L]), mathtext(c["name"]), LOAD, placed, L)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.axis("off")
    return fig


def cycle_figure(phi_deg: np.ndarray, groups: np.ndarray, zhuk_phi: np.ndarray, zhuk: np.ndarray,
                 mark_deg: float, mark_value: float, w_cm: float = 15.0):
    """M_ур(φ1): the group method as a curve, Zhukovsky's lever at the analysed positions as
    markers, the analysed position ringed."""
    fig = new_figure(w_cm, 8.0)
    ax = fig.add_axes([0.12, 0.14, 0.85, 0.8])
    ax.plot(phi_deg, groups, "k-", lw=1.2, label=tr("figures.kst04"))
    ax.plot(zhuk_phi, zhuk, "o", ms=5, mfc="none", mec="tab:red", label=tr("figures.kst05"))
    ax.plot([mark_deg], [mark_value], "s", ms=7, mfc="none", mec="tab:blue", label=tr("figures.kst06"))
    ax.axhline(0.0, color="0.4", lw=0.6)
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 45))
    ax.set_xlabel("$\\varphi_1$, °")
    ax.set_ylabel(tr("figures.kst02"))
    comma_axes(ax)
    ax.legend(fontsize=8, loc="best")
    return fig
