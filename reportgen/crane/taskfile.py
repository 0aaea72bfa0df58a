"""Reading the ``[crane]`` section of a task file into :class:`reportgen.crane.spec.Crane`.

Every key is read with the spec and default of ``reportgen.taskspec`` (its crane sections are
``reportgen.crane.taskspec``): errors name the TOML path (``crane.hoist.rope.diameter_mm``) and what
would be valid. The catalogue data are the student's: they are read here and *checked* by the
calculations (a rope weaker than required is a failed check in the note, not an input error); an
impossible value (a negative speed, an efficiency above 1, more driven wheels than wheels, a wall
thicker than half the drum) is refused here.
"""
from __future__ import annotations

from typing import Any

from ..errors import TaskError
from ..taskfile_values import Table, array_of_tables, index
from .spec import (Brake, Coupling, Crane, Drum, Hoist, Motor, OpenGear, Polyspast, Rail, Reducer, Rope,
                   Trolley, Wheel)


def _section(path: str):
    from ..taskspec import SECTION
    return SECTION[path]


def _table(value: Any, path: str, spec_path: str) -> Table:
    if not isinstance(value, dict):
        raise TaskError(path, "is not a table", f"a table [{spec_path}]")
    return Table(value, path, _section(spec_path).names)


def _get(t: Table, spec_path: str, key: str) -> Any:
    sec = _section(spec_path)
    return t.get(key, sec[key].spec, sec.default(key))


def _sub(t: Table, spec_path: str, key: str) -> Table:
    sub = f"{spec_path}.{key}"
    if key not in t:
        raise TaskError(t.at(key), "is missing", f"a table [{sub}]")
    return _table(t.raw(key), t.at(key), sub)


def _read(cls: type, t: Table, spec_path: str, **extra: Any) -> Any:
    """``cls`` from every value key of the table (its fields carry the keys' names)."""
    values = {k.name: _get(t, spec_path, k.name) for k in _section(spec_path).keys if not k.table}
    return cls(**values, **extra)


def read_crane(value: Any, path: str = "crane") -> Crane:
    t = _table(value, path, "crane")
    values = {k.name: _get(t, "crane", k.name) for k in _section("crane").keys if not k.table}
    hoist = _hoist(_sub(t, "crane", "hoist"))
    trolley = _trolley(_sub(t, "crane", "trolley"))
    return Crane(hoist=hoist, trolley=trolley, **values)


def _hoist(t: Table) -> Hoist:
    p = "crane.hoist"
    og = _open_gear(_sub(t, p, "open_gear")) if "open_gear" in t else None
    drum = _read(Drum, _sub(t, p, "drum"), f"{p}.drum")
    if drum.wall_mm * 2 >= drum.diameter_mm:
        raise TaskError(f"{t.at('drum')}.wall_mm", f"a wall of {drum.wall_mm:g} mm fills a drum of "
                        f"{drum.diameter_mm:g} mm", "a wall thinner than half the drum diameter")
    return _read(Hoist, t, p,
                 polyspast=_read(Polyspast, _sub(t, p, "polyspast"), f"{p}.polyspast"),
                 rope=_read(Rope, _sub(t, p, "rope"), f"{p}.rope"), drum=drum,
                 motor=_motor(_sub(t, p, "motor"), f"{p}.motor"),
                 reducer=_read(Reducer, _sub(t, p, "reducer"), f"{p}.reducer"),
                 couplings=_couplings(t, p), brake=_read(Brake, _sub(t, p, "brake"), f"{p}.brake"),
                 open_gear=og)


def _motor(t: Table, spec_path: str) -> Motor:
    m = _read(Motor, t, spec_path)
    if m.start_torque_ratio >= m.max_torque_ratio:
        raise TaskError(t.at("start_torque_ratio"), f"{m.start_torque_ratio:g} is not below the maximum "
                        f"torque ratio {m.max_torque_ratio:g}", "a mean starting torque ratio below max_torque_ratio")
    return m


def _open_gear(t: Table) -> OpenGear:
    og = _read(OpenGear, t, "crane.hoist.open_gear")
    if og.z2 <= og.z1:
        raise TaskError(t.at("z2"), f"{og.z2} teeth on the drum's wheel, {og.z1} on the pinion",
                        "z2 > z1 (the open gear reduces the speed)")
    return og


def _couplings(t: Table, spec_path: str) -> tuple[Coupling, ...]:
    path = t.at("coupling")
    header = f"{spec_path}.coupling"
    if "coupling" not in t:
        raise TaskError(path, "is missing", f"at least one [[{header}]] on the motor shaft")
    items = array_of_tables(t.raw("coupling"), path, header)
    if not items:
        raise TaskError(path, "has no couplings", f"at least one [[{header}]] on the motor shaft")
    return tuple(_read(Coupling, _table(v, index(path, i), header), header) for i, v in enumerate(items))


def _trolley(t: Table) -> Trolley:
    p = "crane.trolley"
    tr = _read(Trolley, t, p,
               wheel=_wheel(_sub(t, p, "wheel")), rail=_read(Rail, _sub(t, p, "rail"), f"{p}.rail"),
               motor=_motor(_sub(t, p, "motor"), f"{p}.motor"),
               reducer=_read(Reducer, _sub(t, p, "reducer"), f"{p}.reducer"),
               couplings=_couplings(t, p), brake=_read(Brake, _sub(t, p, "brake"), f"{p}.brake"))
    if tr.driven_wheels > tr.wheels:
        raise TaskError(t.at("driven_wheels"), f"{tr.driven_wheels} driven of {tr.wheels} wheels",
                        f"at most {tr.wheels} (trolley.wheels)")
    return tr


def _wheel(t: Table) -> Wheel:
    w = _read(Wheel, t, "crane.trolley.wheel")
    if w.journal_diameter_mm >= w.diameter_mm:
        raise TaskError(t.at("journal_diameter_mm"), f"{w.journal_diameter_mm:g} mm is not below the wheel "
                        f"diameter {w.diameter_mm:g} mm", "a journal smaller than the wheel")
    return w
