"""Section 2 of the note: it renders for every example, every printed record re-evaluates (and
repeats the replica's value: the part checks that itself), the PDF prints M_ур by both methods
equal to results.json's values, and a near-dead-centre position carries the warning."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from kst_build import EXAMPLES, project_of, section_note  # noqa: E402

from reportgen.calc import evaluate_displayed, format_decimal  # noqa: E402
from reportgen.kinetostatics.results import kinetostatics_block, kinetostatics_of  # noqa: E402


@pytest.mark.parametrize("example", EXAMPLES)
def test_kst_section_renders_and_records_reevaluate(example, tmp_path):
    project = project_of(example)
    note = section_note(project)
    tex = note.render(tmp_path).read_text(encoding="utf-8")
    assert "Силовой расчёт рычажного механизма" in tex
    assert "Рычаг Жуковского" in tex
    records = note.records
    assert len(records) > 20
    assert all(evaluate_displayed(r).ok for r in records)
    ks = kinetostatics_of(project)
    # the printed arms of the tangential components are the replica's measured arms
    for gg in ks.graphical.groups:
        for sp in gg.splits:
            for t in sp.terms:
                if t.arm_mm_measured:
                    # 4 significant digits (5 where the record needs them: arms of 100 mm and more)
                    assert any(format_decimal(abs(t.arm_mm_measured), d) in tex for d in (4, 5))
    # every figure of the part is included
    for name in ("kst_crank", "kst_poly_crank", "kst_lever", "kst_cycle"):
        assert name.replace("_", "-") in tex or name in tex


def _norm(s: str) -> str:
    return re.sub(r"[\s\u2009\u202f\u00a0]", "", s).replace("\u2212", "-")


@pytest.mark.slow
@pytest.mark.parametrize("example", ["press", "class3"])
def test_kst_pdf_prints_both_balancing_moments(example, tmp_path):
    project = project_of(example)
    note = section_note(project)
    note.render(tmp_path)
    report = note.build(tmp_path)
    text = _norm(subprocess.run(["pdftotext", str(report.pdf), "-"], capture_output=True, text=True,
                                check=True).stdout)
    block = kinetostatics_block(kinetostatics_of(project))
    for key in ("balancing_moment", "balancing_moment_zhukovsky"):
        printed = _norm(format_decimal(block[key], 6).replace("{,}", ",").replace("\\,", ""))
        assert printed in text, (key, printed)
    assert _norm("Сравнение результатов") in text


def test_kst_warning_near_dead_centre(tmp_path, monkeypatch):
    """No example's analysed position is within 10° of a dead centre: no warning. With the threshold
    raised above the press's transmission angle there, the section prints the warning with that μ
    and the conclusions say so too."""
    from latex_templates.parts import kinetostatics as part
    project = project_of("press")
    ks = kinetostatics_of(project)
    tex = section_note(project).render(tmp_path / "plain").read_text(encoding="utf-8")
    assert "мёртвому положению" not in tex
    mu = min(ks.transmission_deg.values())
    monkeypatch.setattr(part, "WARN_TRANSMISSION_DEG", mu + 1.0)
    note = section_note(project)
    tex = note.render(tmp_path / "warned").read_text(encoding="utf-8")
    assert "мёртвому положению" in tex
    assert format_decimal(mu, decimals=2) in tex


@pytest.mark.parametrize("example", EXAMPLES)
def test_the_levers_arms_are_printed_as_a_drawing_is_read(example):
    """The lever is drawn on sheet 2 and read to 0,1 mm (``reading_mm``), so its moment equation
    prints each arm and pa to one decimal (on main «h₉ = 37,46 мм»: 0,01 mm off a drawing), and F_ур
    follows from the printed numbers (the records re-evaluate, the balance sums to zero)."""
    from reportgen.balance import check_balance
    from latex_templates.parts.kinetostatics import _Counter, _lever

    project = project_of(example)
    ks = kinetostatics_of(project)
    L, step = ks.graphical.lever, ks.graphical.reading_mm
    assert step == pytest.approx(0.1)
    for v in [abs(t.arm_mm_measured) for t in L.terms] + [L.pa_mm_measured]:
        assert abs(v / step - round(v / step)) < 1e-9, v
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings
    with active_strings(Strings("ru")):
        sol = _lever(project, ks, _Counter(), {})["balance"]
    printed = {k: t for rec in (*sol.parts, sol.result) for k, t in rec.displayed_inputs().items()
               if k == "l" or (k.startswith("h") and k[1:].isdigit())}
    assert len(printed) > 1
    for k, text in printed.items():          # «37{,}5», «198»: one decimal at most
        assert "{,}" not in text or len(text.split("{,}")[1]) <= 1, (k, text)
    assert check_balance(sol).ok


@pytest.mark.parametrize("example", EXAMPLES)
def test_the_shift_of_F_i_is_laid_off_as_a_drawing_is_read(example, tmp_path):
    """«На схеме откладываем … мм»: the shift h of Fи′ is laid off on the scheme to the drawing's
    0,1 mm (``READING_MM``, as every arm of section 2 is read), printed as the replica lays it off
    (on main «12,28 мм» beside arms read to 0,1 mm on the lever)."""
    from reportgen.kinetostatics.graphical import READING_MM
    project = project_of(example)
    ks = kinetostatics_of(project)
    tex = section_note(project).render(tmp_path).read_text(encoding="utf-8")
    laid = re.findall(r"откладываем (\S+?)~мм", tex)
    assert len(laid) == len(ks.graphical.inertia)
    for text, x in zip(laid, ks.graphical.inertia):
        assert len((text.split("{,}") + [""])[1]) <= 1, text
        assert float(text.replace("{,}", ".")) == pytest.approx(x.h_mm_measured, abs=1e-9)
        assert abs(x.h_mm_measured / READING_MM - round(x.h_mm_measured / READING_MM)) < 1e-9


@pytest.mark.parametrize("example", EXAMPLES)
def test_no_where_list_explains_two_partial_sums_alike(example, tmp_path):
    """A moment equation split into partial sums Σ₁ … Σₙ explains each by the loads it sums: the
    press's (2.42) printed «— частичная сумма моментов, Н·мм» five times in one «где» list."""
    tex = section_note(project_of(example)).render(tmp_path).read_text(encoding="utf-8")
    lists = re.findall(r"\\begin\{wherelist\}(.*?)\\end\{wherelist\}", tex, flags=re.S)
    assert lists
    for body in lists:
        meanings = []
        for item in re.split(r"\\item\[[^\]]*\]", body)[1:]:
            m = re.match(r"\s*\$(.*?)\$(.*)", item, flags=re.S)
            if m and m.group(1).startswith("\\Sigma"):
                meanings.append(m.group(2).strip())
        assert len(meanings) == len(set(meanings)), meanings
