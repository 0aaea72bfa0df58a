"""A displayed formula stays within the text block: the width that decides a split counts the «=»
the line prints, and a split substitution leaves room on its last line for « = result» (issue 12:
the crane's W0′ and the control work's Σ(Ж) ran over the right margin)."""
from __future__ import annotations

from latex_templates.render import LINE_WIDTH, break_sum, visible_width

SUM = r"-15\,837 + \left(-34\,062\right) + \left(-433\,744\right) + \left(-17\,908\right) + 911{,}8"
RESULT = r"= -500\,639~\text{Н·мм}"


def test_the_last_line_leaves_room_for_the_result():
    assert visible_width(SUM) <= LINE_WIDTH < visible_width(SUM) + visible_width(RESULT)
    assert break_sum(SUM) == [SUM]                    # without the result it fits one line
    lines = break_sum(SUM, tail=visible_width(RESULT))
    assert len(lines) == 2 and " ".join(lines) == SUM
    assert visible_width(lines[-1]) + visible_width(RESULT) <= LINE_WIDTH
    assert all(visible_width(x) <= LINE_WIDTH for x in lines)


def test_a_single_term_is_never_broken():
    assert break_sum(r"588\,420", tail=40) == [r"588\,420"]
