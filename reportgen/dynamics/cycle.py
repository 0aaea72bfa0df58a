"""The machine over one cycle as functions of θ, the crank's rotation from position 0 in its own
sense of turning (θ ∈ [0, 2π]): reduced moment, reduced inertia and its derivative, and the break
angles where the loads switch or kink.

``ProjectCycle`` builds them from a project (kinematics solved at any θ on demand);
``FunctionCycle`` from plain functions, for analytic cases and tests.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from ..geometry import readonly
from ..loads import StrokeWindow, external_loads, link_coordinate
from ..roots import brent_root
from .errors import DynamicsInputError
from .memo import ReducedMemo
from .reduction import constant_inertia, reduced_inertia, reduced_moment
from ..tolerances import EDGE_ANGLE_TOL

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Reduced:
    """M_red (N·m), J_red (kg·m²) and dJ_red/dθ (kg·m²/rad) at angles θ."""
    M: np.ndarray
    J: np.ndarray
    dJ: np.ndarray


class Cycle(Protocol):
    """What the dynamics solver needs of a machine."""
    omega_m: float          # nominal (mean) crank speed, rad/s, > 0
    J_const: float          # the constant part of J_red (Мерцалов's first group without flywheel)
    breaks: np.ndarray      # sorted break angles θ in [0, 2π], 0 and 2π included

    def reduced(self, theta: np.ndarray, with_dJ: bool = True) -> Reduced: ...


def moment_and_inertia(cycle: Cycle, theta: np.ndarray) -> Reduced:
    """M_red and J_red at ``theta`` for the callers that read no dJ_red/dθ (a project's cycle then
    solves no accelerations; dJ may be NaN)."""
    return cycle.reduced(theta, with_dJ=False)


def _breaks(inner: list[float]) -> np.ndarray:
    b = readonly(sorted({0.0, TWO_PI, *[t for t in inner if 0.0 < t < TWO_PI]}))
    return b


@dataclass(frozen=True)
class FunctionCycle:
    """A cycle given by functions of θ (vectorised), e.g. J = const and ΔE sinusoidal."""
    M: Callable[[np.ndarray], np.ndarray]
    J: Callable[[np.ndarray], np.ndarray]
    dJ: Callable[[np.ndarray], np.ndarray]
    omega_m: float
    J_const: float = 0.0
    inner_breaks: tuple[float, ...] = ()
    breaks: np.ndarray = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "breaks", _breaks(list(self.inner_breaks)))

    def reduced(self, theta: np.ndarray, with_dJ: bool = True) -> Reduced:   # noqa: ARG002 (dJ is cheap here)
        t = np.asarray(theta, dtype=float)
        return Reduced(*(np.broadcast_to(np.asarray(g(t), dtype=float), t.shape).copy()
                         for g in (self.M, self.J, self.dJ)))


def start_angle(project) -> float:
    """Crank angle φ1 of position 0 (rad): the start of the working stroke for [analysis] start =
    "extreme", else the given angle — the same position 0 as the kinematics."""
    a = project.task.analysis
    if a.start == "extreme" and project.strokes is not None:
        return float(project.strokes.phi_start)
    if a.start == "extreme":
        return 0.0
    return math.radians(float(a.start))


class ProjectCycle:
    """The project's mechanism over one cycle; every call solves the kinematics at the θ asked for."""

    def __init__(self, project, crank_inertia: float | None = None):
        dyn = project.task.dynamics
        if crank_inertia is None:
            crank_inertia = dyn.crank_inertia if dyn is not None else 0.0
        if not (crank_inertia >= 0 and math.isfinite(crank_inertia)):
            raise DynamicsInputError("dynamics.crank_inertia", f"{crank_inertia!r} is not a moment of inertia",
                                     "a number ≥ 0, kg·m²")
        self.project = project
        self.linkage = project.linkage
        self.mechanism = project.task.mechanism
        w = float(self.linkage.omega)
        if not (w != 0 and math.isfinite(w)):
            raise DynamicsInputError("mechanism.drive.omega", "the crank must turn for a flywheel calculation",
                                     "a non-zero angular speed, rad/s")
        self.omega_m = abs(w)
        self.sign = 1.0 if w > 0 else -1.0
        self.phi0 = start_angle(project)
        self.crank_inertia = float(crank_inertia)
        self.J_const = constant_inertia(self.linkage, self.crank_inertia)
        self.switching = self._switching_thetas()
        self.breaks = _breaks(list(self.switching) + list(self._law_thetas()))
        self._memo = ReducedMemo(self._compute, elementwise=project.model.positions_independent)

    # -- angles ---------------------------------------------------------------------------------
    @property
    def switching_phi(self) -> tuple[float, ...]:
        """Crank angles φ1 (rad) where the resistance switches on and off."""
        return tuple(float(self.phi_of(np.asarray(t))) for t in self.switching)

    def theta_of(self, phi: float) -> float:
        """θ of crank angle φ1, in [0, 2π)."""
        return float(np.mod(self.sign * (phi - self.phi0), TWO_PI))

    def phi_of(self, theta: np.ndarray) -> np.ndarray:
        return self.phi0 + self.sign * np.asarray(theta, dtype=float)

    def _switching_thetas(self) -> tuple[float, ...]:
        st = self.project.strokes
        if st is None or not any(ld.kind == "resistance" for ld in self.mechanism.loads):
            return ()
        return tuple(self.theta_of(p) for p in StrokeWindow(st.phi_start, st.phi_end, self.sign).switching_angles())

    def _law_thetas(self) -> list[float]:
        """θ where the resistance law has a corner or a step inside a stroke: the loaded link's
        coordinate passes law fraction f (found by bracketing and Brent's method)."""
        st = self.project.strokes
        out: list[float] = []
        if st is None:
            return out
        model = self.project.model
        ends_q, _ = model.positions(np.array([st.phi_start, st.phi_end]))
        t_start, t_end = self.theta_of(st.phi_start), self.theta_of(st.phi_end)
        work_span = (t_end - t_start) % TWO_PI
        for ld in self.mechanism.loads:
            if ld.kind != "resistance":
                continue
            xe, kind = link_coordinate(self.linkage, ld.link, ends_q)
            x0, x1 = float(xe[0]), float(xe[1])
            if x1 == x0:
                continue

            def frac(theta: np.ndarray, x0=x0, x1=x1, kind=kind, link=ld.link) -> np.ndarray:
                q, _ = model.positions(np.atleast_1d(self.phi_of(theta)))
                x, _ = link_coordinate(self.linkage, link, q)
                if kind == "rocker":
                    x = x0 + np.mod(x - x0 + math.pi, TWO_PI) - math.pi
                return (x - x0) / (x1 - x0)

            fr = [p[0] for p in ld.law if 0.0 < p[0] < 1.0]
            windows = []
            if ld.stroke in ("working", "both"):
                windows.append((t_start, t_start + work_span, False))
            if ld.stroke in ("idle", "both"):
                windows.append((t_start + work_span, t_start + TWO_PI, True))
            for lo, hi, idle in windows:
                ts = np.linspace(lo, hi, 97)
                fs = frac(ts)
                for f_target in fr:
                    g = (1.0 - fs if idle else fs) - f_target
                    for i in np.nonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0)[0]:
                        def h(t, f_target=f_target, idle=idle):
                            v = float(frac(np.array([t]))[0])
                            return (1.0 - v if idle else v) - f_target
                        out.append(float(np.mod(brent_root(h, ts[i], ts[i + 1], xtol=EDGE_ANGLE_TOL, rtol=EDGE_ANGLE_TOL), TWO_PI)))
        return out

    # -- reduced quantities ---------------------------------------------------------------------
    def kinematics(self, theta: np.ndarray, accelerations: bool = True):
        return self.project.model.solve(self.phi_of(np.atleast_1d(theta)), accelerations=accelerations)

    def reduced(self, theta: np.ndarray, with_dJ: bool = True) -> Reduced:
        """M_red, J_red and dJ_red/dθ at ``theta`` (without ``with_dJ``, dJ is NaN and the
        accelerations are not solved); values already computed for this cycle are not computed
        again (:mod:`reportgen.dynamics.memo`)."""
        t = np.asarray(theta, dtype=float)
        M, J, dJ = self._memo(np.ascontiguousarray(t.ravel()), with_dJ)
        if dJ is None:
            dJ = np.full(t.size, np.nan)
        return Reduced(M.reshape(t.shape), J.reshape(t.shape), dJ.reshape(t.shape))

    def _compute(self, theta: np.ndarray, with_dJ: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
        kin = self.kinematics(theta, accelerations=with_dJ)
        loads = external_loads(self.mechanism, self.linkage, self.project.model, kin, self.project.strokes)
        M = reduced_moment(loads, kin)
        J, dJ = reduced_inertia(kin, self.linkage, self.crank_inertia, with_dJ)
        return M, J, dJ
