"""The control work's numbers at its one position (manual §7; formulas (27)–(38) of seed 001).

Everything comes from the project's stages: the exact kinematics at φ, the loads of the mass rules
((29)–(34): gravity and d'Alembert's inertia), Zhukovsky's lever (the inertia couples as force pairs,
(35)–(37)) for the balancing force P_у at the crank pin, M_у = P_у·l_AB (38), and — as a check by an
independent route — the power balance M_у·ω1 + Σ F·v + Σ M·ω = 0.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..kinetostatics.zhukovsky import couple_points, virtual_power_moment, zhukovsky_lever


@dataclass(frozen=True)
class LinkLoads:
    """One link's row of the masses/forces/moments table (magnitudes; directions in the note)."""
    link: int
    mass: float            # kg, (29)/(30)
    weight: float          # N, G = m·g (31)
    a_com: float           # m/s², |a_S|
    inertia_force: float   # N, |P_и| = m·|a_S| (32)
    inertia: float         # kg·m², J_S (33)
    epsilon: float         # rad/s², signed (CCW +)
    inertia_moment: float  # N·m, M_и = −J_S·ε (34), signed
    pair_points: tuple[str, str] | None   # the points carrying the force pair of M_и
    pair_arm: float        # m, the distance between them
    pair_force: float      # N, P_M = |M_и|/l (35)–(37)


@dataclass(frozen=True)
class ControlWorkResult:
    phi_deg: float
    omega1: float
    W: int
    formula: str
    groups: tuple[str, ...]                 # "II(2,3) RRR", …
    output_point: str
    omegas: Mapping[int, float]             # rad/s, CCW +
    epsilons: Mapping[int, float]           # rad/s², CCW +
    speeds: Mapping[str, float]             # |v| of every point, m/s
    accelerations: Mapping[str, float]      # |a| of every point, m/s²
    links: tuple[LinkLoads, ...]
    turning: frozenset[int]                 # the links that turn (all but sliders)
    l_AB: float
    P_y: float                              # N, balancing force at the crank pin (lever), signed
    M_y: float                              # N·m, P_у·l_AB, CCW +
    M_y_power: float                        # N·m, by the power balance
    deviation_percent: float                # 100·(M_у − M_у,power)/M_у,power

    def answers(self) -> dict[str, float | int | str]:
        """The answers.csv row (names documented in docs/control-work.md)."""
        row: dict[str, float | int | str] = {"phi_deg": self.phi_deg, "omega1": self.omega1, "W": self.W,
                                             "groups": " ".join(self.groups)}
        for k, w in self.omegas.items():
            if k != 1 and k in self.turning:
                row[f"omega{k}"] = w + 0.0
        for k, e in self.epsilons.items():
            if k != 1 and k in self.turning:
                row[f"eps{k}"] = e + 0.0
        for p, v in self.speeds.items():
            row[f"v{p}"] = v
        for p, a in self.accelerations.items():
            row[f"a{p}"] = a
        row["v_out"] = self.speeds[self.output_point]
        row["a_out"] = self.accelerations[self.output_point]
        row["Py"] = self.P_y
        row["My"] = self.M_y
        row["My_power"] = self.M_y_power
        row["deviation_percent"] = self.deviation_percent
        return row


def control_work_of(project, phi_deg: float | None = None) -> ControlWorkResult:
    """The control work's numbers at ``phi_deg`` (default: the task's analysed position
    ``[analysis] start``/``force_position``)."""
    lk = project.linkage
    if phi_deg is None:
        phi = float(project.phi[min(_force_index(project), len(project.phi) - 1)])
    else:
        phi = math.radians(phi_deg)
    kin = project.kinematics_at(np.array([phi]))
    s = project.structure
    loads = project.loads_at(kin, inertia=True)
    lever = zhukovsky_lever(lk, kin, loads)
    m_power = float(virtual_power_moment(loads, kin)[0])
    m_lever = float(lever.balancing_moment[0])
    l_AB = math.dist(lk.sketch[lk.drive_axis], lk.sketch[lk.drive_tip])
    moving = sorted(lk.moving)
    omegas = MappingProxyType({k: float(kin.links[k].omega[0]) for k in moving})
    eps = MappingProxyType({k: float(kin.links[k].epsilon[0]) for k in moving})
    speeds = MappingProxyType({p: float(np.hypot(*m.vel[0])) for p, m in kin.points.items()
                               if p not in lk.ground})
    accs = MappingProxyType({p: float(np.hypot(*m.acc[0])) for p, m in kin.points.items()
                             if p not in lk.ground})
    rows = []
    for k in moving:
        b = lk.bodies[k]
        a_s = float(np.hypot(*kin.coms[k].acc[0]))
        e = eps[k]
        M = -b.inertia * e
        pts = couple_points(lk, k) if b.inertia > 0 else None
        arm = math.dist(b.local[pts[0]], b.local[pts[1]]) if pts else 0.0
        rows.append(LinkLoads(k, b.mass, b.mass * lk.g, a_s, b.mass * a_s, b.inertia, e, M, pts, arm,
                              abs(M) / arm if arm > 0 else 0.0))
    out = next(p for p in lk.bodies[max(moving)].points)
    dev = 0.0 if m_power == 0.0 else 100.0 * (m_lever - m_power) / m_power
    return ControlWorkResult(
        phi_deg=math.degrees(phi) % 360.0, omega1=float(lk.omega), W=s.W, formula=s.formula,
        groups=tuple(f"{g.label} {g.kind}" for g in s.groups[1:]), output_point=out,
        omegas=omegas, epsilons=eps, speeds=speeds, accelerations=accs, links=tuple(rows),
        turning=frozenset(k for k in moving if len(lk.bodies[k].points) > 1), l_AB=l_AB,
        P_y=m_lever / l_AB, M_y=m_lever, M_y_power=m_power, deviation_percent=dev)


def _force_index(project) -> int:
    fp = project.task.analysis.force_position
    return fp if isinstance(fp, int) else 0
