"""Canonical mechanisms as task-file text, for tests, benchmarks and docs.

Every function here is pure: it returns the text of a task file (``docs/task-format.md``,
read by :func:`reportgen.taskfile.loads_task`) and reads or writes nothing.

* :func:`linkage` writes any linkage from its points, links, slides, drive and loads;
* :func:`four_bar`, :func:`slider_crank` and :func:`slotted_lever` compute the sketch of a canonical
  mechanism (the crank at ``phi_deg``, every other point where the lengths put it) and write it with
  :func:`linkage`. ``links`` adds keys to a link (``{2: {"mass": 6.0, "inertia": 0.08}}``), ``loads``
  adds ``[[mechanism.load]]`` tables, ``analysis`` is the ``[analysis]`` table (None: none) and
  ``extra`` is TOML appended as it is (``[dynamics]``, ``[gears]``, a deliberate error …).
"""
from __future__ import annotations

import json
import math
from types import MappingProxyType
from typing import Any, Iterable, Mapping, Sequence

from .geometry import Vec2 as Point
Keys = Mapping[str, Any]

START_AT_ZERO: Keys = MappingProxyType({"start": 0.0})
"""``[analysis] start = 0.0``: the positions counted from φ1 = 0 (the default of the builders)."""


def toml_value(value: Any) -> str:
    """One TOML value: a string, bool, number (``repr``), list/tuple (array) or mapping (inline table)."""
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, Mapping):
        return "{ " + ", ".join(f"{k} = {toml_value(v)}" for k, v in value.items()) + " }"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    return repr(value)


def _table(header: str, keys: Keys) -> list[str]:
    return [header] + [f"{k} = {toml_value(v)}" for k, v in keys.items()]


def linkage(*, ground: Sequence[str], points: Mapping[str, Point], links: Iterable[Keys], omega: float,
            slides: Iterable[Keys] = (), loads: Iterable[Keys] = (), name: str | None = None,
            g: float | None = None, drive_link: int = 1, analysis: Keys | None = None, extra: str = "") -> str:
    """The task text of a linkage: ``[mechanism]`` (``name`` and ``g`` only when given), its points in
    the order given, one ``[[mechanism.link]]``/``[[mechanism.slide]]``/``[[mechanism.load]]`` table
    per mapping (keys in their order), the drive, then ``[analysis]`` when given and ``extra``."""
    head: dict[str, Any] = {}
    if name is not None:
        head["name"] = name
    if g is not None:
        head["g"] = g
    head["ground"] = list(ground)
    lines = _table("[mechanism]", head) + _table("[mechanism.points]", points)
    for keys in links:
        lines += _table("[[mechanism.link]]", keys)
    for keys in slides:
        lines += _table("[[mechanism.slide]]", keys)
    lines += _table("[mechanism.drive]", {"link": drive_link, "omega": omega})
    for keys in loads:
        lines += _table("[[mechanism.load]]", keys)
    if analysis is not None:
        lines += _table("[analysis]", analysis)
    return "\n" + "\n".join(lines) + "\n" + extra


def _links(base: list[dict[str, Any]], more: Mapping[int, Keys] | None) -> list[dict[str, Any]]:
    """The links' own keys, then the keys ``more`` adds to a link by its id."""
    for keys in base:
        keys.update((more or {}).get(keys["id"], {}))
    return base


def four_bar(a: float, b: float, c: float, d: float, *, phi_deg: float, omega: float, branch: float = 1.0,
             name: str | None = "four-bar", g: float | None = None, links: Mapping[int, Keys] | None = None,
             loads: Iterable[Keys] = (), analysis: Keys | None = START_AT_ZERO, extra: str = "") -> str:
    """Crank 1 O–A (a), coupler 2 A–B (b), rocker 3 C–B (c), frame O–C (d) along +x; the sketch at
    φ1 = ``phi_deg``, B on the side ``branch`` (+1 left, −1 right) of the line A→C."""
    ph = math.radians(phi_deg)
    A = (a * math.cos(ph), a * math.sin(ph))
    # B from the two circles |AB| = b, |CB| = c
    dx, dy = d - A[0], 0.0 - A[1]
    D = math.hypot(dx, dy)
    x = (b * b - c * c + D * D) / (2 * D)
    h = math.sqrt(max(b * b - x * x, 0.0))
    ex, ey = dx / D, dy / D
    B = (A[0] + x * ex - branch * h * ey, A[1] + x * ey + branch * h * ex)
    return linkage(
        name=name, g=g, ground=("O", "C"), points={"O": (0.0, 0.0), "C": (d, 0.0), "A": A, "B": B},
        links=_links([{"id": 1, "kind": "crank", "points": ["O", "A"], "length": a},
                      {"id": 2, "kind": "coupler", "points": ["A", "B"], "length": b},
                      {"id": 3, "kind": "rocker", "points": ["C", "B"], "length": c}], links),
        omega=omega, loads=loads, analysis=analysis, extra=extra)


def slider_crank(r: float, l: float, e: float = 0.0, *, phi_deg: float, omega: float,
                 name: str | None = "slider-crank", g: float | None = None,
                 links: Mapping[int, Keys] | None = None, loads: Iterable[Keys] = (),
                 analysis: Keys | None = START_AT_ZERO, extra: str = "") -> str:
    """Crank 1 O–A (r), rod 2 A–B (l), slider 3 at B on the line y = e (offset); the sketch at
    φ1 = ``phi_deg``. A rod too short to reach the line puts B under (over) A: the task then cannot
    be assembled, which is for the solver to report."""
    ph = math.radians(phi_deg)
    A = (r * math.cos(ph), r * math.sin(ph))
    B = (A[0] + math.sqrt(max(l * l - (A[1] - e) ** 2, 0.0)), e)
    return linkage(
        name=name, g=g, ground=("O",), points={"O": (0.0, 0.0), "A": A, "B": B},
        links=_links([{"id": 1, "kind": "crank", "points": ["O", "A"], "length": r},
                      {"id": 2, "kind": "coupler", "points": ["A", "B"], "length": l},
                      {"id": 3, "kind": "slider", "points": ["B"]}], links),
        slides=[{"link": 3, "point": "B", "guide": 0, "line": {"through": [0.0, e], "angle_deg": 0.0}}],
        omega=omega, loads=loads, analysis=analysis, extra=extra)


def slotted_lever(r: float, d: float, L: float = 1.0, *, phi_deg: float, omega: float,
                  name: str | None = "slotted lever", g: float | None = None,
                  links: Mapping[int, Keys] | None = None, loads: Iterable[Keys] = (),
                  analysis: Keys | None = START_AT_ZERO, extra: str = "") -> str:
    """Crank and slotted link (кулисный механизм): crank 1 O–A (r) with O at (0, d) above the pivot C
    of the slotted link 3 C–E (length L) at the origin; block 2 at A slides along C→E. The sketch at
    φ1 = ``phi_deg``."""
    ph = math.radians(phi_deg)
    A = (r * math.cos(ph), d + r * math.sin(ph))
    n = math.hypot(*A)
    E = (L * A[0] / n, L * A[1] / n)
    return linkage(
        name=name, g=g, ground=("O", "C"), points={"C": (0.0, 0.0), "O": (0.0, d), "A": A, "E": E},
        links=_links([{"id": 1, "kind": "crank", "points": ["O", "A"], "length": r},
                      {"id": 2, "kind": "block", "points": ["A"]},
                      {"id": 3, "kind": "slotted", "points": ["C", "E"], "length": L}], links),
        slides=[{"link": 2, "point": "A", "guide": 3, "along": ["C", "E"]}],
        omega=omega, loads=loads, analysis=analysis, extra=extra)
