"""The room each construction is given on paper, mm. The scenes and the graphical replicas choose
their scales from these boxes; the solvers hold none of them (the stages pass ``project.boxes`` in).
The defaults are the views of the A1 sheets; a caller that draws elsewhere passes its own boxes,
and the note draws the same scenes (reduced where the text block is smaller, and says so)."""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from shapely.geometry import Polygon

# ---------------------------------------------------------------------------------------------
# the sheet's free field (numbers of ГОСТ 2.301 and 2.104; drawings.sheet draws them)

#: Sheet formats, landscape, mm (ГОСТ 2.301).
SHEET_MM: dict[str, tuple[float, float]] = {"A1": (841.0, 594.0), "A2": (594.0, 420.0), "A3": (420.0, 297.0)}
#: Frame offsets from the sheet edges (ГОСТ 2.301): left (binding), bottom, right, top.
FRAME_LEFT, FRAME_BOTTOM, FRAME_RIGHT, FRAME_TOP = 20.0, 5.0, 5.0, 5.0
#: Form 1 of ГОСТ 2.104 is 185 × 55 mm; graph 26 is 70 × 14 mm.
TITLE_W, TITLE_H = 185.0, 55.0
EXTRA_W, EXTRA_H = 70.0, 14.0
#: Views keep this far from the frame, the title block and graph 26, mm.
FIELD_MARGIN = 5.0


@lru_cache(maxsize=8)
def free_field(width: float, height: float, margin: float = FIELD_MARGIN) -> "Polygon":
    """The free field of a ``width`` × ``height`` sheet: the frame's interior less the title block
    (bottom right) and graph 26 (top left, turned), ``margin`` mm clear of all."""
    from shapely.geometry import box        # here: `reportgen solve` imports these boxes, not shapely
    x0, y0, x1, y1 = FRAME_LEFT, FRAME_BOTTOM, width - FRAME_RIGHT, height - FRAME_TOP
    region = box(x0 + margin, y0 + margin, x1 - margin, y1 - margin)
    for bx0, by0, bx1, by1 in ((x1 - TITLE_W, y0, x1, y0 + TITLE_H), (x0, y1 - EXTRA_H, x0 + EXTRA_W, y1)):
        region = region.difference(box(bx0 - margin, by0 - margin, bx1 + margin, by1 + margin))
    return region


@dataclass(frozen=True)
class GraphLayout:
    """Room on the sheet for the diagrams of section 3, mm (sized for an A1 sheet 3: the column of M,
    A, ΔE, ω on the left, the Wittenbauer diagram with J_red(φ) turned under it in the middle; the
    note's section 3 uses the same scales, so that note and sheet agree)."""
    phi_axis: float = 260.0       # length of the φ axis for one cycle
    m_height: float = 80.0        # largest |M_red|
    a_height: float = 80.0        # largest |A| of the work diagram
    e_height: float = 80.0        # span of ΔE
    j_width: float = 160.0        # largest J_red (from J = 0)
    #: the Wittenbauer construction from its lowest to its highest point (the curve, K, L, the
    #: tangents to the end of the J axis): sheet 3 gives it the field's height less J_red(φ) under it
    w_height: float = 210.0
    #: the ordinates of M_red, A (with A_дв) and ΔE together, each from its lowest to its highest
    #: point with its axis: sheet 3's left column holds them with ω(φ) (2·omega_height), the four
    #: titles, the position numbers and names and the gaps (tests/hard_cases/test_wittenbauer_fits.py)
    column_height: float = 268.0
    pole_step: float = 10.0       # H is a multiple of this
    omega_height: float = 36.0    # largest |ω − ω_m| (or the band) of ω(φ)


@dataclass(frozen=True)
class SceneBoxes:
    #: Sheet 1: the drawing of the mechanism (the scheme view less its label and caption margins).
    #: At most 270 mm high, so that the band of the A1 field under the scheme's view (584 − 270 −
    #: 74 − 10 = 230 mm) holds a plan position's pair of plans (views up to ~195 mm high) and the
    #: small plans find room beside it or beside the scheme: the shaper at 1:2 (320 mm high) and
    #: class3 at 1:2,5 (284 mm) left no room for their 12 small velocity plans (issue 12).
    scheme: tuple[float, float] = (470.0 - 28.0 - 28.0, 270.0)
    #: Sheet 1: each plan position beyond two (``[analysis] plan_positions``) takes this much height
    #: from ``scheme`` (its pair of plans needs ~140 × 150–200 mm more of the field: the shaper with
    #: three plan positions finds no room at 1:2,5 and is drawn at 1:4).
    scheme_less_per_pair: float = 40.0
    #: Sheet 1: no point of the plans of a plan position other than the analysed one stands farther
    #: than this from the pole, mm (a coarser round μ if it would; the analysed position's plans keep
    #: the scales of :func:`reportgen.plans.build_plans`), so that both stroke's plans find room.
    other_plan_mm: float = 120.0
    #: Sheet 2: the longest vector of a force polygon, mm; the extent
    #: (diagonal) of the mechanism on the scheme of section 2, mm.
    polygon_mm: float = 200.0
    scheme_diagonal_mm: float = 450.0
    #: Sheet 2: a polygon is drawn larger than ``polygon_mm`` gives as long as it fits this box
    #: (width, height); a narrower one when two or more groups (three polygons) share the sheet.
    polygon: tuple[float, float] = (400.0, 180.0)
    polygon_many: tuple[float, float] = (350.0, 180.0)
    #: Sheet 2: Zhukovsky's lever — the turned velocity plan with the feet of the arms (width,
    #: height): its μv is the smallest round one (plans' series) that draws it within this box, the
    #: largest lever sheet 2's arrangement holds beside the groups and the polygons on every example
    #: (tests/scenes/test_lever_scale.py: one round step larger does not fit).
    lever: tuple[float, float] = (250.0, 400.0)
    #: The control work's one sheet (sheet 1's drawing with the lever in place of the diagrams):
    #: the lever's box on A1 and on A3 (``[control_work] sheet``).
    lever_control: tuple[float, float] = (300.0, 250.0)
    lever_control_a3: tuple[float, float] = (110.0, 80.0)
    #: The control work on A3: no point of the velocity or acceleration plan farther than this from
    #: the pole, mm (the smallest round μ of the plans' series that does it); on A1 the plans keep
    #: the scales of :func:`reportgen.plans.build_plans`, the course project's.
    plan_control_a3_mm: float = 75.0
    #: Sheet 3: the diagrams.
    diagrams: GraphLayout = field(default_factory=GraphLayout)

    def lever_for(self, task) -> tuple[float, float]:
        """The box of Zhukovsky's lever on the sheet that draws it for ``task``: sheet 2, or the control
        work's one sheet (A1 or A3). The note draws the same lever at the same μv (reduced)."""
        doc = getattr(task, "document", None)
        if doc is None or getattr(doc, "kind", "") != "control-work":
            return self.lever
        cw = getattr(task, "control_work", None)
        return self.lever_control_a3 if cw is not None and cw.sheet == "A3" else self.lever_control

    def scheme_for(self, task) -> tuple[float, float]:
        """The box of the drawing of the mechanism (the plan of positions) on the sheet that draws it
        for ``task``: sheet 1's ``scheme``; on the control work's one sheet (A1 or A3) the largest
        the free field could hold at all (its extent less the scheme view's strips and the letters'
        room). The scale the note and the sheet print is the largest ГОСТ scale of these at which
        the whole sheet's arrangement fits (:func:`reportgen.scenes.arrangement.choose_layout`),
        not a fixed box's (issue 12: a 90 × 90 mm box on A3 drew table 4 variant 1's mechanism
        55 mm wide at 1:25 beside 120 × 140 mm of empty field, table 10's 33 × 61 mm at 1:40)."""
        sheet = control_sheet(task)
        if sheet is None:
            return self.scheme
        x0, y0, x1, y1 = free_field(*SHEET_MM[sheet]).bounds
        return (x1 - x0 - 2 * SCHEME_LETTERS_MIN_MM,
                y1 - y0 - 2 * SCHEME_LETTERS_MIN_MM - SCHEME_TITLE_STRIP_MM - SCHEME_CAPTION_STRIP_MM)

    def plan_mm_for(self, task) -> float | None:
        """The farthest a point of the analysed position's plans may stand from the pole on the sheet
        that draws them, mm; None: the course project's rule (:func:`reportgen.plans.build_plans`)."""
        return self.plan_control_a3_mm if control_sheet(task) == "A3" else None


def control_sheet(task) -> str | None:
    """The format of the control work's one sheet ("A1" or "A3"), None for a course project."""
    doc = getattr(task, "document", None)
    if doc is None or getattr(doc, "kind", "") != "control-work":
        return None
    cw = getattr(task, "control_work", None)
    return "A3" if cw is not None and cw.sheet == "A3" else "A1"


DEFAULT = SceneBoxes()


# ---------------------------------------------------------------------------------------------
# sheet 1 and the control work's sheet: the views' sizes, from which the core arranges the sheet
# (reportgen.scenes.arrangement) and chooses the scale of the plan of positions

#: Padding of sheet 1's scheme around its model bounds: left, bottom, right, top, mm (the scale
#: caption below, the title above; the crank angles' rays reach 22 mm beyond the crank circle, the
#: stroke's dimension 17,5 mm beyond the guide, with their values).
SCHEME_PADS_MM = (28.0, 36.0, 28.0, 38.0)
#: The scheme view's strips: its title above (drawings.sheet.View.title letters it 5 mm high, 1 mm
#: under the top) and its scale caption below (5 mm high, 4 mm over the bottom), mm; the scheme's
#: letters keep out of them (drawings.scenes.kinematics_scheme).
SCHEME_TITLE_STRIP_MM, SCHEME_CAPTION_STRIP_MM = 9.0, 12.0
#: The control work's scheme (one position: no crank angles, no stroke): room round what its scene
#: draws (links, hinges, pivots, guides, blocks: ``Scene.bounds`` at the scale) for the letters. A
#: letter reaches up to ``SCHEME_LETTERS_MM`` from its point (5 mm high, «S₂» about 6,5 mm wide,
#: 0,6–1,5 mm beside the hinge); on each side the room is what the points nearest to it need, at
#: least ``SCHEME_LETTERS_MIN_MM`` (the links' numbers, circles of 2,8 mm radius, go beside their
#: links, else on a leader inwards). Measured on all 22 tables' variant 1 on A3: the drawing
#: reached at most 7,8 mm beyond its scene.
SCHEME_LETTERS_MM, SCHEME_LETTERS_MIN_MM = 9.0, 3.0
#: The control work's scheme view is at least as wide as its title (5 mm letters): «Механизм в
#: заданном положении, φ1 = …°» on A1, «Механизм, φ1 = …°» on A3.
SCHEME_MIN_WIDTH_MM = {"A1": 125.0, "A3": 85.0}
#: A plan's view: room for letters and names round its points, its caption and title strips, its
#: least width, mm.
PLAN_PAD_MM, PLAN_STRIP_MM, PLAN_MIN_WIDTH_MM = 16.0, 12.0, 120.0
#: The control work on A3: a plan's view is at least this wide (its title is the short «План
#: скоростей»: the one position is named by the scheme's title), mm.
PLAN_MIN_WIDTH_A3_MM = 100.0
#: Zhukovsky's lever's panel: room round the turned plan, the strips of its title, subtitle and
#: scale captions, mm (drawings.scenes.kinetostatics_views.lever_panel draws in them).
LEVER_PAD_MM, LEVER_STRIPS_MM = 12.0, 10.0 + 6.0 + 16.0
#: Sheet 1's small velocity plans: the crank's vector is at most this long, mm (the largest whose
#: plans find room; drawings.sheets.kinematics.small_plans).
SMALL_PLAN_MM = (60.0, 50.0, 40.0, 30.0, 20.0)
#: The table «Масштабы»: a row's height and the strip above it for its title, mm.
TABLE_ROW_MM, TABLE_TITLE_MM = 8.0, 12.0
#: Gap between views, and between the two plans of a plan position put together (smaller, so that
#: a pair reads as one: the views' own margins keep the drawings ~30 mm apart), mm.
VIEW_GAP, PAIR_GAP = 10.0, 4.0
#: The plans may widen by this much to give their names room, mm.
GROW_PLANS_MM = 40.0

#: Room the lettering of these views needs, per language of the sheet (the words are the
#: catalogue's, which the core does not read; the sheet font's widths were measured with
#: drawings.style.text_width and tests/sheet1/test_arrangement_core.py checks every language's
#: lines fit): a plan view's title at 5 mm + 10 mm (velocity, acceleration: «План ускорений,
#: положение 2»; on the control work's A3 sheet «План ускорений», the control work's catalogue is
#: Russian), the lever's title and subtitle + 4 mm. The table «Масштабы» of sheet 1 is measured from
#: its own lines (:func:`reportgen.scenes.arrangement.scales_table_width`).
PLAN_TITLE_MM = {"ru": (133.0, 133.0), "uk": (138.0, 138.0), "en": (138.0, 156.0)}
#: … and each further digit of the position's number.
PLAN_TITLE_DIGIT_MM = 4.6
PLAN_TITLE_A3_MM = {"ru": (75.0, 75.0)}
LEVER_TITLE_MM = {"ru": 116.0, "uk": 119.0, "en": 106.0}


def lettering_room(table, language: str):
    """``table``'s room for ``language`` (the widest of the catalogue's languages for another)."""
    return table.get(language, max(table.values()))
