"""A zoo of canonical mechanisms as task-file text, for the structure and kinematics tests."""
from __future__ import annotations

import math
from pathlib import Path

from reportgen.kinematics import build_model
from reportgen.taskfile import loads_task

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def four_bar(a: float, b: float, c: float, d: float, phi_deg: float = 60.0, omega: float = 10.0,
             branch: float = 1.0) -> str:
    """Crank O–A (a), coupler A–B (b), rocker C–B (c), frame O–C (d) along +x; sketch at φ1."""
    ph = math.radians(phi_deg)
    A = (a * math.cos(ph), a * math.sin(ph))
    # B from the two circles (|AB| = b, |CB| = c), on the side ``branch`` of the line A→C
    C = (d, 0.0)
    dx, dy = C[0] - A[0], C[1] - A[1]
    D = math.hypot(dx, dy)
    x = (b * b - c * c + D * D) / (2 * D)
    h = math.sqrt(max(b * b - x * x, 0.0))
    ex, ey = dx / D, dy / D
    B = (A[0] + x * ex - branch * h * ey, A[1] + x * ey + branch * h * ex)
    return f"""
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
[analysis]
start = 0.0
"""


def slider_crank(r: float, l: float, e: float = 0.0, phi_deg: float = 30.0, omega: float = 10.0) -> str:
    """Crank O–A (r), rod A–B (l), slider B on the line y = e."""
    ph = math.radians(phi_deg)
    A = (r * math.cos(ph), r * math.sin(ph))
    B = (A[0] + math.sqrt(l * l - (A[1] - e) ** 2), e)
    return f"""
[mechanism]
name = "slider-crank"
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
[[mechanism.link]]
id = 3
kind = "slider"
points = ["B"]
[[mechanism.slide]]
link = 3
point = "B"
guide = 0
line = {{ through = [0.0, {e!r}], angle_deg = 0.0 }}
[mechanism.drive]
link = 1
omega = {omega!r}
[analysis]
start = 0.0
"""


def slotted_lever(r: float, d: float, L: float = 1.0, phi_deg: float = 30.0, omega: float = 10.0) -> str:
    """Crank and slotted lever: crank O–A (r) with O at (0, d) above the slotted link's pivot C at
    the origin; block 2 at A slides along C→E of link 3 (length L)."""
    ph = math.radians(phi_deg)
    A = (r * math.cos(ph), d + r * math.sin(ph))
    n = math.hypot(*A)
    E = (L * A[0] / n, L * A[1] / n)
    return f"""
[mechanism]
name = "slotted lever"
ground = ["O", "C"]
[mechanism.points]
C = [0.0, 0.0]
O = [0.0, {d!r}]
A = [{A[0]!r}, {A[1]!r}]
E = [{E[0]!r}, {E[1]!r}]
[[mechanism.link]]
id = 1
kind = "crank"
points = ["O", "A"]
length = {r!r}
[[mechanism.link]]
id = 2
kind = "block"
points = ["A"]
[[mechanism.link]]
id = 3
kind = "slotted"
points = ["C", "E"]
length = {L!r}
[[mechanism.slide]]
link = 2
point = "A"
guide = 3
along = ["C", "E"]
[mechanism.drive]
link = 1
omega = {omega!r}
[analysis]
start = 0.0
"""


def model_from_text(text: str):
    return build_model(loads_task(text).mechanism)


def example_model(name: str):
    from reportgen.taskfile import load_task
    return build_model(load_task(EXAMPLES / name / "task.toml").mechanism)


EXAMPLE_NAMES = ("press", "crank-slider", "shaper", "conveyor", "class3")
