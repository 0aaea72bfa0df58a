"""The numbering of positions, one for the whole work, in two named grids:

- the grid of the kinematic analysis (plan of positions, plans, kinetostatics; sheets 1 and 2):
  ``[analysis] positions`` equal steps numbered 0…N−1 from position 0;
- the grid of the diagrams of section 3 (sheet 3, tables of section 3): ``[dynamics]`` positions
  (usually more) numbered 0…M (M is position 0 again), plus the switching angles «н.р.х.» /
  «к.р.х.» and the corners of the resistance law «и1», «и2»….

Both count from the same position 0 in the sense of rotation, so an angle φ1 that lies on both
grids has a number in each: :func:`diagram_label` gives the diagrams' name of an angle, and the note
names the grid whenever the two numbers differ."""
from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ..tolerances import ABS_ZERO, ANGLE_READ_EPS, WHOLE_EPS


def first_step(theta) -> float:
    """The equal step of the diagrams' positions (the break angles fall between them)."""
    d = np.diff(np.asarray(theta, float))
    return float(d.max()) if d.size else 2 * math.pi


def sense(res) -> float:
    """+1 if φ1 grows with θ (the crank turns counter-clockwise)."""
    if res.phi.size < 2:
        return 1.0
    return 1.0 if res.phi[1] - res.phi[0] > 0 else -1.0


def diagram_positions(res) -> int:
    """The number of equal steps of the diagrams' grid."""
    return int(round(2 * math.pi / first_step(res.graphical.theta)))


def diagram_labels(res, positions: int | None = None) -> list[str]:
    """Names of the diagrams' positions (``res`` a :class:`reportgen.dynamics.result.DynamicsResult`):
    equal steps numbered 0…N (N is position 0 again), the switching angles «к.р.х.» / «н.р.х.»,
    other corners of the resistance law «и1», «и2»…"""
    positions = positions or diagram_positions(res)
    step = 2 * math.pi / positions
    sgn, phi0 = sense(res), float(res.phi[0])
    theta_sw = [float(np.mod(sgn * (p - phi0), 2 * math.pi)) for p in res.switching]
    names = dict(zip(theta_sw, ("н.р.х.", "к.р.х.")))
    out: list[str] = []
    corner = 0
    for t in map(float, res.graphical.theta):
        j = t / step
        if abs(j - round(j)) < WHOLE_EPS:
            out.append(str(int(round(j))))
            continue
        name = next((v for k, v in names.items() if abs(k - t) < ABS_ZERO), None)
        if name is None:
            corner += 1
            name = f"и{corner}"
        out.append(name)
    return out


#: Catalogue keys of the diagrams' named positions: the switching angles and the resistance law's corners.
LABEL_KEYS = {"н.р.х.": "dynamics.m48", "к.р.х.": "dynamics.m49"}
CORNER_KEY = "dynamics.m19"


def translated_diagram_labels(res, tr: Callable[..., str], positions: int | None = None) -> list[str]:
    """:func:`diagram_labels` in the reader's language, the one helper of the note's table and sheet 3
    (so the two name a position alike): «н.р.х.» / «к.р.х.» and the corners «иN» through the
    catalogue (``tr`` is the caller's lookup, ``tr(key, **values)``: the note's or the sheet's)."""
    out = []
    for x in diagram_labels(res, positions):
        if x in LABEL_KEYS:
            x = tr(LABEL_KEYS[x])
        elif x.startswith("и") and x[1:].isdigit():
            x = tr(CORNER_KEY, corner=int(x[1:]))
        out.append(x)
    return out


def diagram_label(res, phi_rad: float) -> str | None:
    """The diagrams' name of the crank angle ``phi_rad`` (None if it is not one of their positions)."""
    theta = float(np.mod(sense(res) * (phi_rad - float(res.phi[0])), 2 * math.pi))
    labels = diagram_labels(res)
    for t, name in zip(map(float, res.graphical.theta), labels):
        if abs(math.remainder(t - theta, 2 * math.pi)) < ANGLE_READ_EPS:
            return name
    return None
