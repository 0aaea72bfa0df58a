"""Building blocks of the crane calculations: a collector of calculation records and the checks.

Every number of the crane note is a :class:`reportgen.calc.CalcRecord` (formula = numbers = result)
made once here; the note, ``reportgen crane`` and results.json all read the same records. A
variable or record is named by a key that means one quantity everywhere (``S_max``, ``D_c``); the
note's «где» list finds its words by that key in the strings catalogue (``crane.where.<key>``), so the
core carries no sentences. ``meaning`` of each Var/record is that key.
"""
from __future__ import annotations

import ast
import math
import re
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Mapping

from ..calc import CalcRecord, Var, format_decimal, record
from ..errors import ParameterError
from ..tolerances import RTOL_EQUAL, TINY


@dataclass(frozen=True)
class Check:
    """One check: ``value relation limit`` (relation "≥" or "≤"), passed or not.

    ``records`` are the keys of the records that show its numbers; a failed check carries
    ``advice`` (a key of ``crane.advice``) and ``advice_value`` (the least/greatest value the next
    catalogue item must have, in ``advice_unit``).
    """
    key: str
    value: float
    limit: float
    relation: str
    unit: str
    passed: bool
    records: tuple[str, ...] = ()
    advice: str = ""
    advice_value: float | None = None
    advice_unit: str = ""


def check(key: str, value: float, relation: str, limit: float, unit: str = "", *,
          records: tuple[str, ...] = (), advice: str = "", advice_value: float | None = None,
          advice_unit: str = "") -> Check:
    """A check of ``value relation limit`` with a small relative tolerance for rounding (1e-9)."""
    tol = RTOL_EQUAL * max(abs(value), abs(limit), TINY)
    if relation == "≥":
        ok = value >= limit - tol
    elif relation == "≤":
        ok = value <= limit + tol
    else:
        raise ParameterError("relation", relation, "≥ or ≤")
    return Check(key, value, limit, relation, unit, ok, records, advice if not ok else "",
                 advice_value if not ok else None, advice_unit if not ok else "")


_CYRILLIC_RUN = re.compile(r"(\\text\{[^}]*\})|([А-Яа-яЁё]+(?:\.[А-Яа-яЁё]+)*\.?)")


def upright_cyrillic(latex: str) -> str:
    """Cyrillic letters in a math formula set upright in ``\\text{}`` (the math font has none):
    ``m_{гр}`` → ``m_{\\text{гр}}``; an existing ``\\text{…}`` is kept."""
    return _CYRILLIC_RUN.sub(lambda mt: mt.group(1) or "\\text{" + mt.group(2) + "}", latex)


def upright_cyrillic_in_math(tex: str) -> str:
    """:func:`upright_cyrillic` applied to every ``$…$`` piece of a text (words outside math stay)."""
    parts = tex.split("$")
    return "$".join(upright_cyrillic(p) if i % 2 else p for i, p in enumerate(parts))


def decimals_digits(value: float, decimals: int) -> int:
    """Significant digits that show ``value`` with ``decimals`` places (its integer part kept)."""
    if value == 0 or not math.isfinite(value):
        return decimals + 1
    return max(1, math.floor(math.log10(abs(value))) + 1) + decimals


def plain_number(value: float, digits: int = 4, mark: str = ",") -> str:
    """The number as the note prints it (same rounding, :func:`reportgen.calc.format_decimal`) in
    plain text for the terminal and the sheets: ``1130,5``, ``2 061 922``, ``0,9657``; ``mark`` is
    the decimal mark of the sheet's language (``.`` in English)."""
    text = format_decimal(value, digits)
    text = text.replace("{,}", mark).replace("\\,", " ").replace(" \\cdot 10^", "·10^")
    return text.replace("{", "").replace("}", "").replace("-", "−")


def shown(rec: CalcRecord, mark: str = ",") -> str:
    """A record's result exactly as the note prints it, in plain text (``mark``: the decimal mark)."""
    return plain_number(rec.value, rec.digits, mark)


def _expr_names(expr: str) -> list[str]:
    out: list[str] = []
    for node in ast.walk(ast.parse(expr, mode="eval")):
        if isinstance(node, ast.Name) and node.id not in out:
            out.append(node.id)
    return out


_FUNCS = {"sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "hypot", "abs", "radians",
          "degrees", "pi"}


class Steps:
    """Collects the inputs (``var``) and records (``rec``) of one mechanism in order."""

    def __init__(self) -> None:
        self.vars: dict[str, Var] = {}
        self.recs: dict[str, CalcRecord] = {}
        self.checks: list[Check] = []

    def var(self, key: str, latex: str, value: float, unit: str = "") -> Var:
        v = Var(key, upright_cyrillic(latex), float(value), unit, key)
        self.vars[key] = v
        return v

    def rec(self, key: str, symbol: str, expr: str, unit: str = "", digits: int = 4,
            decimals: int | None = None) -> CalcRecord:
        """A record of ``expr``; ``decimals`` (default: 1 for a length in mm) fixes the places shown
        instead of ``digits`` significant digits."""
        symbol = upright_cyrillic(symbol)
        if decimals is None and unit == "мм":
            decimals = 1
        named: dict[str, Any] = {}
        for n in _expr_names(expr):
            if n in _FUNCS:
                continue
            named[n] = self.recs[n] if n in self.recs else self.vars[n]
        r = record(symbol, expr, unit, digits=digits, meaning=key, **named)
        if decimals is not None:
            r = record(symbol, expr, unit, digits=max(digits, decimals_digits(r.value, decimals)),
                       meaning=key, **named)
        self.recs[key] = r
        return r

    def value(self, key: str) -> float:
        return self.recs[key].value if key in self.recs else self.vars[key].value

    def add(self, c: Check) -> Check:
        self.checks.append(c)
        return c

    def frozen(self) -> tuple[Mapping[str, Var], Mapping[str, CalcRecord], tuple[Check, ...]]:
        return MappingProxyType(dict(self.vars)), MappingProxyType(dict(self.recs)), tuple(self.checks)

