"""Labels of every figure of every example's note, read back from matplotlib (each text's window
extent): no two texts overlap, each label is within LABEL_NEAR_MM of what it names
(``reportgen_names``, or the point an annotation points at), no other named point is nearer to it,
and no label is left out because its point lies outside the axes (issue 12: fig. 1.3's «5» over
«D», the shaper's «3», «2», «A» stacked, ψmax of the shaper's Wittenbauer diagram not drawn)."""
from __future__ import annotations

import pytest

from reportgen.project import Project
from reportgen.taskfile import load_task
from reportgen.tolerances import LABEL_NEAR_MM

from .conftest import EXAMPLES, ROOT, case
from .notefigs import GROUPS, group_of, note_figures
from .readback import check_figure

_FIGURES: dict[str, dict] = {}
#: Figures whose vectors' names are checked against the other named vectors (issue 12: the force
#: polygons, Zhukovsky's lever, the groups' and the crank's free-body diagrams, the plans).
VECTOR_FIGURES = ("kst_poly", "kst_lever", "kst_group_", "kst_crank", "kin_vplan", "kin_aplan")


def _figures(name: str) -> dict:
    """The figures of one example's note (the last example's only: a note holds ~25 figures)."""
    if name not in _FIGURES:
        import matplotlib.pyplot as plt
        for figs in _FIGURES.values():
            for f in figs.values():
                plt.close(f)
        _FIGURES.clear()
        _FIGURES[name] = note_figures(Project(load_task(ROOT / "examples" / name / "task.toml")))
    return _FIGURES[name]


@pytest.mark.slow
@pytest.mark.parametrize("example,group", [case(e, g) for e in EXAMPLES for g in (*GROUPS, "other")])
def test_note_figure_labels(example, group):
    figs = {k: f for k, f in _figures(example).items() if group_of(k) == group}
    if not figs:
        pytest.skip(f"the note of {example} has no figures of group {group}")
    found = [f"{k}: {x}" for k, fig in sorted(figs.items())
             for x in check_figure(fig, LABEL_NEAR_MM, vectors=any(v in k for v in VECTOR_FIGURES))]
    assert not found, "\n".join(found)


def test_the_check_sees_stacked_labels():
    """Two texts on one spot, a label far from its point and an annotation of a point outside its
    axes are each found."""
    from latex_templates.figures import new_figure
    from latex_templates.figures.labels import names
    fig = new_figure(10.0, 10.0)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_xlim(0, 100)
    ax.set_ylim(0, 100)                      # 1 data unit = 1 mm
    names(ax.text(50, 50, "3", ha="center", va="center"), (50, 45))
    names(ax.text(51, 50, "2", ha="center", va="center"), (60, 45))
    names(ax.text(20, 20, "A", ha="center", va="center"), (20, 40))
    ax.annotate("K", (150, 50), xytext=(4, 2), textcoords="offset points")
    found = [str(f) for f in check_figure(fig, LABEL_NEAR_MM)]
    assert any("overlap" in f and "«3»" in f for f in found), found
    assert any("far" in f and "«A»" in f for f in found), found
    assert any("not drawn" in f and "«K»" in f for f in found), found
