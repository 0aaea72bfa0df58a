"""Calculation records: values, LaTeX forms, and the printed substitution reproducing the result."""
from __future__ import annotations

import math
import re
from dataclasses import replace

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from reportgen.calc import (CalcExpressionError, Var, evaluate_displayed, format_decimal,
                            latex_symbol_for, parse_decimal, record)


# ---------------------------------------------------------------- an independent LaTeX reader
def _group(s: str, i: int) -> tuple[str, int]:
    """The contents of the brace group opening at s[i] and the index after it."""
    assert s[i] == "{", (s, i)
    depth = 0
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0)
        if depth == 0:
            return s[i + 1:j], j + 1
    raise AssertionError(f"unbalanced braces in {s!r}")


def latex_to_python(s: str) -> str:
    """Read back the subset the records print (+ - · frac sqrt powers parentheses numbers)."""
    out: list[str] = []
    i = 0
    while i < len(s):
        if s.startswith(r"\frac", i):
            num, i = _group(s, i + 5)
            den, i = _group(s, i)
            out.append(f"(({latex_to_python(num)})/({latex_to_python(den)}))")
        elif s.startswith(r"\sqrt", i):
            arg, i = _group(s, i + 5)
            out.append(f"sqrt({latex_to_python(arg)})")
        elif s.startswith("^", i):
            arg, i = _group(s, i + 1)
            out.append(f"**({latex_to_python(arg)})")
        elif s.startswith(r"\left(", i):
            out.append("(")
            i += 6
        elif s.startswith(r"\right)", i):
            out.append(")")
            i += 7
        elif s.startswith(r"\cdot", i):
            out.append("*")
            i += 5
        elif s.startswith("{,}", i):
            out.append(".")
            i += 3
        elif s.startswith(r"\,", i):
            i += 2
        elif s[i] == "{":
            arg, i = _group(s, i)
            out.append(f"({latex_to_python(arg)})")
        elif s[i] in "0123456789.+- ":
            out.append(s[i])
            i += 1
        else:
            raise AssertionError(f"unexpected {s[i:]!r} in {s!r}")
    return "".join(out)


def eval_latex(s: str) -> float:
    return float(eval(latex_to_python(s), {"sqrt": math.sqrt, "__builtins__": {}}))


# ---------------------------------------------------------------- random expressions
NAMES = ("a", "b", "c")
leaf = st.sampled_from(NAMES) | st.sampled_from(["2", "3", "0.5"])


def _combine(children):
    binary = st.tuples(children, st.sampled_from(["+", "-", "*", "/", "**"]), children).map(
        lambda t: f"({t[0]}) {t[1]} ({t[2]})" if t[1] != "**" else f"({t[0]}) ** 2")
    unary = children.map(lambda e: f"-({e})")
    root = children.map(lambda e: f"sqrt(abs({e}))")
    return binary | unary | root


expressions = st.recursive(leaf, _combine, max_leaves=6)
values = st.floats(min_value=-1e4, max_value=1e4, allow_nan=False).filter(lambda x: abs(x) > 1e-3)


def _record_or_skip(expr: str, vals: dict[str, float], digits: int):
    used = {n: v for n, v in vals.items() if re.search(rf"\b{n}\b", expr)}
    try:
        rec = record("Y", expr, "м", digits=digits, **used)
    except CalcExpressionError as exc:
        assume(False)
        raise AssertionError from exc
    assume(abs(rec.value) < 1e12)
    return rec


@settings(max_examples=300, deadline=None)
@given(expressions, st.fixed_dictionaries({n: values for n in NAMES}), st.integers(3, 5))
def test_displayed_substitution_reproduces_displayed_result(expr, vals, digits):
    rec = _record_or_skip(expr, vals, digits)
    check = evaluate_displayed(rec)
    assert check.ok, (expr, vals, check, rec.substituted_latex())
    # every displayed input number is what the substitution prints
    for text in rec.displayed_inputs().values():
        assert text in rec.substituted_latex()


@settings(max_examples=300, deadline=None)
@given(expressions.filter(lambda e: "abs" not in e),
       st.fixed_dictionaries({n: values for n in NAMES}))
def test_printed_substitution_reads_back_to_the_printed_result(expr, vals):
    """Parentheses and fractions are right: an independent reader of the LaTeX gets the value."""
    rec = _record_or_skip(expr, vals, 4)
    try:
        again = eval_latex(rec.substituted_latex())
    except (ZeroDivisionError, OverflowError, ValueError):
        assume(False)
        return
    check = evaluate_displayed(rec)
    assert again == pytest.approx(check.recomputed, rel=1e-9, abs=1e-12), rec.substituted_latex()


def test_speed_of_crank_point():
    rec = record("V_A", "omega1 * l_OA", "м/с", Var("omega1", r"\omega_1", 18.0, "рад/с"),
                 Var("l_OA", "l_{OA}", 0.11, "м"))
    assert rec.value == pytest.approx(1.98)
    assert rec.symbolic_latex() == r"\omega_1 \cdot l_{OA}"
    assert rec.substituted_latex() == r"18 \cdot 0{,}11"
    assert rec.result_latex() == r"1{,}98~\text{м/с}"


@pytest.mark.parametrize("expr, vals, symbolic, substituted", [
    ("a - (b - c)", dict(a=1, b=2, c=3), r"a - \left(b - c\right)", r"1 - \left(2 - 3\right)"),
    ("a - b + c", dict(a=1, b=2, c=3), "a - b + c", "1 - 2 + 3"),
    ("(a + b) * c", dict(a=1, b=2, c=3), r"\left(a + b\right) \cdot c", r"\left(1 + 2\right) \cdot 3"),
    ("a / (b + c)", dict(a=1, b=2, c=3), r"\frac{a}{b + c}", r"\frac{1}{2 + 3}"),
    ("(a / b) ** 2", dict(a=1, b=2), r"\left(\frac{a}{b}\right)^{2}", r"\left(\frac{1}{2}\right)^{2}"),
    ("-a ** 2", dict(a=3), "-a^{2}", "-3^{2}"),
    ("(-a) ** 2", dict(a=3), r"\left(-a\right)^{2}", r"\left(-3\right)^{2}"),
    ("a * b", dict(a=3, b=-2), r"a \cdot b", r"3 \cdot \left(-2\right)"),
    ("a + b", dict(a=3, b=-2), "a + b", r"3 + \left(-2\right)"),
    ("a - b", dict(a=3, b=-2), "a - b", r"3 - \left(-2\right)"),
    ("a ** 2", dict(a=-2), "a^{2}", r"\left(-2\right)^{2}"),
    ("-a", dict(a=-2), "-a", r"-\left(-2\right)"),
    ("b * a", dict(a=3, b=-2), r"b \cdot a", r"-2 \cdot 3"),
    ("(a * b) ** c", dict(a=2, b=3, c=2), r"\left(a \cdot b\right)^{c}", r"\left(2 \cdot 3\right)^{2}"),
    ("a ** b ** c", dict(a=2, b=3, c=2), "a^{b^{c}}", "2^{3^{2}}"),
    ("(a ** b) ** c", dict(a=2, b=3, c=2), r"\left(a^{b}\right)^{c}", r"\left(2^{3}\right)^{2}"),
    ("sqrt(a ** 2 + b ** 2)", dict(a=3, b=4), r"\sqrt{a^{2} + b^{2}}", r"\sqrt{3^{2} + 4^{2}}"),
    ("hypot(a, b)", dict(a=3, b=-4), r"\sqrt{a^{2} + b^{2}}", r"\sqrt{3^{2} + \left(-4\right)^{2}}"),
    ("2 * pi * a / 60", dict(a=1500), r"\frac{2 \pi \cdot a}{60}", r"\frac{2 \cdot \pi \cdot 1500}{60}"),
    ("a * sin(radians(b))", dict(a=2, b=30), r"a \cdot \sin b", r"2 \cdot \sin 30^\circ"),
    ("cos(radians(a + b))", dict(a=20, b=10), r"\cos\left(a + b\right)",
     r"\cos\left(20^\circ + 10^\circ\right)"),
    ("degrees(atan(a / b))", dict(a=1, b=2), r"\operatorname{arctg} \frac{a}{b}",
     r"\operatorname{arctg} \frac{1}{2}"),
    ("tan(a) ** 2", dict(a=0.5), r"\left(\operatorname{tg} a\right)^{2}",
     r"\left(\operatorname{tg} 0{,}5\right)^{2}"),
    ("abs(a - b)", dict(a=1, b=3), r"\left|a - b\right|", r"\left|1 - 3\right|"),
    ("a * 1e-05", dict(a=2), r"a \cdot 1 \cdot 10^{-5}", r"2 \cdot 1 \cdot 10^{-5}"),
])
def test_latex_of_tricky_expressions(expr, vals, symbolic, substituted):
    rec = record("Y", expr, "", **vals)
    assert rec.symbolic_latex() == symbolic
    assert rec.substituted_latex() == substituted
    assert evaluate_displayed(rec).ok


def test_difference_of_nearly_equal_numbers_gets_more_input_digits():
    rec = record(r"\Delta", "x - y", "м", x=1.23456, y=1.23321)
    assert rec.result_latex() == r"0{,}00135~\text{м}"
    assert rec.input_digits == 6
    assert rec.substituted_latex() == r"1{,}23456 - 1{,}23321"
    # with the default 4 digits the printed inputs would not reproduce the printed result
    assert not evaluate_displayed(replace(rec, input_digits=4)).ok


def test_records_chain_through_their_full_value():
    va = record("V_A", "w * l", "м/с", w=18.0, l=0.1111)
    nxt = record("V_B", "v / 3", "м/с", v=va)
    assert nxt.value == pytest.approx(18.0 * 0.1111 / 3)
    assert nxt.symbolic_latex() == r"\frac{V_A}{3}"
    assert evaluate_displayed(nxt).ok


@pytest.mark.parametrize("expr, kw, message", [
    ("a + b", dict(a=1), "no value for b"),
    ("a", dict(a=1, b=2), "not in the expression: b"),
    ("a.real", dict(a=1), "not allowed"),
    ("__import__('os')", {}, "unknown function"),
    ("a if a else 1", dict(a=1), "not allowed"),
    ("sin(a, a)", dict(a=1), "wrong arguments"),
    ("a +", dict(a=1), "not a Python expression"),
    ("sqrt", {}, "is a function"),
])
def test_bad_expressions_are_refused(expr, kw, message):
    with pytest.raises(CalcExpressionError, match=re.escape(message)):
        record("Y", expr, "", **kw)


def test_non_finite_results_are_refused():
    with pytest.raises(CalcExpressionError, match="cannot be evaluated"):
        record("Y", "a ** b", "", a=10.0, b=400.0)
    with pytest.raises(CalcExpressionError, match="cannot be evaluated"):
        record("Y", "a / b", "", a=1.0, b=0.0)
    with pytest.raises(CalcExpressionError, match="cannot be evaluated"):
        record("Y", "sqrt(a)", "", a=-1.0)


@pytest.mark.parametrize("value, kwargs, text", [
    (15800.0, {}, r"15\,800"),
    (1500.0, {}, "1500"),
    (1234567.8, {}, r"1\,234\,568"),
    (-0.5, {}, r"-0{,}5"),
    (1.98, {}, r"1{,}98"),
    (1.98, dict(trailing_zeros=True), r"1{,}980"),
    (0.00012345, {}, r"1{,}234 \cdot 10^{-4}"),
    (0.00099999, {}, r"1 \cdot 10^{-3}"),
    (2.5, dict(decimals=3), r"2{,}500"),
    (0.125, dict(digits=2), r"0{,}12"),      # half-even on the exact decimal of the float
    (9.99996, {}, "10"),
    (-0.00001, dict(decimals=2), "0{,}00"),
    (0.0, {}, "0"),
])
def test_format_decimal(value, kwargs, text):
    assert format_decimal(value, **kwargs) == text
    if "decimals" not in kwargs and value:
        assert parse_decimal(text) == pytest.approx(value, rel=10.0 ** (1 - kwargs.get("digits", 4)))


def test_symbol_names_are_guessed_from_variable_names():
    assert latex_symbol_for("omega1") == r"\omega_{1}"
    assert latex_symbol_for("l_OA") == "l_{OA}"
    assert latex_symbol_for("phi") == r"\varphi"
    assert latex_symbol_for("m") == "m"
