"""``project.scenes``: the scenes of one project, each built once, when first asked for, from the
project's stages and its boxes (:mod:`.boxes`). The note and the sheets read them from here."""
from __future__ import annotations

from functools import cached_property
from types import MappingProxyType
from typing import Mapping

from ..errors import InternalError
from .arrangement import SheetChoice, SheetLayout, choose_scale, layout_at
from .dynamics import DynamicsScenes, dynamics_scenes
from .free_body import FreeBody, free_bodies
from .meshing import MeshingScene, meshing_scene
from .output_diagrams import output_diagrams_scene
from .plans import plan_scene
from .positions import SchemeData, bounds, positions_scales, positions_scene, scheme_data
from .scene import Scene


class Scenes:
    def __init__(self, project) -> None:
        self.project = project

    @cached_property
    def scheme_data(self) -> SchemeData:
        return scheme_data(self.project, self.project.analysed)

    @cached_property
    def positions_scales(self) -> list[tuple[float, str]]:
        """The ГОСТ scales of the plan of positions not above the scheme's box, largest first (the
        candidates: :attr:`sheet_layout` takes the first at which the whole sheet fits)."""
        boxes = self.project.boxes
        return positions_scales(bounds(self.scheme_data, self.project.linkage), boxes,
                                len(self.project.plan_positions), boxes.scheme_for(self.project.task))

    @cached_property
    def sheet_choice(self) -> SheetChoice | None:
        """The scale of the plan of positions — the largest of :attr:`positions_scales` at which
        sheet 1 (or the control work's sheet) fits with all its views, sheet 1's small plans
        included — and the small plans' size (:mod:`.arrangement`); None: no scale fits (the sheet
        says so). The note reads the scale from here, without the sheet's arrangement."""
        return choose_scale(self.project, bounds(self.scheme_data, self.project.linkage), self.positions_scales)

    @cached_property
    def sheet_layout(self) -> SheetLayout | None:
        """Sheet 1's (or the control work's sheet's) views arranged at :attr:`sheet_choice`; None:
        no scale fits."""
        choice = self.sheet_choice
        if choice is None:
            return None
        found = layout_at(self.project, bounds(self.scheme_data, self.project.linkage), choice.k, choice.ratio,
                          choice.small)
        if found is None:                   # fits_at said it fits: the same trials
            raise InternalError("sheet layout", f"the chosen scale {choice.ratio} does not arrange")
        return found

    @cached_property
    def positions_scale(self) -> tuple[float, str]:
        """The scale of the plan of positions (mm per metre, «1:N»), the one the note and the sheet
        print: :attr:`sheet_choice`'s; the scheme box's where no arrangement fits (the note can be
        built without the sheet, whose build then stops with a clear error)."""
        found = self.sheet_choice
        return (found.k, found.ratio) if found is not None else self.positions_scales[0]

    @cached_property
    def small_plan_sets(self) -> tuple:
        """Sheet 1's small velocity plans at each of their sizes, the largest drawing first
        (:func:`.small_plans.small_plan_sets`)."""
        from .small_plans import small_plan_sets
        return small_plan_sets(self.project)

    @cached_property
    def lever(self) -> Scene:
        """Zhukovsky's lever of the analysed position at the replica's μv (the control work's sheet
        arranges its panel at every scale it tries: built once)."""
        from .lever import lever_scene
        return lever_scene(self.project.kinetostatics, self.project.linkage)

    def positions_at(self, k: float, ratio: str) -> Scene:
        """The plan of positions at another scale (each built once: the arrangement measures the
        control work's scheme at every scale it tries, the sheet draws the chosen one)."""
        cache = self.__dict__.setdefault("_positions_at", {})
        if (k, ratio) not in cache:
            cache[(k, ratio)] = positions_scene(self.project, self.scheme_data, k, ratio)
        return cache[(k, ratio)]

    @cached_property
    def positions(self) -> Scene:
        """The plan of positions at its scale (sheet 1's scheme; the note's figure, reduced)."""
        return self.positions_at(*self.positions_scale)

    @cached_property
    def velocity_plan(self) -> Scene:
        """The velocity plan of the analysed position."""
        return self.velocity_plans[self.project.analysed]

    @cached_property
    def acceleration_plan(self) -> Scene:
        """The acceleration plan of the analysed position."""
        return self.acceleration_plans[self.project.analysed]

    @cached_property
    def velocity_plans(self) -> Mapping[int, Scene]:
        """The velocity plan of every plan position (``project.plan_positions``, in its order)."""
        return MappingProxyType({j: plan_scene(v) for j, (v, _) in self.project.plans_by_position.items()})

    @cached_property
    def acceleration_plans(self) -> Mapping[int, Scene]:
        """The acceleration plan of every plan position (letters of the velocity plan's images)."""
        return MappingProxyType({j: plan_scene(a, (set(v.points) - {"p"}) | {"π"})
                                 for j, (v, a) in self.project.plans_by_position.items()})

    @cached_property
    def dynamics(self) -> DynamicsScenes | None:
        """The diagrams of section 3 (sheet 3): M_red, A, ΔE, Wittenbauer, J_red, ω (None without
        [dynamics])."""
        res = self.project.dynamics
        return None if res is None else dynamics_scenes(res, self.project.boxes.diagrams)

    @cached_property
    def output_diagrams(self) -> Scene | None:
        """The s–v–a diagrams of the output (sheet 1, section 1; None if the output has no strokes)."""
        d = self.project.output_diagrams
        return None if d is None else output_diagrams_scene(d, len(self.project.phi))

    @cached_property
    def free_bodies(self) -> tuple[FreeBody, ...]:
        """The free-body diagrams of section 2 and sheet 2 at the replica's μl: each Assur group
        (the last attached first), then the crank."""
        ks = self.project.kinetostatics
        return free_bodies(ks, self.project.linkage, self.project.structure, ks.graphical.length_scale)

    def free_bodies_at(self, mu_l: float) -> tuple[FreeBody, ...]:
        """The free-body diagrams at another μl (a sheet whose views do not fit at the replica's)."""
        ks = self.project.kinetostatics
        return free_bodies(ks, self.project.linkage, self.project.structure, mu_l)

    @cached_property
    def meshing(self) -> MeshingScene:
        """The meshing picture of the [gears] pair at sheet 4's scale (the note's figure is a
        window of it)."""
        return meshing_scene(self.project.gears)
