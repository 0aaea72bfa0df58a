"""A demonstration sheet shared by the drawing tests: a crank-rocker scheme with hinge symbols,
a velocity plan with lettered vectors, a dimension, and a diagram with axes."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from drawings import Sheet


@dataclass(frozen=True)
class FakeDocument:
    """Stands in for ``reportgen.task.Document``."""
    title: str = "Проектирование и исследование механизма пресса"
    author: str = "Иванов И. И."
    group: str = "ТМ-21"
    supervisor: str = "Слободюк А. П."
    organization: str = "БГТУ им. В. Г. Шухова"
    city: str = "Белгород"
    year: int | None = 2026
    language: str = "ru"


def crank_rocker(phi_deg: float):
    """Positions (m) of a crank-rocker O–A–B–C at crank angle ``phi_deg``."""
    o, c = np.array([0.0, 0.0]), np.array([0.28, 0.0])
    l1, l2, l3 = 0.08, 0.26, 0.18
    a = o + l1 * np.array([math.cos(math.radians(phi_deg)), math.sin(math.radians(phi_deg))])
    d = float(np.linalg.norm(c - a))
    x = (l2 * l2 - l3 * l3 + d * d) / (2 * d)
    h = math.sqrt((l2 - x) * (l2 + x))
    u = (c - a) / d
    b = a + x * u + h * np.array([-u[1], u[0]])
    return o, a, b, c


def build_demo_sheet() -> Sheet:
    sheet = Sheet.a1(FakeDocument(), title="Кинематический анализ рычажного механизма",
                     code="ТММ.КП.01.001", number=1, count=4)
    o, a, b, c = crank_rocker(60.0)
    pts = np.array([o, a, b, c])
    mu_l = 0.002  # m/mm
    scheme = sheet.add_model_view("scheme", (pts[:, 0].min(), pts[:, 1].min(), pts[:, 0].max(),
                                             pts[:, 1].max()), 1 / mu_l, padding_mm=30)
    r = 2.0
    scheme.segment(o, a, trim_mm=(r, r))
    scheme.segment(a, b, trim_mm=(r, r))
    scheme.segment(b, c, trim_mm=(r, r))
    for p in (a, b):
        scheme.hinge(p, r)
    scheme.fixed_pivot(o)
    scheme.fixed_pivot(c)
    scheme.line((o[0] - 0.02, o[1]), (c[0] + 0.02, c[1]), layer="axis")
    for name, p in zip("OABC", pts):
        scheme.label(p, name)
    scheme.dimension(o, c, offset_mm=-22.0, unit_factor=1000.0, decimals=0)
    scheme.scale_caption((pts[:, 0].min(), pts[:, 1].min() - 0.08), "μl", mu_l, "м/мм")
    scheme.title("Кинематическая схема")

    # velocity plan: p → a, p → b, a → b (mm of the plan, scale 1)
    plan = sheet.add_view("plan_v", 140, 130, preferred="top-right")
    p0 = (40.0, 40.0)
    va = (p0[0] - 60.0 * math.sin(math.radians(60)), p0[1] + 60.0 * math.cos(math.radians(60)))
    vb = (p0[0] + 45.0, p0[1] + 52.0)
    plan.arrow(p0, va, "a")
    plan.arrow(p0, vb, "b")
    plan.arrow(va, vb)
    plan.label(p0, "p", prefer_deg=225)
    plan.text((5.0, 8.0), "μv = 0,02 (м/с)/мм", 5.0)
    plan.title("План скоростей")

    # a diagram with axes
    graph = sheet.add_view("graph", 260, 120, preferred="bottom-left")
    x0, y0 = 15.0, 50.0
    xs = np.linspace(0, 200, 121)
    ys = 40 * np.sin(np.radians(xs * 360 / 200))
    graph.axes((x0, y0), 220, 55, 45, x_label="φ1", y_label="Мпр, Н·м",
               x_ticks=[(i * 200 / 12, str(i)) for i in range(1, 13)],
               y_ticks=[(-40, "-40"), (-20, "-20"), (20, "20"), (40, "40")])
    graph.curve(xs + x0, ys + y0)
    graph.title("Диаграмма приведённого момента")
    return sheet
