"""Number formatting for the note's text (Jinja filters); pure Python, no Jinja import.

Math-mode numbers come from :func:`reportgen.calc.format_decimal` (``-1\\,234{,}5``); the text
forms here use the same rounding, a decimal comma, a thin space between thousand groups
(``15\\,800``; four-digit numbers are not grouped, as in Russian typesetting), a real minus sign
U+2212 (``−``) and ``·10`` with a superscript for very small magnitudes.
"""
from __future__ import annotations

import math
import re

from reportgen.calc import format_decimal

TEXT_MINUS = "\u2212"
_POWER_RE = re.compile(r" \\cdot 10\^\{(-?\d+)\}$")


def _to_text(math_form: str) -> str:
    """Turn the math-mode number into text mode: U+2212 minus, ·10 with a superscript exponent."""
    text = math_form
    m = _POWER_RE.search(text)
    if m:
        exponent = m.group(1).replace("-", TEXT_MINUS)
        text = text[: m.start()] + "\\,\u00b7\\,10\\textsuperscript{" + exponent + "}"
    if text.startswith("-"):
        text = TEXT_MINUS + text[1:]
    return text


def num(value: float, digits: int = 4) -> str:
    """``value`` with ``digits`` significant digits (integer part never rounded), text mode."""
    if isinstance(value, int) and not isinstance(value, bool):
        return _to_text(format_decimal(float(value), max(digits, len(str(abs(value))))))
    return _to_text(format_decimal(float(value), digits))


def fixed(value: float, decimals: int = 2) -> str:
    """``value`` with exactly ``decimals`` places (zeros kept): ``fixed(2.5, 3)`` → ``2{,}500``."""
    return _to_text(format_decimal(float(value), decimals=decimals))


def deg(value: float, decimals: int | None = 1, *, from_radians: bool = False) -> str:
    """An angle in degrees with the degree sign: ``deg(30)`` → ``30{,}0°``.

    ``decimals=None`` shows 4 significant digits instead. ``from_radians`` converts first.
    """
    if from_radians:
        value = math.degrees(value)
    body = format_decimal(float(value), decimals=decimals) if decimals is not None \
        else format_decimal(float(value), 4)
    return _to_text(body) + "\u00b0"


def angle(value_rad: float, decimals: int | None = 1) -> str:
    """An angle given in radians, printed in degrees (``angle(pi/2)`` → ``90{,}0°``)."""
    return deg(value_rad, decimals, from_radians=True)


def mnum(value: float, digits: int = 4) -> str:
    """The math-mode form, for use inside ``$…$`` or an equation."""
    return format_decimal(float(value), digits)


def mfixed(value: float, decimals: int = 2) -> str:
    """Math-mode form with fixed decimals."""
    return format_decimal(float(value), decimals=decimals)
