"""Reduction of loads and masses to the crank (Артоболевский, «Теория механизмов и машин»;
seed 000, section 3).

    M_red = Σ(F·v_F + M·ω) / |ω1|                    (equal power; negative for a resisting load)
    J_red = J_crank + Σ_k [m_k·|v_Sk|² + J_Sk·ω_k²] / ω1²   (equal kinetic energy)
    dJ_red/dθ = 2·Σ_k [m_k·v_Sk·a_Sk + J_Sk·ω_k·ε_k] / |ω1|³

The kinematics are those of the crank turning uniformly at the nominal ω1, so v/ω1 and a/ω1² are
the first and second derivatives of the positions with respect to the crank angle: the reduced
quantities depend on the position only. θ is the crank's rotation in its own sense of turning,
so dividing by |ω1| keeps "negative = resisting" for a clockwise crank as well.
"""
from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ..kinematics import KinematicsResult
from ..linkage import Linkage
from ..loads import LoadSet, power
from ..geometry import dot as _dot, readonly as _ro


def reduced_moment(loads: LoadSet, kin: KinematicsResult) -> np.ndarray:
    """M_red = P / |ω1|, N·m at every position of ``kin`` (all loads in ``loads``)."""
    return _ro(power(loads, kin) / abs(kin.omega1))


def inertia_terms(kin: KinematicsResult, linkage: Linkage) -> Mapping[int, np.ndarray]:
    """Each moving link's share of J_red, [m_k·v_Sk² + J_Sk·ω_k²]/ω1², kg·m² (links with mass)."""
    w2 = kin.omega1 ** 2
    out: dict[int, np.ndarray] = {}
    for k in linkage.moving:
        b = linkage.bodies[k]
        if b.mass <= 0 and b.inertia <= 0:
            continue
        v = np.asarray(kin.coms[k].vel)
        om = np.asarray(kin.links[k].omega)
        out[k] = _ro((b.mass * _dot(v, v) + b.inertia * om * om) / w2)
    return out


def reduced_inertia(kin: KinematicsResult, linkage: Linkage, crank_inertia: float,
                    with_dJ: bool = True) -> tuple[np.ndarray, np.ndarray | None]:
    """(J_red, dJ_red/dθ) at every position: ``crank_inertia`` (rotor, gears) plus every link's
    own share — the crank's own mass and J_S1 included (they are not part of ``crank_inertia``,
    which TASK_FORMAT.md defines as the rotor and gears reduced to the crank). Without ``with_dJ``
    dJ is None and the accelerations are not read (a solve of positions and velocities only)."""
    w = abs(kin.omega1)
    J = np.full(kin.phi.size, float(crank_inertia))
    dJ = np.zeros(kin.phi.size) if with_dJ else None
    for k in linkage.moving:
        b = linkage.bodies[k]
        if b.mass <= 0 and b.inertia <= 0:
            continue
        v = np.asarray(kin.coms[k].vel)
        om = np.asarray(kin.links[k].omega)
        J += (b.mass * _dot(v, v) + b.inertia * om * om) / w ** 2
        if dJ is not None:
            a, eps = np.asarray(kin.coms[k].acc), np.asarray(kin.links[k].epsilon)
            dJ += 2.0 * (b.mass * _dot(v, a) + b.inertia * om * eps) / w ** 3
    return _ro(J), (None if dJ is None else _ro(dJ))


def constant_inertia(linkage: Linkage, crank_inertia: float) -> float:
    """The part of J_red that does not change over the cycle (Мерцалов's first group): the rotor and
    gears plus the crank itself about its axis, J_S1 + m1·|O S1|²."""
    b = linkage.bodies[linkage.drive_link]
    o = np.asarray(b.local[linkage.drive_axis])
    r = np.asarray(b.com_local) - o
    return float(crank_inertia) + b.inertia + b.mass * float(r @ r)
