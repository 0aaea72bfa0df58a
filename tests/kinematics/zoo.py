"""The canonical mechanisms of ``reportgen.zoo`` with the defaults of the structure and kinematics
tests (the sketch at 60° for a four-bar, 30° otherwise; ω1 = 10 rad/s)."""
from __future__ import annotations

from pathlib import Path

from reportgen import zoo
from reportgen.kinematics import build_model
from reportgen.taskfile import loads_task

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def four_bar(a: float, b: float, c: float, d: float, phi_deg: float = 60.0, omega: float = 10.0,
             branch: float = 1.0) -> str:
    """Crank O–A (a), coupler A–B (b), rocker C–B (c), frame O–C (d) along +x; sketch at φ1."""
    return zoo.four_bar(a, b, c, d, phi_deg=phi_deg, omega=omega, branch=branch)


def slider_crank(r: float, l: float, e: float = 0.0, phi_deg: float = 30.0, omega: float = 10.0) -> str:
    """Crank O–A (r), rod A–B (l), slider B on the line y = e."""
    return zoo.slider_crank(r, l, e, phi_deg=phi_deg, omega=omega)


def slotted_lever(r: float, d: float, L: float = 1.0, phi_deg: float = 30.0, omega: float = 10.0) -> str:
    """Crank and slotted lever: crank O–A (r) with O at (0, d) above the slotted link's pivot C at
    the origin; block 2 at A slides along C→E of link 3 (length L)."""
    return zoo.slotted_lever(r, d, L, phi_deg=phi_deg, omega=omega)


def model_from_text(text: str):
    return build_model(loads_task(text).mechanism)


def example_model(name: str):
    from reportgen.taskfile import load_task
    return build_model(load_task(EXAMPLES / name / "task.toml").mechanism)


EXAMPLE_NAMES = ("press", "crank-slider", "shaper", "conveyor", "class3")
