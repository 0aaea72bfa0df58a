"""Figures of section 2 (kinetostatics, matplotlib): an Assur group or the crank cut out of the
mechanism with every force at its point, a force polygon at μF, Zhukovsky's lever (the velocity plan
turned by −90° with the loads at the image points and their arms), and M_ур over the cycle.

Every geometric number comes from the solver's objects (``reportgen.kinetostatics``) through the
scenes; nothing here computes a force. The group diagrams are the scenes sheet 2 draws
(:mod:`reportgen.scenes.free_body`: arrow lengths schematic, one rule for both); the polygons are
drawn at their scale μF."""
from __future__ import annotations

import numpy as np

from ..parts import active, tr
from reportgen.scenes.forces import force_tex

from . import comma_axes, new_figure
from .keyed import keyed_plot

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


#: The free-body diagrams' largest page size (mm): the text block's width, 0,8 of its height (a tall group
#: keeps room for its labels; the caption and a line of text fit under it).
FBD_MAX_W_MM, FBD_MAX_H_MM = 160.0, 170.0


def free_body_figure(scene):
    """A free-body diagram: the scene of :mod:`reportgen.scenes.free_body` that sheet 2 draws, at
    its μl (reduced where it does not fit, the caption says so), arrows coloured by role (loads
    black, reactions known from earlier steps blue, reactions found here red), their lengths the
    scene's schematic ones."""
    from .scene import scene_figure
    return scene_figure(scene, max_w_mm=FBD_MAX_W_MM, max_h_mm=FBD_MAX_H_MM, roles=("point", "vector", "link"))


@keyed_plot()
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
