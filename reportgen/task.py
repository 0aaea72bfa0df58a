"""The task (задание) as frozen dataclasses: the format of ``docs/task-format.md`` (generated from ``reportgen/taskspec.py``).

``reportgen.taskfile.load_task(path)`` reads a TOML file into a :class:`Task`, validating every key
(errors carry the TOML path). Units are SI here (m, kg, s, N, rad), except that gear sizes stay in
millimetres and user-facing angles keep their ``_deg`` names, as in the task format.
"""
from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Literal, Mapping

if TYPE_CHECKING:
    from .crane.spec import Crane

from .errors import NameLookupError
from .geometry import Vec2

LINK_KINDS = ("crank", "coupler", "rocker", "slider", "block", "slotted")
LANGUAGES = ("ru", "uk", "en")


@dataclass(frozen=True)
class Document:
    """Title-page data; every field optional."""
    title: str = "Проектирование и исследование рычажного механизма"
    author: str = ""
    group: str = ""
    supervisor: str = ""
    university: str = ""          # the title page's institution (above the department)
    organization: str = ""
    city: str = ""
    year: int | None = None
    language: str = "ru"
    kind: str = ""          # "" = by the sections (crane if [crane]), "course-project", "crane", …
    #: The project's designation (ЕСКД, ГОСТ 2.201): sheet k is "<code>.<k:03d>", the note
    #: "<code>.000 ПЗ".
    code: str = "ТММ.КП.00.00"

    def sheet_code(self, number: int) -> str:
        """The designation of drawing sheet ``number`` (title block, graph 2)."""
        return f"{self.code}.{number:03d}"

    def note_code(self) -> str:
        """The designation of the explanatory note (ПЗ)."""
        return f"{self.code}.000 ПЗ"


@dataclass(frozen=True)
class Link:
    """A moving link. ``points`` in the order the task gives them.

    ``lengths``: the distances the task gives explicitly, as ``(p, q, metres)`` with p, q point names
    of this link (``length`` of a two-point link becomes one entry). Distances not given come from
    the sketch coordinates. ``mass``/``inertia`` are the resolved values (given or by mass_rules);
    ``mass_given``/``inertia_given`` say which. ``com``: a fraction along points[0]→points[1], or a
    point name, or None for the default (middle of a bar, centroid of a triangle, the point of a
    one-point link).
    """
    id: int
    kind: str
    points: tuple[str, ...]
    lengths: tuple[tuple[str, str, float], ...] = ()
    mass: float = 0.0
    inertia: float = 0.0
    com: float | str | None = None
    mass_given: bool = False
    inertia_given: bool = False


@dataclass(frozen=True)
class Slide:
    """A prismatic pair: ``link`` translates along a line carried by ``guide`` (0 = the frame).

    For guide 0 the line is ``through`` (m) at ``angle_deg``; for guide k the line runs through two
    points of link k, ``along = (P, Q)``, directed P→Q. ``point`` is the point of ``link`` that
    runs on the line.
    """
    link: int
    point: str
    guide: int
    through: Vec2 | None = None
    angle_deg: float | None = None
    along: tuple[str, str] | None = None


@dataclass(frozen=True)
class Drive:
    link: int
    omega: float  # rad/s, positive = counter-clockwise


@dataclass(frozen=True)
class MassRules:
    """Defaults of the course manual (seed 001): m = q·l, slider = factor·m1, J = m·l²/12,
    triangular link J = triangle_factor · J of its longest bar."""
    q: float = 10.0
    slider_factor: float = 6.0
    triangle_factor: float = 2.5


#: A resistance constant along the stroke: (fraction of the stroke, fraction of the maximum).
DEFAULT_LAW: tuple[tuple[float, float], ...] = ((0.0, 1.0), (1.0, 1.0))


@dataclass(frozen=True)
class Load:
    """A load on a link.

    kind = "resistance": ``force`` (N, on a slider) or ``moment`` (N·m, on a rotating link), its
    ``law`` along the stroke as (fraction of stroke, fraction of maximum) pairs, acting on the
    ``stroke`` given (working | idle | both), against the motion.
    kind = "force": constant ``vector`` (N) at ``point`` of the link, or at its centre of mass when
    ``com`` is true. kind = "moment": constant couple ``value`` (N·m, + counter-clockwise).
    """
    kind: Literal["resistance", "force", "moment"]
    link: int
    force: float | None = None
    moment: float | None = None
    law: tuple[tuple[float, float], ...] = DEFAULT_LAW
    stroke: Literal["working", "idle", "both"] = "working"
    point: str | None = None
    com: bool = False
    vector: Vec2 | None = None
    value: float | None = None


@dataclass(frozen=True)
class Mechanism:
    name: str
    ground: tuple[str, ...]
    points: Mapping[str, Vec2]
    links: tuple[Link, ...]
    drive: Drive
    slides: tuple[Slide, ...] = ()
    loads: tuple[Load, ...] = ()
    mass_rules: MassRules = MassRules()
    g: float = 9.81

    def link(self, link_id: int) -> Link:
        for ln in self.links:
            if ln.id == link_id:
                return ln
        raise NameLookupError("link", link_id, tuple(ln.id for ln in self.links))


@dataclass(frozen=True)
class Analysis:
    positions: int = 8
    start: Literal["extreme"] | float = "extreme"   # or a crank angle, deg
    force_position: int | Literal["max-load"] = 2
    #: positions whose plans are drawn in full; None: the rule of ``Project.plan_positions``
    plan_positions: tuple[int, ...] | None = None


@dataclass(frozen=True)
class Flywheel:
    shape: Literal["disk", "rim"] = "disk"
    density: float = 7860.0
    width_ratio: float = 1.0


@dataclass(frozen=True)
class Dynamics:
    delta: float
    crank_inertia: float = 0.0
    flywheel: Flywheel = Flywheel()


@dataclass(frozen=True)
class Gears:
    """External involute pair; sizes in mm. x1/x2 a number or "auto"."""
    z1: int
    z2: int
    module: float
    x1: float | Literal["auto"] = 0.0
    x2: float | Literal["auto"] = 0.0
    alpha_deg: float = 20.0
    ha: float = 1.0
    c: float = 0.25
    eps_min: float = 1.2      # least transverse contact ratio εα (Болотовский; seed 000 accepts 1.05)
    sa_min: float = 0.25      # least tip thickness as a share of the module: sa ≥ sa_min·m


@dataclass(frozen=True)
class Planetary:
    scheme: Literal["single-row", "two-row-ext-int", "two-row-ext-ext", "two-row-int-int"]
    motor_rpm: float | None = None
    ratio: float | Literal["auto"] = "auto"
    tolerance: float = 0.05
    satellites: int | Literal["auto"] = "auto"
    module: float | None = None  # mm


@dataclass(frozen=True)
class ControlWork:
    """``[control_work]``: the assignment of a control work (seed 001, §7–8; docs/control-work.md)."""
    table: int | None = None              # the manual's table 1…22 (None: a mechanism of one's own)
    variant: int | None = None            # 1…10
    sheet: str = "A1"                     # "A1" or "A3"
    tolerance_percent: float = 5.0        # accepted deviation of a value read from a construction


@dataclass(frozen=True)
class Task:
    """The whole assignment. A section the file leaves out is None."""
    document: Document = Document()
    mechanism: Mechanism | None = None
    analysis: Analysis = Analysis()
    dynamics: Dynamics | None = None
    gears: Gears | None = None
    planetary: Planetary | None = None
    crane: "Crane | None" = None    # the hoist and trolley travel of a bridge crane (docs/crane.md)
    control_work: ControlWork | None = None
    source: str = ""

    def has(self, section: str) -> bool:
        """Whether the task file has the section ``[section]`` (one of the fields above that a file
        may leave out). What a note or sheet asks when only the section's presence matters: the
        build cache then records that, not the section's values (:mod:`reportgen.read_trace`)."""
        return getattr(self, section) is not None

    @property
    def kind(self) -> str:
        """The kind of document: [document] kind if given, else "crane" for a task with [crane],
        else "course-project" (the ТММ note)."""
        if self.document.kind:
            return self.document.kind
        return "crane" if self.crane is not None else "course-project"


def frozen_mapping(d: Mapping) -> Mapping:
    """A read-only view of a dict (results and tasks are immutable)."""
    return MappingProxyType(dict(d))
