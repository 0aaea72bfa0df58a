"""Task loading: a TOML task file (``docs/task-format.md``) → :class:`reportgen.task.Task`.

``load_task(path)`` reads a file, ``loads_task(text)`` a string, ``parse_task(data)`` an already
parsed TOML document (a dict). Every key is validated; every error is a
:class:`~reportgen.errors.TaskError` (or its :class:`~reportgen.errors.UnknownKeyError`) whose
``path`` is the TOML path of the value (``mechanism.link[3].length``, 0-based array indices, i.e. the
position of the ``[[mechanism.link]]`` block in the file counted from 0) and whose message says what
would be valid. Masses and moments of inertia not given are filled in by ``[mechanism.mass_rules]``.
Decisions that the format leaves open are written down in ``docs/task-format-notes.md``.
"""
from __future__ import annotations

import itertools
import math
import os
import re
import tomllib
from dataclasses import dataclass
from typing import Any, Mapping

from .errors import TaskError, TaskSyntaxError
from .task import (DEFAULT_LAW, Analysis, ControlWork, Document, Drive, Dynamics, Flywheel, Gears,
                   Link, Load, MassRules, Mechanism, Planetary, Slide, Task, Vec2, frozen_mapping)
from .taskfile_values import (Array, Int, OneOf, Spec, Table, Word, array_of_tables, check_keys, fmt,
                              index, join, show, suggest)
from .taskspec import (COURSE_POSITIONS, INERTIA, LAW, LENGTH, LINK_ID, LOAD_KINDS, MAX_LENGTH, MIN_LENGTH,
                       POINT_NAME, POINT_XY, SECTION)
from .tolerances import RTOL_EQUAL

__all__ = ["load_task", "loads_task", "parse_task", "MAX_LENGTH", "MIN_LENGTH", "COLLINEAR_RTOL"]

#: Relative tolerance within which three points of a link count as collinear (a straight bar).
COLLINEAR_RTOL = RTOL_EQUAL

# The keys of every table and the specs of their values: reportgen.taskspec (one source for the
# loader, docs/task-format.md and the JSON Schema).
TOP_KEYS = SECTION[""].names
DOCUMENT_KEYS = SECTION["document"].names
MECHANISM_KEYS = SECTION["mechanism"].names
LINK_KEYS = SECTION["mechanism.link"].names
SLIDE_KEYS = SECTION["mechanism.slide"].names
LINE_KEYS = SECTION["mechanism.slide.line"].names
DRIVE_KEYS = SECTION["mechanism.drive"].names
MASS_RULES_KEYS = SECTION["mechanism.mass_rules"].names
LOAD_KEYS_BY_KIND = {kind: tuple(k.name for k in SECTION["mechanism.load"].keys if kind in k.kinds)
                     for kind in LOAD_KINDS}
LOAD_KEYS = SECTION["mechanism.load"].names
ANALYSIS_KEYS = SECTION["analysis"].names
DYNAMICS_KEYS = SECTION["dynamics"].names
FLYWHEEL_KEYS = SECTION["dynamics.flywheel"].names
GEARS_KEYS = SECTION["gears"].names
PLANETARY_KEYS = SECTION["planetary"].names
CONTROL_WORK_KEYS = SECTION["control_work"].names

_LENGTH = LENGTH
_INERTIA = INERTIA
_POINT_NAME = POINT_NAME
_LINK_ID = LINK_ID


def _get(t: Table, section: str, key: str) -> Any:
    """Read ``key`` of table ``t`` with the spec and default of ``reportgen.taskspec``."""
    sec = SECTION[section]
    spec = sec[key].spec
    assert spec is not None, f"{section}.{key} is a table"
    return t.get(key, spec, sec.default(key))


# ============================================================================================ entry
def load_task(path: str | os.PathLike) -> Task:
    """Read and validate the task file at ``path``."""
    name = os.fspath(path)
    try:
        with open(name, "rb") as fh:
            raw = fh.read()
    except FileNotFoundError:
        raise TaskError(name, "no such file", "the path of a TOML task file") from None
    except IsADirectoryError:
        raise TaskError(name, "is a directory", "the path of a TOML task file") from None
    except OSError as exc:
        raise TaskError(name, f"cannot be read: {exc.strerror or exc}", "a readable TOML task file") from None
    try:
        text = raw.decode("utf-8-sig")  # a BOM written by Windows Notepad is harmless
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        col = exc.start - (raw.rfind(b"\n", 0, exc.start) + 1) + 1
        raise TaskSyntaxError(name, line, col, "is not UTF-8 text") from None
    return loads_task(text, source=name)


def loads_task(text: str, source: str = "") -> Task:
    """Read and validate a task given as TOML text; ``source`` names it in errors and in the Task."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        if m:
            line, col = int(m.group(1)), int(m.group(2))
            msg = msg[:m.start()].strip()
        else:
            m = re.search(r"\(at end of document\)", msg)
            line = text.count("\n") + 1
            col = len(text) - (text.rfind("\n") + 1) + 1
            if m:
                msg = msg[:m.start()].strip()
        raise TaskSyntaxError(source or "<string>", line, col, f"is not valid TOML: {msg}") from None
    return parse_task(data, source)


def parse_task(data: dict, source: str = "") -> Task:
    """Validate a parsed TOML document and build the :class:`Task`."""
    top = Table(data, "", TOP_KEYS, "a TOML document (a table of sections)")
    document = _document(top.raw("document"), "document") if "document" in top else Document()
    mechanism = _mechanism(top.raw("mechanism"), "mechanism") if "mechanism" in top else None
    control = document.kind == "control-work"         # a control work: one position may be enough
    analysis = _analysis(top.raw("analysis"), "analysis", control) if "analysis" in top else Analysis()
    dynamics = _dynamics(top.raw("dynamics"), "dynamics") if "dynamics" in top else None
    gears = _gears(top.raw("gears"), "gears") if "gears" in top else None
    planetary = _planetary(top.raw("planetary"), "planetary") if "planetary" in top else None
    crane = None
    if "crane" in top:
        from .crane.taskfile import read_crane
        crane = read_crane(top.raw("crane"), "crane")
    if document.kind == "crane" and crane is None:
        raise TaskError("crane", 'is missing; [document] kind = "crane" needs it', "a [crane] section")
    if mechanism is None and gears is None and planetary is None and crane is None:
        given = [f"[{k}]" for k in data] if data else []
        raise TaskError("", "the task has nothing to build" + (
            f": it gives only {', '.join(given)}" if given else ": it is empty or holds only comments"),
            "at least one of the sections [mechanism] (a linkage: note sections 1–3, sheets 1–3), "
            "[gears] (a gear pair: section 4, sheet 4), [planetary] (a planetary reducer) or [crane] "
            "(a bridge crane: the crane note and its sheets)")
    control_work = _control_work(top.raw("control_work"), "control_work") if "control_work" in top else None
    if control:
        if mechanism is None:
            raise TaskError("document.kind", '"control-work" but the task has no [mechanism]',
                            "a [mechanism] section (reportgen new --table T --variant V writes one)")
        if control_work is None:
            control_work = ControlWork()
    task = Task(document=document, mechanism=mechanism, analysis=analysis, dynamics=dynamics,
                gears=gears, planetary=planetary, crane=crane, control_work=control_work, source=str(source))
    return task


def _control_work(value: Any, path: str) -> ControlWork:
    t = Table(value, path, CONTROL_WORK_KEYS)
    return ControlWork(**{key: _get(t, "control_work", key) for key in CONTROL_WORK_KEYS})


# ========================================================================================= document
def _document(value: Any, path: str) -> Document:
    t = Table(value, path, DOCUMENT_KEYS)
    return Document(**{key: _get(t, "document", key) for key in DOCUMENT_KEYS})


# ======================================================================================== mechanism
@dataclass
class _RawLink:
    """A link as read from the file, before the mass rules."""
    pos: int
    path: str
    id: int
    kind: str | None
    points: tuple[str, ...]
    given: dict[frozenset, tuple[str, str, float, str]]  # {p, q} → (p, q, metres, TOML path)
    mass: float | None
    inertia: float | None
    com: float | str | None


def _mechanism(value: Any, path: str) -> Mechanism:
    t = Table(value, path, MECHANISM_KEYS)
    name = _get(t, "mechanism", "name")
    g = _get(t, "mechanism", "g")
    points = _points(t.get("points", _ANY_TABLE), t.at("points"))
    ground = _ground(_get(t, "mechanism", "ground"), t.at("ground"), points)

    link_path = t.at("link")
    raw_links = [_read_link(v, index(link_path, i), i, points)
                 for i, v in enumerate(array_of_tables(t.get("link", _ANY), link_path, "mechanism.link"))]
    if not raw_links:
        raise TaskError(link_path, "has no links", "at least one [[mechanism.link]]")
    by_id = _check_ids(raw_links)

    drive = _drive(t.get("drive", _ANY_TABLE), t.at("drive"), by_id, ground)
    slide_pairs = _slide_pairs(t.raw("slide", []))
    for ln in raw_links:
        if ln.kind is None:
            ln.kind = infer_kind(ln.id, ln.points, drive.link, ground, slide_pairs)
    rules = _mass_rules(t.raw("mass_rules", {}), t.at("mass_rules"))
    links = _resolve_links(raw_links, by_id, drive.link, rules, points)
    links_by_id = {ln.id: ln for ln in links}

    slides: list[Slide] = []
    if "slide" in t:
        sp = t.at("slide")
        for i, v in enumerate(array_of_tables(t.raw("slide"), sp, "mechanism.slide")):
            slides.append(_slide(v, index(sp, i), links_by_id, slides))
    loads: list[Load] = []
    if "load" in t:
        lp = t.at("load")
        for i, v in enumerate(array_of_tables(t.raw("load"), lp, "mechanism.load")):
            loads.append(_load(v, index(lp, i), links_by_id))

    return Mechanism(name=name, ground=ground, points=frozen_mapping(points), links=tuple(links),
                     drive=drive, slides=tuple(slides), loads=tuple(loads), mass_rules=rules, g=g)


def _slide_pairs(raw: Any) -> tuple[tuple[int, int], ...]:
    """(link, guide) of every [[mechanism.slide]] that names both as integers (the slides are
    validated later, by ``_slide``); used only to infer the kind of a link."""
    pairs = []
    for v in raw if isinstance(raw, list) else []:
        if isinstance(v, dict):
            lk, gd = v.get("link"), v.get("guide")
            if isinstance(lk, int) and isinstance(gd, int) and not isinstance(lk, bool) and not isinstance(gd, bool):
                pairs.append((lk, gd))
    return tuple(pairs)


def infer_kind(link_id: int, points: tuple[str, ...], drive_link: int, ground: tuple[str, ...],
               slides: tuple[tuple[int, int], ...]) -> str:
    """The kind of a link that the task leaves out, from the structure (the kind is wording and the
    mass rule of a slider; the solvers never read it):

    the driving link is a crank; a link that carries another link's guide is a slotted link
    (кулиса); a link that slides on a guide of the frame is a slider if it has one point, and so is
    a one-point link on any guide a block (камень) when the guide is a link; a link turning about a
    frame point is a rocker; any other a coupler.
    """
    guides = {g for lk, g in slides if lk == link_id}
    if link_id == drive_link:
        return "crank"
    if any(g == link_id for _, g in slides):
        return "slotted"
    if len(points) == 1:
        return "slider" if 0 in guides or not guides else "block"
    if 0 in guides:
        return "slider"
    if any(p in ground for p in points):
        return "rocker"
    return "coupler"


class _AnyValue(Spec):
    """Accepts anything (the caller checks); used to require presence of a key."""
    def __init__(self, expected: str) -> None:
        self.expected = expected

    def read(self, value: Any, _path: str) -> Any:
        return value


_ANY = _AnyValue("an array of tables")
_ANY_TABLE = _AnyValue("a table")


def _points(value: Any, path: str) -> dict[str, Vec2]:
    if not isinstance(value, dict):
        raise TaskError(path, f"got {show(value)}", "a table of point names → [x, y] in m")
    if not value:
        raise TaskError(path, "is empty", "a table of point names → [x, y] in m")
    spec = POINT_XY
    out: dict[str, Vec2] = {}
    for name, xy in value.items():
        if not isinstance(name, str) or not name.strip():
            raise TaskError(path, "has an empty point name", "non-empty point names")
        x, y = spec.read(xy, join(path, name))
        out[name] = (x, y)
    return out


def _point_ref(name: str, path: str, allowed: tuple[str, ...] | list[str], where: str) -> str:
    """Check that ``name`` is one of ``allowed``; else an error suggesting the nearest."""
    if name in allowed:
        return name
    near = suggest(name, allowed)
    problem = f"no point \"{name}\" in {where}" + (f"; did you mean \"{near}\"?" if near else "")
    raise TaskError(path, problem, "one of: " + ", ".join(allowed))


def _ground(names: tuple[str, ...], path: str, points: dict[str, Vec2]) -> tuple[str, ...]:
    seen: list[str] = []
    for i, p in enumerate(names):
        _point_ref(p, index(path, i), list(points), "[mechanism.points]")
        if p in seen:
            raise TaskError(index(path, i), f"\"{p}\" is listed twice", "each ground point once")
        seen.append(p)
    return tuple(names)


def _split_pair(key: str, pts: tuple[str, ...]) -> list[tuple[str, str]]:
    """The ways ``key`` names two distinct points of the link: ``PQ`` or ``P-Q``."""
    found: dict[frozenset, tuple[str, str]] = {}
    for p, q in itertools.permutations(pts, 2):
        if key in (p + q, f"{p}-{q}"):
            found.setdefault(frozenset((p, q)), (p, q))
    return list(found.values())


def _read_link(value: Any, path: str, pos: int, points: dict[str, Vec2]) -> _RawLink:
    t = Table(value, path, LINK_KEYS)
    lid = _get(t, "mechanism.link", "id")
    kind = _get(t, "mechanism.link", "kind")   # None: inferred from the structure (infer_kind)
    pts = _get(t, "mechanism.link", "points")
    pp = t.at("points")
    for j, p in enumerate(pts):
        _point_ref(p, index(pp, j), list(points), "[mechanism.points]")
        if p in pts[:j]:
            raise TaskError(index(pp, j), f"point \"{p}\" is listed twice", "each point of the link once")

    given: dict[frozenset, tuple[str, str, float, str]] = {}
    if len(pts) == 1:
        for key in ("length", "lengths"):
            if key in t:
                raise TaskError(t.at(key), "a one-point link (slider, block) has no length",
                                "no length/lengths on a link with one point")
    if "length" in t:
        if len(pts) != 2:
            raise TaskError(t.at("length"), f"a link with {len(pts)} points gives its distances in `lengths`",
                            f"lengths = {{ {pts[0]}{pts[1]} = … }}")
        if "lengths" in t:
            raise TaskError(t.at("lengths"), "both `length` and `lengths` are given",
                            "one of them for a two-point link")
        given[frozenset(pts)] = (pts[0], pts[1], t.get("length", _LENGTH), t.at("length"))
    if "lengths" in t and len(pts) > 1:
        lp = t.at("lengths")
        table = t.raw("lengths")
        pair_names = [p + q for p, q in itertools.permutations(pts, 2)]
        if not isinstance(table, dict):
            raise TaskError(lp, f"got {show(table)}",
                            "an inline table of distances, e.g. { " + ", ".join(
                                f"{p}{q} = …" for p, q in itertools.combinations(pts, 2)) + " }")
        if not table:              # the key spec's (and the schema's) at least one distance
            raise TaskError(lp, "is empty", "at least one distance, e.g. { " + ", ".join(
                f"{p}{q} = …" for p, q in itertools.combinations(pts, 2)) + " }, or no `lengths` (from the coordinates)")
        for key, v in table.items():
            if not isinstance(key, str):
                raise TaskError(lp, "has a key that is not a string", "keys naming two points of the link")
            kp = join(lp, key)
            pairs = _split_pair(key, pts)
            if not pairs:
                check_keys({key: None}, lp, pair_names)  # raises UnknownKeyError with a suggestion
            if len(pairs) > 1:
                raise TaskError(kp, f"\"{key}\" can be read as " + " or ".join(f"{p}–{q}" for p, q in pairs),
                                "write it as \"P-Q\", e.g. " + f"\"{pairs[0][0]}-{pairs[0][1]}\"")
            p, q = pairs[0]
            if frozenset((p, q)) in given:
                raise TaskError(kp, f"the distance {p}–{q} is given twice", "each distance once")
            given[frozenset((p, q))] = (p, q, _LENGTH.read(v, kp), kp)

    mass = _get(t, "mechanism.link", "mass")
    inertia = _get(t, "mechanism.link", "inertia")
    com = None
    if "com" in t:
        cp = t.at("com")
        raw = t.raw("com")
        if len(pts) == 1:
            if not isinstance(raw, str):
                raise TaskError(cp, f"got {show(raw)}", f"the link's point name \"{pts[0]}\"")
            com = _point_ref(raw, cp, list(pts), "the points of this link")
        else:
            com = _get(t, "mechanism.link", "com")
            if isinstance(com, str):
                _point_ref(com, cp, list(pts), "the points of this link")
    return _RawLink(pos, path, lid, kind, tuple(pts), given, mass, inertia, com)


def _check_ids(raw_links: list[_RawLink]) -> dict[int, _RawLink]:
    by_id: dict[int, _RawLink] = {}
    for ln in raw_links:
        if ln.id in by_id:
            raise TaskError(join(ln.path, "id"), f"id {ln.id} is already used by {by_id[ln.id].path}",
                            f"ids 1..{len(raw_links)}, each once")
        by_id[ln.id] = ln
    n = len(raw_links)
    for ln in raw_links:
        if ln.id > n:
            missing = sorted(set(range(1, n + 1)) - set(by_id))
            raise TaskError(join(ln.path, "id"), f"id {ln.id} is beyond the number of links ({n}); "
                            f"missing id{'s' if len(missing) > 1 else ''} {', '.join(map(str, missing))}",
                            f"ids 1..{n}, each once; 0 is the frame")
    return by_id


def _drive(value: Any, path: str, by_id: dict[int, _RawLink], ground: tuple[str, ...]) -> Drive:
    t = Table(value, path, DRIVE_KEYS)
    lid = _get(t, "mechanism.drive", "link")
    if lid not in by_id:
        raise TaskError(t.at("link"), f"there is no link {lid}", f"a link id 1..{len(by_id)}")
    ln = by_id[lid]
    axes = [p for p in ln.points if p in ground]
    if len(axes) != 1 or len(ln.points) < 2:
        why = ("it lists no ground point" if not axes else
               f"it lists {len(axes)} ground points ({', '.join(axes)})" if len(axes) > 1 else
               "it has no moving point")
        raise TaskError(t.at("link"), f"link {lid} cannot be the driving crank: {why}",
                        "a link that lists exactly one ground point, its axis, and a moving point")
    omega = _get(t, "mechanism.drive", "omega")
    return Drive(link=lid, omega=omega)


def _mass_rules(value: Any, path: str) -> MassRules:
    t = Table(value, path, MASS_RULES_KEYS)
    return MassRules(**{key: _get(t, "mechanism.mass_rules", key) for key in MASS_RULES_KEYS})


# ------------------------------------------------------------------------------------- mass rules
def _distances(ln: _RawLink, points: Mapping[str, Vec2]) -> dict[frozenset, tuple[float, bool]]:
    """Every pairwise distance of the link: (metres, given?) — given, else from the sketch."""
    out: dict[frozenset, tuple[float, bool]] = {}
    for p, q in itertools.combinations(ln.points, 2):
        key = frozenset((p, q))
        if key in ln.given:
            out[key] = (ln.given[key][2], True)
            continue
        (x1, y1), (x2, y2) = points[p], points[q]
        d = math.hypot(x2 - x1, y2 - y1)
        if not d > 0.0:
            where = join(ln.path, "length" if len(ln.points) == 2 else "lengths")
            raise TaskError(where, f"the distance {p}–{q} is not given and the sketch puts {p} and {q} "
                            "at the same place", f"a length > 0 in m, or distinct coordinates of {p} and {q}")
        out[key] = (d, False)
    return out


def _triangle(ln: _RawLink, dist: dict[frozenset, tuple[float, bool]]) -> tuple[float, float, bool]:
    """Check a three-point link; return (sum of sides, longest side, collinear?)."""
    sides = [(f"{p}{q}", *dist[frozenset((p, q))]) for p, q in itertools.combinations(ln.points, 2)]
    sides.sort(key=lambda s: s[1])
    (na, a, ga), (nb, b, gb), (nc, c, gc) = sides
    if c > (a + b) * (1.0 + COLLINEAR_RTOL):
        def txt(nm: str, v: float, g: bool) -> str:
            return f"{nm} = {v:.6g}" + ("" if g else " (from the sketch)")
        raise TaskError(join(ln.path, "lengths"),
                        f"the sides {txt(na, a, ga)}, {txt(nb, b, gb)}, {txt(nc, c, gc)} do not form a "
                        f"triangle: {na} + {nb} = {a + b:.6g} < {nc} = {c:.6g}",
                        "each side shorter than the sum of the other two; equal for a straight bar")
    collinear = c >= (a + b) * (1.0 - COLLINEAR_RTOL)
    return a + b + c, c, collinear


def _resolve_links(raw_links: list[_RawLink], by_id: dict[int, _RawLink], drive_id: int,
                   rules: MassRules, points: Mapping[str, Vec2]) -> list[Link]:
    """Apply the mass rules (course manual, seed 001) and build the frozen links, sorted by id."""
    def slider_rule(ln: _RawLink) -> bool:
        return ln.id != drive_id and (len(ln.points) == 1 or ln.kind in ("slider", "block"))

    def bar_mass_inertia(ln: _RawLink) -> tuple[float, float]:
        """(mass, inertia) of a two- or three-point link: given values, else the rules."""
        dist = _distances(ln, points)
        if len(ln.points) == 2:
            (l, _), = dist.values()
            m = ln.mass if ln.mass is not None else rules.q * l
            j = m * l * l / 12.0
        else:
            total, longest, collinear = _triangle(ln, dist)
            if collinear:  # a straight bar with a point between its ends
                m = ln.mass if ln.mass is not None else rules.q * longest
                j = m * longest * longest / 12.0
            else:  # three bars; J = factor · J of the longest bar at the link's mass per metre
                m = ln.mass if ln.mass is not None else rules.q * total
                m_longest = m * longest / total
                j = rules.triangle_factor * m_longest * longest * longest / 12.0
        return m, j

    drive = by_id[drive_id]
    m1, _ = bar_mass_inertia(drive)
    out: list[Link] = []
    for ln in sorted(raw_links, key=lambda r: r.id):
        if slider_rule(ln):
            if len(ln.points) > 1:
                _distances(ln, points)  # the distances must still be usable
                if len(ln.points) == 3:
                    _triangle(ln, _distances(ln, points))
            m = ln.mass if ln.mass is not None else rules.slider_factor * m1
            j = 0.0
        else:
            m, j = bar_mass_inertia(ln)
            if ln.inertia is not None and ln.inertia == 0.0:
                raise TaskError(join(ln.path, "inertia"), "got 0; only a slider or block may have no inertia",
                                "a number > 0, in kg·m² (or leave it out for the mass rules)")
        if ln.inertia is not None:
            j = ln.inertia
        for what, v in (("mass", m), ("inertia", j)):
            if not math.isfinite(v):
                raise TaskError(join(ln.path, what), f"the mass rules give a {what} that is not finite",
                                f"a smaller [mechanism.mass_rules], or {what} given explicitly")
        lengths = tuple((p, q, l) for p, q, l, _ in ln.given.values())
        assert ln.kind is not None  # given, or inferred in _mechanism before the mass rules
        out.append(Link(id=ln.id, kind=ln.kind, points=ln.points, lengths=lengths, mass=m, inertia=j,
                        com=ln.com, mass_given=ln.mass is not None, inertia_given=ln.inertia is not None))
    return out


# ------------------------------------------------------------------------------------ slides, loads
def _link_ref(value: Any, path: str, links: Mapping[int, Link]) -> Link:
    lid = _LINK_ID.read(value, path)
    if lid not in links:
        raise TaskError(path, f"there is no link {lid}", f"a link id 1..{len(links)}")
    return links[lid]


def _slide(value: Any, path: str, links: Mapping[int, Link], before: list[Slide]) -> Slide:
    t = Table(value, path, SLIDE_KEYS)
    ln = _link_ref(_get(t, "mechanism.slide", "link"), t.at("link"), links)
    if "point" in t or len(ln.points) != 1:
        point = t.get("point", POINT_NAME)
        _point_ref(point, t.at("point"), list(ln.points), f"link {ln.id}")
    else:
        point = ln.points[0]
    guide = _get(t, "mechanism.slide", "guide")
    through = angle = along = None
    if guide == 0:
        if "along" in t:
            raise TaskError(t.at("along"), "is for a guide carried by a link (guide = k > 0)",
                            "line = { through = [x, y], angle_deg = … } for guide = 0")
        lt = Table(t.get("line", _ANY_TABLE), t.at("line"), LINE_KEYS,
                   "an inline table { through = [x, y], angle_deg = … }")
        through = _get(lt, "mechanism.slide.line", "through")
        angle = _get(lt, "mechanism.slide.line", "angle_deg")
    else:
        if guide not in links:
            raise TaskError(t.at("guide"), f"there is no link {guide}", f"0 (the frame) or a link id 1..{len(links)}")
        if guide == ln.id:
            raise TaskError(t.at("guide"), f"link {ln.id} cannot slide along itself",
                            "0 (the frame) or the id of another link")
        if "line" in t:
            raise TaskError(t.at("line"), "is for a guide fixed to the frame (guide = 0)",
                            "along = [P, Q]: two points of the guide link")
        gl = links[guide]
        ap = t.at("along")
        along = t.get("along", _along_spec(guide))
        for j, p in enumerate(along):
            _point_ref(p, index(ap, j), list(gl.points), f"link {guide}")
        if along[0] == along[1]:
            raise TaskError(index(ap, 1), "the same point twice", f"two different points of link {guide}")
        along = (along[0], along[1])
    for s in before:
        if s.link == ln.id and s.guide == guide:
            raise TaskError(path, f"link {ln.id} already slides on guide {guide}", "one slide per link and guide")
    return Slide(link=ln.id, point=point, guide=guide, through=through, angle_deg=angle, along=along)


def _along_spec(guide: int) -> Spec:
    """``along`` as the slide's spec reads it, naming the guide link in the message."""
    spec = SECTION["mechanism.slide"]["along"].spec
    assert isinstance(spec, Array)
    return Array(spec.item, spec.min_len, spec.max_len, what=f"two point names of link {guide}")


def _law(value: Any, path: str) -> tuple[tuple[float, float], ...]:
    law = LAW.read(value, path)
    for i in range(1, len(law)):
        if not law[i][0] > law[i - 1][0]:
            raise TaskError(index(index(path, i), 0),
                            f"{fmt(law[i][0])} does not follow {fmt(law[i - 1][0])}",
                            "stroke fractions increasing strictly")
    if law[0][0] != 0.0:
        raise TaskError(index(index(path, 0), 0), f"the law starts at {fmt(law[0][0])}",
                        "the first pair at stroke fraction 0")
    if law[-1][0] != 1.0:
        raise TaskError(index(index(path, len(law) - 1), 0), f"the law ends at {fmt(law[-1][0])}",
                        "the last pair at stroke fraction 1")
    return tuple((x, y) for x, y in law)


def _load(value: Any, path: str, links: Mapping[int, Link]) -> Load:
    t = Table(value, path, LOAD_KEYS)
    kind = _get(t, "mechanism.load", "kind")
    allowed = LOAD_KEYS_BY_KIND[kind]
    for key in t.data:
        if key not in allowed:
            raise TaskError(t.at(key), f"`{key}` is not a key of a {kind} load",
                            "one of: " + ", ".join(allowed))
    ln = _link_ref(_get(t, "mechanism.load", "link"), t.at("link"), links)
    if kind == "resistance":
        has_f, has_m = "force" in t, "moment" in t
        if has_f == has_m:
            raise TaskError(path, "gives both force and moment" if has_f else "gives neither force nor moment",
                            "exactly one of force = … N (a slider) or moment = … N·m (a rotating link)")
        force = _get(t, "mechanism.load", "force")
        moment = _get(t, "mechanism.load", "moment")
        law = _law(t.raw("law"), t.at("law")) if "law" in t else DEFAULT_LAW
        stroke = _get(t, "mechanism.load", "stroke")
        return Load(kind="resistance", link=ln.id, force=force, moment=moment, law=law, stroke=stroke)
    if kind == "force":
        com = _get(t, "mechanism.load", "com")
        if com and "point" in t:
            raise TaskError(t.at("com"), "com = true and a point are both given",
                            "either point = \"…\" or com = true")
        point = None
        if not com:
            if "point" not in t:
                raise TaskError(t.at("point"), "is missing",
                                f"a point of link {ln.id} (one of: {', '.join(ln.points)}) or com = true")
            point = _point_ref(t.get("point", POINT_NAME), t.at("point"), list(ln.points), f"link {ln.id}")
        vector = _get(t, "mechanism.load", "vector")
        return Load(kind="force", link=ln.id, point=point, com=com, vector=vector)
    value_ = _get(t, "mechanism.load", "value")
    return Load(kind="moment", link=ln.id, value=value_)


# ====================================================================== analysis, dynamics, gears…
def _analysis(value: Any, path: str, control: bool = False) -> Analysis:
    t = Table(value, path, ANALYSIS_KEYS)
    positions = _get(t, "analysis", "positions") if control \
        else t.get("positions", COURSE_POSITIONS, SECTION["analysis"].default("positions"))
    start = _get(t, "analysis", "start")
    fp_spec = OneOf(Word("max-load"), Int(ge=0, le=positions - 1, what="a position index"))
    force_position = t.get("force_position", fp_spec, SECTION["analysis"].default("force_position"))
    if isinstance(force_position, int) and force_position >= positions:  # the default with few positions
        raise TaskError(t.at("force_position"), f"got {force_position}", fp_spec.expected)
    plan_positions = _plan_positions(t, positions, force_position)
    return Analysis(positions=positions, start=start, force_position=force_position,
                    plan_positions=plan_positions)


def _plan_positions(t: Table, positions: int, force_position: int | str) -> tuple[int, ...] | None:
    """``[analysis] plan_positions``: 1–3 distinct indices below ``positions`` that hold the position
    analysed in detail when ``force_position`` names one (its acceleration plan gives the inertia
    forces of the kinetostatics); None when left out (the default rule of ``Project.plan_positions``)."""
    if "plan_positions" not in t:
        return None
    spec = Array(Int(ge=0, le=positions - 1, what=f"a position index 0…{positions - 1}"), 1, 3,
                 what=f"an array of 1 to 3 distinct position indices 0…{positions - 1}")
    value = t.get("plan_positions", spec)
    if len(set(value)) != len(value):
        raise TaskError(t.at("plan_positions"), f"got {list(value)} (a position twice)", spec.expected)
    if isinstance(force_position, int) and force_position not in value:
        raise TaskError(t.at("plan_positions"), f"got {list(value)}, without force_position = {force_position}",
                        f"positions that hold {force_position} (the kinetostatics uses its acceleration "
                        "plan), or force_position set to one of them")
    return tuple(value)


def _dynamics(value: Any, path: str) -> Dynamics:
    t = Table(value, path, DYNAMICS_KEYS)
    flywheel = Flywheel()
    if "flywheel" in t:
        ft = Table(t.raw("flywheel"), t.at("flywheel"), FLYWHEEL_KEYS,
                   "a table { shape = \"disk\" | \"rim\", density = …, width_ratio = … }")
        flywheel = Flywheel(**{key: _get(ft, "dynamics.flywheel", key) for key in FLYWHEEL_KEYS})
    return Dynamics(
        delta=_get(t, "dynamics", "delta"),
        crank_inertia=_get(t, "dynamics", "crank_inertia"),
        flywheel=flywheel,
    )


def _gears(value: Any, path: str) -> Gears:
    t = Table(value, path, GEARS_KEYS)
    return Gears(**{key: _get(t, "gears", key) for key in GEARS_KEYS})


def _planetary(value: Any, path: str) -> Planetary:
    t = Table(value, path, PLANETARY_KEYS)
    scheme = _get(t, "planetary", "scheme")
    motor_rpm = _get(t, "planetary", "motor_rpm")
    ratio = _get(t, "planetary", "ratio")
    if ratio == "auto" and motor_rpm is None:
        raise TaskError(t.at("motor_rpm"), "is missing; ratio = \"auto\" is computed from it",
                        "a number > 0, in rpm (or a numeric ratio)")
    return Planetary(
        scheme=scheme,
        motor_rpm=motor_rpm,
        ratio=ratio,
        tolerance=_get(t, "planetary", "tolerance"),
        satellites=_get(t, "planetary", "satellites"),
        module=_get(t, "planetary", "module"),
    )
