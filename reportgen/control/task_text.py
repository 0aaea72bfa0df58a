"""The task file of a control-work variant: complete, commented TOML that ``reportgen build`` reads.

Pure text: the points come from :func:`reportgen.control.sketch.sketch` (the printed φ), the links
from the reconstructed scheme; every choice the manual leaves to the student (q, the slider's mass
factor, the sheet format, the tolerance of a graphical construction) is a key with its default.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

from ..zoo import toml_value
from .sketch import link4_key, sketch
from .tables import Table, Variant
from ..tolerances import RTOL_EQUAL

#: Defaults of the choices the manual leaves open (§5: q = 8…25 kg/m, m_slider = (4…18)·m1).
DEFAULT_Q = 10.0
DEFAULT_SLIDER_FACTOR = 6.0
DEFAULT_TRIANGLE_FACTOR = 2.5
DEFAULT_G = 9.8                 # the manual's g, (31)
DEFAULT_TOLERANCE_PERCENT = 5.0
DEFAULT_SHEET = "A1"


def _num(x: float) -> str:
    """A coordinate rounded to 0.1 µm (enough for a sketch; the lengths are given exactly)."""
    return repr(round(float(x), 7) + 0.0)


def _bar_or_triangle(pts, names: tuple[str, str, str]) -> tuple[list[str], bool]:
    """The point order of a three-point link and whether it is a straight bar (ends first)."""
    d = {frozenset((p, q)): math.dist(pts[p], pts[q]) for p, q in itertools.combinations(names, 2)}
    (p, q), longest = max(((tuple(k), v) for k, v in d.items()), key=lambda kv: kv[1])
    mid = next(n for n in names if n not in (p, q))
    straight = abs(d[frozenset((p, mid))] + d[frozenset((mid, q))] - longest) <= RTOL_EQUAL * longest
    return ([names[0], names[1], names[2]] if not straight else sorted((p, q)) + [mid]), straight


@dataclass(frozen=True)
class TaskWords:
    """The words of a new task file in its language (the command layer reads them from the note's
    catalogue, ``document_defaults`` of ``latex_templates/strings/<lang>/document.toml``, with the
    table's and variant's numbers filled in): the title, the mechanism's name, the department and the
    designation (ГОСТ 2.201 letters in ru/uk, Latin in en: docs/task-format-notes.md)."""
    language: str
    title: str
    mechanism: str
    organization: str
    code: str


def task_text(t: Table, v: Variant, *, words: TaskWords, q: float = DEFAULT_Q,
              slider_factor: float = DEFAULT_SLIDER_FACTOR, sheet: str = DEFAULT_SHEET,
              tolerance_percent: float = DEFAULT_TOLERANCE_PERCENT) -> str:
    """The commented task file of table ``t``, variant ``v`` in the language of ``words`` (raises
    VariantGeometryError if the printed dimensions cannot form the scheme at φ)."""
    sc = t.scheme
    sk = sketch(sc, v)
    P = sk.points
    L = dict(sk.lengths)
    S = sc.slider
    def cell(c) -> str:
        name, _, unit = c.label.partition(",")
        return f"{' '.join(name.split())} = {c.printed[v.number - 1]}" + (f" {unit.strip()}" if unit.strip() else "")
    row = "; ".join(cell(c) for c in t.columns)
    out: list[str] = [
        f"# Control work in the theory of machines and mechanisms: table {t.number}, variant {v.number} "
        f"(course manual, §7–8, p. {t.page}).",
        f"# Row of table {t.number} as printed: {row}.",
        "# The manual's scheme pictures are lost: the layout below (where D, E and the guide of the slider",
        "# stand) is a RECONSTRUCTION chosen so that the printed dimensions assemble; see docs/control-work.md.",
        f"# Scheme reasoning: {sc.reasoning}",
        "# Units: SI (m, kg, s, N). Build: reportgen build THIS_FILE -o out/",
        "",
        "[document]",
        'kind = "control-work"             # the control-work note and its one sheet (not the course project)',
        f"title = {toml_value(words.title)}",
        'author = ""                        # your name',
        'group = ""',
        'supervisor = ""',
        f"organization = {toml_value(words.organization)}",
        'city = ""',
        "year = 2026",
        f"language = {toml_value(words.language)}",
        f"code = {toml_value(words.code)}            # designation: the note's ….000, the sheet ….001",
        "",
        "[control_work]",
        f"table = {t.number}",
        f"variant = {v.number}",
        f'sheet = "{sheet}"                     # "A1" (as the course sheets) or "A3"',
        f"tolerance_percent = {tolerance_percent!r}         # accepted deviation of a graphical value (reportgen check)",
        "",
        "[mechanism]",
        f"name = {toml_value(words.mechanism)}",
        f"g = {DEFAULT_G!r}                           # m/s², formula (31) of the manual",
        'ground = ["A", "D"]                 # crank axis A, rocker axis D',
        "",
        f"# The mechanism at the variant's crank angle φ = {v.phi_deg:g}° (frame points exact, the others where",
        "# the lengths put them on the reconstructed branch).",
        "[mechanism.points]",
    ]
    for name in ("A", "D", "B", "C", "E", "F"):
        if name in P:
            out.append(f"{name} = [{_num(P[name][0])}, {_num(P[name][1])}]")
    out.append("")

    def link(i: int, kind: str, names: list[str], comment: str) -> None:
        out.append(f"[[mechanism.link]]                  # {comment}")
        out.append(f"id = {i}")
        out.append(f'kind = "{kind}"')
        if len(names) == 1:
            out.append(f"points = {toml_value(names)}")
        elif len(names) == 2:
            out.append(f"points = {toml_value(names)}")
            out.append(f"length = {L['l_' + ''.join(sorted(names))]!r}")
        else:
            order, straight = _bar_or_triangle(P, (names[0], names[1], names[2]))
            out.append(f"points = {toml_value(order)}")
            sides = {}
            for a, b in itertools.combinations(order, 2):
                key = "l_" + "".join(sorted(a + b))
                sides[a + b] = L.get(key, round(math.dist(P[a], P[b]), 9))
            out.append("lengths = { " + ", ".join(f"{k} = {val!r}" for k, val in sides.items()) + " }")
            if straight:
                out.append("com = 0.5                            # a straight bar: the middle of its length (§5)")
        out.append("")

    link(1, "crank", ["A", "B"], "crank AB")
    two = ["B", "C"] + (["E"] if sc.e_kind != "none" and sc.e_link == 2 else [])
    three = ["D", "C"] + (["E"] if sc.e_kind != "none" and sc.e_link == 3 else [])
    link(2, "coupler", two, "coupler B" + "".join(two[1:]))
    link(3, "rocker", three, "rocker D" + "".join(three[1:]))
    link(4, "coupler", [sc.f_from, S], f"coupler {sc.f_from}{S} ({link4_key(sc)})")
    link(5, "slider", [S], f"slider {S}")
    ang = sc.guide_angle_deg
    out += [
        "[[mechanism.slide]]                 # the slider on a guide of the frame (reconstructed)",
        "link = 5",
        f'point = "{S}"',
        "guide = 0",
        f"line = {{ through = [{_num(P[S][0])}, {_num(P[S][1])}], angle_deg = {ang!r} }}",
        "",
        "[mechanism.drive]",
        "link = 1",
        f"omega = {v.omega1!r}                        # rad/s, counter-clockwise (ω1 of the table)",
        "",
        "# Masses and moments of inertia by the manual's rules (§5): m = q·l (29), slider (4…18)·m1 (30),",
        "# J = m·l²/12 (33), a triangular link 2.5× the J of its longest bar. Change q and the factor",
        "# within the manual's ranges if your teacher asks.",
        "[mechanism.mass_rules]",
        f"q = {q!r}                             # kg/m, 8…25",
        f"slider_factor = {slider_factor!r}                 # 4…18",
        f"triangle_factor = {DEFAULT_TRIANGLE_FACTOR!r}",
        "",
        "# The table gives no useful resistance; a teacher may add one, e.g. (N, frame coordinates):",
        "# [[mechanism.load]]",
        "# kind = \"force\"",
        "# link = 5",
        f'# point = "{S}"',
        "# vector = [-1000.0, 0.0]",
        "",
        "[analysis]",
        "positions = 1                        # one position: the variant's φ",
        f"start = {v.phi_deg!r}",
        "force_position = 0",
        "",
    ]
    return "\n".join(out)
