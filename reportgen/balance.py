"""Balance equations shown in the note: one object prints the equation and solves it.

A balance equation of the course (a sum of moments about a point, a lever about its pole) is

    ΣM = s_u·U·l + Σ s_i·F_i·h_i + Σ s_j·M_j/μ = 0,

with the unknown ``U`` (its sense fixed by the sign ``s_u`` of its term: ``U > 0`` acts in the sense
that gives ``s_u·U·l`` the sign of a counter-clockwise moment), its arm ``l`` and the known terms.
:class:`Balance` holds that expression once; the printed equation (:meth:`Balance.equation_latex`) and
the solution records (:meth:`Balance.solve`: partial sums, then ``U = −(Σ)/(s_u·l)``) are both made
from it, so an equation can no longer show the opposite sign of its result.

:func:`check_balance` puts the printed result back into the printed equation, with every other
quantity as the substitutions print it, and tells whether the sum is zero within the rounding of the
printed numbers; the note builder runs it on every balance it prints.

Pure: no presentation import (the LaTeX strings are plain text).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Callable

from .errors import ParameterError
from .calc import (
    CalcRecord, DisplayCheck, Var, _evaluate, _parse, _SymbolicLeaves, _to_latex, _tolerance,
    parse_decimal, record,
)
from .tolerances import ABS_ROUNDOFF, RTOL_EQUAL

__all__ = ["BalanceTerm", "Balance", "BalanceSolution", "check_balance", "balance_is_consistent", "UNKNOWN"]

#: The name of the unknown inside a balance expression.
UNKNOWN = "U"


@dataclass(frozen=True)
class BalanceTerm:
    """A known term ``sign·value·arm`` (``arm`` given) or ``sign·value/divisor`` (a couple at μ)."""
    sign: int
    value: Var
    arm: Var | None = None
    divisor: Var | None = None

    def __post_init__(self) -> None:
        if self.sign not in (1, -1):
            raise ParameterError("sign", self.sign, "+1 or -1")
        if (self.arm is None) == (self.divisor is None):
            raise ParameterError("arm/divisor", (self.arm, self.divisor), "exactly one of arm= or divisor=")


@dataclass(frozen=True)
class Balance:
    """``lhs = s_u·U·arm + Σ terms = 0`` (see the module docstring).

    ``symbol``/``unit``/``meaning`` describe the unknown (its record); ``partial`` is the symbol of
    the partial sums (``\\Sigma^{(3)}``) used when there are more than ``per_line`` terms.
    """
    lhs: str
    symbol: str
    unit: str
    unknown_sign: int
    arm: Var
    terms: tuple[BalanceTerm, ...]
    meaning: str = ""
    partial: str = "\\Sigma"
    partial_unit: str = ""
    #: a partial sum's meaning, or a function of the loads it sums (each term's force or power, in
    #: order) giving it: five partial sums explained alike read as one line printed five times
    partial_meaning: str | Callable[[tuple[Var, ...]], str] = ""
    per_line: int = 3
    #: the meaning of the total of the partial sums (``partial`` alone): not a partial sum itself
    total_meaning: str = ""

    def __post_init__(self) -> None:
        if self.unknown_sign not in (1, -1):
            raise ParameterError("unknown_sign", self.unknown_sign, "+1 or -1")

    # ---- one expression for the equation and the check -----------------------------------------
    def _items(self) -> list[tuple[str, dict[str, Var]]]:
        """Each known term as (signed expression piece, its variables under unique names)."""
        out = []
        for n, t in enumerate(self.terms):
            sign = "- " if t.sign < 0 else "+ "
            if t.arm is not None:
                out.append((f"{sign}F{n} * h{n}", {f"F{n}": t.value, f"h{n}": t.arm}))
            else:
                assert t.divisor is not None
                out.append((f"{sign}X{n} / d{n}", {f"X{n}": t.value, f"d{n}": t.divisor}))
        return out

    def expression(self) -> str:
        """The left side as a Python expression over ``U``, ``l`` and the terms' names."""
        head = f"{'-' if self.unknown_sign < 0 else ''}{UNKNOWN} * l"
        return " ".join([head] + [e for e, _ in self._items()])

    def variables(self, unknown_value: float = 0.0) -> dict[str, Var]:
        named: dict[str, Var] = {UNKNOWN: Var(UNKNOWN, self.symbol, unknown_value, self.unit),
                                 "l": self.arm}
        for _, d in self._items():
            named.update(d)
        return named

    def equation_latex(self) -> str:
        """``\\sum M_{O} = F_{ур} \\cdot OA - G_{1} \\cdot h_{7} = 0`` (symbols only)."""
        body = _to_latex(_parse(self.expression()), _SymbolicLeaves(self.variables()))
        return f"{self.lhs} = {body} = 0"

    # ---- the solution ----------------------------------------------------------------------------
    def solve(self) -> "BalanceSolution":
        """Partial sums of ``per_line`` terms (when longer; their total too when there are more than
        ``per_line`` of them), then ``U = −(Σ)/(s_u·l)``."""
        items: list[tuple[str, dict[str, Var | CalcRecord]]] = [(e, dict(d)) for e, d in self._items()]
        parts: list[CalcRecord] = []
        final_items = items
        if len(items) > self.per_line:
            final_items = []
            for c in range(0, len(items), self.per_line):
                chunk = items[c:c + self.per_line]
                expr = " ".join(e for e, _ in chunk).removeprefix("+ ").strip()
                named: dict[str, Var | CalcRecord] = {k: v for _, d in chunk for k, v in d.items()}
                n = c // self.per_line
                loads = tuple(v for _, d in chunk for k, v in d.items() if k[0] in "FX" and isinstance(v, Var))
                meaning = self.partial_meaning(loads) if callable(self.partial_meaning) else self.partial_meaning
                rec = record(f"{self.partial}_{{{n + 1}}}", expr, self.partial_unit, *_vars(named),
                             meaning=meaning)
                parts.append(rec)
                final_items.append((f"+ S{n}", {f"S{n}": rec}))
        if len(final_items) > self.per_line:
            # many partial sums: their total first (a sum wraps over lines; a long fraction cannot)
            expr = " ".join(e for e, _ in final_items).removeprefix("+ ").strip()
            named = {k: v for _, d in final_items for k, v in d.items()}
            total = record(self.partial, expr, self.partial_unit, *_vars(named),
                           meaning=self.total_meaning or (self.partial_meaning if isinstance(self.partial_meaning, str) else ""))
            parts.append(total)
            final_items = [("+ T", {"T": total})]
        expr = " ".join(e for e, _ in final_items).removeprefix("+ ").strip()
        named = {k: v for _, d in final_items for k, v in d.items()}
        if not expr:
            full, named = "0 * l", {}
        elif self.unknown_sign > 0:
            full = f"-({expr}) / l"
        else:
            full = f"({expr}) / l"
        result = record(self.symbol, full, self.unit, *_vars({**named, "l": self.arm}), meaning=self.meaning)
        return BalanceSolution(self, tuple(parts), result)


def _vars(named: dict[str, Var | CalcRecord]) -> list[Var]:
    """Inputs of a record under the names its expression uses (a record's result as its symbol)."""
    return [v.as_var(k) if isinstance(v, CalcRecord) else replace(v, name=k) for k, v in named.items()]


@dataclass(frozen=True)
class BalanceSolution:
    """A balance with the records that solve it (printed right after the equation)."""
    balance: Balance
    parts: tuple[CalcRecord, ...]
    result: CalcRecord

    @property
    def value(self) -> float:
        return self.result.value

    def equation_latex(self) -> str:
        return self.balance.equation_latex()


def check_balance(sol: BalanceSolution) -> DisplayCheck:
    """The printed equation with the printed result and printed inputs put back in.

    Every quantity takes the value its substitution prints (a term's force and arm from the partial
    sum or final record that shows them); the unknown takes its printed result. ``recomputed`` is
    the left side, ``displayed`` is 0, and the tolerance is the rounding of the printed result times
    its arm plus the rounding of each printed partial sum (the only places where a printed number
    differs from the one the next line uses).
    """
    b = sol.balance
    printed: dict[str, float] = {}
    for rec in (*sol.parts, sol.result):
        for name, text in rec.displayed_inputs().items():
            printed.setdefault(name, parse_decimal(text))
    u = parse_decimal(sol.result.result_number_latex())
    values = {name: printed.get(name, var.value) for name, var in b.variables().items()}
    values[UNKNOWN] = u
    residual = _evaluate(_parse(b.expression()), values)
    arm = abs(values["l"])
    tol = _tolerance(sol.result.value, sol.result.digits) * arm
    tol += sum(_tolerance(p.value, p.digits) for p in sol.parts)
    scale = abs(u) * arm + sum(abs(p.value) for p in sol.parts)
    tol += RTOL_EQUAL * scale + ABS_ROUNDOFF
    return DisplayCheck(residual, 0.0, tol)


def balance_is_consistent(sol: BalanceSolution) -> bool:
    """Shorthand for ``check_balance(sol).ok``."""
    return check_balance(sol).ok

