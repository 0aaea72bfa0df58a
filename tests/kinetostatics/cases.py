"""Mechanisms for the kinetostatics tests: the examples and generated slider-cranks and four-bars."""
from __future__ import annotations

import math
from pathlib import Path

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
    ph = math.radians(phi_deg)
    A = (r * math.cos(ph), r * math.sin(ph))
    B = (A[0] + math.sqrt(l * l - (A[1] - e) ** 2), e)
    text = f"""
[mechanism]
name = "slider-crank"
g = {g!r}
ground = ["O"]
[mechanism.points]
O = [0.0, 0.0]
A = [{A[0]!r}, {A[1]!r}]
B = [{B[0]!r}, {e!r}]
[[mechanism.link]]
id = 1
kind = "crank"
points = ["O", "A"]
length = {r!r}
[[mechanism.link]]
id = 2
kind = "coupler"
points = ["A", "B"]
length = {l!r}
mass = {m2!r}
inertia = {j2!r}
[[mechanism.link]]
id = 3
kind = "slider"
points = ["B"]
mass = {m3!r}
[[mechanism.slide]]
link = 3
point = "B"
guide = 0
line = {{ through = [0.0, {e!r}], angle_deg = 0.0 }}
[mechanism.drive]
link = 1
omega = {omega!r}
[[mechanism.load]]
kind = "force"
link = 3
point = "B"
vector = [{force!r}, 0.0]
[analysis]
positions = 12
start = 0.0
force_position = 1
"""
    return Project(loads_task(text))


def four_bar(a: float, b: float, c: float, d: float, omega: float = 10.0, moment: float = -30.0,
             phi_deg: float = 60.0) -> Project:
    """Crank O–A (a), coupler A–B (b), rocker C–B (c), frame O–C (d) along +x; a couple on the rocker."""
    ph = math.radians(phi_deg)
    A = (a * math.cos(ph), a * math.sin(ph))
    dx, dy = d - A[0], -A[1]
    D = math.hypot(dx, dy)
    x = (b * b - c * c + D * D) / (2 * D)
    h = math.sqrt(max(b * b - x * x, 0.0))
    ex, ey = dx / D, dy / D
    B = (A[0] + x * ex - h * ey, A[1] + x * ey + h * ex)
    text = f"""
[mechanism]
name = "four-bar"
ground = ["O", "C"]
[mechanism.points]
O = [0.0, 0.0]
C = [{d!r}, 0.0]
A = [{A[0]!r}, {A[1]!r}]
B = [{B[0]!r}, {B[1]!r}]
[[mechanism.link]]
id = 1
kind = "crank"
points = ["O", "A"]
length = {a!r}
[[mechanism.link]]
id = 2
kind = "coupler"
points = ["A", "B"]
length = {b!r}
[[mechanism.link]]
id = 3
kind = "rocker"
points = ["C", "B"]
length = {c!r}
[mechanism.drive]
link = 1
omega = {omega!r}
[[mechanism.load]]
kind = "moment"
link = 3
value = {moment!r}
[analysis]
positions = 12
start = 0.0
"""
    return Project(loads_task(text))
