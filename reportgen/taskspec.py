"""The task format as data: every section and key the loader (``reportgen.taskfile``) accepts.

One entry a key: its value spec (the reader that checks it, ``taskfile_values``), its meaning, its
default and an example. The loader takes the key lists and the specs from here, and
``reportgen.taskdoc`` writes ``docs/task-format.md`` and the JSON Schema from the same data, so the
reference cannot drift from what is checked (``tests/taskfile/test_taskspec.py`` regenerates both and
compares). A rule that ties two keys together (e.g. ``force_position`` < ``positions``) is checked by
the loader and written in the key's ``doc``.
"""
from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, Literal

from .crane.taskspec import crane_sections
from .errors import NameLookupError
from .task import (LANGUAGES, LINK_KINDS, Analysis, ControlWork, Document, Dynamics, Flywheel, Gears, Load, MassRules,
                   Mechanism, Planetary)
from .taskfile_values import REQUIRED, Array, Bool, Int, NameMap, Number, OneOf, Spec, Str, Word, vec2

__all__ = ["Key", "Section", "SECTIONS", "SECTION", "MAX_LENGTH", "MIN_LENGTH", "REQUIRED", "OPTIONAL"]

#: Largest coordinate magnitude and link length accepted, m (catches gross unit slips; solver
#: scale tests go up to ~400 m).
MAX_LENGTH = 1000.0
#: Smallest link length accepted, m: 1 µm. Between the two, reportgen.gost_scales draws every
#: mechanism within a sheet (1:50000 … (100·n):1).
MIN_LENGTH = 1e-6

#: Kinds of document ([document] kind): the ТММ course project, the crane note (docs/crane.md) and
#: the control work (docs/control-work.md).
DOCUMENT_KINDS = ("course-project", "crane", "control-work")


class _Optional:
    """Default of a key that may be left out and has no single value (the loader derives one)."""

    def __repr__(self) -> str:
        return "OPTIONAL"


#: The key may be left out; ``Key.default_text`` says what is used instead.
OPTIONAL: Any = _Optional()


@dataclass(frozen=True)
class Key:
    """One key of a table: ``name = value`` read by ``spec``.

    ``default``: the value used when the key is left out, ``REQUIRED`` or ``OPTIONAL`` (see
    ``default_text``). ``table``: the path of the sub-table this key holds (its keys are that
    section's), else "". ``kinds``: for ``[[mechanism.load]]``, the load kinds that take the key.
    """
    name: str
    spec: Spec | None
    doc: str
    example: Any
    default: Any = REQUIRED
    default_text: str = ""
    table: str = ""
    kinds: tuple[str, ...] = ()

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    def unit(self) -> str:
        """The unit of a number (or of the numbers of an array), "" for none."""
        spec = self.spec
        while isinstance(spec, (Array, OneOf, NameMap)):
            spec = spec.item if isinstance(spec, (Array, NameMap)) else next(
                (s for s in spec.specs if isinstance(s, (Number, Array))), None)
        return spec.unit if isinstance(spec, Number) else ""


@dataclass(frozen=True)
class Section:
    """A TOML table: ``table`` ([name]), ``array`` ([[name]], an array of tables) or ``inline``
    ({ … } on one line, as the examples write it)."""
    path: str
    title: str
    doc: str
    keys: tuple[Key, ...]
    shape: Literal["table", "array", "inline"] = "table"

    @property
    def names(self) -> tuple[str, ...]:
        """The keys this table may hold, in the order of the reference."""
        return tuple(k.name for k in self.keys)

    def __getitem__(self, name: str) -> Key:
        for k in self.keys:
            if k.name == name:
                return k
        raise NameLookupError(f"key of [{self.path}]", name, self.names)

    def default(self, name: str) -> Any:
        """The loader's default for ``name`` (``REQUIRED`` if it must be given)."""
        key = self[name]
        return None if key.default is OPTIONAL else key.default


# ------------------------------------------------------------------------------- shared value specs
LENGTH = Number(ge=MIN_LENGTH, le=MAX_LENGTH, unit="m")
MASS = Number(gt=0, unit="kg")
INERTIA = Number(ge=0, unit="kg·m²")  # > 0 is checked afterwards, except for slider-rule links
INERTIA.expected = "a number > 0, in kg·m² (0 allowed for a slider or block)"
POINT_NAME = Str(nonempty=True)
LINK_ID = Int(ge=1, what="a link id: an integer")
POINT_XY = vec2("m", MAX_LENGTH)
POINTS = NameMap(POINT_XY, 1, what="a table of point names → [x, y] in m")
LENGTHS = NameMap(LENGTH, 1, what="an inline table of distances, e.g. { CB = …, CE = …, BE = … }")
LAW_PAIR = Array(Number(ge=0, le=1), 2, 2,
                 what="[fraction of the stroke, fraction of the maximum], both numbers in [0, 1]")
LAW = Array(LAW_PAIR, 2, what="an array of at least 2 pairs [stroke fraction, load fraction] in [0, 1], "
                              "from [0, …] to [1, …]")
#: ``positions`` as documented (1 for a control work); the loader narrows a course project to ≥ 3.
POSITIONS = Int(ge=1, le=360)
COURSE_POSITIONS = Int(ge=3, le=360)
#: ``force_position`` as documented; the loader narrows the index to ``positions - 1``.
FORCE_POSITION = OneOf(Word("max-load"), Int(ge=0, le=359, what="a position index"))
#: ``plan_positions`` as documented; the loader narrows the indices to ``positions - 1``, asks
#: them distinct and holding the kinetostatics position (docs/task-format-notes.md).
PLAN_POSITIONS = Array(Int(ge=0, le=359, what="a position index"), 1, 3,
                       what="an array of 1 to 3 distinct position indices")
TEETH = Int(ge=5, le=1000, what="a number of teeth: an integer")
SHIFT = OneOf(Word("auto"), Number(ge=-3, le=3))
GEAR_MODULE = Number(gt=0, le=1000, unit="mm")

LOAD_KINDS = ("resistance", "force", "moment")
STROKES = ("working", "idle", "both")
FLYWHEEL_SHAPES = ("disk", "rim")
PLANETARY_SCHEMES = ("single-row", "two-row-ext-int", "two-row-ext-ext", "two-row-int-int")
SHEET_FORMATS = ("A1", "A3")


def _dflt(cls: type, name: str) -> Any:
    """The default of field ``name`` of the task dataclass ``cls`` (the loader's default)."""
    return {f.name: f.default for f in fields(cls)}[name]


# ---------------------------------------------------------------------------------------- sections
SECTIONS: tuple[Section, ...] = (
    Section("", "the task file", "A task file is one TOML document; every section may be left out, and "
            "the note and the sheets then leave out what depends on it.", (
                Key("document", None, "title page of the note and title blocks of the sheets", None,
                    OPTIONAL, "all defaults", table="document"),
                Key("mechanism", None, "the linkage", None, OPTIONAL,
                    "no linkage (gears or planetary only)", table="mechanism"),
                Key("analysis", None, "what the sheets and tables show", None, OPTIONAL,
                    "all defaults", table="analysis"),
                Key("dynamics", None, "the flywheel", None, OPTIONAL, "no flywheel", table="dynamics"),
                Key("gears", None, "the external involute pair", None, OPTIONAL, "no gear pair",
                    table="gears"),
                Key("planetary", None, "the planetary reduction gear", None, OPTIONAL,
                    "no planetary gear", table="planetary"),
                Key("crane", None, "a bridge crane: hoist and trolley travel (another kind of document, "
                    "docs/crane.md)", None, OPTIONAL, "no crane", table="crane"),
                Key("control_work", None, "the assignment of a control work (seed 001)", None, OPTIONAL,
                    "none; its defaults with document.kind = \"control-work\"", table="control_work"),
            )),
    Section("document", "title page", "Words of the title page and title blocks; all optional.", (
        Key("title", Str(), "title of the project", "Проектирование и исследование механизма пресса",
            _dflt(Document, "title")),
        Key("author", Str(), "the student", "И. И. Иванов", _dflt(Document, "author")),
        Key("group", Str(), "the student's group", "ТМ-21", _dflt(Document, "group")),
        Key("supervisor", Str(), "the teacher", "А. П. Слободюк", _dflt(Document, "supervisor")),
        Key("university", Str(), "the institution, printed on the title page above the department",
            "Технический университет", _dflt(Document, "university")),
        Key("organization", Str(), "department or university", "Кафедра теории механизмов и машин",
            _dflt(Document, "organization")),
        Key("city", Str(), "city on the title page", "Белгород", _dflt(Document, "city")),
        Key("year", Int(ge=1000, le=9999, what="a year: an integer"), "year on the title page", 2026,
            OPTIONAL, "left out of the title page"),
        Key("code", Str(nonempty=True), "the project's designation: sheet k is <code>.00k, the note "
            "<code>.000 ПЗ (title blocks, graph 2)", "ТММ.КП.01.00", _dflt(Document, "code")),
        Key("language", Word(*LANGUAGES), "language of the note and the sheets", "ru", _dflt(Document, "language")),
        Key("kind", Word(*DOCUMENT_KINDS), "the kind of document: \"course-project\" (the ТММ note of "
            "sections 1–4 and its sheets), \"crane\" (docs/crane.md) or \"control-work\" (one position: the "
            "note of the control work and its one sheet; needs [mechanism]); left out: \"crane\" for a task "
            "with [crane], else \"course-project\"", "crane", _dflt(Document, "kind")),
    )),
    Section("mechanism", "the linkage", "The links, their pairs, the drive, masses and loads.", (
        Key("name", Str(), "name of the mechanism in the note", "Механизм пресса", ""),
        Key("g", Number(ge=0, le=50, unit="m/s²"), "gravity acting on every link with a mass; "
            "0 leaves gravity out", 9.81, _dflt(Mechanism, "g")),
        Key("ground", Array(POINT_NAME, 1, what="an array of ground point names"),
            "points fixed to the frame (link 0), each a name of [mechanism.points], each once",
            ["O", "C"]),
        Key("points", POINTS, "coordinates of every point, name → [x, y]. Ground points: exact. Moving "
            "points: where the assignment sketch shows them (the crank at any angle); the solver "
            "assembles the mechanism at the sketch's crank angle and keeps, for every group, the assembly "
            "branch nearest to the sketch. A distance that no link gives is taken from these coordinates. "
            "A point listed by two links is a revolute pair between them",
            {"O": [0.0, 0.0], "A": [0.0, 0.11]}),
        Key("link", None, "the links 1..n", None, table="mechanism.link"),
        Key("slide", None, "prismatic pairs", None, OPTIONAL, "no prismatic pair",
            table="mechanism.slide"),
        Key("drive", None, "the driving crank", None, table="mechanism.drive"),
        Key("mass_rules", None, "masses and inertias of links that give none", None, OPTIONAL,
            "all defaults", table="mechanism.mass_rules"),
        Key("load", None, "external loads", None, OPTIONAL, "no load", table="mechanism.load"),
    )),
    Section("mechanism.link", "links",
            "One [[mechanism.link]] block a link, ids 1..n each once (0 is the frame). A link with three "
            "points is a rigid triangle, or a straight bar with a point between its ends.", (
                Key("id", LINK_ID, "the link's number 1..n", 1),
                Key("kind", Word(*LINK_KINDS), "what the link is called in the note (wording only)",
                    "crank", OPTIONAL, "inferred from the structure: the driver a crank, a link "
                    "carrying a guide a slotted link, a one-point link a slider (frame guide) or block, "
                    "a link on a frame guide a slider, a link turning about the frame a rocker, "
                    "any other a coupler"),
                Key("points", Array(POINT_NAME, 1, 3, what="an array of 1 to 3 point names"),
                    "the link's points, names of [mechanism.points], each once; a slider or block has one",
                    ["O", "A"]),
                Key("length", LENGTH, "distance between the two points of a two-point link "
                    "(not with `lengths`, not on a one-point link)", 0.11, OPTIONAL,
                    "from the coordinates"),
                Key("lengths", LENGTHS, "distances of a three-point link: keys name two of its points "
                    "(`CB` or `C-B`); the three sides must form a triangle (equal sum: a straight bar)",
                    {"CB": 0.26, "CE": 0.40, "BE": 0.20}, OPTIONAL, "from the coordinates"),
                Key("mass", MASS, "mass of the link", 4.0, OPTIONAL, "by [mechanism.mass_rules]"),
                Key("inertia", INERTIA, "J_S, moment of inertia about the centre of mass", 0.02,
                    OPTIONAL, "by [mechanism.mass_rules]"),
                Key("com", OneOf(Number(ge=0, le=1), Str(nonempty=True)),
                    "centre of mass: a fraction along points[0]→points[1], or a point name of the link "
                    "(a one-point link: its point)", 0.5, OPTIONAL,
                    "the middle of a two-point link, the centroid of a triangle"),
            ), shape="array"),
    Section("mechanism.slide", "prismatic pairs",
            "`link` translates along a guide line: guide = 0, a line fixed to the frame (`line`); "
            "guide = k, a line carried by link k through two of its points (`along`, a slotted link).", (
                Key("link", LINK_ID, "the link that slides", 5),
                Key("point", POINT_NAME, "the point of `link` that runs on the line", "D", OPTIONAL,
                    "the point of a one-point link"),
                Key("guide", Int(ge=0, what="0 (the frame) or a link id: an integer"),
                    "0 for the frame, or the id of the link carrying the line", 0),
                Key("line", None, "the line fixed to the frame (guide = 0 only)", None, OPTIONAL,
                    "required with guide = 0", table="mechanism.slide.line"),
                Key("along", Array(POINT_NAME, 2, 2, what="two point names of the guide link"),
                    "two different points of the guide link (guide = k > 0 only)", ["C", "E"], OPTIONAL,
                    "required with guide = k > 0"),
            ), shape="array"),
    Section("mechanism.slide.line", "a guide line of the frame", "", (
        Key("through", POINT_XY, "a point of the line", [0.0, -0.05]),
        Key("angle_deg", Number(ge=-360, le=360, unit="degrees"), "its angle from +x, counter-clockwise",
            0.0),
    ), shape="inline"),
    Section("mechanism.drive", "the driving crank", "", (
        Key("link", LINK_ID, "the driving crank: a link that lists exactly one ground point (its axis) "
            "and a moving point", 1),
        Key("omega", Number(nonzero=True, ge=-1e4, le=1e4, unit="rad/s"),
            "constant angular speed; positive = counter-clockwise", 18.0),
    )),
    Section("mechanism.mass_rules", "masses of links that give none",
            "The rules of the course manual for links with no mass or inertia given.", (
                Key("q", Number(gt=0, unit="kg/m"), "mass per metre of link length: m = q·l", 10.0,
                    _dflt(MassRules, "q")),
                Key("slider_factor", Number(gt=0), "slider mass = factor · mass of link 1", 6.0,
                    _dflt(MassRules, "slider_factor")),
                Key("triangle_factor", Number(gt=0),
                    "J of a triangular link = factor · J of its longest bar (J = m·l²/12)", 2.5,
                    _dflt(MassRules, "triangle_factor")),
            )),
    Section("mechanism.load", "loads",
            "`kind` chooses the keys: a resistance of the working process, a constant force at a "
            "point, or a constant couple. A key of another kind is an error.", (
                Key("kind", Word(*LOAD_KINDS), "what the load is", "resistance",
                    kinds=LOAD_KINDS),
                Key("link", LINK_ID, "the link it acts on", 5, kinds=LOAD_KINDS),
                Key("force", Number(gt=0, unit="N"), "largest resistance force on a slider "
                    "(exactly one of force, moment)", 15800.0, OPTIONAL, "one of force, moment",
                    kinds=("resistance",)),
                Key("moment", Number(gt=0, unit="N·m"), "largest resistance moment on a rotating link "
                    "(exactly one of force, moment)", 120.0, OPTIONAL, "one of force, moment",
                    kinds=("resistance",)),
                Key("law", LAW, "the resistance along the stroke: pairs (fraction of the stroke, fraction "
                    "of the maximum), stroke fractions strictly increasing from 0 to 1, linear between",
                    [[0.0, 0.0], [1.0, 1.0]], [list(p) for p in _dflt(Load, "law")],
                    kinds=("resistance",)),
                Key("stroke", Word(*STROKES), "the stroke the resistance acts on, against the motion",
                    "working", _dflt(Load, "stroke"), kinds=("resistance",)),
                Key("point", POINT_NAME, "the point of the link the force acts at (or com = true)", "D",
                    OPTIONAL, "required unless com = true", kinds=("force",)),
                Key("com", Bool(), "the force acts at the link's centre of mass", False,
                    _dflt(Load, "com"), kinds=("force",)),
                Key("vector", vec2("N"), "the force, in frame coordinates", [500.0, 0.0],
                    kinds=("force",)),
                Key("value", Number(unit="N·m"), "the couple; positive = counter-clockwise", -40.0,
                    kinds=("moment",)),
            ), shape="array"),
    Section("analysis", "what the sheets and tables show",
            "The crank angle φ1 is the angle of the crank vector (axis → moving point) from +x, "
            "counter-clockwise, in degrees.", (
                Key("positions", POSITIONS, "equally spaced crank positions for plans and tables "
                    "(at least 3 in a course project; 1 in a control work)", 8,
                    _dflt(Analysis, "positions")),
                Key("start", OneOf(Word("extreme"), Number(ge=-360, le=360, unit="degrees (a crank angle)")),
                    "position 0: \"extreme\" (the output link at the start of the working stroke) or a "
                    "crank angle", "extreme", _dflt(Analysis, "start")),
                Key("force_position", FORCE_POSITION, "the position analysed on the kinetostatics sheet: "
                    "an index below `positions`, or \"max-load\"", 2, _dflt(Analysis, "force_position")),
                Key("plan_positions", PLAN_POSITIONS, "the positions whose velocity and acceleration "
                    "plans the note (section 1) and sheet 1 draw in full; they must hold the position "
                    "analysed in detail (`force_position` when it is an index)", [2, 6], OPTIONAL,
                    "that position and, when the output has extreme positions, the position of the other "
                    "stroke nearest the middle of that stroke (one in the working, one in the idle stroke)"),
            )),
    Section("control_work", "the control work", "The assignment of a control work (course manual of seed "
            "001, §7–8; docs/control-work.md): `reportgen new --table T --variant V` writes it.", (
                Key("table", Int(ge=1, le=22, what="a table of the manual, 1…22"), "the manual's table", 1,
                    OPTIONAL, "none (a mechanism of one's own)"),
                Key("variant", Int(ge=1, le=10, what="a variant, 1…10"), "the variant of the table", 1,
                    OPTIONAL, "none"),
                Key("sheet", Word(*SHEET_FORMATS), "format of the one sheet", "A1", _dflt(ControlWork, "sheet")),
                Key("tolerance_percent", Number(gt=0, le=100, unit="%"), "accepted deviation of a value read "
                    "from a construction (reportgen check)", 5.0, _dflt(ControlWork, "tolerance_percent")),
            )),
    Section("dynamics", "the flywheel", "", (
        Key("delta", Number(gt=0, lt=1), "coefficient of non-uniformity δ", 0.05),
        Key("crank_inertia", Number(ge=0, unit="kg·m²"),
            "everything rotating with the crank (rotor and gears reduced to it)", 2.2,
            _dflt(Dynamics, "crank_inertia")),
        Key("flywheel", None, "shape and material of the flywheel", None, OPTIONAL, "all defaults",
            table="dynamics.flywheel"),
    )),
    Section("dynamics.flywheel", "the flywheel's shape", "", (
        Key("shape", Word(*FLYWHEEL_SHAPES), "a solid disk or a rim", "disk", _dflt(Flywheel, "shape")),
        Key("density", Number(gt=0, unit="kg/m³"), "density of its material", 7860.0, _dflt(Flywheel, "density")),
        Key("width_ratio", Number(gt=0), "width / diameter (disk) or width / rim thickness", 1.0,
            _dflt(Flywheel, "width_ratio")),
    ), shape="inline"),
    Section("gears", "the external involute pair", "Basic rack of ГОСТ 13755 by default.", (
        Key("z1", TEETH, "teeth of the pinion", 13),
        Key("z2", TEETH, "teeth of the wheel", 26),
        Key("module", GEAR_MODULE, "module m", 9.0),
        Key("x1", SHIFT, "profile-shift coefficient of the pinion, or \"auto\"", 0.63, _dflt(Gears, "x1")),
        Key("x2", SHIFT, "profile-shift coefficient of the wheel, or \"auto\"", 0.67, _dflt(Gears, "x2")),
        Key("alpha_deg", Number(gt=0, lt=45, unit="degrees"), "pressure angle of the basic rack", 20.0,
            _dflt(Gears, "alpha_deg")),
        Key("ha", Number(gt=0, le=2), "addendum coefficient h*a", 1.0, _dflt(Gears, "ha")),
        Key("c", Number(ge=0, le=1), "bottom clearance coefficient c*", 0.25, _dflt(Gears, "c")),
        Key("eps_min", Number(ge=1, le=2.5), "least transverse contact ratio εα of the quality check "
            "(Болотовский 1.2; seed 000 accepts 1.05)", 1.05, _dflt(Gears, "eps_min")),
        Key("sa_min", Number(ge=0, le=1, unit="a share of the module"), "least tip thickness: sa ≥ sa_min·m "
            "(the seed uses 0.2; Болотовский 0.25…0.3 for hardened teeth)", 0.25, _dflt(Gears, "sa_min")),
    )),
    Section("planetary", "the planetary reduction gear", "", (
        Key("scheme", Word(*PLANETARY_SCHEMES), "the reducer's scheme", "two-row-ext-int"),
        Key("motor_rpm", Number(gt=0, le=1e5, unit="rpm"), "motor speed (required with ratio = \"auto\")",
            1500, OPTIONAL, "required with ratio = \"auto\""),
        Key("ratio", OneOf(Word("auto"), Number(gt=1)), "the reducer's ratio, or \"auto\": motor → open "
            "pair [gears] → planetary → crank speed", "auto", _dflt(Planetary, "ratio")),
        Key("tolerance", Number(gt=0, lt=1), "allowed relative error of the ratio", 0.05, _dflt(Planetary, "tolerance")),
        Key("satellites", OneOf(Word("auto"), Int(ge=1, le=12)), "number of satellites K, or \"auto\"",
            "auto", _dflt(Planetary, "satellites")),
        Key("module", GEAR_MODULE, "module for the drawing", 6.4, OPTIONAL, "chosen by the solver"),
    )),
)

SECTIONS += crane_sections(Key, Section, OPTIONAL)

#: Section by path ("" is the document itself).
SECTION: dict[str, Section] = {s.path: s for s in SECTIONS}
