"""Shared presentation of the crane note (course «Грузоподъёмные машины»): records with their «где»
words from ``strings/ru/crane.toml``, check sentences, the summary table, the note's strings overlay.

A crane part is a list of *blocks* rendered in order by ``sections/crane_blocks.tex.j2``::

    ("sub", title)    a subsection         ("text", tex)      a paragraph
    ("calc", record)  a numbered formula   ("table", dict)    a table (caption, header, rows)

so the order of the course lives in Python (one place) and every word in the catalogue.
"""
from __future__ import annotations

import math
import re
from dataclasses import replace

from markupsafe import Markup

from reportgen.calc import CalcRecord, format_decimal, unit_latex
from reportgen.crane.steps import upright_cyrillic_in_math
from reportgen.errors import NameLookupError
from reportgen.tolerances import ABS_ZERO, RTOL_EQUAL

from ..render import Strings, _StringTable, escape_latex


class CraneStrings(Strings):
    """The catalogue with ``crane.note.<key>`` overlaying ``<key>`` (title page, introduction,
    references of the crane document); everything else as usual."""

    def raw(self, key: str):
        if not key.startswith("crane."):
            try:
                value = super().raw(f"crane.note.{key}")
            except KeyError:
                value = None
            if value is not None and not isinstance(value, dict):
                return value        # a leaf of the overlay
        return super().raw(key)

    def get(self, key: str):
        if not key.startswith("crane."):
            try:
                value = super().get(f"crane.note.{key}")
            except KeyError:
                value = None
            if value is not None and not isinstance(value, _StringTable):
                return value        # a leaf of the overlay; a table is overlaid leaf by leaf
        return super().get(key)


def strings_of(project) -> Strings:
    return CraneStrings(project.task.document.language or "ru")


def where_word(strings: Strings, mechanism: str, key: str) -> str:
    """The «где» meaning of a quantity key: ``crane.where.<mechanism>.<key>``, then
    ``crane.where.<key>``, then the key without a trailing index (``J_c2`` → ``J_c``)."""
    for k in (f"crane.where.{mechanism}.{key}", f"crane.where.{key}",
              f"crane.where.{re.sub(r'[0-9]+$', '', key)}"):
        try:
            value = strings.get(k)
        except KeyError:
            continue
        if isinstance(value, str):
            return value
    raise NameLookupError("«где» words (crane.where.<key> in strings/ru/crane.toml)", key)


_INDEX = re.compile(r"^(.*?)([0-9]+)$")


def symbol_in(strings: Strings, mechanism: str, key: str, latex: str) -> str:
    """The symbol of the quantity ``key`` in the note's language.

    The solver writes the course's Russian symbols (``D_{\\text{бл}}``), which Russian prints as
    they are. Ukrainian and English give each quantity its own symbol in the catalogue table
    ``crane_symbols`` (docs/languages.md: one Russian subscript stands for several words — «т» is
    тележка, тормоз and тихоходный — so a table of subscripts cannot translate them):
    ``crane_symbols.<mechanism>.<key>``, then ``crane_symbols.<key>``; a table there is keyed by the
    Russian symbol (one key, two formulas: ``h_dr`` is h₁ under ПБ 10-382-00 and e_б under the 1969
    rules); an indexed key (``J_c2``) takes ``crane_symbols.J_c#`` with ``#`` the index the Russian
    symbol shows. A missing symbol in uk/en is a :class:`MissingString`.
    """
    if not strings.has("crane_symbols"):
        return latex
    for k in (f"crane_symbols.{mechanism}.{key}", f"crane_symbols.{key}"):
        if strings.has(k):
            value = strings.raw(k)
            if isinstance(value, dict):
                if latex not in value:
                    strings.raw(f"{k}.{latex}")        # raises MissingString naming the symbol
                value = value[latex]
            return str(value)
    m = _INDEX.match(key)
    if m and strings.has(f"crane_symbols.{m.group(1)}#"):
        shown_index = m.group(2) if re.search(m.group(2) + r"\W*$", latex) else ""
        return str(strings.raw(f"crane_symbols.{m.group(1)}#")).replace("#", shown_index)
    strings.raw(f"crane_symbols.{key}")                # raises MissingString
    return latex


def localize(rec: CalcRecord, strings: Strings, mechanism: str) -> CalcRecord:
    """The record with the catalogue's meanings and symbols for itself and each of its variables."""
    variables = tuple(replace(v, latex=symbol_in(strings, mechanism, v.meaning or v.name, v.latex),
                              meaning=Markup(where_word(strings, mechanism, v.meaning or v.name)))
                      for v in rec.variables)
    return replace(rec, variables=variables, symbol=symbol_in(strings, mechanism, rec.meaning, rec.symbol),
                   meaning=Markup(where_word(strings, mechanism, rec.meaning)))


def m(value: float, digits: int = 4) -> str:
    return format_decimal(float(value), digits)


def fmt(template, **values) -> Markup:
    """A catalogue sentence with ``{name}`` fields: numbers in math form, text escaped."""
    out = {}
    for k, v in values.items():
        if isinstance(v, Markup):
            out[k] = v
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            out[k] = Markup(m(v))
        else:
            out[k] = escape_latex(v)
    return Markup(upright_cyrillic_in_math(str(template).format(**out)))


class Blocks:
    """Builds the block list of a part."""

    def __init__(self, calc, strings: Strings, mechanism: str) -> None:
        self.calc = calc
        self.s = strings
        self.mech = mechanism
        self.items: list[tuple] = []

    def sub(self, key: str) -> None:
        self.items.append(("sub", self.s.get(f"crane.sub.{key}")))

    def text(self, key: str, **values) -> None:
        self.items.append(("text", fmt(self.s.get(f"crane.text.{key}"), **values)))

    def raw(self, tex: Markup) -> None:
        self.items.append(("text", Markup(tex)))

    def rec(self, *keys: str) -> None:
        for key in keys:
            if key in self.calc.records:
                self.items.append(("calc", localize(self.calc.records[key], self.s, self.mech)))

    def check(self, key: str) -> None:
        """The sentence of a check: its symbols, numbers, verdict and (failed) the advice."""
        c = next((c for c in self.calc.checks if c.key == key), None)
        if c is None:
            return
        self.items.append(("text", check_sentence(c, self.calc, self.s, self.mech)))

    def table(self, caption, header, rows) -> None:
        self.items.append(("table", {"caption": caption, "header": header, "rows": rows}))


#: The quantity keys whose symbols stand for (value, limit) of each check.
CHECK_SYMBOLS = {
    "rope": ("F_br", "F_req"), "block": ("D_bl", "D_bl_min"), "drum": ("D_c", "D_dr_min"),
    "groove": ("t", None), "reserve_turns": ("z_res", None), "smooth_min": ("l_0", "B"),
    "smooth_max": ("l_0", "l_0max"), "wall": ("sigma_a", "sigma"), "speed": ("dv", "dv_max"),
    "overload": ("M_lim", "M_st"), "start_torque": ("M_p", "M_st"), "acceleration": ("a_p", "a_max"),
    "start_time": ("t_p", "t_max"), "heating": ("M_nom", "M_eq_pv"), "reducer_torque": ("T_r", "T_out"),
    "brake": ("T_bn", "T_br"), "wheel_load": ("P_a", "P_max"), "tread_min": ("gap", None),
    "tread_max": ("gap", None), "adhesion_start": ("k_sp", "k_adh"), "adhesion_brake": ("k_sb", "k_adh"),
}


def _symbol(calc, key: str | None, strings: Strings | None = None, mechanism: str = "") -> str:
    if key is None:
        return ""
    if key in calc.records:
        latex = calc.records[key].symbol
    elif key in calc.vars:
        latex = calc.vars[key].latex
    else:
        return ""
    return symbol_in(strings, mechanism, key, latex) if strings is not None else latex


def _as_printed(calc, key: str | None, value: float) -> str:
    """A checked quantity as its formula printed it (issue 12: «D_бл = 1130,5 мм» in (1.6) and
    «D_бл = 1130 ≥ …» in the check were one quantity with two roundings); else 4 digits."""
    rec = calc.records.get(key) if key else None
    if rec is not None and math.isclose(rec.value, value, rel_tol=RTOL_EQUAL, abs_tol=ABS_ZERO):
        return rec.result_number_latex()
    return m(value)


def check_sentence(c, calc, strings: Strings, mechanism: str = "") -> Markup:
    sym_a, sym_b = CHECK_SYMBOLS.get(c.key, (None, None))
    if c.key.startswith("coupling"):
        sym_a, sym_b = f"T_c{c.key[len('coupling'):]}", "T_c"
    rel = r"\ge" if c.relation == "≥" else r"\le"
    a = _symbol(calc, sym_a, strings, mechanism)
    b = _symbol(calc, sym_b, strings, mechanism)
    value = ("|" + a + "|" if c.key == "speed" and a else a)
    left = f"{value} = {_as_printed(calc, sym_a, c.value)}" if value else m(c.value)
    right = f"{b} = {_as_printed(calc, sym_b, c.limit)}" if b else m(c.limit)
    unit_tex = f"~{unit_latex(c.unit)}" if c.unit else ""
    verdict = strings.get("crane.text.pass" if c.passed else "crane.text.fail")
    text = fmt(strings.get("crane.text.check_line"), name=Markup(upright_cyrillic_in_math(strings.get(f"crane.checks.{c.key}"))),
               a=Markup(left), rel=Markup(rel), b=Markup(right), unit=Markup(unit_tex), verdict=verdict)
    if not c.passed and c.advice:
        value = c.advice_value
        advice = fmt(strings.get(f"crane.advice.{c.advice}"),
                     value=Markup(m(value)) if value is not None else Markup(""))
        text = Markup(text + " " + strings.get("crane.text.advice_lead") + " " + advice)
    return text


def summary_rows(calc, strings: Strings) -> list[tuple]:
    """One row a check: its name, the condition with its numbers, the verdict."""
    rows = []
    for c in calc.checks:
        rel = r"\ge" if c.relation == "≥" else r"\le"
        unit = f"~{unit_latex(c.unit)}" if c.unit else ""
        rows.append((strings.get(f"crane.checks.{c.key}"),
                     Markup("$" + m(c.value) + " " + rel + " " + m(c.limit) + unit + "$"),
                     strings.get("crane.text.ok" if c.passed else "crane.text.no")))
    return rows


def summary(b: Blocks) -> None:
    s = b.s
    b.sub("summary")
    b.text("summary_intro")
    b.table(s.get("crane.sub.summary"), [s.get("crane.text.head_check"), s.get("crane.text.head_condition"),
                                         s.get("crane.text.head_result")],
            summary_rows(b.calc, s))


def failed_names(calc, strings: Strings) -> str:
    return "; ".join(str(strings.get(f"crane.checks.{c.key}")) for c in calc.checks if not c.passed)
