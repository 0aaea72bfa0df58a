"""One number formatter for note, sheets, figures and tables (issue 12 item 5, issue 13 item 3).

Before: the note printed 2,675 as "2,68" (decimal rounding of the written number) and the sheets as
"2,67" (``f"{2.675:.2f}"`` rounds the binary float 2.67499999…)."""
from __future__ import annotations

from hypothesis import given, settings, strategies as st

from drawings.primitives import format_number, format_significant
from latex_templates.figures import comma
from latex_templates.numbers import fixed, num
from reportgen.numbers import clean, decimal_text, is_residue, plain, significant


def _text(note: str) -> str:
    """The note's LaTeX text form as it reads on paper."""
    return note.replace("{,}", ",").replace("\\,", "").replace("\u2212", "-")


def test_the_defect_of_the_issue():
    assert _text(fixed(2.675, 2)) == "2,68"
    assert format_number(2.675, 2) == "2,68"
    assert format_significant(2.675, 3) == "2,68"
    assert comma(2.675) == "2,675"


def test_a_bare_five_rounds_to_even_as_st_sev_543_prescribes():
    assert decimal_text(0.125, 2) == "0.12" and decimal_text(0.135, 2) == "0.14"
    assert plain(2.665, 2) == "2,66" and plain(-2.675, 2) == "-2,68"
    assert plain(-0.001, 2) == "0" and plain(0.0200, 2) == "0,02"
    assert significant(9.9996, 4) == "10" and significant(1230.4, 3) == "1230"


_decimals = st.integers(min_value=0, max_value=4)
_values = st.builds(lambda k, e: k / 10 ** e, st.integers(-10**7, 10**7), st.integers(0, 5))


@settings(max_examples=400, deadline=None)
@given(_values, _decimals)
def test_fixed_places_agree_between_note_and_sheet(value, decimals):
    assert _text(fixed(value, decimals)) == format_number(value, decimals, strip=False)


@settings(max_examples=400, deadline=None)
@given(_values, st.integers(min_value=1, max_value=6))
def test_significant_digits_agree_between_note_and_sheet(value, digits):
    if value != 0 and abs(value) < 1e-3:
        return                       # the note writes m·10^k there; the sheets never show such values
    assert _text(num(value, digits)) == format_significant(value, digits)


def test_residue_is_told_from_a_real_value():
    assert is_residue(3.068e-16, 9.81) and clean(3.068e-16, 9.81) == 0.0
    assert not is_residue(1.2e-5, 9.81) and clean(1.2e-5, 9.81) == 1.2e-5
    assert not is_residue(0.0, 1.0)
