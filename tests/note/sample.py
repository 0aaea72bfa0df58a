"""A small sample note (one dummy section made of records, a long table and a vector figure)."""
from __future__ import annotations

from pathlib import Path

from reportgen.calc import Var, record
from reportgen.task import Document

from latex_templates import NoteBuilder, Section, tex

NASTY_TITLE = r"Пресс #1 & $x_5$ ~ 100% {a} ^ \relax"

SECTION_TEMPLATE = r"""
\subsection{Скорости}
Скорость точки $A$ кривошипа
\VAR{m.calc(va)}
Ускорение точки $A$ (скорость по формуле~\eqref{eq:va})
\VAR{m.calc(aa)}
Длина диагонали
\VAR{m.calc(ac)}
\VAR{m.table("Скорости точек", header, rows, decimals=[0, 3, None])}
Результаты показаны на рисунке~\ref{\VAR{figures.plot.label}}.
\VAR{m.figure(figures.plot, "Перемещение ползуна")}
"""


def sample_records() -> dict:
    w = Var("omega1", r"\omega_1", 18.0, "рад/с", "угловая скорость кривошипа")
    l_oa = Var("l_OA", r"l_{OA}", 0.11, "м", "длина кривошипа")
    va = record("V_A", "omega1*l_OA", "м/с", w, l_oa, label="eq:va")
    aa = record("a_A", "omega1**2*l_OA", "м/с²", w, l_oa)
    ac = record(r"l_{AC}", "sqrt(a**2 + b**2 - 2*a*b*cos(radians(g)))", "м",
                a=l_oa, b=Var("b", "l_{AB}", 0.38, "м", "длина шатуна"),
                g=Var("g", r"\gamma", 120.0, "°", "угол между кривошипом и шатуном"))
    return {"va": va, "aa": aa, "ac": ac}


def sample_note(tmp: Path, *, body_template: str = SECTION_TEMPLATE, title: str = NASTY_TITLE,
                frame: str = "eskd") -> NoteBuilder:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 3))
    ax.plot([0, 90, 180, 270, 360], [0, 0.1, 0.2, 0.1, 0])
    ax.set_xlabel("φ1, °")
    tpl_dir = tmp / "templates"
    tpl_dir.mkdir(parents=True, exist_ok=True)
    (tpl_dir / "dummy.tex.j2").write_text(body_template, encoding="utf-8")
    doc = Document(title=title, author="И. И. Иванов", group="ТМ-21", supervisor="А. П. Слободюк",
                   organization="Кафедра теории механизмов и машин", city="Белгород", year=2026)
    note = NoteBuilder(doc, template_dirs=[tpl_dir], frame=frame, designation="ТММ.КП.01.00.000 ПЗ",
                       conclusions=["Скорость точки A равна 1,98 м/с."])
    rows = [[45.0 * i, 1.98 + 0.0015 * i, f"п_{i}"] for i in range(40)]
    header = [tex(r"$\varphi_1$, \textdegree"), tex(r"$V_A$, м/с"), "Примечание"]
    note.add_section(Section(key="kinematics", title="Кинематический анализ",
                             template="dummy.tex.j2",
                             context={**sample_records(), "rows": rows, "header": header},
                             figures={"plot": fig}))
    plt.close(fig)
    return note
