"""Named tolerances: one place for the small numbers that decide "equal", "round-off" or "keep a
ratio finite" (issue 13 item 3). Solver-specific stopping rules keep their own names beside the
solver (``kinematics.positions.NEWTON_REL_TOL``, ``kinematics.extremes.ROOT_XTOL``,
``dynamics.energy.EXTREME_XTOL``) because they are properties of that method, not of the data.
"""
from __future__ import annotations

__all__ = ["RTOL_EQUAL", "RTOL_ROUNDOFF", "RTOL_RANK", "TINY", "MM_EPS", "LABEL_NEAR_MM"]

#: Relative: two quantities equal by construction count as equal (three collinear points of a
#: link, a check exactly on its limit, a tie between candidates, a ratio on the edge of its band).
RTOL_EQUAL = 1e-9
#: Relative: a difference this small is round-off of float arithmetic (a scale that already fits,
#: a value that reaches its target).
RTOL_ROUNDOFF = 1e-12
#: Relative, per row of a matrix: a singular value below σ_max · (rows or columns) · RTOL_RANK
#: counts as zero in a numerical rank (Chebyshev's W checked on the constraint Jacobian).
RTOL_RANK = 1e-10
#: A floor that keeps a ratio finite where its denominator can be an exact 0 (not a tolerance).
TINY = 1e-300
#: Absolute, in sheet millimetres: two coordinates of a drawing this close are the same point.
MM_EPS = 1e-6
#: Absolute, in mm of paper (a sheet, or a note figure at its own size): the largest gap between a
#: label's box and what it names (its point, its vector or link). 1.6 letter heights of a sheet's
#: 5 mm lettering: a placer that tries the rings round a point at 1.5 and 6.5 mm (Canvas.label)
#: stays within it; a label farther than this reads as the name of whatever is nearer
#: (tests/labels checks every sheet and note figure of every example against it).
LABEL_NEAR_MM = 8.0
