"""Figures of section 2 (kinetostatics, matplotlib): an Assur group or the crank cut out of the
mechanism with every force at its point, a force polygon at μF, Zhukovsky's lever (the velocity plan
turned by −90° with the loads at the image points and their arms), and M_ур over the cycle.

Every geometric number comes from the solver's objects (``reportgen.kinetostatics``); nothing here
computes a force. Arrow lengths on the group diagrams are schematic (a square-root law, so that a
10 N weight stays visible beside a 10 kN resistance); the polygons are drawn at their scale μF."""
from __future__ import annotations

import math
import re

import numpy as np

from reportgen.geometry import vec2
from matplotlib.patches import Circle, FancyArrowPatch, Polygon

from . import comma_axes, math_name, new_figure
from .mechanism import world_points

#: Colours: loads, reactions found in this step, reactions known from an earlier step.
LOAD = "black"
FOUND = "tab:red"
KNOWN = "tab:blue"


def mathtext(name: str) -> str:
    """A solver's force name as matplotlib mathtext: ``Fи4′`` → ``$F'_{\\mathrm{и}4}$``."""
    return "$" + symbol(name, text="\\mathrm") + "$"


def symbol(name: str, text: str = "\\text") -> str:
    """A solver's force or moment name as a math symbol (LaTeX or mathtext).

    ``Fпс`` → F_{\\text{пс}}, ``G4`` → G_{4}, ``Fи4′`` → F'_{\\text{и}4}, ``Mи2`` → M_{\\text{и}2},
    ``Rn24`` → R^{n}_{24}, ``Rτ24`` → R^{\\tau}_{24}, ``R3,12`` → R_{3,12}, ``Fур`` → F_{\\text{ур}},
    a lever's couple force ``Mи2:B`` → F^{B}_{M\\text{и}2}."""
    if ":" in name:                                   # a force of the pair replacing a couple
        base, point = name.split(":", 1)
        m = re.fullmatch(r"M(и|пс)?(.*)", base)
        sub = (f"{text}{{{m.group(1)}}}" if m and m.group(1) else "") + (m.group(2) if m else base)
        return f"F^{{{point}}}_{{M{sub}}}"
    prime = name.endswith("′")
    core = name[:-1] if prime else name
    m = re.fullmatch(r"R([nτ])?(\d+(?:,\d+)?)", core)
    if m:
        sup = {"n": "^{n}", "τ": "^{\\tau}"}.get(m.group(1) or "", "")
        return f"R{sup}_{{{m.group(2)}}}"
    m = re.fullmatch(r"([A-Za-z])(и|пс|ур)?([\d.,]*)", core)
    if not m:
        return core
    letter, word, digits = m.groups()
    sub = (f"{text}{{{word}}}" if word else "") + (digits or "")
    p = "'" if prime else ""
    return f"{letter}{p}_{{{sub}}}" if sub else f"{letter}{p}"


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
    top = max(mags + [1e-300])
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
    L = float(max(span.max(), 1e-9))
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
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-9)
    h_cm = min(11.0, max(5.0, w_cm * aspect))
    w_cm = max(5.0, min(w_cm, h_cm / max(aspect, 1e-9)))
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
        nrm = np.array([-d[1], d[0]]) / (np.hypot(*d) + 1e-300)
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
        d = d / (np.hypot(*d) + 1e-300)
        _label(ax, p - d * 0.06 * L + np.array([0.0, 0.04 * L]), math_name(n), "black", placed, L)
    colour = {"load": LOAD, "found": FOUND, "known": KNOWN}
    for a, (tail, head) in zip(arrows, ends):
        col = colour[a["role"]]
        _arrow(ax, tail, head, col)
        d = head - tail
        d = d / (np.hypot(*d) + 1e-300)
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


def polygon_figure(polygon, w_cm: float = 13.0):
    """A force polygon: its sides head to tail from its origin (mm at μF), the found reactions in
    red, the reactions read as diagonals dashed, and the scale."""
    vecs = polygon.vectors
    pts = [np.asarray(v.start_mm, float) for v in vecs] + [np.asarray(v.end_mm, float) for v in vecs]
    pts += [np.asarray(v.end_mm, float) for v in polygon.extra]
    arr = np.vstack(pts + [np.zeros(2)])
    size = float(max(np.ptp(arr, axis=0).max(), 1e-9))
    lo, hi = arr.min(0) - 0.12 * size, arr.max(0) + 0.12 * size
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-9)
    w = w_cm if aspect <= 1 else max(7.0, w_cm / aspect)
    fig = new_figure(w, min(13.0, max(5.0, w * aspect)))
    ax = fig.add_axes([0.01, 0.01, 0.98, 0.98])
    placed: list[np.ndarray] = []
    for v in vecs:
        a, e = np.asarray(v.start_mm, float), np.asarray(v.end_mm, float)
        if np.hypot(*(e - a)) < 1e-9:
            continue
        col = LOAD if v.known else FOUND
        _arrow(ax, a, e, col, lw=1.2)
        d = e - a
        n = np.array([-d[1], d[0]]) / (np.hypot(*d) + 1e-300)
        _label(ax, (a + e) / 2 + n * 0.045 * size, mathtext(v.name), col, placed, size)
    origin = np.asarray(vecs[0].start_mm, float)
    for v in polygon.extra:
        # a diagonal from the polygon's points: find the side it joins
        e = np.asarray(v.end_mm, float)
        a, b = _diagonal(polygon, v)
        _arrow(ax, a, b, KNOWN, lw=1.0, ls="--")
        d = b - a
        n = np.array([-d[1], d[0]]) / (np.hypot(*d) + 1e-300)
        _label(ax, (a + b) / 2 - n * 0.045 * size, mathtext(v.name), KNOWN, placed, size)
        del e
    ax.plot([origin[0]], [origin[1]], "ko", ms=2.5)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.axis("off")
    ax.text(0.01, 0.01, f"$\\mu_F$ = {polygon.scale:g} Н/мм".replace(".", ","), transform=ax.transAxes, fontsize=9)
    return fig


def _diagonal(polygon, v) -> tuple[np.ndarray, np.ndarray]:
    """The two vertices of the polygon that the read vector ``v`` joins (tail, head)."""
    verts = [np.asarray(x.start_mm, float) for x in polygon.vectors] + [np.asarray(polygon.vectors[-1].end_mm, float)]
    d = np.asarray(v.end_mm, float)
    best, err = (verts[0], verts[0] + d), math.inf
    for i, a in enumerate(verts):
        for b in verts[i + 1:] + verts[:i]:
            e = float(np.hypot(*((b - a) - d)))
            if e < err:
                best, err = (a, b), e
    return best


def lever_figure(points: dict[str, np.ndarray], segments: list[tuple[str, str]], loads: list[dict],
                 w_cm: float = 14.0, max_h_cm: float = 12.0):
    """Zhukovsky's lever: the turned plan (images in mm at μv: ``points``, the pole ``p`` at 0),
    the loads (``{"image": mm, "vector": N, "name", "arm_mm", "h": label}``) and their arms (green,
    from the pole square to each force's line)."""
    arr = np.vstack([np.zeros(2)] + list(points.values()))
    size = float(max(np.ptp(arr, axis=0).max(), 1e-9))
    lengths = schematic_lengths([float(np.hypot(*ld["vector"])) for ld in loads], 0.16 * size)
    heads, feet = [], []
    for ld, ln in zip(loads, lengths):
        v = np.asarray(ld["vector"], float)
        u = v / (np.hypot(*v) + 1e-300)
        img = np.asarray(ld["image"], float)
        heads.append(img + u * ln)
        feet.append(img - (img @ u) * u if ld.get("h") else None)
    allp = np.vstack([arr] + heads + [f for f in feet if f is not None])
    lo, hi = allp.min(0) - 0.08 * size, allp.max(0) + 0.08 * size
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-9)
    w = min(w_cm, max_h_cm / aspect) if aspect > 0 else w_cm
    fig = new_figure(w, max(6.0, min(max_h_cm, w * aspect)))
    ax = fig.add_axes([0.01, 0.01, 0.98, 0.98])
    placed: list[np.ndarray] = []
    for a, b in segments:
        pa = np.zeros(2) if a == "p" else points[a]
        pb = points[b]
        ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="0.3", lw=1.0, zorder=2)
    for name, p in points.items():
        ax.plot([p[0]], [p[1]], "ko", ms=2.5, zorder=3)
        _label(ax, p + np.array([0.03, 0.03]) * size, math_name(name), "black", placed, size)
    ax.plot([0], [0], "ko", ms=3)
    _label(ax, np.array([-0.04, -0.04]) * size, "$p$", "black", placed, size)
    for ld, head, foot in zip(loads, heads, feet):
        img = np.asarray(ld["image"], float)
        _arrow(ax, img, head, LOAD, lw=1.0)
        d = head - img
        u = d / (np.hypot(*d) + 1e-300)
        _label(ax, head + u * 0.035 * size, mathtext(ld["name"]), LOAD, placed, size)
        if foot is not None:
            ax.plot([0, foot[0]], [0, foot[1]], color="tab:green", lw=0.6, ls="--", zorder=1)
            ax.plot([img[0], foot[0]], [img[1], foot[1]], color="0.7", lw=0.4, ls=":", zorder=1)
            _label(ax, foot, f"${ld['h']}$", "tab:green", placed, size)
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
    ax.plot(phi_deg, groups, "k-", lw=1.2, label="метод планов сил (группы Ассура)")
    ax.plot(zhuk_phi, zhuk, "o", ms=5, mfc="none", mec="tab:red", label="рычаг Жуковского")
    ax.plot([mark_deg], [mark_value], "s", ms=7, mfc="none", mec="tab:blue", label="положение силового расчёта")
    ax.axhline(0.0, color="0.4", lw=0.6)
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 45))
    ax.set_xlabel("$\\varphi_1$, °")
    ax.set_ylabel("$M_{\\mathrm{ур}}$, Н·м")
    comma_axes(ax)
    ax.legend(fontsize=8, loc="best")
    return fig
