"""The room each construction is given on paper, mm (width, height). The scenes choose their scales
from these boxes; the solvers never hold them (they take scales, or a box, as arguments). The
defaults are the views of the A1 sheets; a caller that draws elsewhere passes its own boxes, and
the note draws the same scenes (reduced where the text block is smaller, and says so)."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SceneBoxes:
    #: Sheet 1: the drawing of the mechanism (the scheme view less its label and caption margins).
    scheme: tuple[float, float] = (470.0 - 28.0 - 28.0, 400.0 - 36.0 - 38.0)


DEFAULT = SceneBoxes()
