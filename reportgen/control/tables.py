"""The 22 assignment tables of the control work (seed 001, §8) and their reconstructed schemes.

The data ship in ``reportgen/data/control_work/``: ``tables.toml`` holds the columns exactly as the
manual prints them, ``schemes.toml`` the layout of each table's mechanism, reconstructed (the manual's
pictures are lost) so that the printed dimensions assemble. Both are read once and kept immutable.
"""
from __future__ import annotations

import ast
import operator
import tomllib
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from types import MappingProxyType
from typing import Mapping

from ..errors import InternalError, OptionError

#: Number of variants in every table of the manual.
VARIANTS = 10


@dataclass(frozen=True)
class Column:
    """One printed column: heading, unit and values as printed, the quantities it names."""
    label: str
    unit: str
    keys: tuple[str, ...]
    printed: tuple[str, ...]
    derived: Mapping[str, str]

    def value(self, variant: int) -> float:
        """The value of variant ``variant`` (1…10) as a number (decimal comma read as a point)."""
        return float(self.printed[variant - 1].replace(",", "."))


@dataclass(frozen=True)
class Scheme:
    """The reconstructed layout of a table's mechanism (schemes.toml; all of it a reconstruction).

    A is the crank's axis at the origin, B the crank pin; D the rocker's axis at ``D`` (x, y), C the
    joint of coupler 2 and rocker 3 on the side ``c_side`` of the line B→D (+1 left); E is carried by
    link ``e_link`` (2 or 3): a ``bar`` point on the line ``e_from``→``e_toward`` at ``e_distance``,
    or a ``triangle`` vertex at ``e_distances`` from ``e_from``/``e_toward`` on side ``e_side``;
    ``e_kind`` = "none": no point E (link 4 starts at C); link 4 joins ``f_from`` (E, or C) to the
    slider's point ``slider`` (F, or E when there is no E on links 2, 3) on the frame guide through ``guide_through``
    at ``guide_angle_deg``, F on the side ``f_side`` (+1: forward along the guide).
    """
    table: int
    D: tuple[str, str]
    c_side: int
    e_link: int
    e_kind: str
    e_from: str
    e_toward: str
    e_distance: str
    e_distances: tuple[str, str]
    e_side: int
    f_from: str
    guide_through: tuple[str, str]
    guide_angle_deg: float
    f_side: int
    slider: str
    reasoning: str


@dataclass(frozen=True)
class Variant:
    """One variant of a table: its quantities (m, rad/s, deg) and whether the scheme assembles."""
    table: int
    number: int
    values: Mapping[str, float]
    flag: str | None                     # why the variant cannot form the mechanism (None: it can)

    @property
    def phi_deg(self) -> float:
        return self.values["phi_deg"]

    @property
    def omega1(self) -> float:
        return self.values["omega1"]


@dataclass(frozen=True)
class Table:
    number: int
    page: int
    columns: tuple[Column, ...]
    scheme: Scheme
    flags: Mapping[int, str]             # variant → the reason it cannot be built (schemes.toml)

    def variant(self, number: int) -> Variant:
        if not 1 <= number <= VARIANTS:
            raise OptionError("--variant", f"got {number}", f"a variant 1…{VARIANTS} of table {self.number}")
        values: dict[str, float] = {}
        for col in self.columns:
            for k in col.keys:
                values[k] = col.value(number)
            for k, expr in col.derived.items():
                values[k] = evaluate(expr, values)
        return Variant(self.number, number, MappingProxyType(values), self.flags.get(number))

    @property
    def variants(self) -> tuple[Variant, ...]:
        return tuple(self.variant(v) for v in range(1, VARIANTS + 1))

    @property
    def dimensions(self) -> tuple[Column, ...]:
        """The columns of lengths (all but φ and ω1)."""
        return tuple(c for c in self.columns if c.keys[0] not in ("phi_deg", "omega1"))


_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv}


def evaluate(expr: str, values: Mapping[str, float]) -> float:
    """An arithmetic expression of the table's quantities ("a", "-b", "l_CD + l_CE", "2*b", "0")."""
    def ev(node: ast.AST) -> float:
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            return float(node.value)
        if isinstance(node, ast.Name):
            return float(values[node.id])
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = ev(node.operand)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](ev(node.left), ev(node.right))
        raise InternalError("control_work/schemes.toml", f"unsupported expression {expr!r}")
    return ev(ast.parse(expr, mode="eval"))


def _read(name: str) -> dict:
    with resources.files("reportgen.data.control_work").joinpath(name).open("rb") as f:
        return tomllib.load(f)


def _scheme(raw: dict) -> Scheme:
    e = raw.get("E", {"link": 0, "kind": "none", "from": "", "toward": ""})
    g = raw["guide"]
    return Scheme(
        table=int(raw["table"]), D=tuple(raw["D"]), c_side=int(raw.get("c_side", 1)),
        e_link=int(e["link"]), e_kind=e["kind"], e_from=e["from"], e_toward=e["toward"],
        e_distance=e.get("distance", "0"), e_distances=tuple(e.get("distances", ("0", "0"))),
        e_side=int(e.get("side", 1)), f_from=raw.get("f_from", "E"),
        guide_through=tuple(g["through"]), guide_angle_deg=float(g["angle_deg"]),
        f_side=int(g.get("f_side", 1)), slider=raw.get("slider", "F"), reasoning=raw["reasoning"].strip())


@lru_cache(maxsize=1)
def _all() -> tuple[Table, ...]:
    schemes = {int(s["table"]): s for s in _read("schemes.toml")["scheme"]}
    out = []
    for t in _read("tables.toml")["table"]:
        n = int(t["number"])
        cols = tuple(Column(c["label"], c["unit"], tuple(c["keys"]), tuple(c["printed"]),
                            MappingProxyType(dict(c.get("derived", {})))) for c in t["column"])
        raw = schemes[n]
        flags = MappingProxyType({int(k): v for k, v in raw.get("flags", {}).items()})
        out.append(Table(n, int(t["page"]), cols, _scheme(raw), flags))
    return tuple(out)


def tables() -> tuple[Table, ...]:
    """All 22 tables, in the manual's order."""
    return _all()


def table(number: int) -> Table:
    """Table ``number`` (1…22)."""
    for t in _all():
        if t.number == number:
            return t
    raise OptionError("--table", f"got {number}", f"a table 1…{len(_all())} of the control work (see `reportgen new --list`)")
