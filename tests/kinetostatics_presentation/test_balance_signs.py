"""Every balance equation the note prints holds with the result printed after it (issue 12, item 3).

The equation is read back from its printed LaTeX (terms split at the signs, each ``A \\cdot B`` or
``\\frac{A}{B}``), every symbol takes the number its substitution prints and the unknown its printed
result: the sum must be zero within the rounding of the printed result. Before the fix the crank's
equation printed ``−F_ур·OA − G1·h7 − R21·h8 = 0`` above ``F_ур = +7867 Н``.

Every length such an equation prints (the arms h_n, the arm of the unknown: OA, BD, pa…) is read off a
drawing — the scheme, the lever — so it is printed as read, to ``READING_MM`` (0,1 mm), and the sum
is taken with those printed readings (issue 12: «h₁ = 85,69 мм» on the scheme of a group)."""
from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from kst_build import EXAMPLES, project_of, section_note  # noqa: E402

from reportgen.balance import Balance, BalanceTerm, check_balance  # noqa: E402
from reportgen.calc import Var, parse_decimal  # noqa: E402
from reportgen.kinetostatics.graphical import READING_MM  # noqa: E402


def _split_terms(body: str) -> list[tuple[int, str]]:
    """``a - b + c`` → [(+1, a), (-1, b), (+1, c)] at the top level (no brackets in these sums)."""
    out, sign, depth, cur = [], 1, 0, ""
    i = 0
    if body.startswith("-"):
        sign, i = -1, 1
    while i < len(body):
        ch = body[i]
        depth += ch == "{"
        depth -= ch == "}"
        if depth == 0 and body[i:i + 3] in (" + ", " - "):
            out.append((sign, cur.strip()))
            sign, cur = (1 if body[i + 1] == "+" else -1), ""
            i += 3
            continue
        cur += ch
        i += 1
    out.append((sign, cur.strip()))
    return out


def _factors(term: str) -> tuple[str, str, str]:
    """(a, op, b) of ``a \\cdot b`` or ``\\frac{a}{b}``."""
    if term.startswith("\\frac{"):
        depth, k = 0, len("\\frac")
        for k in range(len("\\frac"), len(term)):
            depth += term[k] == "{"
            depth -= term[k] == "}"
            if depth == 0:
                break
        return term[len("\\frac") + 1:k], "/", term[k + 2:-1]
    a, _, b = term.partition(" \\cdot ")
    return a.strip(), "*", b.strip()


def _printed_sum(sol) -> tuple[float, float]:
    """The printed equation evaluated at the printed numbers; and the size of its largest term."""
    eq = sol.equation_latex()
    body = eq.split(" = ", 1)[1].rsplit(" = 0", 1)[0]
    printed: dict[str, float] = {}
    for rec in (*sol.parts, sol.result):
        shown = rec.displayed_inputs()
        for v in rec.variables:
            printed.setdefault(v.latex, parse_decimal(shown[v.name]))
    printed[sol.result.symbol] = parse_decimal(sol.result.result_number_latex())
    total, big = 0.0, 0.0
    for sign, term in _split_terms(body):
        a, op, b = _factors(term)
        x = printed[a] * printed[b] if op == "*" else printed[a] / printed[b]
        total += sign * x
        big = max(big, abs(x))
    return total, big


def _printed_lengths(sol) -> dict[str, str]:
    """Every length (unit мм: the arms, the unknown's arm) a balance prints, by symbol, as printed."""
    out: dict[str, str] = {}
    for rec in (*sol.parts, sol.result):
        shown = rec.displayed_inputs()
        for v in rec.variables:
            if v.unit == "мм":
                out[v.latex] = shown[v.name]
    return out


@pytest.mark.parametrize("example", EXAMPLES)
def test_every_printed_balance_holds_with_its_printed_result(example, tmp_path):
    project = project_of(example)
    note = section_note(project)
    tex = note.render(tmp_path).read_text(encoding="utf-8")
    balances = note.symbols.balances
    assert len(balances) >= 2          # at least the crank and the lever
    for sol in balances:
        assert sol.equation_latex() in tex
        total, big = _printed_sum(sol)
        arm = parse_decimal(sol.result.displayed_inputs()["l"])
        # rounding of the printed result (half a unit of its last digit) times its arm, partial sums
        res = sol.result.result_number_latex().replace("\\,", "")
        last = res.split("{,}")[1] if "{,}" in res else ""
        half = 0.5 * 10.0 ** (-len(last))
        tol = half * arm * 1.0001 + sum(0.5 * 10.0 ** (-len((p.result_number_latex().split("{,}") + [""])[1]))
                                          for p in sol.parts) + 1e-9 * big
        assert abs(total) <= tol, (example, sol.equation_latex(), sol.result.result_number_latex(), total, tol)
        assert check_balance(sol).ok
        lengths = _printed_lengths(sol)
        assert lengths, sol.equation_latex()
        for symbol, text in lengths.items():        # read off the drawing: 0,1 mm, printed as read
            value = parse_decimal(text)
            assert abs(value / READING_MM - round(value / READING_MM)) < 1e-9, (example, symbol, text)
            assert len((text.split("{,}") + [""])[1]) <= 1, (example, symbol, text)


def test_balance_sign_of_the_unknown_follows_its_term():
    F = Var("F", "G_{1}", 10.0, "Н", "вес")
    h = Var("h", "h_{1}", 2.0, "мм", "плечо")
    l = Var("l", "OA", 5.0, "мм", "кривошип")
    plus = Balance("\\sum M_{O}", "F_{\\text{ур}}", "Н", 1, l, (BalanceTerm(1, F, h),)).solve()
    minus = Balance("\\sum M_{O}", "F_{\\text{ур}}", "Н", -1, l, (BalanceTerm(1, F, h),)).solve()
    assert plus.value == pytest.approx(-4.0) and minus.value == pytest.approx(4.0)
    assert plus.equation_latex() == "\\sum M_{O} = F_{\\text{ур}} \\cdot OA + G_{1} \\cdot h_{1} = 0"
    assert minus.equation_latex().startswith("\\sum M_{O} = -F_{\\text{ур}} \\cdot OA")
    for sol in (plus, minus):
        assert check_balance(sol).ok and abs(_printed_sum(sol)[0]) < 1e-9


def test_check_catches_an_equation_printed_with_the_wrong_sign():
    """The defect of the old note: the equation of one sign, the result of the other."""
    from dataclasses import replace
    F = Var("F", "R_{21}", 7947.5, "Н", "реакция")
    h = Var("h", "h_{8}", 54.44, "мм", "плечо")
    l = Var("l", "OA", 55.0, "мм", "кривошип")
    good = Balance("\\sum M_{O}", "F_{\\text{ур}}", "Н", -1, l, (BalanceTerm(-1, F, h),)).solve()
    assert check_balance(good).ok
    wrong = replace(good, balance=replace(good.balance, unknown_sign=1))
    assert not check_balance(wrong).ok
    assert abs(_printed_sum(wrong)[0]) > 1e5


def test_many_terms_go_through_partial_sums_and_still_balance():
    terms = tuple(BalanceTerm(1 if k % 3 else -1, Var("F", f"F_{{{k}}}", 100.0 + 7.3 * k, "Н", "сила"),
                              Var("h", f"h_{{{k}}}", 10.0 + 1.37 * k, "мм", "плечо")) for k in range(8))
    couple = BalanceTerm(-1, Var("M", "M_{2}", 3.21, "Н·м", "пара"), divisor=Var("mu", "\\mu_l", 0.005, "м/мм", "м"))
    sol = Balance("\\sum M_{p}", "F", "Н", 1, Var("l", "pa", 77.7, "мм", "отрезок"), terms + (couple,),
                  partial="\\Sigma", partial_unit="Н·мм").solve()
    assert len(sol.parts) == 3
    assert check_balance(sol).ok
    total, _ = _printed_sum(sol)
    assert abs(total) < 0.5 * 77.7 + 3


def test_the_total_of_partial_sums_is_not_called_a_partial_sum():
    """Issue 12 (press p. 38): «Σ(Ж) — частичная сумма моментов» was printed for the total of the
    five partial sums; the total record carries its own meaning."""
    terms = tuple(BalanceTerm(1, Var("F", f"F_{{{k}}}", 10.0 + k, "Н", "сила"),
                              Var("h", f"h_{{{k}}}", 5.0 + k, "мм", "плечо")) for k in range(13))
    sol = Balance("\\sum M_{p}", "F", "Н", 1, Var("l", "pa", 50.0, "мм", "отрезок"), terms,
                  partial="\\Sigma", partial_unit="Н·мм", partial_meaning="частичная сумма моментов",
                  total_meaning="сумма моментов всех известных сил").solve()
    *partials, total = sol.parts
    assert len(partials) == 5 and total.symbol == "\\Sigma"
    assert all(p.meaning == "частичная сумма моментов" for p in partials)
    assert total.meaning == "сумма моментов всех известных сил"


def test_split_terms_reads_signs():
    assert _split_terms("-a \\cdot b + c \\cdot d - \\frac{e}{f}") == [(-1, "a \\cdot b"), (1, "c \\cdot d"),
                                                                       (-1, "\\frac{e}{f}")]
    assert _factors("\\frac{M_{2}}{\\mu_l}") == ("M_{2}", "/", "\\mu_l")
    assert re.sub("x", "y", "x") == "y"
