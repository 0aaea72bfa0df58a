"""The note's Zhukovsky lever (issue 12, the press's fig. 2.7): a name that stands on a leader keeps
clear of every other named vector, or it reads as that one's — on main the press's «F^B_Mи4» stood
0,6 mm from the tail of F_ур (its leader to its own arrow at b unseen beside it), «F_ур» 0,2 mm
from G₂, the crank-slider's «F_и2» 0,2 mm from F^A_Mи2, and the arms' names at the pole (h₁₀,
h₁₄, h₂) sat on leaders 0,5 mm from the other arms. Read back from the matplotlib figure (figure mm)
of the lever's scene as the note draws it, for every example with a lever. The arms' names now try
the spot just past the arm's foot (away from the pole where the arms meet) before a leader."""
from __future__ import annotations

import pytest
from shapely.geometry import LineString

from latex_templates.figures.scene import scene_figure
from latex_templates.parts import active_strings
from latex_templates.render import Strings
from reportgen.project import Project
from reportgen.scenes.lever import lever_scene
from reportgen.taskfile import load_task

from .conftest import EXAMPLES, ROOT
from .readback import figure_texts

#: A name on a leader keeps at least this far (figure mm) from every other named vector.
CLEAR_MM = 0.5


def leader_names_too_close(fig) -> list[str]:
    """Names on a leader (what they name: the leader, then their vector) nearer than CLEAR_MM to
    another named vector (the last segment of what another text names)."""
    texts = [t for t in figure_texts(fig) if isinstance(t.names, LineString)]
    vectors = [(t.text, LineString(list(t.names.coords)[-2:])) for t in texts]
    found = []
    for t in texts:
        if len(t.names.coords) <= 2:
            continue
        own = LineString(list(t.names.coords)[-2:])
        for name, line in vectors:
            if not line.equals(own) and t.box.distance(line) < CLEAR_MM:
                found.append(f"{t.text} on a leader {t.box.distance(line):.2f} mm from {name}")
    return found


def _with_lever(name: str) -> bool:
    return load_task(ROOT / "examples" / name / "task.toml").mechanism is not None


@pytest.mark.slow
@pytest.mark.parametrize("example", [e for e in EXAMPLES if _with_lever(e)])
def test_lever_leader_names_keep_clear(example):
    import matplotlib.pyplot as plt
    project = Project(load_task(ROOT / "examples" / example / "task.toml"))
    with active_strings(Strings(project.task.document.language or "ru")):
        fig = scene_figure(lever_scene(project.kinetostatics, project.linkage))
    try:
        found = leader_names_too_close(fig)
    finally:
        plt.close(fig)
    assert not found, "\n".join(found)
