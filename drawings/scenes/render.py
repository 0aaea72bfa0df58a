"""Draw a :class:`reportgen.scenes.scene.Scene` on a sheet view: every entity at the scene's own
coordinates (paper mm), mapped into the view by ``unit`` (model units per scene mm, so that the
view's transform puts each scene mm on one sheet mm). Labels are placed by the sheet's own label
placement (:mod:`drawings.scenes.kinematics_labels`): beside the point or along the vector they
belong to, where they overlap no text and cross no line."""
from __future__ import annotations

from typing import Iterable

from reportgen.errors import InternalError
from reportgen.scenes.scene import Arrow, Circle, Entity, Polyline, Scene, Segment

from drawings.primitives import Canvas


def draw_entities(view: Canvas, entities: Iterable[Entity], unit: float = 1.0, *,
                  head_mm: float = 5.0) -> None:
    """Draw ``entities`` (scene mm) on ``view`` whose model unit is ``unit`` scene mm⁻¹."""
    def m(p):
        return (p[0] * unit, p[1] * unit)

    for e in entities:
        if isinstance(e, Segment):
            view.segment(m(e.a), m(e.b), e.kind, trim_mm=e.trim)
        elif isinstance(e, Arrow):
            view.arrow(m(e.a), m(e.b), layer=e.kind, head_mm=head_mm)
        elif isinstance(e, Polyline):
            view.polyline([m(p) for p in e.points], e.kind, closed=e.closed)
        elif isinstance(e, Circle):
            view.circle_mm(m(e.c), e.r, e.kind)
        else:  # pragma: no cover - the scene has no other entities
            raise InternalError("scene entity", f"cannot draw {type(e).__name__}")


def draw_scene(view: Canvas, scene: Scene, unit: float = 1.0, *, head_mm: float = 5.0) -> None:
    draw_entities(view, scene.entities, unit, head_mm=head_mm)
