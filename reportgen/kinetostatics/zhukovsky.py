"""Zhukovsky's lever: the balancing moment without the reactions.

Жуковский Н. Е. (1909); Артоболевский, «Теория механизмов и машин», «Рычаг Жуковского»; course
manual (seed 001, section 6): the velocity plan turned by 90° about its pole, loaded at the images
of the points with the forces of the mechanism (inertia included) carried over parallel to
themselves, is a rigid lever in equilibrium about the pole.

Turning the plan by −90° (clockwise, as seed 000 does) takes the image of a point P with velocity v
to ``p' = (v_y, −v_x)``; the moment of F applied there about the pole is ``p' × F = v·F``: the arm
of each force times the force is exactly its power. A couple M on link k is a pair of forces ±M/l
square to the link at two of its points (the manual's replacement), whose moments sum to ``M·ω_k``.
Equilibrium of the lever with the balancing force at the crank pin gives the virtual-power balance

    M_ур·ω1 + Σ F_i·v_i + Σ M_k·ω_k = 0,   M_ур = −(Σ F_i·v_i + Σ M_k·ω_k)/ω1.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..kinematics import KinematicsResult
from ..kinematics.constraints import world
from ..linkage import Linkage
from ..loads import LoadSet
from ..geometry import readonly as _ro


def turn_cw(v: np.ndarray) -> np.ndarray:
    """A velocity image turned by −90° (clockwise): (vx, vy) → (vy, −vx)."""
    return np.stack((v[..., 1], -v[..., 0]), axis=-1)


def point_velocity(kin: KinematicsResult, k: int, point: np.ndarray) -> np.ndarray:
    """Velocity of the point of link k that stands at ``point`` (N, 2): v_k + ω_k × r."""
    q, qd = np.asarray(kin.q), np.asarray(kin.qd)
    r = np.asarray(point) - q[:, k, :2]
    return qd[:, k, :2] + qd[:, k, 2][:, None] * np.stack((-r[:, 1], r[:, 0]), axis=-1)


@dataclass(frozen=True)
class LeverForce:
    """One force on the lever: its image point (turned velocity, m/s), vector (N), moment about the
    pole (N·m/s = W, CCW positive) and signed arm (m/s: moment = |F|·arm)."""
    name: str
    link: int
    source: str              # the load's name; a couple's pair is "Mи2+"/"Mи2−"
    image: np.ndarray        # (N, 2)
    vector: np.ndarray       # (N, 2)
    moment: np.ndarray       # (N,)
    arm: np.ndarray          # (N,)


@dataclass(frozen=True)
class Lever:
    """The lever at every position: the forces on it, the couples taken directly as M·ω (links with
    one point), the balancing moment and the balancing force at the crank pin's image."""
    forces: tuple[LeverForce, ...]
    direct: tuple[tuple[str, int, np.ndarray], ...]     # (name, link, M·ω (N,))
    crank_pin_image: np.ndarray                         # (N, 2)
    balancing_moment: np.ndarray                        # (N,)
    balancing_force: np.ndarray                         # (N,) magnitude along the pin's image normal
    omega1: float


def couple_points(linkage: Linkage, k: int) -> tuple[str, str] | None:
    """The two points of link k that carry the force pair of a couple (its first two points)."""
    pts = linkage.bodies[k].points
    return (pts[0], pts[1]) if len(pts) >= 2 else None


def zhukovsky_lever(linkage: Linkage, kin: KinematicsResult, loads: LoadSet) -> Lever:
    """Load the turned velocity plan and take moments about its pole (all positions of ``kin``)."""
    q = np.asarray(kin.q)
    forces: list[LeverForce] = []
    direct: list[tuple[str, int, np.ndarray]] = []
    total = np.zeros(kin.phi.size)

    def put(name: str, k: int, source: str, point: np.ndarray, vec: np.ndarray) -> None:
        nonlocal total
        img = turn_cw(point_velocity(kin, k, point))
        mom = img[:, 0] * vec[:, 1] - img[:, 1] * vec[:, 0]
        mag = np.hypot(vec[:, 0], vec[:, 1])
        arm = np.divide(mom, mag, out=np.zeros_like(mom), where=mag > 0)
        forces.append(LeverForce(name, k, source, _ro(img), _ro(vec), _ro(mom), _ro(arm)))
        total = total + mom

    for f in loads.forces:
        put(f.name, f.link, f.name, np.asarray(f.point), np.asarray(f.vector))
    for m in loads.moments:
        k = m.link
        pts = couple_points(linkage, k)
        val = np.asarray(m.value, dtype=float)
        if pts is None:
            p = val * np.asarray(kin.qd)[:, k, 2]
            direct.append((m.name, k, _ro(p)))
            total = total + p
            continue
        b = linkage.bodies[k]
        P1 = world(q, k, b.local[pts[0]])
        P2 = world(q, k, b.local[pts[1]])
        d = P2 - P1
        l2 = (d * d).sum(-1)
        # F at P2 and −F at P1 with (P2 − P1) × F = M:  F = M·perp(d)/|d|²
        F = (val / l2)[:, None] * np.stack((-d[:, 1], d[:, 0]), axis=-1)
        put(f"{m.name}:{pts[1]}", k, m.name, P2, F)
        put(f"{m.name}:{pts[0]}", k, m.name, P1, -F)
    d = linkage.drive_link
    A = world(q, d, linkage.bodies[d].local[linkage.drive_tip])
    pin = turn_cw(point_velocity(kin, d, A))
    w1 = float(kin.omega1)
    M_b = -total / w1
    O = world(q, d, linkage.bodies[d].local[linkage.drive_axis])
    l_OA = np.hypot(*(A - O).T)
    return Lever(tuple(forces), tuple(direct), _ro(pin), _ro(M_b), _ro(M_b / l_OA), w1)


def virtual_power_moment(loads: LoadSet, kin: KinematicsResult) -> np.ndarray:
    """M_ур = −P/ω1 with P = Σ F·v + Σ M·ω the power of the loads (:func:`reportgen.loads.power`)."""
    from ..loads import power
    return -power(loads, kin) / float(kin.omega1)


__all__ = ["Lever", "LeverForce", "zhukovsky_lever", "virtual_power_moment", "turn_cw", "point_velocity"]
