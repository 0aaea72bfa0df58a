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

from .errors import TaskError
from .kinematics import KinematicModel, KinematicsResult
from .kinematics.extremes import NoExtremesError, Strokes, find_strokes
from .linkage import Linkage, compile_linkage
from .structure import Structure, analyse_structure
from .task import Task

if TYPE_CHECKING:  # the planetary package is imported when a task has [planetary]
    from .planetary.drive import DriveCheck, DriveRatio
    from .planetary.search import PlanetaryDesign
    from .planetary.velocity import VelocityTriangle


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

    def __init__(self, task: Task, at_deg: list[float] | None = None):
        self.task = task
        self.at_deg = list(at_deg) if at_deg else None

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
    def strokes(self) -> Strokes | None:
        """Extreme positions of the output; None if the output turns fully (no dead centres)."""
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
    def dynamics(self):
        """Reduced moments and inertia, work, ΔE, Wittenbauer, the flywheel, the integrated motion
        (None if the task has no [dynamics] or no [mechanism])."""
        if self.task.dynamics is None or self.task.mechanism is None:
            return None
        from .dynamics import dynamics_of
        return dynamics_of(self)

    def loads_at(self, kin: KinematicsResult, inertia: bool = True):
        """External loads (+ inertia) at the positions of ``kin``."""
        from .loads import external_loads, inertia_loads
        ls = external_loads(self._need_mechanism(), self.linkage, self.model, kin, self.strokes)
        return ls + inertia_loads(self.linkage, kin) if inertia else ls
