"""The one number formatter of the work: note, sheets, figures and tables round the same way.

Rounding is done on the number as written (``repr``, the shortest decimal that reads back as the
float), never on the binary float underneath (``f"{2.675:.2f}"`` gives 2.67 because 2.675 is stored
as 2.67499999…); a trailing 5 with nothing after it rounds to the even digit, as СТ СЭВ 543-77
«Числа. Правила записи и округления» prescribes (2,675 → 2,68; 0,125 → 0,12).

Forms built on :func:`decimal_text` (a plain ``-1234.5`` string):

* :func:`plain` — sheets, figures, tick labels: decimal comma, ``-`` minus, no grouping
  (``plain(2.675, 2) == "2,68"``; ``plain(0.0200, 2) == "0,02"``);
* :func:`significant` — ``digits`` significant digits, the integer part never rounded away;
* ``reportgen.calc.format_decimal`` — the LaTeX form of the note (``{,}``, thin-space groups).

Round-off residue. A quantity computed as a difference of equal parts (the acceleration of a centre
of mass that does not move, the discrepancy of two methods that express one equation) comes out as
~1e-16 of its scale. :func:`is_residue` tells such a value from a real one by comparing it with the
scale of the problem (:data:`RESIDUE_REL`); :func:`clean` returns an exact 0 for it, so that the
note prints 0 and says so instead of printing 3,068·10⁻¹⁶ as physics.

Pure: no presentation import.
"""
from __future__ import annotations

import math
from decimal import ROUND_HALF_EVEN, Decimal

from .errors import ParameterError
from .tolerances import RTOL_EQUAL

__all__ = ["RESIDUE_REL", "ANGLE_DECIMALS", "decimal_text", "significant_decimals", "plain", "significant",
           "is_residue", "clean", "clean_array"]

#: A value below this fraction of its problem's scale is round-off residue (double precision leaves
#: ~1e-16; every measured quantity of the course is above 1e-6 of its scale).
RESIDUE_REL = RTOL_EQUAL
#: Angles are printed to 0,01° (the course reads angles off a drawing to a tenth of a degree; the
#: extra digit keeps the computed value recognisable).
ANGLE_DECIMALS = 2


def decimal_text(value: float, decimals: int) -> str:
    """``value`` rounded (see the module docstring) to ``decimals`` places, plain ``'.'`` form, trailing zeros kept.

    ``-0`` becomes ``0``: ``decimal_text(-0.001, 2) == "0.00"``.
    """
    if not math.isfinite(value):
        raise ParameterError("value", value, "a finite number to print")
    d = Decimal(repr(float(value))).quantize(Decimal(1).scaleb(-decimals), rounding=ROUND_HALF_EVEN)
    text = format(d, "f")
    if text.startswith("-") and d == 0:
        text = text[1:]
    return text


def significant_decimals(value: float, digits: int) -> int:
    """Decimals that keep ``digits`` significant digits but never round the integer part away."""
    if value == 0 or not math.isfinite(value):
        return max(digits - 1, 0)
    exponent = math.floor(math.log10(abs(value)))
    return max(digits - 1 - exponent, 0)


def _strip(text: str) -> str:
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "", "-") else text


def plain(value: float, decimals: int = 2, *, strip: bool = True, mark: str = ",") -> str:
    """``value`` to ``decimals`` places with the decimal ``mark`` (comma by default; the presentation
    passes its language's) and zeros dropped when ``strip``."""
    text = decimal_text(value, decimals)
    return (_strip(text) if strip else text).replace(".", mark)


def significant(value: float, digits: int = 3, *, mark: str = ",") -> str:
    """``value`` to ``digits`` significant digits, decimal ``mark``: ``0,00123``, ``24,54``, ``1230``."""
    if value == 0 or not math.isfinite(value):
        return plain(value, 0, mark=mark)
    places = significant_decimals(value, digits)
    text = decimal_text(value, places)
    # rounding may add a digit (9,996 → 10,00): keep `digits` significant digits of the result
    places2 = significant_decimals(float(text), digits)
    if places2 < places:
        text = decimal_text(float(text), places2)
    return _strip(text).replace(".", mark)


def is_residue(value: float, scale: float, rel: float = RESIDUE_REL) -> bool:
    """True when ``value`` is round-off residue against the problem's ``scale`` (same unit)."""
    return value != 0.0 and abs(value) <= rel * abs(scale)


def clean(value: float, scale: float, rel: float = RESIDUE_REL) -> float:
    """``value``, or an exact 0.0 when it is round-off residue against ``scale``."""
    return 0.0 if is_residue(value, scale, rel) else value


def clean_array(values, scale, rel: float = RESIDUE_REL):
    """:func:`clean` element-wise on a NumPy array (``scale`` broadcast against it); a new array."""
    import numpy as np
    v = np.asarray(values, dtype=float)
    return np.where(np.abs(v) <= rel * np.abs(np.asarray(scale, dtype=float)), 0.0, v)
