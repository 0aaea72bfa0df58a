"""The Jinja environment, escaping, strings catalogue and rendering of a note (no TeX needed)."""
from __future__ import annotations

import tomllib
from importlib import resources

import jinja2
import pytest

from reportgen.errors import InternalError

from reportgen.calc import Var, record
from reportgen.task import Document

from latex_templates import NoteBuilder, Section, Strings, SymbolTracker, escape_latex, tex
from latex_templates import numbers
from latex_templates.render import MissingString, make_environment, visible_width

from .sample import NASTY_TITLE, sample_note


def render_string(source: str, **context) -> str:
    return make_environment().from_string(source).render(**context)


def test_escape_every_special_character():
    assert escape_latex(r"# $ % & _ { } ~ ^ \ ") == (
        r"\# \$ \% \& \_ \{ \} \textasciitilde{} \textasciicircum{} \textbackslash{} ")


def test_user_text_is_escaped_and_tex_is_not():
    out = render_string(r"\section{\VAR{title}} \VAR{raw}", title="50% of $x_1$", raw=tex(r"\alpha"))
    assert out == r"\section{50\% of \$x\_1\$} \alpha"


def test_numbers_print_with_decimal_comma_and_filters():
    out = render_string(r"\VAR{x} \VAR{y|fixed(3)} \VAR{z|deg} \VAR{big} \VAR{neg} $\VAR{neg|mnum}$",
                        x=1.98, y=2.5, z=30, big=15800, neg=-0.25)
    assert out == "1{,}98 2{,}500 30{,}0\u00b0 15\\,800 \u22120{,}25 $-0{,}25$"


def test_small_numbers_in_text_use_a_superscript_power():
    assert numbers.num(-0.0000123) == "\u22121{,}23\\,\u00b7\\,10\\textsuperscript{\u22125}"
    assert numbers.angle(3.141592653589793 / 2) == "90{,}0\u00b0"


def test_undefined_and_none_are_errors_not_empty_text():
    with pytest.raises(jinja2.UndefinedError):
        render_string(r"\VAR{missing}")
    with pytest.raises(jinja2.UndefinedError):
        render_string(r"\VAR{x}", x=None)


def test_strings_catalogue_without_fallback():
    ru = Strings("ru")
    assert str(ru.headings.contents) == "Содержание"
    en = Strings("en")
    assert str(en.headings.contents) == "Contents"
    assert en.references.items and "Uicker" in str(en.references.items[0])   # English, not Russian
    assert not en.fallbacks               # no key is ever taken from another language
    with pytest.raises(MissingString):
        ru.get("headings.nonexistent")
    with pytest.raises(ValueError):
        Strings("de")


def _keys(table, prefix=""):
    for k, v in table.items():
        if isinstance(v, dict):
            yield from _keys(v, f"{prefix}{k}.")
        else:
            yield prefix + k


def test_every_english_key_exists_in_russian():
    root = resources.files("latex_templates").joinpath("strings")
    ru = set(_keys(tomllib.loads(root.joinpath("ru.toml").read_text(encoding="utf-8"))))
    en = set(_keys(tomllib.loads(root.joinpath("en.toml").read_text(encoding="utf-8"))))
    assert en <= ru, en - ru


def test_symbol_tracker_explains_each_symbol_once():
    tracker = SymbolTracker()
    w = Var("w", r"\omega_1", 18.0, "рад/с", "угловая скорость")
    l = Var("l", "l", 0.1, "м", "длина")
    n = Var("n", "n", 3.0)            # no meaning: cannot be explained
    assert tracker.first([w, n]) == [w]
    assert tracker.first([w, l]) == [l]
    assert tracker.first([w, l]) == []
    assert tracker.unexplained == {"n"}


def _macros(tracker):
    env = make_environment()
    return env, env.get_template("macros.tex.j2").make_module(
        {"s": Strings("ru"), "sym": tracker})


def test_calc_macro_prints_numbered_equation_and_first_where_list():
    tracker = SymbolTracker()
    env, m = _macros(tracker)
    w = Var("omega1", r"\omega_1", 18.0, "рад/с", "угловая скорость кривошипа")
    l_oa = Var("l_OA", "l_{OA}", 0.11, "м", "длина кривошипа")
    va = record("V_A", "omega1 * l_OA", "м/с", w, l_oa, label="eq:va")
    first = str(m.calc(va))
    assert (r"V_A = \omega_1 \cdot l_{OA} = 18 \cdot 0{,}11 = 1{,}98~\text{м/с}" in first)
    assert r"\label{eq:va}" in first and r"\begin{equation}" in first
    assert r"\item[где] $\omega_1$~--- угловая скорость кривошипа, рад/с;" in first
    assert r"\item[] $l_{OA}$~--- длина кривошипа, м." in first
    second = str(m.calc(record("a_A", "omega1**2 * l_OA", "м/с²", w, l_oa)))
    assert "wherelist" not in second
    assert tracker.records[0] is va and len(tracker.records) == 2


def test_an_angle_result_takes_the_degree_sign_without_a_space():
    """Issue 12: «ψmax = arctg … = 9,98 °» — the degree sign follows the number, as in 85,23°."""
    env, m = _macros(SymbolTracker())
    out = str(m.calc(record(r"\psi", "degrees(atan(x))", "°", Var("x", "x", 0.176, "", "отношение"))))
    assert r"= 9{,}982^\circ" in out and r"\text{°}" not in out


def test_wide_formula_is_split_after_the_symbolic_form():
    env, m = _macros(SymbolTracker())
    rec = record("l_{AC}", "sqrt(a**2 + b**2 - 2*a*b*cos(radians(g)))", "м",
                 Var("a", "l_{OA}", 0.11), Var("b", "l_{AB}", 0.38), Var("g", r"\gamma", 120.0))
    out = str(m.calc(rec))
    assert r"\begin{split}" in out and r"&= \sqrt{0{,}11^{2}" in out
    short = str(m.calc(record("x", "a*b", "м", a=1.5, b=2.0)))
    assert r"\begin{split}" not in short
    assert visible_width(r"\frac{a}{b}") == 2


def test_table_macro_repeats_header_and_formats_columns():
    env, m = _macros(SymbolTracker())
    out = str(m.table("Скорости", ["φ", tex("$V$")], [[0.0, 1.98], [45.0, None]], decimals=[0, 3]))
    assert r"\caption{Скорости}" in out and r"\endfirsthead" in out and r"\endhead" in out
    assert r"Продолжение таблицы~\thetable" in out
    assert r"0 & 1{,}980 \\" in out and r"45 &  \\" in out


def test_render_writes_tex_with_escaped_title_and_figure(tmp_path):
    note = sample_note(tmp_path)
    tex_path = note.render(tmp_path / "out")
    text = tex_path.read_text(encoding="utf-8")
    assert r"Пресс \#1 \& \$x\_5\$ \textasciitilde{} 100\% \{a\} \textasciicircum{} \textbackslash{}relax" in text
    assert NASTY_TITLE not in text
    assert r"\section{Кинематический анализ}\label{sec:kinematics}" in text
    assert (r"\notefigure{\includegraphics[width=0.85\textwidth,height=\notefigmaxheight,keepaspectratio]"
            r"{figures/kinematics-plot.pdf}}") in text
    figure = (tmp_path / "out" / "figures" / "kinematics-plot.pdf").read_bytes()
    assert figure.startswith(b"%PDF") and b"CreationDate" not in figure
    assert [r.symbol for r in note.records] == ["V_A", "a_A", "l_{AC}"]
    assert "\\VAR" not in text and "\\BLOCK" not in text


def test_render_without_frame_numbers_pages_at_the_bottom(tmp_path):
    text = sample_note(tmp_path, frame="none").render(tmp_path / "out").read_text(encoding="utf-8")
    assert r"\pagestyle{plain}" in text and r"\put(20,-277)" not in text


def test_language_comes_from_the_document(tmp_path):
    note = NoteBuilder(Document(title="Press", language="en"), frame="none")
    note.add_section(Section(key="demo", title="Demo", body="Text."))
    text = note.render(tmp_path).read_text(encoding="utf-8")
    assert r"\usepackage[english]{babel}" in text and "Contents" in text


def test_section_needs_a_clean_key_and_one_source():
    with pytest.raises(ValueError, match="key"):
        Section(key="Kinematics 1", title="x", body="y")
    with pytest.raises(ValueError, match="exactly one"):
        Section(key="k", title="x")
    note = NoteBuilder(Document())
    note.add_section(Section(key="k", title="x", body="y"))
    with pytest.raises(ValueError, match="twice"):
        note.add_section(Section(key="k", title="z", body="w"))


def test_assignment_goes_between_title_page_and_contents(tmp_path):
    assignment = Section(key="assignment", title="", body="Текст задания: схема и таблицы.")
    note = NoteBuilder(Document(title="Пресс"), assignment=assignment, frame="none")
    text = note.render(tmp_path).read_text(encoding="utf-8")
    title_end = text.index(r"\end{singlespace}")
    at = text.index(r"\noteplainheading{Задание на курсовой проект}")
    contents = text.index(r"\notecontents{Содержание}")
    assert title_end < at < text.index("схема и таблицы") < contents
    assert text.index(r"\noteframetrue") > at      # no frame on the title and assignment pages


def test_a_record_that_misprints_is_refused_at_render(tmp_path):
    from dataclasses import replace
    bad = replace(record("d", "x - y", "м", x=1.23456, y=1.23321), input_digits=4)
    tpl = tmp_path / "t"
    tpl.mkdir()
    (tpl / "bad.tex.j2").write_text(r"\VAR{m.calc(r)}", encoding="utf-8")
    note = NoteBuilder(Document(), frame="none", template_dirs=[tpl])
    note.add_section(Section(key="k", title="K", template="bad.tex.j2", context={"r": bad}))
    with pytest.raises(InternalError, match="do not reproduce"):
        note.render(tmp_path / "out")
