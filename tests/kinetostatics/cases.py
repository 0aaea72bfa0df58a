"""Mechanisms for the kinetostatics tests: the examples and generated slider-cranks and four-bars."""
from __future__ import annotations

from pathlib import Path

from reportgen import zoo
from reportgen.project import Project
from reportgen.taskfile import load_task, loads_task

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXAMPLE_NAMES = ("press", "crank-slider", "shaper", "conveyor", "class3")


def example(name: str, at_deg=None) -> Project:
    return Project(load_task(EXAMPLES / name / "task.toml"), at_deg=at_deg)


def slider_crank(r: float, l: float, e: float = 0.0, omega: float = 10.0, m2: float = 2.0, j2: float = 0.02,
                 m3: float = 3.0, force: float = 500.0, g: float = 9.81, phi_deg: float = 31.7) -> Project:
    """Crank O–A (r), rod A–B (l) with mass m2 and J2, slider B (m3) on the line y = e, a constant
    force ``force`` along +x on the slider. The sketch stands at 31.7° (not 30°): with the sketch at
    30° the stroke search of reportgen.kinematics.extremes can land a grid point on a dead centre and
    brentq fails (reported; e.g. r = 0.125, l = 0.25, e = 0, ω = −2)."""
    text = zoo.slider_crank(r, l, e, phi_deg=phi_deg, omega=omega, g=g,
                            links={2: {"mass": m2, "inertia": j2}, 3: {"mass": m3}},
                            loads=[{"kind": "force", "link": 3, "point": "B", "vector": [force, 0.0]}],
                            analysis={"positions": 12, "start": 0.0, "force_position": 1})
    return Project(loads_task(text))


def four_bar(a: float, b: float, c: float, d: float, omega: float = 10.0, moment: float = -30.0,
             phi_deg: float = 60.0) -> Project:
    """Crank O–A (a), coupler A–B (b), rocker C–B (c), frame O–C (d) along +x; a couple on the rocker."""
    text = zoo.four_bar(a, b, c, d, phi_deg=phi_deg, omega=omega,
                        loads=[{"kind": "moment", "link": 3, "value": moment}],
                        analysis={"positions": 12, "start": 0.0})
    return Project(loads_task(text))
