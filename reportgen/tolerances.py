"""Named tolerances: one place for the small numbers that decide "equal", "round-off", "zero" or
"keep a ratio finite" (issue 13 item 3), and for the stopping rules of the solvers.

One name per meaning, not per value: two names may hold the same number (RTOL_EQUAL and ABS_ZERO are
both 1e-9) because they answer different questions (relative to a scale, or absolute in a unit).
Every ``1e-N`` literal of reportgen/, drawings/ and latex_templates/ lives here
(tests/test_tolerances.py greps the packages). A module that gave a tolerance a name of its own
(``numbers.RESIDUE_REL``, ``kinematics.extremes.ROOT_XTOL`` …) imports it from here under that name.
Changing a value here changes results: every example's results.json must stay byte-identical.
"""
from __future__ import annotations

__all__ = [
    # relative
    "RTOL_EQUAL", "RTOL_ROUNDOFF", "RTOL_RANK", "FLAT_PATH_RATIO",
    # absolute, in the quantity's SI unit
    "ABS_ZERO", "ABS_ROUNDOFF", "WHOLE_EPS", "ANGLE_READ_EPS", "TINY",
    # absolute, on paper
    "MM_EPS", "MM_ROUNDOFF", "AREA_EPS_MM2", "BLANK_INK", "LABEL_NEAR_MM",
    # stopping rules of the solvers
    "BRENT_XTOL", "BRENT_RTOL", "EXTREME_XTOL", "BRACKET_NODE_EPS", "ROOT_XTOL", "CONSTRUCTION_TOL",
    "NEWTON_REL_TOL", "EDGE_ANGLE_TOL", "MEAN_SPEED_XREL", "MEAN_SPEED_RTOL", "MEAN_SPEED_REFINE",
    "IVP_RTOL", "INV_INVERSE_TOL", "SHIFT_FD_STEP", "SHIFT_SECANT_TOL", "SHIFT_BISECT_TOL",
    "TOOTH_SIMPLIFY_REL",
]

# ---------------------------------------------------------------------------------------- relative
RTOL_EQUAL = 1e-9
"""Relative: two quantities equal by construction count as equal (three collinear points of a link,
a check exactly on its limit, a tie between candidates, a ratio on the edge of its band), and a value
below this fraction of its problem's scale is round-off residue (``numbers.RESIDUE_REL``: double
precision leaves ~1e-16, every measured quantity of the course is above 1e-6 of its scale)."""

RTOL_ROUNDOFF = 1e-12
"""Relative: a difference this small is round-off of float arithmetic (a scale that already fits,
a value that reaches its target, a ГОСТ scale factor computed from its ratio)."""

RTOL_RANK = 1e-10
"""Relative, per row of a matrix: a singular value below σ_max · (rows or columns) · RTOL_RANK counts
as zero in a numerical rank (Chebyshev's W checked on the constraint Jacobian)."""

FLAT_PATH_RATIO = 1e-4
"""Relative: a closed path whose enclosed area is below this share of its length squared is a straight
back-and-forth (a slider's path on its guide), not a curve worth drawing as a trajectory."""

# ------------------------------------------------------------------ absolute, in the quantity's unit
ABS_ZERO = 1e-9
"""Absolute, in the quantity's SI unit (m, rad, N, N·m, or a unit vector's component): a value this
small is zero — a length with no direction, two angles that are one angle, a span or a force that
gets this floor so that a scale stays finite. The smallest accepted length is 1 µm (1e-6 m), so
nothing real in a task is this small."""

ABS_ROUNDOFF = 1e-12
"""Absolute, in the quantity's SI unit: round-off of a quantity of order one (an angle at the end of
the working stroke, a sum of distances in m that ties with another, a length scale or a force that
is exactly zero, a balance whose terms all vanish)."""

WHOLE_EPS = 1e-9
"""A computed count or grid index this close to a whole number is that whole number (a position on
the diagrams' grid, the turns of a rope on its drum rounded up)."""

ANGLE_READ_EPS = 1e-7
"""Radians: an angle that went through degrees and back (the analysed position of a task, given in
degrees) names the grid position within this of it."""

TINY = 1e-300
"""A floor that keeps a ratio finite where its denominator can be an exact 0 (not a tolerance)."""

# --------------------------------------------------------------------------------- absolute, on paper
MM_EPS = 1e-6
"""Absolute, in sheet millimetres: two coordinates of a drawing this close are the same point (a
segment this short is not drawn, a step that starts there continues the one before, an edge that
reaches a limit touches it)."""

MM_ROUNDOFF = 1e-9
"""Absolute, in millimetres of paper (or mm² for squared distances): float round-off of a drawing's
computation — a length below it has no direction, a candidate must beat the best by more than it to
win a tie, a size or a position within it of a limit is on the limit."""

AREA_EPS_MM2 = 1e-6
"""Absolute, in mm² of paper: two boxes or shapes whose overlap has a smaller area only touch (a label
box on an edge, a view against its neighbour), they do not overlap."""

BLANK_INK = 1e-4
"""Share of inked pixels in a rendered sheet below which it is blank: a drawn sheet has its frame and
title block, far more ink than this."""

LABEL_NEAR_MM = 8.0
"""Absolute, in mm of paper (a sheet, or a note figure at its own size): the largest gap between a
label's box and what it names (its point, its vector or link). 1.6 letter heights of a sheet's 5 mm
lettering: a placer that tries the rings round a point at 1.5 and 6.5 mm (Canvas.label) stays within
it; a label farther than this reads as the name of whatever is nearer (tests/labels checks every
sheet and note figure of every example against it)."""

# ----------------------------------------------------------------------- stopping rules of the solvers
BRENT_XTOL = 2e-12
"""Brent's method (``roots.brent_root``): default absolute tolerance on the root, as SciPy's brentq."""

BRENT_RTOL = 8.881784197001252e-16
"""Brent's method: default relative tolerance on the root, 4·ε of double precision (SciPy's default)."""

EXTREME_XTOL = 1e-9
"""``roots.extremes``: absolute tolerance on the abscissa of an extreme (rad; the value near an extreme
errs by the square of it)."""

BRACKET_NODE_EPS = 1e-15
"""``roots.extremes``: a best sample within this of the node two brackets share lies on that node, so
both brackets are kept as one (absolute, on the abscissa)."""

ROOT_XTOL = 1e-13
"""Extreme positions of the output link (``kinematics.extremes``): absolute tolerance on the crank
angle of a dead centre, rad."""

CONSTRUCTION_TOL = 1e-6
"""The course's construction of the extreme positions: collinearity or perpendicularity within this
sine (relative) counts as met."""

NEWTON_REL_TOL = 1e-13
"""Newton on class III+ groups (``kinematics.positions``): relative step below which it has converged."""

EDGE_ANGLE_TOL = 1e-14
"""The angle where a cycle's load fraction reaches its target (``dynamics.cycle``): Brent's absolute and
relative tolerance, rad."""

MEAN_SPEED_XREL = 1e-14
"""Motion with a flywheel (``dynamics.motion``): Brent's absolute tolerance on the energy constant, as
a share of the bracket's upper end."""

MEAN_SPEED_RTOL = 1e-15
"""Motion with a flywheel: Brent's relative tolerance on the energy constant."""

MEAN_SPEED_REFINE = 1e-13
"""Motion with a flywheel: the refinement on the extremes of ω stops when the energy constant moves
less than this share of itself."""

IVP_RTOL = 1e-10
"""Motion from the differential equation (``dynamics.motion.integrate_ivp``): the ODE solver's relative
tolerance."""

INV_INVERSE_TOL = 1e-15
"""Inverse involute function (``gears.involute.inv_inverse``): relative Newton step that stops it."""

SHIFT_FD_STEP = 1e-4
"""Shift coefficients on the equal-sliding line (``gears.shifts``): the finite-difference step in x2
that gives the secant its slope."""

SHIFT_SECANT_TOL = 1e-13
"""``gears.shifts``: a secant step in x2 below this ends the projection onto λ1 = λ2."""

SHIFT_BISECT_TOL = 1e-12
"""``gears.shifts``: the bisection along a contour stops when its bracket is this short in (x1, x2)."""

TOOTH_SIMPLIFY_REL = 2e-4
"""The meshing picture's tooth polylines are simplified to this share of the module m (a deviation far
below a line's width at any scale the sheet uses)."""
