"""Calculation records: one record per formula shown in the note.

A record is made once from a Python arithmetic expression over named variables. It holds the value
(used by the program) and produces the three LaTeX forms the note prints, all from the same
expression tree, so a formula is never typed twice::

    >>> r = record(r"V_A", "omega1 * l_OA", "м/с",
    ...            Var("omega1", r"\\omega_1", 18.0, "рад/с"), Var("l_OA", r"l_{OA}", 0.11, "м"))
    >>> round(r.value, 12)
    1.98
    >>> r.symbolic_latex()
    '\\\\omega_1 \\\\cdot l_{OA}'
    >>> r.substituted_latex()
    '18 \\\\cdot 0{,}11'
    >>> r.result_latex()
    '1{,}98~\\\\text{м/с}'

Displayed digits. The result is rounded to ``digits`` significant digits (never rounding the
integer part away: 15834.3 shows as 15834). Every input is first shown with the same number of
significant digits; if the expression re-evaluated from the inputs *as displayed* does not round to
the displayed result (a difference of nearly equal numbers, a steep function), the inputs get one
more digit, and so on up to 15. Trailing zeros are dropped (0.11 stays 0,11). So the printed
substitution always reproduces the printed result; :func:`evaluate_displayed` checks that from the
printed strings themselves.

This module is pure: no Jinja, no LaTeX build; it only writes LaTeX source strings.
"""
from __future__ import annotations

import ast
import math
import re
from dataclasses import dataclass, field, replace
from decimal import Decimal
from typing import Callable, Mapping

from .errors import InternalError, ParameterError
from .numbers import decimal_text, significant_decimals
from .tolerances import RTOL_EQUAL

__all__ = [
    "Var", "CalcRecord", "DisplayCheck", "CalcExpressionError", "record", "evaluate_displayed",
    "format_decimal", "parse_decimal", "round_significant_decimals", "latex_symbol_for",
]

MAX_DIGITS = 15
SMALL_NUMBER = 1e-3   # below this magnitude a number is shown as m·10^k


class CalcExpressionError(InternalError, ValueError):
    """An expression uses something a calculation record does not allow, or names no variable."""


# --------------------------------------------------------------------------- number formatting
def round_significant_decimals(value: float, digits: int) -> int:
    """Number of decimals that keeps ``digits`` significant digits but never rounds an integer part.

    May be negative only if ``digits`` < 1; for ``|value| >= 10**digits`` it is 0.
    (The one rule of the work: :func:`reportgen.numbers.significant_decimals`.)
    """
    return significant_decimals(value, digits)


def _decimal_text(value: float, decimals: int) -> str:
    """``value`` rounded (:func:`reportgen.numbers.decimal_text`: on the written number, a bare 5 to even) to
    ``decimals`` places, trailing zeros dropped, plain '.' form."""
    text = decimal_text(value, decimals)
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    if text in ("-0", ""):
        text = "0"
    return text


def _group_thousands(integer_part: str, sep: str) -> str:
    if len(integer_part) <= 4:        # Russian typography: 1500, but 15 800
        return integer_part
    groups = []
    while integer_part:
        groups.append(integer_part[-3:])
        integer_part = integer_part[:-3]
    return sep.join(reversed(groups))


def format_decimal(value: float, digits: int = 4, *, decimals: int | None = None,
                   group: bool = True, minus: str = "-", trailing_zeros: bool = False) -> str:
    """LaTeX (math-mode safe) text of a number: decimal comma ``{,}``, thin-space groups ``\\,``.

    ``digits`` significant digits unless ``decimals`` is given (fixed places, zeros kept).
    Magnitudes below 1e-3 are shown as ``1{,}2 \\cdot 10^{-5}``. ``minus`` is put before a negative
    number (``-`` is a proper minus in math mode; text mode callers pass ``\\textminus{}``).
    ``trailing_zeros`` keeps them (``1{,}980``).
    """
    if not math.isfinite(value):
        raise ParameterError("value", value, "a finite number to print")
    if decimals is None and value != 0 and abs(value) < SMALL_NUMBER:
        exponent = math.floor(math.log10(abs(value)))
        mantissa = value / 10.0 ** exponent
        mant = format_decimal(mantissa, digits, group=False, minus=minus, trailing_zeros=trailing_zeros)
        if mant.lstrip(minus).startswith("10"):          # 9.9996 rounded up to 10
            mantissa /= 10.0
            exponent += 1
            mant = format_decimal(mantissa, digits, group=False, minus=minus,
                                  trailing_zeros=trailing_zeros)
        return f"{mant} \\cdot 10^{{{exponent}}}"
    if decimals is None:
        places = round_significant_decimals(value, digits)
        text = _decimal_text(value, places)
        keep = trailing_zeros
    else:
        places = decimals
        text = _decimal_text(value, places)
        keep = True
    if keep and places > 0:
        d = Decimal(text).quantize(Decimal(1).scaleb(-places))
        text = format(d, "f")
        if decimals is None:
            # keep exactly `digits` significant digits (rounding may have added an integer digit)
            places2 = round_significant_decimals(float(text), digits)
            d = Decimal(text).quantize(Decimal(1).scaleb(-places2)) if places2 > 0 else Decimal(text)
            text = format(d, "f")
    negative = text.startswith("-")
    text = text.lstrip("-")
    integer_part, _, fraction = text.partition(".")
    if group:
        integer_part = _group_thousands(integer_part, "\\,")
    out = integer_part + ("{,}" + fraction if fraction else "")
    if negative and out.strip("0{,}\\") != "":
        out = minus + out
    return out


_NUMBER_RE = re.compile(r"^(?P<sign>-?)(?P<mant>[0-9\\,{}]+)(?: \\cdot 10\^\{(?P<exp>-?\d+)\})?$")


def parse_decimal(text: str) -> float:
    """Inverse of :func:`format_decimal` (math-mode form): ``-1\\,234{,}5`` → -1234.5."""
    m = _NUMBER_RE.match(text.strip())
    if not m:
        raise ParameterError("text", text, "a number as the note prints it, e.g. -1\\,234{,}5")
    mant = m.group("mant").replace("\\,", "").replace("{,}", ".")
    value = float(Decimal(mant))
    if m.group("exp") is not None:
        value = float(Decimal(mant).scaleb(int(m.group("exp"))))
    return -value if m.group("sign") else value


# --------------------------------------------------------------------------- symbols
_GREEK = {
    "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta",
    "iota", "kappa", "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi",
    "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma",
    "Phi", "Psi", "Omega",
}


def latex_symbol_for(name: str) -> str:
    """A LaTeX symbol guessed from a variable name: ``omega1`` → ``\\omega_{1}``, ``l_OA`` → ``l_{OA}``.

    A Greek letter name becomes the letter (``phi`` → ``\\varphi``); the rest after ``_`` or the
    trailing digits becomes the subscript.
    """
    base, sep, sub = name.partition("_")
    if not sep:
        m = re.match(r"^([A-Za-z]+?)(\d+)$", name)
        base, sub = (m.group(1), m.group(2)) if m else (name, "")
    if base in _GREEK:
        base = "\\varphi" if base == "phi" else "\\" + base
    return f"{base}_{{{sub}}}" if sub else base


# --------------------------------------------------------------------------- records
@dataclass(frozen=True)
class Var:
    """A named input of a formula: ``name`` as in the expression, ``latex`` as printed, SI ``value``.

    ``meaning`` is the phrase of the «где» list (``угловая скорость кривошипа``).
    """
    name: str
    latex: str
    value: float
    unit: str = ""
    meaning: str = ""

    def __post_init__(self) -> None:
        if not self.name.isidentifier():
            raise CalcExpressionError(f"variable name {self.name!r} is not an identifier")
        object.__setattr__(self, "value", float(self.value))
        if not math.isfinite(self.value):
            raise CalcExpressionError(f"variable {self.name} is not finite: {self.value!r}")


@dataclass(frozen=True)
class CalcRecord:
    """One displayed formula: ``symbol = expr = substituted numbers = value unit``.

    ``input_digits`` are the significant digits chosen for the inputs so that the displayed
    substitution reproduces the displayed result (see the module docstring).
    """
    symbol: str
    expr: str
    variables: tuple[Var, ...]
    value: float
    unit: str
    label: str = ""
    digits: int = 4
    meaning: str = ""
    input_digits: int = field(default=4, compare=False)

    # ---- forms -------------------------------------------------------------------------------
    def symbolic_latex(self) -> str:
        """The formula in symbols: ``\\omega_1 \\cdot l_{OA}``."""
        return _to_latex(_parse(self.expr), _SymbolicLeaves(self._by_name()))

    def substituted_latex(self) -> str:
        """The formula with the numbers as displayed: ``18 \\cdot 0{,}11``."""
        return _to_latex(_parse(self.expr), _NumberLeaves(self._by_name(), self.input_digits))

    def result_number_latex(self) -> str:
        """The result number alone, e.g. ``1{,}98``."""
        return format_decimal(self.value, self.digits)

    def result_latex(self) -> str:
        """The result with its unit: ``1{,}98~\\text{м/с}``."""
        number = self.result_number_latex()
        return number + (f"~{unit_latex(self.unit)}" if self.unit else "")

    def as_var(self, name: str, meaning: str = "") -> Var:
        """This result as an input of a next record (its full value, printed as ``symbol``)."""
        return Var(name, self.symbol, self.value, self.unit, meaning or self.meaning)

    def displayed_inputs(self) -> dict[str, str]:
        """Each variable's number exactly as the substitution prints it."""
        return {v.name: format_decimal(v.value, self.input_digits) for v in self.variables}

    def _by_name(self) -> dict[str, Var]:
        return {v.name: v for v in self.variables}


def unit_latex(unit: str) -> str:
    """A unit in upright text inside math: ``\\text{м/с²}`` (special characters escaped)."""
    specials = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "%": r"\%", "&": r"\&",
                "#": r"\#", "$": r"\$", "_": r"\_", "^": r"\textasciicircum{}", "~": r"\textasciitilde{}"}
    return "\\text{" + "".join(specials.get(c, c) for c in unit) + "}"


@dataclass(frozen=True)
class DisplayCheck:
    """The printed substitution re-evaluated: ``recomputed`` vs the printed ``displayed`` result."""
    recomputed: float
    displayed: float
    tolerance: float

    @property
    def ok(self) -> bool:
        return abs(self.recomputed - self.displayed) <= self.tolerance


def evaluate_displayed(rec: CalcRecord) -> DisplayCheck:
    """Re-evaluate the expression from the printed (rounded) numbers, parsed back from their LaTeX.

    The tolerance is half a unit of the last place the result was rounded to (plus a few ulps).
    """
    shown = {name: parse_decimal(text) for name, text in rec.displayed_inputs().items()}
    recomputed = _evaluate(_parse(rec.expr), shown)
    displayed = parse_decimal(rec.result_number_latex())
    return DisplayCheck(recomputed, displayed, _tolerance(rec.value, rec.digits))


def _tolerance(value: float, digits: int) -> float:
    if value != 0 and abs(value) < SMALL_NUMBER:
        exponent = math.floor(math.log10(abs(value)))
        half_unit = 0.5 * 10.0 ** (exponent - digits + 1)
    else:
        half_unit = 0.5 * 10.0 ** (-round_significant_decimals(value, digits))
    return half_unit * (1 + RTOL_EQUAL) + 4 * math.ulp(abs(value))


def record(symbol: str, expr: str, unit: str = "", *variables: Var, label: str = "",
           digits: int = 4, meaning: str = "", **named: "Var | CalcRecord | float") -> CalcRecord:
    """Evaluate ``expr`` over the given variables and return its calculation record.

    Variables come as positional :class:`Var` (by their ``name``) or as keywords: a ``Var`` (renamed
    to the keyword), a ``CalcRecord`` (its result, printed as its symbol) or a bare number (its
    symbol guessed by :func:`latex_symbol_for`). Every name of the expression must be given; extra
    variables are an error too (they would appear in no formula).
    """
    if not 1 <= digits <= MAX_DIGITS:
        raise CalcExpressionError(f"digits must be 1..{MAX_DIGITS}, got {digits}")
    by_name: dict[str, Var] = {}
    for v in variables:
        by_name[v.name] = v
    for key, item in named.items():
        if isinstance(item, Var):
            by_name[key] = replace(item, name=key)
        elif isinstance(item, CalcRecord):
            by_name[key] = item.as_var(key)
        else:
            by_name[key] = Var(key, latex_symbol_for(key), float(item))
    tree = _parse(expr)
    used = _names(tree)
    missing = used - by_name.keys()
    if missing:
        raise CalcExpressionError(f"{expr!r}: no value for {', '.join(sorted(missing))}")
    unused = by_name.keys() - used
    if unused:
        raise CalcExpressionError(f"{expr!r}: variables not in the expression: {', '.join(sorted(unused))}")
    ordered = tuple(by_name[n] for n in _names_in_order(tree))
    values = {v.name: v.value for v in ordered}
    try:
        value = _evaluate(tree, values)
    except (ArithmeticError, ValueError) as exc:
        raise CalcExpressionError(f"{expr!r} cannot be evaluated: {exc}") from None
    if not math.isfinite(value):
        raise CalcExpressionError(f"{expr!r} is not finite: {value!r}")
    rec = CalcRecord(symbol, expr, ordered, value, unit, label, digits, meaning, digits)
    return replace(rec, input_digits=_choose_input_digits(rec, tree))


def _choose_input_digits(rec: CalcRecord, tree: ast.expr) -> int:
    """Fewest input digits (≥ rec.digits) whose displayed numbers reproduce the displayed result."""
    if not rec.variables:
        return rec.digits
    displayed = parse_decimal(format_decimal(rec.value, rec.digits))
    tol = _tolerance(rec.value, rec.digits)
    for d in range(rec.digits, MAX_DIGITS + 1):
        shown = {v.name: parse_decimal(format_decimal(v.value, d)) for v in rec.variables}
        try:
            again = _evaluate(tree, shown)
        except (ValueError, ZeroDivisionError, OverflowError):
            continue
        if abs(again - displayed) <= tol:
            return d
    raise CalcExpressionError(
        f"{rec.expr!r}: the result {rec.value!r} cannot be reproduced from inputs shown with up to "
        f"{MAX_DIGITS} digits (ill-conditioned); rewrite the formula or show fewer result digits")


# --------------------------------------------------------------------------- expression tree
_FUNCTIONS: dict[str, Callable[..., float]] = {
    "sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": math.asin,
    "acos": math.acos, "atan": math.atan, "atan2": math.atan2, "hypot": math.hypot, "abs": abs,
    "radians": math.radians, "degrees": math.degrees,
}
_ARITY = {"atan2": 2, "hypot": 2}
_CONSTANTS = {"pi": math.pi}
_BINOPS = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow)


def _parse(expr: str) -> ast.expr:
    try:
        tree = ast.parse(expr, mode="eval").body
    except SyntaxError as exc:
        raise CalcExpressionError(f"{expr!r} is not a Python expression: {exc.msg}") from None
    _check(tree, expr)
    return tree


def _check(node: ast.AST, expr: str) -> None:
    if isinstance(node, ast.BinOp) and isinstance(node.op, _BINOPS):
        _check(node.left, expr)
        _check(node.right, expr)
    elif isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        _check(node.operand, expr)
    elif isinstance(node, ast.Constant) and type(node.value) in (int, float):
        pass
    elif isinstance(node, ast.Name):
        if node.id in _FUNCTIONS:
            raise CalcExpressionError(f"{expr!r}: {node.id} is a function, call it")
    elif isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCTIONS:
            raise CalcExpressionError(f"{expr!r}: unknown function {ast.unparse(node.func)}")
        if node.keywords or len(node.args) != _ARITY.get(node.func.id, 1):
            raise CalcExpressionError(f"{expr!r}: wrong arguments to {node.func.id}")
        for arg in node.args:
            _check(arg, expr)
    else:
        raise CalcExpressionError(f"{expr!r}: {ast.unparse(node)} is not allowed in a formula")


def _names(tree: ast.expr) -> set[str]:
    return set(_names_in_order(tree))


def _names_in_order(tree: ast.expr) -> list[str]:
    out: list[str] = []

    def walk(node: ast.AST) -> None:
        if isinstance(node, ast.Name):
            if node.id not in _CONSTANTS and node.id not in out:
                out.append(node.id)
        elif isinstance(node, ast.Call):
            for a in node.args:
                walk(a)
        else:
            for child in ast.iter_child_nodes(node):
                walk(child)
    walk(tree)
    return out


def _evaluate(node: ast.AST, values: Mapping[str, float]) -> float:
    if isinstance(node, ast.Constant):
        assert isinstance(node.value, (int, float)), "the parser admits numeric constants only"
        return float(node.value)
    if isinstance(node, ast.Name):
        return _CONSTANTS[node.id] if node.id in _CONSTANTS and node.id not in values else values[node.id]
    if isinstance(node, ast.UnaryOp):
        v = _evaluate(node.operand, values)
        return -v if isinstance(node.op, ast.USub) else v
    if isinstance(node, ast.BinOp):
        a, b = _evaluate(node.left, values), _evaluate(node.right, values)
        op = node.op
        if isinstance(op, ast.Add):
            return a + b
        if isinstance(op, ast.Sub):
            return a - b
        if isinstance(op, ast.Mult):
            return a * b
        if isinstance(op, ast.Div):
            return a / b
        return float(a ** b)
    if isinstance(node, ast.Call):
        assert isinstance(node.func, ast.Name), "the parser admits calls of named functions only"
        return float(_FUNCTIONS[node.func.id](*(_evaluate(a, values) for a in node.args)))
    raise CalcExpressionError(f"cannot evaluate {ast.dump(node)}")


# --------------------------------------------------------------------------- LaTeX of the tree
# Precedence of a printed piece: how tightly it binds when placed next to an operator.
_P_ADD, _P_MUL, _P_NEG, _P_POW, _P_ATOM = 1, 2, 3, 4, 5


@dataclass(frozen=True)
class _Tex:
    text: str
    prec: int
    negative: bool = False     # starts with a minus sign
    fraction: bool = False     # a \frac (an atom, but needs parentheses as a power base)
    function: bool = False     # \sin x ... (needs parentheses as a power base or a left factor)


def _paren(t: _Tex) -> str:
    return f"\\left({t.text}\\right)"


class _SymbolicLeaves:
    def __init__(self, vars_: Mapping[str, Var]) -> None:
        self.vars = vars_
        self.symbolic = True

    def name(self, name: str, _in_degrees: bool) -> _Tex:
        if name in _CONSTANTS and name not in self.vars:
            return _Tex("\\pi", _P_ATOM)
        return _Tex(self.vars[name].latex, _P_ATOM)


class _NumberLeaves:
    def __init__(self, vars_: Mapping[str, Var], digits: int) -> None:
        self.vars = vars_
        self.digits = digits
        self.symbolic = False

    def name(self, name: str, in_degrees: bool) -> _Tex:
        if name in _CONSTANTS and name not in self.vars:
            return _Tex("\\pi", _P_ATOM)
        value = self.vars[name].value
        text = format_decimal(value, self.digits)
        if in_degrees:
            text += "^\\circ"
        if value < 0 and text.startswith("-"):
            return _Tex(text, _P_NEG, negative=True)
        return _Tex(text, _P_POW if " \\cdot 10^" in text else _P_ATOM)


_FUNCTION_NAMES = {
    "sin": "\\sin", "cos": "\\cos", "tan": "\\operatorname{tg}", "asin": "\\arcsin",
    "acos": "\\arccos", "atan": "\\operatorname{arctg}",
}


def _constant_text(value: float) -> str:
    """A constant written in the expression is exact: all its digits are shown."""
    return format_decimal(value, MAX_DIGITS)


def _to_latex(node: ast.AST, leaves: "_SymbolicLeaves | _NumberLeaves", in_degrees: bool = False) -> str:
    return _tex(node, leaves, in_degrees).text


def _tex(node: ast.AST, leaves: "_SymbolicLeaves | _NumberLeaves", in_degrees: bool = False) -> _Tex:
    if isinstance(node, ast.Constant):
        assert isinstance(node.value, (int, float)), "the parser admits numeric constants only"
        text = _constant_text(float(node.value)) + ("^\\circ" if in_degrees else "")
        return _Tex(text, _P_ATOM)
    if isinstance(node, ast.Name):
        return leaves.name(node.id, in_degrees)
    if isinstance(node, ast.UnaryOp):
        inner = _tex(node.operand, leaves, in_degrees)
        body = _paren(inner) if inner.prec <= _P_ADD or inner.negative else inner.text
        if isinstance(node.op, ast.UAdd):
            return _Tex("+" + body, _P_NEG, negative=True)
        return _Tex("-" + body, _P_NEG, negative=True)
    if isinstance(node, ast.BinOp):
        return _binop(node, leaves, in_degrees)
    if isinstance(node, ast.Call):
        return _call(node, leaves, in_degrees)
    raise CalcExpressionError(f"cannot print {ast.dump(node)}")


def _binop(node: ast.BinOp, leaves: "_SymbolicLeaves | _NumberLeaves", deg: bool) -> _Tex:
    op = node.op
    if isinstance(op, ast.Div):
        num = _tex(node.left, leaves, deg)
        den = _tex(node.right, leaves, deg)
        return _Tex(f"\\frac{{{num.text}}}{{{den.text}}}", _P_ATOM, fraction=True)
    left = _tex(node.left, leaves, deg)
    right = _tex(node.right, leaves, deg)
    if isinstance(op, ast.Pow):
        base = left.text
        if left.prec < _P_ATOM or left.fraction or left.function or left.negative or "^" in left.text:
            base = _paren(left)
        return _Tex(f"{base}^{{{right.text}}}", _P_POW)
    if isinstance(op, (ast.Add, ast.Sub)):
        sign = "+" if isinstance(op, ast.Add) else "-"
        rtext = right.text
        if right.negative or (isinstance(op, ast.Sub) and right.prec <= _P_ADD):
            rtext = _paren(right)
        return _Tex(f"{left.text} {sign} {rtext}", _P_ADD, negative=left.negative)
    # multiplication
    ltext = _paren(left) if left.prec <= _P_ADD or left.function else left.text
    rtext = _paren(right) if right.prec <= _P_ADD or right.negative else right.text
    implicit = (leaves.symbolic and isinstance(node.left, ast.Constant) and not left.negative
                and isinstance(node.right, (ast.Name, ast.Call)) and not right.negative
                and not right.function)
    joiner = " " if implicit else " \\cdot "
    return _Tex(f"{ltext}{joiner}{rtext}", _P_MUL, negative=left.negative and ltext == left.text)


def _call(node: ast.Call, leaves: "_SymbolicLeaves | _NumberLeaves", deg: bool) -> _Tex:
    assert isinstance(node.func, ast.Name), "the parser admits calls of named functions only"
    fname = node.func.id
    if fname == "radians":
        # An angle given in degrees: the symbol alone, or its number with a degree sign.
        inner = _tex(node.args[0], leaves, True)
        if not leaves.symbolic and inner.prec < _P_ATOM and not inner.text.endswith("^\\circ"):
            return _Tex(f"{_paren(inner)}^\\circ", _P_POW)
        return inner
    if fname == "degrees":
        return _tex(node.args[0], leaves, deg)
    args = [_tex(a, leaves, False) for a in node.args]
    if fname == "sqrt":
        return _Tex(f"\\sqrt{{{args[0].text}}}", _P_ATOM)
    if fname == "abs":
        return _Tex(f"\\left|{args[0].text}\\right|", _P_ATOM)
    if fname == "hypot":
        a, b = (f"{_paren(t) if t.prec < _P_ATOM or t.negative or t.fraction else t.text}^{{2}}"
                for t in args)
        return _Tex(f"\\sqrt{{{a} + {b}}}", _P_ATOM)
    if fname == "atan2":
        return _Tex(f"\\operatorname{{atan2}}\\left({args[0].text},\\ {args[1].text}\\right)",
                    _P_ATOM, function=True)
    arg = args[0]
    simple = arg.prec == _P_ATOM and not arg.function
    body = f" {arg.text}" if simple else _paren(arg)
    return _Tex(f"{_FUNCTION_NAMES[fname]}{body}", _P_MUL, function=True)
