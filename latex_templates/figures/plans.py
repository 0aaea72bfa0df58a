"""Velocity and acceleration plans (matplotlib) from :class:`reportgen.plans.Plan`."""
from __future__ import annotations

import numpy as np

from . import new_figure

COLOURS = {"absolute": "black", "relative": "tab:blue", "normal": "tab:green", "tangential": "tab:red",
           "coriolis": "tab:purple", "sliding": "tab:orange"}


def plan_figure(plan, w_cm: float = 12.0):
    pts = {k: np.asarray(v) for k, v in plan.points.items()}
    used = {c.start for c in plan.components} | {c.end for c in plan.components}
    shown = {k: v for k, v in pts.items() if k in used or k.startswith("s")}
    arr = np.array(list(shown.values()))
    span = np.ptp(arr, axis=0) + 1e-9
    size = float(max(span.max(), 1e-9))
    h_cm = min(9.0, max(6.0, w_cm * span[1] / max(span[0], 1e-9) + 1.5))
    w_cm = min(w_cm, max(6.0, (h_cm - 1.5) * span[0] / max(span[1], 1e-9) + 1.5))
    fig = new_figure(w_cm, h_cm)
    ax = fig.add_axes([0.02, 0.02, 0.96, 0.96])
    for c in plan.components:
        a, e = pts[c.start], pts[c.end]
        d = e - a
        if np.hypot(*d) < 1e-9:
            continue
        ax.annotate("", xy=e, xytext=a, arrowprops=dict(arrowstyle="-|>", color=COLOURS.get(c.kind, "black"),
                                                        lw=1.1, mutation_scale=9, shrinkA=0, shrinkB=0))
    # centres of mass: thin lines from the pole
    pole = "p" if plan.kind == "velocity" else "π"
    for k, v in shown.items():
        if k.startswith("s") and k[1:].isdigit():
            ax.plot([0, v[0]], [0, v[1]], color="0.5", lw=0.6, ls="--")
    centre = arr.mean(axis=0)
    placed: list[np.ndarray] = []
    for k, v in shown.items():
        d = v - centre
        n = np.hypot(*d)
        d = d / n if n > 1e-9 else np.array([0.0, 1.0])
        p = v + d * 0.045 * size
        for q in placed:
            if np.hypot(*(p - q)) < 0.04 * size:
                p = p + np.array([0.0, 0.05 * size])
        placed.append(p)
        label = k if not k.startswith("n") and not k.startswith("k") else k[0]
        ax.text(p[0], p[1], label if k != pole else pole, fontsize=10, style="italic", ha="center", va="center")
        ax.plot([v[0]], [v[1]], "ko", ms=2)
    pad = 0.12 * size
    ax.set_xlim(arr[:, 0].min() - pad, arr[:, 0].max() + pad)
    ax.set_ylim(arr[:, 1].min() - pad, arr[:, 1].max() + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    unit = "(м/с)/мм" if plan.kind == "velocity" else "(м/с²)/мм"
    mu = "μ_v" if plan.kind == "velocity" else "μ_a"
    ax.text(0.01, 0.01, f"${mu}$ = {plan.scale:g} {unit}".replace(".", ","), transform=ax.transAxes, fontsize=9)
    return fig


def positions_figure(linkage, q_all: np.ndarray, bold: tuple[int, ...], traces: dict[str, np.ndarray], w_cm=15.0):
    """All positions of the mechanism: the ``bold`` ones drawn fully, the others thin, with traces."""
    from .mechanism import draw_mechanism, world_points
    fig = new_figure(w_cm, 11.0)
    ax = fig.add_axes([0.02, 0.02, 0.96, 0.96])
    allpts = np.concatenate([np.array(list(world_points(linkage, q).values())) for q in q_all])
    L = float(max(np.ptp(allpts[:, 0]), np.ptp(allpts[:, 1])))
    for tr in traces.values():
        ax.plot(tr[:, 0], tr[:, 1], color="0.55", lw=0.6, ls="-.")
    for i, q in enumerate(q_all):
        if i in bold:
            continue
        draw_mechanism(ax, linkage, q, labels=False, numbers=False, lw=0.6, alpha=0.45, guides=False, size=L)
    for i in bold:
        draw_mechanism(ax, linkage, q_all[i], labels=(i == bold[0]), numbers=(i == bold[0]), size=L)
    # position numbers at the crank pin
    tip = linkage.drive_tip
    for i, q in enumerate(q_all):
        p = world_points(linkage, q)[tip]
        o = np.asarray(linkage.sketch[linkage.drive_axis])
        d = p - o
        d = d / (np.hypot(*d) + 1e-300)
        t = p + d * 0.05 * L
        ax.text(t[0], t[1], str(i), fontsize=8, ha="center", va="center", color="tab:blue")
    pad = 0.1 * L
    ax.set_xlim(allpts[:, 0].min() - pad, allpts[:, 0].max() + pad)
    ax.set_ylim(allpts[:, 1].min() - pad, allpts[:, 1].max() + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig


def diagrams_figure(d, w_cm: float = 16.0):
    """s–v–a of the output: exact curves and the chord replica (steps), against the crank angle."""
    from . import comma_axes
    fig = new_figure(w_cm, 17.0)
    deg = np.degrees(d.dense_offset)
    nodes = np.degrees(d.nodes)
    mids = (nodes[:-1] + nodes[1:]) / 2
    unit_s = "м" if d.unit == "м" else "рад"
    unit_v = "м/с" if d.unit == "м" else "рад/с"
    unit_a = "м/с²" if d.unit == "м" else "рад/с²"
    axes = fig.subplots(3, 1, sharex=True)
    ax = axes[0]
    ax.plot(deg, d.s, "k-", lw=1.0, label="точно")
    ax.plot(nodes, d.s_nodes_mm * d.mu_s, "o-", color="tab:blue", lw=0.7, ms=2.5, label="хорды")
    ax.set_ylabel(f"$s$, {unit_s}")
    ax.legend(fontsize=8, loc="best")
    ax = axes[1]
    ax.plot(deg, d.v, "k-", lw=1.0, label="точно")
    ax.step(np.append(nodes[:-1], nodes[-1]), np.append(d.v_graph, d.v_graph[-1]), where="post",
            color="tab:orange", lw=0.8, label="ступени графического дифференцирования")
    ax.plot(mids, d.v_graph, "o", color="tab:blue", ms=2.5)
    ax.set_ylabel(f"$v$, {unit_v}")
    ax.legend(fontsize=8, loc="best")
    ax = axes[2]
    ax.plot(deg, d.a, "k-", lw=1.0, label="точно")
    a_mid = np.mod(mids + (nodes[1] - nodes[0]) / 2, 360.0)
    order = np.argsort(a_mid)
    ax.plot(a_mid[order], d.a_graph[order], "o-", color="tab:blue", lw=0.7, ms=2.5, label="графически")
    ax.set_ylabel(f"$a$, {unit_a}")
    ax.set_xlabel("$\\varphi_1$ от положения 0, град")
    ax.legend(fontsize=8, loc="best")
    for ax in axes:
        comma_axes(ax)
        ax.set_xlim(0, 360)
        ax.set_xticks(nodes[:: max(1, d.n // 12)])
    fig.tight_layout()
    return fig
