"""The scale of the meshing picture (картина зацепления) of sheet 4, decided once for the window the
sheet gives it; the note quotes the same scale and the length of ab read on the sheet."""
from __future__ import annotations

from dataclasses import dataclass

from ..gears.meshing import GOST_SCALES, MeshingPicture, meshing_picture

#: The view of the meshing picture on the left of sheet 4, sheet mm: the whole height of the
#: sheet; the picture (teeth, circles' arcs and both centres) fits inside it less the padding, the
#: caption's strip and a margin on each side for the designations' leaders and the dimension aw.
VIEW_W = 390.0
VIEW_H = 560.0
PADDING = 10.0
CAPTION = 8.0
LABEL_MARGIN = 35.0
WINDOW_W = VIEW_W - 2 * PADDING - 2 * LABEL_MARGIN
WINDOW_H = VIEW_H - 2 * PADDING - CAPTION


@dataclass(frozen=True)
class DrawingScale:
    """A ГОСТ 2.302 scale: ``factor`` sheet mm per real mm and its caption text."""
    factor: float

    @property
    def label(self) -> str:
        """«2:1», «2,5:1», «1:2» (decimal comma)."""
        if self.factor >= 1:
            return f"{self.factor:g}:1".replace(".", ",")
        return f"1:{1 / self.factor:g}".replace(".", ",")


def model_bounds(pair, pic: MeshingPicture) -> tuple[float, float, float, float]:
    """What the picture shows, real mm: the drawn teeth, N1, N2 and both centres O1, O2."""
    x0, y0, x1, y1 = pic.view
    return (min(x0, 0.0), min(y0, 0.0), max(x1, 0.0), max(y1, pair.geometry.aw))


def meshing_scale(pair, pic: MeshingPicture | None = None,
                  window: tuple[float, float] = (WINDOW_W, WINDOW_H)) -> DrawingScale:
    """The largest ГОСТ 2.302 scale at which the whole picture (centres included) fits ``window``."""
    pic = pic if pic is not None else meshing_picture(pair)
    x0, y0, x1, y1 = model_bounds(pair, pic)
    for k in GOST_SCALES:
        if (x1 - x0) * k <= window[0] and (y1 - y0) * k <= window[1]:
            return DrawingScale(k)
    return DrawingScale(GOST_SCALES[-1])


def model_centre(pair, pic: MeshingPicture) -> tuple[float, float]:
    """The real point drawn at the centre of the view's window."""
    x0, y0, x1, y1 = model_bounds(pair, pic)
    return ((x0 + x1) / 2, (y0 + y1) / 2)


def label_room(pair, pic: MeshingPicture, scale: DrawingScale) -> tuple[float, float, float, float]:
    """The room (real mm) the designations may take: the view less its padding and caption."""
    cx, cy = model_centre(pair, pic)
    k = scale.factor
    hw = (VIEW_W - 2 * PADDING) / 2 / k
    hh = (VIEW_H - 2 * PADDING - CAPTION) / 2 / k
    return (cx - hw, cy - hh, cx + hw, cy + hh)


def meshing_marks(pair, pic: MeshingPicture, scale: DrawingScale | None = None):
    """The designations of the picture at the sheet's scale (the note draws the same ones)."""
    from .meshing_marks import place_marks
    scale = scale if scale is not None else meshing_scale(pair, pic)
    return place_marks(pair, pic, scale.factor, label_room(pair, pic, scale))


def ab_on_sheet(pic: MeshingPicture, scale: DrawingScale) -> float:
    """|ab| as read on the sheet, to 0,1 mm."""
    return round(pic.ab_drawn * scale.factor, 1)
