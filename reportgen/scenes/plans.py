"""Velocity and acceleration plans as scenes (plan mm are paper mm): every component of
:func:`reportgen.plans.build_plans` as an arrow between its plan points, the absolute vectors from
the pole to the images no component starts there (a computed component shorter than
``reportgen.plans.LEGIBLE_MM`` is not laid off), the letters of the plan points (coincident points
share one label) and the names of the components along their arrows; ``values`` the measured
length (mm, to ``MEASURE_MM``) and the value read back of every component."""
from __future__ import annotations

import math
import re

import numpy as np

from ..plans import Plan
from ..geometry import vec2 as _pt
from .scene import Arrow, Entity, Label, Scale, Scene, frozen

#: Plan points closer than this (mm) share one label.
SAME_MM = 0.3

UNITS = {"velocity": ("μv", "(м/с)/мм", "V"), "acceleration": ("μa", "(м/с²)/мм", "a")}


def pole(plan: Plan) -> str:
    return "p" if plan.kind == "velocity" else "π"


def image_keys(plan: Plan) -> set[str]:
    """Plan letters that are images of mechanism points or centres of mass (not the helper points
    n…, k… that end normal and Coriolis components)."""
    ends = {c.end for c in plan.components if c.kind in ("normal", "coriolis") and c.start != pole(plan)}
    return {k for k in plan.points if k not in ends}


def helpers(plan: Plan, keys: set[str]) -> set[str]:
    return {k for k in plan.points if k not in keys and k != pole(plan)}


def letter_tex(key: str, helper: bool = False) -> str:
    """A plan letter with its index: ``s2`` → ``s_{2}``; a helper point ``nba`` → ``n_{ba}``."""
    if helper and len(key) > 1:
        return f"{key[0]}_{{{key[1:]}}}"
    m = re.match(r"^(\D+)(\d+)$", key)
    return f"{m.group(1)}_{{{m.group(2)}}}" if m else key


def groups(plan: Plan, keys: list[str]) -> list[tuple[tuple[float, float], list[str]]]:
    """Plan points grouped by position (coincident points share a label), in ``keys`` order."""
    out: list[tuple[tuple[float, float], list[str]]] = []
    for k in keys:
        p = plan.points[k]
        for pos, names in out:
            if math.dist(pos, p) < SAME_MM:
                names.append(k)
                break
        else:
            out.append(((float(p[0]), float(p[1])), [k]))
    return out


def plan_scene(plan: Plan, keys: set[str] | None = None, name: str | None = None) -> Scene:
    """The scene of ``plan``; ``keys`` the plan letters that are images of points (default: all but
    the helper points)."""
    keys = image_keys(plan) if keys is None else keys
    pl = pole(plan)
    helper = helpers(plan, keys)
    order = [pl] + [k for k in plan.points if k != pl and k not in helper] + sorted(helper)
    symbol, unit, letter = UNITS[plan.kind]
    ents: list[Entity] = []
    labels: list[Label] = []
    from_pole = {c.end for c in plan.components if c.start == pl}
    ends_done = {tuple(np.round(plan.points[e], 6)) for e in from_pole}
    for k in order:
        if k == pl or k in helper or k in from_pole:
            continue
        p = plan.points[k]
        key = tuple(np.round(p, 6))
        if math.hypot(*p) < SAME_MM or key in ends_done:
            continue
        ends_done.add(key)
        ents.append(Arrow(f"{letter}_{{{k.upper()}}}", (0.0, 0.0), _pt(p), "absolute"))
    values: dict[str, float] = {}
    for c in plan.components:
        a, b = plan.points[c.start], plan.points[c.end]
        values[c.name] = plan.measured_mm(c)
        values[f"{c.name}:read"] = plan.read_value(c)
        if not plan.drawn(c):       # a computed component under LEGIBLE_MM is not laid off
            continue
        ents.append(Arrow(c.name, _pt(a), _pt(b), c.kind))
        if math.dist(a, b) >= 1.0:
            labels.append(Label(c.name, c.name, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), "vector",
                                (_pt(a), _pt(b))))
    for pos, names in groups(plan, order):
        text = ",".join(letter_tex(k, k in helper) for k in names)
        labels.append(Label(text, "point:" + ",".join(names), (float(pos[0]), float(pos[1])), "point"))
    points = {k: (float(v[0]), float(v[1])) for k, v in plan.points.items()}
    return Scene(name or f"{plan.kind}-plan-{plan.position}", (Scale(symbol, plan.scale, unit),),
                 tuple(ents), tuple(labels), frozen(points), frozen(values))
