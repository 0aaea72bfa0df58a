"""Every joint of the structure is drawn as a joint with its letter wherever the mechanism is drawn
(issue 12): the note's kinematic scheme and its Assur groups' figures, and the plan of positions
(the scene that sheet 1 and the note's figure draw). The crank–rocker with an offset slider
(tests/data/crank-rocker-offset-slider.toml) drew its group (2,3) with link 3 running past B to D
and no hinge or letter at D, where group (4,5) attaches."""
from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from matplotlib.patches import Circle as MplCircle  # noqa: E402

from latex_templates.figures.groups import group_figure  # noqa: E402
from latex_templates.figures.mechanism import scheme_figure, world_points  # noqa: E402
from reportgen.project import Project  # noqa: E402
from reportgen.scenes.scene import Circle  # noqa: E402
from reportgen.taskfile import load_task  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
TASKS = {name: ROOT / "examples" / name / "task.toml"
         for name in ("press", "shaper", "conveyor", "crank-slider", "class3", "control-work")}
TASKS.update({name: ROOT / "tests" / "data" / f"{name}.toml"
              for name in ("crank-rocker-offset-slider", "crank-rocker", "shaper-short-crank")})
_PROJECTS: dict[str, Project] = {}


def _project(name: str) -> Project:
    if name not in _PROJECTS:
        _PROJECTS[name] = Project(load_task(TASKS[name]))
    return _PROJECTS[name]


def _marks(fig) -> tuple[list[np.ndarray], dict[str, list[np.ndarray]], float]:
    """The hinge circles' centres, the texts' positions by text, and the drawing's size (data units)."""
    ax = fig.axes[0]
    circles = [np.asarray(p.center, float) for p in ax.patches if isinstance(p, MplCircle)]
    texts: dict[str, list[np.ndarray]] = {}
    for t in ax.texts:
        texts.setdefault(t.get_text(), []).append(np.asarray(t.get_position(), float))
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    return circles, texts, max(abs(x1 - x0), abs(y1 - y0))


def _check_figure(fig, points: dict[str, np.ndarray], names: set[str], what: str) -> None:
    circles, texts, size = _marks(fig)
    for name in sorted(names):
        p = points[name]
        assert any(np.hypot(*(c - p)) <= 1e-9 * max(size, 1.0) + 1e-12 for c in circles), \
            f"{what}: no hinge at joint {name}"
        near = [np.hypot(*(t - p)) for t in texts.get(name, [])]
        assert near, f"{what}: no letter {name}"
        assert min(near) <= 0.2 * size, f"{what}: the letter {name} is {min(near):.3g} from its joint (size {size:.3g})"


@pytest.mark.parametrize("name", sorted(TASKS))
def test_note_scheme_and_groups_mark_every_joint(name):
    import matplotlib.pyplot as plt

    project = _project(name)
    lk = project.linkage
    q0 = np.asarray(project.kinematics.q)[0]
    pts = world_points(lk, q0)
    joints = {j.name for j in lk.joints}
    fig = scheme_figure(lk, q0)
    try:
        _check_figure(fig, pts, joints, f"{name}: scheme")
    finally:
        plt.close(fig)
    for g in project.structure.groups[1:]:
        on_group = {p for k in g.links for p in lk.bodies[k].points}
        fig = group_figure(lk, q0, g)
        try:
            _check_figure(fig, pts, joints & on_group, f"{name}: group {g.label}")
        finally:
            plt.close(fig)


@pytest.mark.parametrize("name", sorted(TASKS))
def test_plan_of_positions_marks_every_joint(name):
    """Sheet 1's scheme and the note's plan of positions (one scene): at the analysed position a
    hinge at every moving joint, a fixed pivot at every frame joint, and every joint's letter."""
    project = _project(name)
    lk = project.linkage
    scene = project.scenes.positions
    i = project.analysed
    ids = {e.id: e for e in scene.entities}
    letters = {(lb.text, lb.anchor) for lb in scene.labels if lb.role == "point"}
    for j in lk.joints:
        if 0 in j.bodies:
            assert any(k.startswith(f"pivot:{j.name}") for k in ids), f"{name}: no fixed pivot at {j.name}"
        else:
            e = ids.get(f"pos{i}:joint:{j.name}")
            assert isinstance(e, Circle) and e.hinge, f"{name}: no hinge at joint {j.name}"
            assert np.allclose(e.c, scene.points[j.name]), f"{name}: the hinge {j.name} is off its point"
        assert (j.name, f"pos{i}:{j.name}") in letters, f"{name}: no letter {j.name}"
