"""Force polygons as scenes (polygon mm at μF are paper mm): the sides head to tail (the loads and
the reactions found by closing it), the reactions read off it as dashed diagonals, each named beside
its own vector; a vector too short to carry its name gets a leader (the name is drawn away from it
with a thin line to its middle)."""
from __future__ import annotations

import math
import re

import numpy as np

from ..geometry import vec2 as _pt
from .scene import Arrow, Entity, Label, Scale, Scene, frozen
from ..tolerances import MM_EPS

#: A vector shorter than this (mm) is named with a leader.
LEADER_MM = 12.0


def force_tex(name: str) -> str:
    """A solver's force or moment name as a TeX symbol: ``Fпс`` → F_{\\text{пс}}, ``G4`` → G_{4},
    ``Fи4′`` → F'_{\\text{и}4}, ``Rn24`` → R^{n}_{24}, ``Rτ24`` → R^{\\tau}_{24}, a lever's couple
    force ``Mи2:B`` → F^{B}_{M\\text{и}2}."""
    text = "\\text"
    if ":" in name:
        base, point = name.split(":", 1)
        m = re.fullmatch(r"M(и|пс)?(.*)", base)
        sub = (f"{text}{{{m.group(1)}}}" if m and m.group(1) else "") + (m.group(2) if m else base)
        return f"F^{{{point}}}_{{M{sub}}}"
    prime = name.endswith("′")
    core = name[:-1] if prime else name
    m = re.fullmatch(r"R([nτ])?(\d+(?:,\d+)?)", core)
    if m:
        sup = {"n": "^{n}", "τ": "^{\\tau}"}.get(m.group(1) or "", "")
        return f"R{sup}_{{{m.group(2)}}}"
    m = re.fullmatch(r"([A-Za-z])(и|пс|ур)?([\d.,]*)", core)
    if not m:
        return core
    letter, word, digits = m.groups()
    sub = (f"{text}{{{word}}}" if word else "") + (digits or "")
    p = "'" if prime else ""
    return f"{letter}{p}_{{{sub}}}" if sub else f"{letter}{p}"


def diagonal(polygon, v) -> tuple[np.ndarray, np.ndarray]:
    """The two vertices of the polygon that the read vector ``v`` joins (tail, head)."""
    verts = [np.asarray(x.start_mm, float) for x in polygon.vectors] + [np.asarray(polygon.vectors[-1].end_mm, float)]
    d = np.asarray(v.end_mm, float)
    best, err = (verts[0], verts[0] + d), math.inf
    for i, a in enumerate(verts):
        for b in verts[i + 1:] + verts[:i]:
            e = float(np.hypot(*((b - a) - d)))
            if e < err:
                best, err = (a, b), e
    return best


def polygon_scene(polygon, name: str | None = None) -> Scene:
    """The scene of a :class:`reportgen.kinetostatics.graphical.ForcePolygon`."""
    ents: list[Entity] = []
    labels: list[Label] = []
    values: dict[str, float] = {}
    for v in polygon.vectors:
        a, e = _pt(v.start_mm), _pt(v.end_mm)
        values[v.name] = v.measured_mm
        values[f"{v.name}:read"] = v.read_value
        if math.dist(a, e) < MM_EPS:
            continue
        ents.append(Arrow(f"vec:{v.name}", a, e, "load" if v.known else "found"))
        labels.append(Label(force_tex(v.name), f"vec:{v.name}", ((a[0] + e[0]) / 2, (a[1] + e[1]) / 2),
                            "vector", (a, e), leader=math.dist(a, e) < LEADER_MM))
    for v in polygon.extra:
        a, b = (_pt(p) for p in diagonal(polygon, v))
        values[v.name] = v.measured_mm
        values[f"{v.name}:read"] = v.read_value
        if math.dist(a, b) < MM_EPS:
            continue
        ents.append(Arrow(f"read:{v.name}", a, b, "read", "hidden"))
        labels.append(Label(force_tex(v.name), f"read:{v.name}", ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2),
                            "vector", (a, b), leader=math.dist(a, b) < LEADER_MM))
    return Scene(name or f"polygon-{polygon.key}", (Scale("μF", polygon.scale, "Н/мм"),), tuple(ents),
                 tuple(labels), frozen({}), frozen(values))
