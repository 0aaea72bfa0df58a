"""Reading the ``[crane]`` section of a task file into :class:`reportgen.crane.spec.Crane`.

Every key is validated with the readers of :mod:`reportgen.taskfile_values` (errors name the TOML
path, e.g. ``crane.hoist.rope.diameter_mm``, and what would be valid). The catalogue data are the
student's: they are read here and *checked* by the calculations (a rope weaker than required is a
failed check in the note, not an input error); an impossible value (a negative speed, an
efficiency above 1, more driven wheels than wheels) is refused here.
"""
from __future__ import annotations

from typing import Any

from ..errors import TaskError
from ..taskfile_values import Int, Number, Str, Table, Word, array_of_tables, index
from .rules import GROUPS, RULES
from .spec import (Brake, Coupling, Crane, Drum, Hoist, Motor, OpenGear, Polyspast, Rail, Reducer, Rope,
                   Trolley, Wheel)

CRANE_KEYS = ("name", "group", "rules", "use_class", "load_class", "span_m", "g", "hoist", "trolley")
HOIST_KEYS = ("capacity_t", "hook_mass_kg", "lifting_height_m", "lifting_speed_m_min", "max_acceleration",
              "max_start_time", "polyspast", "rope", "drum", "motor", "reducer", "open_gear", "coupling",
              "brake")
POLYSPAST_KEYS = ("ratio", "branches", "block_efficiency", "guide_blocks", "hook_block_diameter_mm",
                  "hook_block_spread_mm")
ROPE_KEYS = ("designation", "diameter_mm", "breaking_force_kn")
DRUM_KEYS = ("diameter_mm", "groove_pitch_mm", "wall_mm", "allowable_stress_mpa", "material",
             "reserve_turns", "clamp_turns", "smooth_length_mm", "end_length_mm", "ring_width_mm",
             "hook_distance_mm", "efficiency")
MOTOR_KEYS = ("designation", "power_kw", "pv_percent", "speed_rpm", "rotor_inertia", "max_torque_ratio",
              "start_torque_ratio")
REDUCER_KEYS = ("designation", "ratio", "rated_torque", "efficiency")
OPEN_GEAR_KEYS = ("z1", "z2", "module_mm", "efficiency")
COUPLING_KEYS = ("designation", "rated_torque", "inertia")
BRAKE_KEYS = ("designation", "rated_torque", "pulley_diameter_mm", "count")
TROLLEY_KEYS = ("mass_t", "speed_m_min", "wheel_base_m", "gauge_m", "wheels", "driven_wheels",
                "travel_length_m", "max_acceleration", "max_start_time", "brake_deceleration", "adhesion", "adhesion_safety",
                "wheel", "rail", "motor", "reducer", "coupling", "brake")
WHEEL_KEYS = ("designation", "diameter_mm", "journal_diameter_mm", "tread_width_mm", "allowable_load_kn",
              "rolling_arm_mm", "bearing_friction", "flange_factor")
RAIL_KEYS = ("designation", "head_width_mm", "slope")
USE_CLASSES = ("А0", "А1", "А2", "А3", "А4", "А5", "А6")
LOAD_CLASSES = ("В1", "В2", "В3", "В4")

_POS = Number(gt=0)
_EFF = Number(gt=0, le=1)
_NAME = Str(nonempty=True)


def _pos(unit: str, le: float | None = None) -> Number:
    return Number(gt=0, le=le, unit=unit)


def read_crane(value: Any, path: str = "crane") -> Crane:
    t = Table(value, path, CRANE_KEYS)
    group = t.get("group", Word(*GROUPS))
    rules = t.get("rules", Word(*RULES), "PB-10-382-00")
    span = t.get("span_m", _pos("m", 200))
    hoist = _hoist(t.get("hoist", _TABLE), t.at("hoist"))
    trolley = _trolley(t.get("trolley", _TABLE), t.at("trolley"))
    return Crane(group=group, rules=rules, span_m=span, hoist=hoist, trolley=trolley,
                 use_class=t.get("use_class", Word(*USE_CLASSES), ""),
                 load_class=t.get("load_class", Word(*LOAD_CLASSES), ""),
                 g=t.get("g", Number(gt=9, lt=10.5, unit="m/s²"), 9.81), name=t.get("name", Str(), ""))


class _AnyTable(Str):
    expected = "a table"

    def read(self, value: Any, path: str) -> Any:
        if not isinstance(value, dict):
            raise self.fail(value, path)
        return value


_TABLE = _AnyTable()


def _hoist(value: Any, path: str) -> Hoist:
    t = Table(value, path, HOIST_KEYS)
    og = _open_gear(t.raw("open_gear"), t.at("open_gear")) if "open_gear" in t else None
    return Hoist(
        capacity_t=t.get("capacity_t", _pos("t", 2000)),
        hook_mass_kg=t.get("hook_mass_kg", Number(ge=0, unit="kg")),
        lifting_height_m=t.get("lifting_height_m", _pos("m", 500)),
        lifting_speed_m_min=t.get("lifting_speed_m_min", _pos("m/min", 300)),
        polyspast=_polyspast(t.get("polyspast", _TABLE), t.at("polyspast")),
        rope=_rope(t.get("rope", _TABLE), t.at("rope")),
        drum=_drum(t.get("drum", _TABLE), t.at("drum")),
        motor=_motor(t.get("motor", _TABLE), t.at("motor")),
        reducer=_reducer(t.get("reducer", _TABLE), t.at("reducer")),
        couplings=_couplings(t, "crane.hoist.coupling"),
        brake=_brake(t.get("brake", _TABLE), t.at("brake")),
        open_gear=og,
        max_acceleration=t.get("max_acceleration", _pos("m/s²", 5), 0.2),
        max_start_time=t.get("max_start_time", _pos("s", 60), 2.0),
    )


def _polyspast(value: Any, path: str) -> Polyspast:
    t = Table(value, path, POLYSPAST_KEYS)
    return Polyspast(
        ratio=t.get("ratio", Int(ge=1, le=20, what="the polyspast ratio: an integer")),
        branches=t.get("branches", Int(ge=1, le=2, what="rope branches wound on the drum: 1 or 2")),
        block_efficiency=t.get("block_efficiency", Number(gt=0.8, le=1), 0.98),
        guide_blocks=t.get("guide_blocks", Int(ge=0, le=10, what="guide blocks: an integer"), 0),
        hook_block_diameter_mm=t.get("hook_block_diameter_mm", _pos("mm", 5000)),
        hook_block_spread_mm=t.get("hook_block_spread_mm", Number(ge=0, le=5000, unit="mm"), 0.0),
    )


def _rope(value: Any, path: str) -> Rope:
    t = Table(value, path, ROPE_KEYS)
    return Rope(t.get("designation", _NAME), t.get("diameter_mm", _pos("mm", 200)),
                t.get("breaking_force_kn", _pos("kN", 1e5)))


def _drum(value: Any, path: str) -> Drum:
    t = Table(value, path, DRUM_KEYS)
    d = Drum(
        diameter_mm=t.get("diameter_mm", _pos("mm", 5000)),
        groove_pitch_mm=t.get("groove_pitch_mm", _pos("mm", 300)),
        wall_mm=t.get("wall_mm", _pos("mm", 300)),
        allowable_stress_mpa=t.get("allowable_stress_mpa", _pos("MPa", 2000)),
        material=t.get("material", Str(), ""),
        reserve_turns=t.get("reserve_turns", Number(ge=0, le=10), 1.5),
        clamp_turns=t.get("clamp_turns", Number(ge=0, le=10), 3.0),
        smooth_length_mm=t.get("smooth_length_mm", Number(ge=0, le=10000, unit="mm"), 0.0),
        end_length_mm=t.get("end_length_mm", Number(ge=0, le=2000, unit="mm"), 0.0),
        ring_width_mm=t.get("ring_width_mm", Number(ge=0, le=2000, unit="mm"), 0.0),
        hook_distance_mm=t.get("hook_distance_mm", Number(ge=0, le=50000, unit="mm"), 0.0),
        efficiency=t.get("efficiency", _EFF, 0.99),
    )
    if d.wall_mm * 2 >= d.diameter_mm:
        raise TaskError(t.at("wall_mm"), f"a wall of {d.wall_mm:g} mm fills a drum of {d.diameter_mm:g} mm",
                        "a wall thinner than half the drum diameter")
    return d


def _motor(value: Any, path: str) -> Motor:
    t = Table(value, path, MOTOR_KEYS)
    m = Motor(
        designation=t.get("designation", _NAME),
        power_kw=t.get("power_kw", _pos("kW", 5000)),
        pv_percent=t.get("pv_percent", Number(gt=0, le=100, unit="%")),
        speed_rpm=t.get("speed_rpm", _pos("rpm", 10000)),
        rotor_inertia=t.get("rotor_inertia", _pos("kg·m²", 1000)),
        max_torque_ratio=t.get("max_torque_ratio", Number(gt=1, le=5)),
        start_torque_ratio=t.get("start_torque_ratio", Number(gt=1, le=5), 1.5),
    )
    if m.start_torque_ratio >= m.max_torque_ratio:
        raise TaskError(f"{path}.start_torque_ratio", f"{m.start_torque_ratio:g} is not below the maximum "
                        f"torque ratio {m.max_torque_ratio:g}", "a mean starting torque ratio below max_torque_ratio")
    return m


def _reducer(value: Any, path: str) -> Reducer:
    t = Table(value, path, REDUCER_KEYS)
    return Reducer(t.get("designation", _NAME), t.get("ratio", Number(gt=1, le=1000)),
                   t.get("rated_torque", _pos("N·m", 1e7)), t.get("efficiency", _EFF))


def _open_gear(value: Any, path: str) -> OpenGear:
    t = Table(value, path, OPEN_GEAR_KEYS)
    z = Int(ge=8, le=500, what="a number of teeth: an integer")
    og = OpenGear(t.get("z1", z), t.get("z2", z), t.get("module_mm", _pos("mm", 100)),
                  t.get("efficiency", _EFF, 0.96))
    if og.z2 <= og.z1:
        raise TaskError(f"{path}.z2", f"{og.z2} teeth on the drum's wheel, {og.z1} on the pinion",
                        "z2 > z1 (the open gear reduces the speed)")
    return og


def _couplings(t: Table, header: str) -> tuple[Coupling, ...]:
    path = t.at("coupling")
    items = array_of_tables(t.get("coupling", _ANY), path, header)
    if not items:
        raise TaskError(path, "has no couplings", f"at least one [[{header}]] on the motor shaft")
    out = []
    for i, v in enumerate(items):
        ct = Table(v, index(path, i), COUPLING_KEYS)
        out.append(Coupling(ct.get("designation", _NAME), ct.get("rated_torque", _pos("N·m", 1e7)),
                            ct.get("inertia", Number(ge=0, le=1000, unit="kg·m²"))))
    return tuple(out)


class _Any(Str):
    expected = "an array of tables"

    def read(self, value: Any, path: str) -> Any:
        return value


_ANY = _Any()


def _brake(value: Any, path: str) -> Brake:
    t = Table(value, path, BRAKE_KEYS)
    return Brake(t.get("designation", _NAME), t.get("rated_torque", _pos("N·m", 1e6)),
                 t.get("pulley_diameter_mm", _pos("mm", 2000)),
                 t.get("count", Int(ge=1, le=2, what="brakes on the mechanism: 1 or 2"), 1))


def _trolley(value: Any, path: str) -> Trolley:
    t = Table(value, path, TROLLEY_KEYS)
    wheels = t.get("wheels", Int(ge=3, le=16, what="trolley wheels: an integer"))
    driven = t.get("driven_wheels", Int(ge=1, le=16, what="driven wheels: an integer"))
    if driven > wheels:
        raise TaskError(t.at("driven_wheels"), f"{driven} driven of {wheels} wheels",
                        f"at most {wheels} (trolley.wheels)")
    return Trolley(
        mass_t=t.get("mass_t", _pos("t", 2000)),
        speed_m_min=t.get("speed_m_min", _pos("m/min", 300)),
        wheel_base_m=t.get("wheel_base_m", _pos("m", 50)),
        gauge_m=t.get("gauge_m", _pos("m", 50)),
        wheels=wheels, driven_wheels=driven,
        wheel=_wheel(t.get("wheel", _TABLE), t.at("wheel")),
        rail=_rail(t.get("rail", _TABLE), t.at("rail")),
        motor=_motor(t.get("motor", _TABLE), t.at("motor")),
        reducer=_reducer(t.get("reducer", _TABLE), t.at("reducer")),
        couplings=_couplings(t, "crane.trolley.coupling"),
        brake=_brake(t.get("brake", _TABLE), t.at("brake")),
        travel_length_m=t.get("travel_length_m", Number(ge=0, le=200, unit="m"), 0.0),
        max_acceleration=t.get("max_acceleration", _pos("m/s²", 5), 0.2),
        max_start_time=t.get("max_start_time", _pos("s", 60), 5.0),
        brake_deceleration=t.get("brake_deceleration", _pos("m/s²", 5), 0.1),
        adhesion=t.get("adhesion", Number(gt=0, lt=1), 0.2),
        adhesion_safety=t.get("adhesion_safety", Number(ge=1, le=5), 1.2),
    )


def _wheel(value: Any, path: str) -> Wheel:
    t = Table(value, path, WHEEL_KEYS)
    w = Wheel(
        designation=t.get("designation", _NAME),
        diameter_mm=t.get("diameter_mm", _pos("mm", 3000)),
        journal_diameter_mm=t.get("journal_diameter_mm", _pos("mm", 1000)),
        tread_width_mm=t.get("tread_width_mm", _pos("mm", 500)),
        allowable_load_kn=t.get("allowable_load_kn", _pos("kN", 1e5)),
        rolling_arm_mm=t.get("rolling_arm_mm", Number(gt=0, le=5, unit="mm"), 0.6),
        bearing_friction=t.get("bearing_friction", Number(gt=0, lt=0.5), 0.015),
        flange_factor=t.get("flange_factor", Number(ge=1, le=5), 2.0),
    )
    if w.journal_diameter_mm >= w.diameter_mm:
        raise TaskError(f"{path}.journal_diameter_mm", f"{w.journal_diameter_mm:g} mm is not below the wheel "
                        f"diameter {w.diameter_mm:g} mm", "a journal smaller than the wheel")
    return w


def _rail(value: Any, path: str) -> Rail:
    t = Table(value, path, RAIL_KEYS)
    return Rail(t.get("designation", _NAME), t.get("head_width_mm", _pos("mm", 500)),
                t.get("slope", Number(ge=0, le=0.05), 0.002))
