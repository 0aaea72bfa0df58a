"""ГОСТ 2.302-68 drawing scales: the one list every scheme, gear picture and planetary drawing picks from.

ГОСТ 2.302-68 «Масштабы» (with amendments 1–3), item 2:

- reductions 1:2; 1:2,5; 1:4; 1:5; 1:10; 1:15; 1:20; 1:25; 1:40; 1:50; 1:75; 1:100; 1:200; 1:400;
  1:500; 1:800; 1:1000, and for the general plans of large objects 1:2000; 1:5000; 1:10000;
  1:20000; 1:25000; 1:50000;
- natural size 1:1;
- enlargements 2:1; 2,5:1; 4:1; 5:1; 10:1; 20:1; 40:1; 50:1; 100:1, and, where needed, (100·n):1
  with n an integer.

A scale is ``(paper, real)``: 1:2,5 is ``(1, 2.5)``; its factor (drawing length per real length) is
``paper / real``. With the (100·n):1 series every length the task loader accepts (up to
``taskfile.MAX_LENGTH`` = 1000 m, down to ``taskfile.MIN_LENGTH``) has a scale that draws it
within a sheet.
"""
from __future__ import annotations

import math
from typing import NamedTuple

from .errors import ParameterError
from .tolerances import RTOL_ROUNDOFF


class Scale(NamedTuple):
    """A scale as ``paper:real`` (1:2,5 is ``Scale(1, 2.5)``); a plain ``(paper, real)`` tuple compares equal.

    :meth:`text` is the one home of a scale's ratio as printed, in a given decimal mark: the note
    and the sheets call it with their language's mark («1:2,5» in ru/uk, «1:2.5» in en)."""
    paper: float
    real: float

    def text(self, decimal: str = ",") -> str:
        """«1:2,5», «2,5:1», «200:1» with ``decimal`` as the decimal mark (:func:`label`)."""
        return label(self, decimal)

    @classmethod
    def of_factor(cls, k: float) -> "Scale":
        """The scale of factor ``k`` (drawing length per real length): ``k:1`` for k ≥ 1, else
        ``1:(1/k)`` (1/k to 6 decimals, so 0.4 gives 1:2,5)."""
        if not (k > 0 and math.isfinite(k)):
            raise ParameterError("k", k, "a finite drawing factor > 0")
        return cls(float(k), 1.0) if k >= 1 else cls(1.0, round(1.0 / k, 6))

    @classmethod
    def parse(cls, text: str) -> "Scale":
        """A ratio as the core writes it, «1:2,5» or «2.5:1» (either decimal mark), back to a Scale."""
        paper, sep, real = str(text).strip().partition(":")
        try:
            out = cls(float(paper.replace(",", ".")), float(real.replace(",", ".")))
        except ValueError:
            out = None
        if not sep or out is None or not (out.paper > 0 and out.real > 0):
            raise ParameterError("scale", text, "a ratio «paper:real» such as 1:2,5 or 2.5:1")
        return out


ENLARGEMENTS: tuple[tuple[float, float], ...] = ((100, 1), (50, 1), (40, 1), (20, 1), (10, 1), (5, 1), (4, 1), (2.5, 1), (2, 1))
NATURAL: tuple[float, float] = (1, 1)
REDUCTIONS: tuple[tuple[float, float], ...] = (
    (1, 2), (1, 2.5), (1, 4), (1, 5), (1, 10), (1, 15), (1, 20), (1, 25), (1, 40), (1, 50), (1, 75),
    (1, 100), (1, 200), (1, 400), (1, 500), (1, 800), (1, 1000),
    (1, 2000), (1, 5000), (1, 10000), (1, 20000), (1, 25000), (1, 50000))
#: Every listed scale, the largest first.
GOST_2_302: tuple[tuple[float, float], ...] = ENLARGEMENTS + (NATURAL,) + REDUCTIONS


def factor(scale: tuple[float, float]) -> float:
    """Drawing length per real length."""
    return scale[0] / scale[1]


def label(scale: tuple[float, float], decimal: str = ",") -> str:
    """«1:2,5», «200:1» (the decimal comma of ГОСТ; ``decimal="."`` for results.json)."""
    def num(x: float) -> str:
        return (f"{x:g}" if x != int(x) else str(int(x))).replace(".", decimal)
    return f"{num(scale[0])}:{num(scale[1])}"


def scales(largest: float = math.inf, smallest: float = 0.0) -> tuple[tuple[float, float], ...]:
    """The listed scales with ``smallest ≤ factor ≤ largest``, the largest first."""
    return tuple(s for s in GOST_2_302 if smallest * (1 - RTOL_ROUNDOFF) <= factor(s) <= largest * (1 + RTOL_ROUNDOFF))


def largest_fitting(needed: float) -> tuple[float, float]:
    """The largest ГОСТ scale whose factor is at most ``needed`` (e.g. window / extent).

    Beyond 100:1, the (100·n):1 series: n = ⌊needed/100⌋. Below the smallest reduction 1:50000 the
    smallest is returned (the loader's limits keep a mechanism above it).
    """
    if not needed > 0 or math.isinf(needed):
        return GOST_2_302[0] if math.isinf(needed) else GOST_2_302[-1]
    if needed >= 200:
        return Scale(100 * math.floor(needed / 100 * (1 + RTOL_ROUNDOFF)), 1)
    for s in GOST_2_302:
        if factor(s) <= needed * (1 + RTOL_ROUNDOFF):
            return s
    return GOST_2_302[-1]


def fitting(needed: float) -> tuple[tuple[float, float], ...]:
    """The scales to try for a view, largest first: :func:`largest_fitting` and every smaller one."""
    top = largest_fitting(needed)
    return ((top,) if top not in GOST_2_302 else ()) + scales(largest=factor(top))
