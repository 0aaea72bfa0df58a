"""The lettering's room comes from the lines themselves (issue 12): the core measures a sheet's text
as the sheet does (reportgen/scenes/lettering.py: the measuring font's one advance) and keeps of the
catalogue's words only how many characters each line's fixed part has; the table «Масштабы» of sheet
1 is reserved from its own lines. On main the core reserved a fixed width per language (ru 200, uk
197, en 229 mm), measured on the examples: a task whose table is wider — a longer ratio, longer
values — ran over it.
"""
from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from drawings import style
from drawings.sheets import kinematics as sheet1
from drawings.words import language, tr, unit
from reportgen.project import Project
from reportgen.scenes import arrangement, lettering
from reportgen.taskfile import load_task

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "sheet1"))
from test_arrangement_core import long_crank_slider  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
LANGUAGES = ("ru", "uk", "en")
#: The room main reserved for the table, per language, mm.
OLD_ROOM = {"ru": 200.0, "uk": 197.0, "en": 229.0}


def _catalogue_lines(lang: str) -> list[str]:
    """Every line of the sheets' catalogues (sheets, sheet1, control) in ``lang``, the values empty."""
    import tomllib
    out = []
    for name in ("sheets", "sheet1", "control"):
        path = ROOT / "latex_templates" / "strings" / lang / f"{name}.toml"
        if not path.exists():
            continue
        todo = [tomllib.loads(path.read_text(encoding="utf-8"))]
        while todo:
            for value in todo.pop().values():
                if isinstance(value, dict):
                    todo.append(value)
                elif isinstance(value, str):
                    out.append(value.replace(r"\VAR{", "{"))
    return out


@pytest.mark.parametrize("lang", LANGUAGES)
def test_the_cores_measure_is_the_sheets(lang):
    lines = _catalogue_lines(lang)
    assert len(lines) > 50
    for text in lines:
        for height in (3.5, 5.0, 7.0):
            assert lettering.text_width(text, height) == pytest.approx(style.text_width(text, height), rel=1e-9, abs=1e-9), text


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet=st.characters(min_codepoint=32, max_codepoint=0x4FF, blacklist_categories=("Cs", "Cc")),
               max_size=40), st.sampled_from((2.5, 3.5, 5.0, 7.0, 10.0)))
def test_the_cores_measure_is_the_sheets_for_any_text(text, height):
    assert lettering.text_width(text, height) == pytest.approx(style.text_width(text, height), rel=1e-9, abs=1e-9)


def _fixed_chars(lang: str) -> dict[str, int]:
    """The fixed part of every line of the table «Масштабы», from the catalogue (the values empty)."""
    keys = {"header_name": ("sheets.sk106", {}), "header_value": ("sheets.sk107", {}),
            "scheme": ("sheets.sk109", {"scale_text": ""}), "vplan": ("sheet1.scales_vplan", {"i": ""}),
            "vplans": ("sheet1.scales_vplans", {"i": ""}), "aplan": ("sheet1.scales_aplan", {"i": ""}),
            "aplans": ("sheet1.scales_aplans", {"i": ""}), "small": ("sheet1.scales_small", {"last": ""}),
            "vplan_given": ("sheet1.scales_vplan_given", {}), "aplan_given": ("sheet1.scales_aplan_given", {}),
            "phi_axis": ("sheets.sk115", {}), "t_axis": ("sheets.sk117", {}), "pole": ("sheets.sk119", {}),
            "value_l": ("sheets.sk110", {"v1": ""}), "value_v": ("sheets.sk112", {"v1": ""}),
            "value_a": ("sheets.sk114", {"v1": ""}), "value_phi": ("sheets.sk116", {"v1": ""}),
            "value_t": ("sheets.sk118", {"v1": ""}), "value_mm": ("sheets.sk120", {"v1": ""})}
    with language(lang):
        out = {k: len(tr(key, **values)) for k, (key, values) in keys.items()}
        out["symbol"] = len(tr("sheets.sk105"))
        assert len(tr("sheets.sk121")) <= out["pole"] and len(tr("sheets.sk122", v1="")) <= out["value_mm"]
        for kind, titles, units in (("m", (10, 11, 12), ("м/мм", "(м/с)/мм", "(м/с²)/мм")),
                                    ("rad", (7, 8, 9), ("рад/мм", "(рад/с)/мм", "(рад/с²)/мм"))):
            out[f"diagrams_{kind}"] = max(len(sheet1._lower_title(tr(f"sheets.kd{n:02d}"))) for n in titles)
            out[f"value_{kind}"] = max(len(" " + unit(u)) for u in units)
    return out


@pytest.mark.parametrize("lang", LANGUAGES)
def test_the_cores_words_are_the_catalogues(lang):
    assert dict(lettering.SCALES_TABLE_CHARS[lang]) == _fixed_chars(lang)


def _table_drawn(project, k: float, ratio: str, lang: str) -> float:
    """The width of the table as the sheet letters it, the widest of its small plans' choices."""
    pairs = dict(project.plans_by_position)
    with language(lang):
        d = sheet1.diagrams_of(project)
        rows = [sheet1.scale_rows(1.0 / k, ratio, pairs, d, sheet1.small_plans(project, c)) for c in sheet1.SMALL_PLAN_MM]
        return sum(sheet1._table_widths(rows))


@pytest.mark.parametrize("lang", LANGUAGES)
def test_a_long_table_of_scales_has_its_room(tmp_path, lang):
    """Deliberately long lines: three plan positions of two digits sharing their μ («planы скоростей
    положений 3, 10, 11»), the scheme at 1:25000 (a long ratio), the plans' μ with four significant
    digits (0,0001234): the core reserves what the sheet letters, where main's fixed room was
    narrower (en: 229 mm)."""
    path = long_crank_slider(tmp_path, plan_positions="3, 10, 11")
    path.write_text(path.read_text(encoding="utf-8").replace("[document]", f'[document]\nlanguage = "{lang}"', 1)
                    if "language =" not in path.read_text(encoding="utf-8") else
                    path.read_text(encoding="utf-8").replace('language = "ru"', f'language = "{lang}"'), encoding="utf-8")
    project = Project(load_task(path))
    assert project.task.document.language == lang
    pairs = {j: (dataclasses.replace(v, scale=v.scale * 1.234e-3), dataclasses.replace(a, scale=a.scale * 5.678e-3))
             for j, (v, a) in project.plans_by_position.items()}
    project.__dict__["plans_by_position"] = pairs
    k, ratio = 1000.0 / 25000.0, "1:25000"
    drawn = _table_drawn(project, k, ratio, lang)
    reserved = arrangement.scales_table_width(project, k, ratio, project.output_diagrams, True)
    assert drawn <= reserved + 1e-9
    assert reserved - drawn < 3 * lettering.SHEET_ADVANCE * lettering.TABLE_TEXT_MM + 1e-9  # a small plan's μ at most
    assert drawn > OLD_ROOM[lang], (drawn, OLD_ROOM[lang])


@pytest.mark.parametrize("example", ["press", "shaper", "conveyor", "class3", "press-en", "shaper-uk"])
def test_the_examples_tables_are_reserved_from_their_lines(example):
    project = Project(load_task(ROOT / "examples" / example / "task.toml"))
    layout = project.scenes.sheet_layout
    drawn = _table_drawn(project, layout.k, layout.ratio, project.task.document.language)
    assert drawn <= layout.rects["scales"].width + 1e-9
    assert layout.rects["scales"].width - drawn < 3 * lettering.SHEET_ADVANCE * lettering.TABLE_TEXT_MM + 1e-9


# ------------------------------------------------------------------------------------------------
# sheet 1's small plans: their block's lettering reserve is the same in every language (issue 12)


def _small_chars(lang: str) -> dict[str, tuple[int, ...]]:
    """The small plans' title (its words) and caption (its fixed part) from the catalogue."""
    with language(lang):
        title = tr("sheets.kp01", v1="")
        return {"title": tuple(len(w) for w in title.split(" ")), "caption": (len(tr("sheets.kp02", v1="")),)}


@pytest.mark.parametrize("lang", LANGUAGES)
def test_the_small_plans_words_are_the_catalogues(lang):
    assert dict(lettering.SMALL_PLANS_CHARS[lang]) == _small_chars(lang)


@settings(max_examples=200, deadline=None)
@given(st.floats(20.0, 800.0), st.integers(1, 199), st.sampled_from(("0,04", "0,1", "0,0025", "12,5")))
def test_the_small_plans_lettering_fits_the_cores_reserve_in_every_language(width, last, mu):
    """The sheet letters the title over a grid ``width`` mm wide (in two lines where one does not fit)
    and the caption under it: in no language more lines, nor wider, than the core reserved (one
    reserve for all languages, so that the small plans' scale cannot depend on the language)."""
    from drawings.scenes import kinematics_plans as kp
    lines, need = lettering.small_plans_lettering(str(last), mu, width)
    for lang in LANGUAGES:
        with language(lang):
            drawn = kp.title_lines(tr("sheets.kp01", v1=last), width)
            caption = style.text_width(tr("sheets.kp02", v1=mu), kp.SMALL_TITLE_H) + kp.SMALL_TITLE_PAD_MM
        assert len(drawn) <= lines
        assert max(style.text_width(t, kp.SMALL_TITLE_H) for t in drawn) + kp.SMALL_TITLE_PAD_MM <= need + 1e-9
        assert caption <= need + 1e-9
