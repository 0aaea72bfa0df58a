"""``solve_dynamics(project)``: the whole flywheel calculation of issue #5, items 1–4."""
from __future__ import annotations

import math
import weakref

import numpy as np

from .cycle import TWO_PI, Cycle, ProjectCycle
from .energy import EnergyProfile
from .errors import DynamicsInputError
from .flywheel import flywheel_size
from .graphical import GraphLayout, graphical_replica
from .motion import steady_motion
from .quadrature import DEFAULT_ORDER
from .result import DynamicsResult, compare
from .wittenbauer import wittenbauer_and_merzalov
from ..errors import ParameterError
from ..geometry import readonly as _ro

#: The fewest grid positions kept in results.json (RESULTS_FORMAT.md / issue #5).
MIN_POSITIONS = 360


def check_delta(delta: float) -> float:
    if not (isinstance(delta, (int, float)) and math.isfinite(delta) and 0 < delta < 1):
        raise DynamicsInputError("dynamics.delta", f"{delta!r} is not a coefficient of non-uniformity",
                                 "a number in (0, 1), e.g. 0.05")
    return float(delta)


def solve_cycle(cycle: Cycle, delta: float, n: int = MIN_POSITIONS, *, shape: str = "disk",
                density: float = 7860.0, width_ratio: float = 1.0, crank_inertia: float = 0.0,
                graphical_positions: int = 12, layout: GraphLayout,
                order: int = DEFAULT_ORDER, phi_of=None, profile: EnergyProfile | None = None) -> DynamicsResult:
    """The flywheel calculation of any cycle (a project's or an analytic one); ``profile``: ΔE of
    this cycle on the same grid, when the caller has it already."""
    delta = check_delta(delta)
    if n < 8:
        raise ParameterError("n", n, "at least 8 crank positions")
    theta = np.arange(n) * TWO_PI / n
    prof = profile if profile is not None else EnergyProfile(cycle, theta, order)
    idx = np.searchsorted(prof.nodes, theta)
    A = prof.A_nodes[idx]
    red = cycle.reduced(theta)
    ex, mz = wittenbauer_and_merzalov(cycle, prof, delta)
    gr = graphical_replica(cycle, delta, graphical_positions, layout=layout)
    J_fly = max(ex.J_fly, 0.0)
    motion = steady_motion(cycle, prof, J_fly, theta, delta)
    fw = flywheel_size(J_fly, shape, density, width_ratio)
    phi = phi_of(theta) if phi_of is not None else theta
    return DynamicsResult(
        theta=_ro(theta), phi=_ro(phi), M_red=_ro(red.M), J_red=_ro(red.J), dJ_red=_ro(red.dJ),
        work_resistance=_ro(A), work_drive=_ro(prof.M_drive * theta), delta_E=_ro(prof.M_drive * theta + A),
        M_drive=prof.M_drive, work_cycle=prof.work_cycle, omega_m=cycle.omega_m, delta_target=delta,
        crank_inertia=crank_inertia, J_const=cycle.J_const, breaks=_ro(cycle.breaks),
        switching=tuple(getattr(cycle, "switching_phi", ())), exact=ex, merzalov=mz, graphical=gr,
        comparison=compare(ex.J_fly, {"merzalov": mz.J_fly, "graphical": gr.J_fly}),
        J_flywheel=J_fly, flywheel=fw, motion=motion)


def solve_dynamics(project, n: int = MIN_POSITIONS, graphical_positions: int | None = None,
                   layout: GraphLayout | None = None, order: int = DEFAULT_ORDER) -> DynamicsResult:
    """Reduced moment and inertia, work, ΔE, the flywheel (exact, Мерцалов, graphical), its size and
    the steady motion with it, over ``n`` equal steps from position 0 of the project's task."""
    dyn = project.task.dynamics
    if dyn is None:
        raise DynamicsInputError("dynamics", "the task has no [dynamics] section", "a [dynamics] section with delta")
    cycle, profile = energy_of(project, n, order)
    if graphical_positions is None:
        graphical_positions = max(project.task.analysis.positions, 12)
    fw = dyn.flywheel
    layout = layout or project.boxes.diagrams
    return solve_cycle(cycle, dyn.delta, n, shape=fw.shape, density=fw.density, width_ratio=fw.width_ratio,
                       crank_inertia=dyn.crank_inertia, graphical_positions=graphical_positions,
                       layout=layout, order=order, phi_of=cycle.phi_of, profile=profile)


_CACHE: "weakref.WeakKeyDictionary[object, DynamicsResult]" = weakref.WeakKeyDictionary()
_ENERGY: "weakref.WeakKeyDictionary[object, dict]" = weakref.WeakKeyDictionary()


def energy_of(project, n: int = MIN_POSITIONS, order: int = DEFAULT_ORDER) -> tuple[ProjectCycle, EnergyProfile]:
    """The project's cycle and its ΔE profile on ``n`` equal steps, computed once per project and grid
    (the solver and the note's comparison of flywheels share them)."""
    known = _ENERGY.setdefault(project, {})
    key = (n, order)
    if key not in known:
        dyn = project.task.dynamics
        cycle = ProjectCycle(project, dyn.crank_inertia)
        known[key] = (cycle, EnergyProfile(cycle, np.arange(n) * TWO_PI / n, order))
    return known[key]


def dynamics_of(project) -> DynamicsResult:
    """``solve_dynamics(project)`` with the defaults, computed once per project (results.json and the
    command's summary share it; until ``Project`` has a ``dynamics`` stage of its own)."""
    r = _CACHE.get(project)
    if r is None:
        project.need_full_cycle("[dynamics] (the motion over a cycle and the flywheel)")
        r = _CACHE[project] = solve_dynamics(project)
    return r
