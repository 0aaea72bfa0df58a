"""The s–v–a diagrams of the output (matplotlib). The plans and the plan of positions are scenes
(:mod:`latex_templates.figures.scene`)."""
from __future__ import annotations

import numpy as np

from ..parts import tr, unit
from . import new_figure


def diagrams_figure(d, w_cm: float = 16.0):
    """s–v–a of the output: exact curves and the chord replica (steps), against the crank angle."""
    from . import comma_axes
    fig = new_figure(w_cm, 17.0)
    deg = np.degrees(d.dense_offset)
    nodes = np.degrees(d.nodes)
    mids = (nodes[:-1] + nodes[1:]) / 2
    unit_s = unit("м" if d.unit == "м" else "рад")
    unit_v = unit("м/с" if d.unit == "м" else "рад/с")
    unit_a = unit("м/с²" if d.unit == "м" else "рад/с²")
    axes = fig.subplots(3, 1, sharex=True)
    ax = axes[0]
    ax.plot(deg, d.s, "k-", lw=1.0, label=tr("figures.wpla01"))
    ax.plot(nodes, d.s_nodes_mm * d.mu_s, "o-", color="tab:blue", lw=0.7, ms=2.5, label=tr("figures.wpla02"))
    ax.set_ylabel(f"$s$, {unit_s}")
    ax.legend(fontsize=8, loc="best")
    ax = axes[1]
    ax.plot(deg, d.v, "k-", lw=1.0, label=tr("figures.wpla03"))
    ax.step(np.append(nodes[:-1], nodes[-1]), np.append(d.v_graph, d.v_graph[-1]), where="post",
            color="tab:orange", lw=0.8, label=tr("figures.plan02"))
    ax.plot(mids, d.v_graph, "o", color="tab:blue", ms=2.5)
    ax.set_ylabel(f"$v$, {unit_v}")
    ax.legend(fontsize=8, loc="best")
    ax = axes[2]
    ax.plot(deg, d.a, "k-", lw=1.0, label=tr("figures.wpla04"))
    a_mid = np.mod(mids + (nodes[1] - nodes[0]) / 2, 360.0)
    order = np.argsort(a_mid)
    ax.plot(a_mid[order], d.a_graph[order], "o-", color="tab:blue", lw=0.7, ms=2.5, label=tr("figures.wpla05"))
    ax.set_ylabel(f"$a$, {unit_a}")
    ax.set_xlabel(tr("figures.plan01"))
    ax.legend(fontsize=8, loc="best")
    for ax in axes:
        comma_axes(ax)
        ax.set_xlim(0, 360)
        ax.set_xticks(nodes[:: max(1, d.n // 12)])
    fig.tight_layout()
    return fig
