"""The room each construction is given on paper, mm. The scenes and the graphical replicas choose
their scales from these boxes; the solvers hold none of them (the stages pass ``project.boxes`` in).
The defaults are the views of the A1 sheets; a caller that draws elsewhere passes its own boxes,
and the note draws the same scenes (reduced where the text block is smaller, and says so)."""
from __future__ import annotations

from dataclasses import dataclass, field


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
    #: The control work's sheet: the drawing of the mechanism at φ (``scheme`` is sheet 1's, whose
    #: field holds no lever) on A1 and on A3. The plan of positions takes the largest ГОСТ scale
    #: that draws it within the box, and sheet and note print that one (issue 12; on main the sheet
    #: fell back to a smaller scale where its views did not fit: t22-v1 1:15 on A1, the example
    #: 1:40 on A3, while the note printed 1:10).
    scheme_control: tuple[float, float] = (200.0, 200.0)
    scheme_control_a3: tuple[float, float] = (40.0, 40.0)
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
        for ``task``: sheet 1, or the control work's one sheet (A1 or A3)."""
        sheet = control_sheet(task)
        if sheet is None:
            return self.scheme
        return self.scheme_control_a3 if sheet == "A3" else self.scheme_control

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
