"""Kinetostatics of a project: the analysed position, the exact solution there, both methods over
the cycle, and the near-dead-centre warning.

The analysed position (RESULTS_FORMAT ``kinetostatics.phi_deg``): ``--force-at DEG`` if given, else
``[analysis] force_position`` — an index into the task's [analysis] positions (``project.phi``
without ``--at``; with ``--at`` the angle of that position of the task's grid), or ``"max-load"``: the crank angle of
the largest production resistance on a grid of :data:`MAX_LOAD_GRID` angles from position 0 in the
direction of rotation; where the law has a plateau (equal maxima), the angle where the resistance
takes the most power (|F·v| or |M·ω|, the largest share of the balancing moment), then the earliest.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..geometry import readonly
from ..errors import OptionError, TaskError
from ..kinematics.transmission import NEAR_SINGULAR_DEG
from .graphical import GraphicalReplica, graphical_replica
from .reactions import Reactions, solve_reactions
from .zhukovsky import Lever, zhukovsky_lever
from ..tolerances import ABS_ZERO, RTOL_EQUAL

#: Grid of crank angles searched for "max-load".
MAX_LOAD_GRID = 720
#: Below this transmission angle (or NEAR_SINGULAR_DEG if larger) the result carries a warning.
WARN_TRANSMISSION_DEG = max(10.0, NEAR_SINGULAR_DEG)


@dataclass(frozen=True)
class Kinetostatics:
    """Section 2 at one crank angle: exact reactions, the balancing moment by the groups and by
    Zhukovsky's lever, their discrepancy, and the graphical replica."""
    phi: float                              # rad
    position: int | None                    # index into project.phi, if it is one of them
    reactions: Reactions                    # N = 1
    lever: Lever                            # N = 1
    graphical: GraphicalReplica
    transmission_deg: Mapping[str, float]
    warnings: tuple[str, ...]

    @property
    def phi_deg(self) -> float:
        return math.degrees(self.phi) % 360.0

    @property
    def balancing_moment(self) -> float:
        return float(self.reactions.balancing_moment[0])

    @property
    def balancing_moment_zhukovsky(self) -> float:
        return float(self.lever.balancing_moment[0])

    @property
    def balancing_force(self) -> float:
        """F_ур = M_ур/l_OA, N (signed: positive gives a counter-clockwise moment)."""
        O = self.reactions.pair(self.frame_pair).point[0]
        return self.balancing_moment / float(np.hypot(*(self.reactions.balancing_point[0] - O)))

    @property
    def frame_pair(self) -> str:
        return next(p.name for p in self.reactions.pairs if p.group == str(self.reactions.crank))

    @property
    def discrepancy_percent(self) -> float:
        """100·(M_groups − M_Zhukovsky)/M_Zhukovsky — round-off only (~1e-12 %)."""
        mz = self.balancing_moment_zhukovsky
        return 0.0 if mz == 0.0 else 100.0 * (self.balancing_moment - mz) / mz


def resistance_magnitude(project, kin) -> tuple[np.ndarray, np.ndarray]:
    """(|resistance| summed over the resistance loads, |its power|) at the positions of ``kin``."""
    from ..loads import power, resistance_loads, LoadSet
    ls = resistance_loads(project.task.mechanism, project.linkage, project.model, kin, project.strokes)
    mag = np.zeros(kin.phi.size)
    for f in ls.forces:
        mag += np.hypot(*np.asarray(f.vector).T)
    for m in ls.moments:
        mag += np.abs(m.value)
    return mag, np.abs(power(LoadSet(ls.forces, ls.moments), kin))


def force_angle(project, force_at_deg: float | None = None) -> tuple[float, int | None]:
    """(crank angle, rad; index into project.phi or None) of the analysed position."""
    if force_at_deg is not None:
        if isinstance(force_at_deg, bool) or not math.isfinite(float(force_at_deg)):
            raise OptionError("--force-at", f"got {force_at_deg!r}", "a finite crank angle in degrees")
        phi = math.radians(float(force_at_deg))
        idx = _index_of(project.phi, phi)
        return phi, idx
    fp = project.task.analysis.force_position
    if fp == "max-load":
        n = MAX_LOAD_GRID
        sgn = 1.0 if project.model.omega >= 0 else -1.0
        base = project if getattr(project, "at_deg", None) is None else type(project)(project.task)
        grid = np.mod(float(base.phi[0]) + sgn * np.arange(n) * 2 * math.pi / n, 2 * math.pi)
        kin = project.kinematics_at(grid)
        mag, pw = resistance_magnitude(project, kin)
        top = mag.max()
        if top <= 0.0:
            raise TaskError("analysis.force_position", "\"max-load\" but the task has no production resistance",
                            "a position index, or a [[mechanism.load]] of kind \"resistance\"")
        cand = np.flatnonzero(mag >= top * (1 - RTOL_EQUAL))
        best = cand[np.argmax(pw[cand] >= pw[cand].max() * (1 - RTOL_EQUAL))]
        phi = float(grid[best])
        return phi, _index_of(project.phi, phi)
    # the index names a position of the task's own [analysis] grid, also when --at replaces it
    base = project if getattr(project, "at_deg", None) is None else type(project)(project.task)
    idx = int(fp)
    if not 0 <= idx < len(base.phi):
        raise TaskError("analysis.force_position", f"got {idx}, but only {len(base.phi)} positions are analysed",
                        f"an index 0…{len(base.phi) - 1} or \"max-load\"")
    phi = float(base.phi[idx])
    return phi, _index_of(project.phi, phi)


def _index_of(phis: np.ndarray, phi: float) -> int | None:
    d = np.abs(np.angle(np.exp(1j * (np.asarray(phis) - phi))))
    j = int(np.argmin(d)) if d.size else -1
    return j if j >= 0 and d[j] < ABS_ZERO else None


def kinetostatics_at(project, force_at_deg: float | None = None, **graphical_options) -> Kinetostatics:
    """Section 2 at ``--force-at`` (deg) or at the task's force position."""
    phi, idx = force_angle(project, force_at_deg)
    kin = project.kinematics_at(np.array([phi]))
    loads = project.loads_at(kin, inertia=True)
    reactions = solve_reactions(project.linkage, project.structure, kin, loads)
    lever = zhukovsky_lever(project.linkage, kin, loads)
    graphical_options.setdefault("boxes", project.boxes)
    graphical_options.setdefault("lever_box", project.boxes.lever_for(project.task))
    graph = graphical_replica(project.linkage, project.structure, reactions, lever, 0, **graphical_options)
    trans = {k: float(v[0]) for k, v in kin.transmission_deg.items()}
    warnings = tuple(
        f"group {k}: transmission angle μ = {mu:.2f}° < {WARN_TRANSMISSION_DEG:g}°: near a dead centre the "
        f"reactions grow like 1/sin μ" for k, mu in trans.items() if mu < WARN_TRANSMISSION_DEG)
    return Kinetostatics(phi, idx, reactions, lever, graph, MappingProxyType(trans), warnings)


@dataclass(frozen=True)
class BalancingCycle:
    """The balancing moment by both methods at crank angles ``phi`` (rad)."""
    phi: np.ndarray
    groups: np.ndarray
    zhukovsky: np.ndarray


def balancing_cycle(project, phi, inertia: bool = True) -> BalancingCycle:
    """Both methods at every angle of ``phi`` (rad), vectorised."""
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    kin = project.kinematics_at(phi)
    loads = project.loads_at(kin, inertia=inertia)
    r = solve_reactions(project.linkage, project.structure, kin, loads)
    z = zhukovsky_lever(project.linkage, kin, loads)
    return BalancingCycle(readonly(phi), readonly(r.balancing_moment), readonly(z.balancing_moment))


def balancing_moment_cycle(project, phi, inertia: bool = True) -> np.ndarray:
    """M_ур (N·m, CCW positive, applied by the drive) at the crank angles ``phi`` (rad), by the
    group method; with ``inertia=False`` the static part only (no d'Alembert loads)."""
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    kin = project.kinematics_at(phi)
    loads = project.loads_at(kin, inertia=inertia)
    return solve_reactions(project.linkage, project.structure, kin, loads).balancing_moment
