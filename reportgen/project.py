"""``Project(task)``: the stages of the course project, each computed once, when first asked for.

structure ─▶ kinematics ─▶ (kinetostatics, dynamics); gears and planetary are independent. A
section of the note or a sheet reads only the stages it needs, so ``reportgen gear`` or the gear
sheet never runs the linkage solver.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from .errors import IncompleteCycleError, InternalError, ParameterError, TaskError
from .kinematics import KinematicModel, KinematicsResult
from .kinematics.extremes import NoExtremesError, Strokes, find_strokes
from .linkage import Linkage, compile_linkage
from .structure import Structure, analyse_structure
from .scenes.boxes import DEFAULT as DEFAULT_BOXES
from .scenes.boxes import SceneBoxes
from .task import Task

if TYPE_CHECKING:  # the planetary package is imported when a task has [planetary]
    from .planetary.drive import DriveCheck, DriveRatio
    from .planetary.search import PlanetaryDesign
    from .planetary.velocity import VelocityTriangle


#: Angles of the dense cycle of M_ур (section 2's graph).
CYCLE_POINTS = 361

#: The stages of a project: what a part of the note or a sheet declares in its ``NEEDS``.
STAGES = frozenset({"linkage", "structure", "model", "strokes", "phi", "kinematics", "analysed", "plans",
                    "plan_positions", "plans_by_position", "output_diagrams", "scenes", "kinetostatics",
                    "balancing_cycle", "balancing_cycle_dense", "resistance",
                    "gears", "planetary", "dynamics", "crane"})


class UndeclaredStage(InternalError, AttributeError):
    """A part or a sheet read a stage it does not declare in its ``NEEDS`` (a bug of that part)."""

    def __init__(self, owner: str, stage: str, needs: tuple[str, ...]):
        self.owner, self.stage, self.needs = owner, stage, needs
        super().__init__(f"{owner} reads the stage {stage!r}", f"it declares NEEDS = {needs!r}")


class Needs:
    """``project`` as a part or a sheet may see it: the stages of its ``NEEDS`` (and what they are
    built from, which the stages read themselves), the task, the boxes and the helpers; any other
    stage raises :class:`UndeclaredStage`, so a part that reads more than it says fails its test."""

    def __init__(self, project: "Project", needs: tuple[str, ...], owner: str):
        unknown = set(needs) - STAGES
        if unknown:
            raise ParameterError(f"{owner}: NEEDS", sorted(unknown), f"stages among {sorted(STAGES)}")
        self._project, self._needs, self._owner = project, tuple(needs), owner

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        if name in STAGES and name not in self._needs:
            raise UndeclaredStage(self._owner, name, self._needs)
        return getattr(self._project, name)


@dataclass(frozen=True)
class PlanetaryStage:
    """The reducer chosen for the task: the drive's required ratio (if "auto"), the design, its
    velocity triangle (if a module is given) and the achieved crank speed."""
    target: float
    drive: DriveRatio | None
    design: PlanetaryDesign
    triangle: VelocityTriangle | None
    check: DriveCheck | None


class Project:
    """Lazy, cached stages of one task. ``at_deg`` replaces the [analysis] positions."""

    def __init__(self, task: Task, at_deg: list[float] | None = None, boxes: SceneBoxes = DEFAULT_BOXES):
        self.task = task
        self.at_deg = list(at_deg) if at_deg else None
        self.boxes = boxes

    def _need_mechanism(self):
        if self.task.mechanism is None:
            raise TaskError("mechanism", "the task has no [mechanism] section", "a [mechanism] section")
        return self.task.mechanism

    @cached_property
    def linkage(self) -> Linkage:
        return compile_linkage(self._need_mechanism())

    @cached_property
    def structure(self) -> Structure:
        return analyse_structure(self.linkage)

    @cached_property
    def model(self) -> KinematicModel:
        return KinematicModel(self.linkage, self.structure)

    @cached_property
    def feasible_deg(self) -> tuple[tuple[float, float], ...]:
        """Crank-angle ranges (deg) where the mechanism assembles; ((0, 360),) when it turns fully."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return self.model.feasible_ranges()

    @property
    def full_cycle(self) -> bool:
        """The crank can turn fully (every group assembles at every crank angle)."""
        r = self.feasible_deg
        return len(r) == 1 and r[0][0] <= 0.0 and r[0][1] >= 360.0

    def need_full_cycle(self, stage: str) -> None:
        """Refuse ``stage`` (IncompleteCycleError with the feasible range) if the crank cannot turn fully."""
        if not self.full_cycle:
            raise IncompleteCycleError(stage, self.feasible_deg)

    @cached_property
    def strokes(self) -> Strokes | None:
        """Extreme positions of the output; None if the output turns fully (no dead centres), or if
        the crank cannot turn fully and nothing needs them (a production resistance over the strokes
        does: it is refused with the feasible range)."""
        if not self.full_cycle:
            mech = self._need_mechanism()
            if any(ld.kind == "resistance" for ld in mech.loads):
                self.need_full_cycle("the production resistance (given over the working stroke)")
            return None
        try:
            return find_strokes(self.model)
        except NoExtremesError:
            return None

    @cached_property
    def phi(self) -> np.ndarray:
        """The analysed crank angles, rad: [analysis] positions from position 0, or ``at_deg``."""
        if self.at_deg is not None:
            return np.radians(np.asarray(self.at_deg, dtype=float))
        a = self.task.analysis
        sgn = 1.0 if self.model.omega >= 0 else -1.0
        if a.start == "extreme":
            self.need_full_cycle('[analysis] start = "extreme" (the extreme positions)')
            if self.strokes is None:
                raise TaskError("analysis.start", "the output link has no extreme position (it turns fully)",
                                "a crank angle in degrees")
            phi0 = self.strokes.phi_start
        else:
            phi0 = math.radians(float(a.start))
        k = np.arange(a.positions)
        return np.mod(phi0 + sgn * k * 2 * math.pi / a.positions, 2 * math.pi)

    @cached_property
    def kinematics(self) -> KinematicsResult:
        return self.model.solve(self.phi)

    def kinematics_at(self, phi_rad) -> KinematicsResult:
        return self.model.solve(phi_rad)

    @cached_property
    def analysed(self) -> int:
        """The position analysed in detail (plans, kinetostatics): ``[analysis] force_position`` if
        it is a position number, else the first of ``[analysis] plan_positions`` if given, else 2
        (clipped to the positions)."""
        a = self.task.analysis
        fp = a.force_position
        n = len(self.phi)
        if isinstance(fp, int) and not isinstance(fp, bool):
            i = fp
        else:
            i = a.plan_positions[0] if a.plan_positions else 2
        return min(max(i, 0), n - 1)

    @cached_property
    def plan_positions(self) -> tuple[int, ...]:
        """The positions whose velocity and acceleration plans are drawn in full, the analysed one
        first: ``[analysis] plan_positions`` (those within the positions), else the default rule of
        :mod:`reportgen.plan_positions` (one of the working and one of the idle stroke)."""
        from .plan_positions import default_plan_positions
        i, n = self.analysed, len(self.phi)
        given = self.task.analysis.plan_positions
        if given is None:
            strokes = self.strokes if self.task.document.kind != "control-work" else None
            sgn = 1.0 if self.model.omega >= 0 else -1.0
            return default_plan_positions([float(x) for x in self.phi], strokes, sgn, i)
        return (i, *sorted(j for j in set(given) if j != i and 0 <= j < n))

    @cached_property
    def plans_by_position(self):
        """The velocity and acceleration plans of every plan position (position → (Plan, Plan)): the
        analysed one is ``plans``; the others at the scales of :func:`reportgen.plans.build_plans`,
        coarser where a point would stand beyond ``boxes.other_plan_mm`` from the pole."""
        from types import MappingProxyType
        from .plans import build_plans, round_scale
        out = {}
        for j in self.plan_positions:
            if j == self.analysed:
                out[j] = self.plans
                continue
            v, a = build_plans(self.linkage, self.structure, self.kinematics, j)
            far = [max(math.hypot(*pt) for pt in plan.points.values()) * plan.scale for plan in (v, a)]
            mu = [max(plan.scale, round_scale(f, self.boxes.other_plan_mm)) for plan, f in zip((v, a), far)]
            if mu != [v.scale, a.scale]:
                v, a = build_plans(self.linkage, self.structure, self.kinematics, j, mu_v=mu[0], mu_a=mu[1])
            out[j] = (v, a)
        return MappingProxyType(out)

    @cached_property
    def plans(self):
        """The velocity and acceleration plans of the analysed position (reportgen.plans.Plan), at the
        scales of the sheet that draws them (``boxes.plan_mm_for``: the control work on A3)."""
        from .plans import build_plans, round_scale
        i, far_mm = self.analysed, self.boxes.plan_mm_for(self.task)
        if far_mm is None:
            return build_plans(self.linkage, self.structure, self.kinematics, i)
        kin = self.kinematics     # the control work on A3: every point within far_mm of the pole
        far = [max(math.hypot(*np.asarray(getattr(m, q)[i])) for m in kin.points.values()) for q in ("vel", "acc")]
        return build_plans(self.linkage, self.structure, kin, i,
                           mu_v=round_scale(far[0], far_mm), mu_a=round_scale(far[1], far_mm))

    @cached_property
    def scenes(self):
        """The constructions that the note and the sheets both draw (reportgen.scenes.stage.Scenes)."""
        from .scenes.stage import Scenes
        return Scenes(self)

    @cached_property
    def gears(self):
        """The external involute pair of [gears] (None if the task has none)."""
        if self.task.gears is None:
            return None
        from .gears.pair import from_task
        return from_task(self.task.gears)

    @cached_property
    def planetary(self) -> PlanetaryStage | None:
        """The planetary reducer of [planetary] (None if the task has none)."""
        p = self.task.planetary
        if p is None:
            return None
        from .planetary.drive import drive_check, drive_ratio, input_speed
        from .planetary.search import synthesize
        from .planetary.velocity import velocity_triangle
        drive = None
        if p.ratio == "auto":
            if self.task.gears is None or self.task.mechanism is None or p.motor_rpm is None:
                raise TaskError("planetary.ratio", '"auto" needs planetary.motor_rpm, [gears] (the open pair) '
                                "and [mechanism] (the crank speed)", "a number, or those sections")
            drive = drive_ratio(p.motor_rpm, self.task.gears.z1, self.task.gears.z2, self.task.mechanism.drive.omega)
            target = drive.required
        else:
            target = float(p.ratio)
        design = synthesize(p.scheme, target, p.tolerance, p.satellites, p.module)
        omega_in, _ = input_speed(drive, p.motor_rpm)
        triangle = velocity_triangle(design, omega_in, p.module) if p.module else None
        check = drive_check(drive, design.ratio) if drive is not None else None
        return PlanetaryStage(target, drive, design, triangle, check)

    @cached_property
    def crane(self):
        """The hoist and trolley-travel calculations of [crane] (None if the task has none)."""
        if getattr(self.task, "crane", None) is None:
            return None
        from .crane import crane_calc
        return crane_calc(self.task.crane)

    @cached_property
    def output_diagrams(self):
        """The s–v–a diagrams of the output (reportgen.diagrams.Diagrams) from position 0, with the
        chord replica at ``diagrams.INTERVALS``; None if the output has no extreme positions."""
        if self.strokes is None:
            return None
        from .diagrams import INTERVALS, build_diagrams
        return build_diagrams(self.model, self.strokes, float(self.phi[0]), n=INTERVALS)

    @cached_property
    def dynamics(self):
        """Reduced moments and inertia, work, ΔE, Wittenbauer, the flywheel, the integrated motion
        (None if the task has no [dynamics] or no [mechanism])."""
        if self.task.dynamics is None or self.task.mechanism is None:
            return None
        self.need_full_cycle("[dynamics] (the motion over a cycle and the flywheel)")
        from .dynamics import dynamics_of
        return dynamics_of(self)

    @cached_property
    def kinetostatics(self):
        """Section 2 at the task's force position (reportgen.kinetostatics.Kinetostatics)."""
        from .kinetostatics.results import kinetostatics_of
        return kinetostatics_of(self)

    @cached_property
    def balancing_cycle(self):
        """M_ур by the groups and by the lever at every analysed position (BalancingCycle)."""
        from .kinetostatics import balancing_cycle
        return balancing_cycle(self, self.phi)

    @cached_property
    def balancing_cycle_dense(self):
        """M_ur over one turn at ``CYCLE_POINTS`` angles from position 0 (for the graph of section 2)."""
        from .kinetostatics import balancing_cycle
        sgn = 1.0 if self.model.omega >= 0 else -1.0
        return balancing_cycle(self, float(self.phi[0]) + sgn * np.linspace(0.0, 2 * math.pi, CYCLE_POINTS))

    @cached_property
    def resistance(self):
        """The production resistance at the force position from its law (reportgen.loads.resistance_at)."""
        from .loads import resistance_at
        return resistance_at(self)

    def loads_at(self, kin: KinematicsResult, inertia: bool = True):
        """External loads (+ inertia) at the positions of ``kin``."""
        from .loads import external_loads, inertia_loads
        mech = self._need_mechanism()
        # the strokes (a search over the whole turn) only when a resistance is given over them
        strokes = self.strokes if any(ld.kind == "resistance" for ld in mech.loads) else None
        ls = external_loads(mech, self.linkage, self.model, kin, strokes)
        return ls + inertia_loads(self.linkage, kin) if inertia else ls
