"""The ``[crane]`` sections of the task format as data (``reportgen.taskspec`` appends them): every
key, its spec, meaning, example and default. ``reportgen.crane.taskfile`` reads each key with the
spec and default given here, and ``reportgen.taskdoc`` writes the reference and the JSON Schema from
the same entries."""
from __future__ import annotations

from typing import Any

from ..taskfile_values import REQUIRED, Int, Number, Str, Word
from .rules import GROUPS, RULES
from .spec import Brake, Drum, Hoist, Motor, OpenGear, Polyspast, Rail, Trolley, Wheel


def _d(cls: Any, name: str) -> Any:
    return cls.__dataclass_fields__[name].default


def _pos(unit: str, le: float | None = None) -> Number:
    return Number(gt=0, le=le, unit=unit)


EFF = Number(gt=0, le=1)
NAME = Str(nonempty=True)
USE_CLASSES = ("А0", "А1", "А2", "А3", "А4", "А5", "А6")
LOAD_CLASSES = ("В1", "В2", "В3", "В4")


def crane_sections(Key, Section, OPTIONAL) -> tuple:
    """The sections, built with ``reportgen.taskspec``'s Key and Section (passed in: no cycle)."""
    def motor(path: str, example: dict) -> Any:
        return Section(path, "the motor chosen from the catalogue", "Checked by overload, start and heating.", (
            Key("designation", NAME, "the catalogue designation", example["designation"]),
            Key("power_kw", _pos("kW", 5000), "rated power at the motor's ПВ", example["power_kw"]),
            Key("pv_percent", Number(gt=0, le=100, unit="%"), "the ПВ of that rating", 25),
            Key("speed_rpm", _pos("rpm", 10000), "rated speed", example["speed_rpm"]),
            Key("rotor_inertia", _pos("kg·m²", 1000), "moment of inertia of the rotor", example["rotor_inertia"]),
            Key("max_torque_ratio", Number(gt=1, le=5), "ψ_max = M_max/M_nom", 2.8),
            Key("start_torque_ratio", Number(gt=1, le=5), "ψ_п: the mean starting torque / M_nom "
                "(below max_torque_ratio)", 1.5, _d(Motor, "start_torque_ratio")),
        ))

    def reducer(path: str, example: dict) -> Any:
        return Section(path, "the reducer chosen from the catalogue", "", (
            Key("designation", NAME, "the catalogue designation", example["designation"]),
            Key("ratio", Number(gt=1, le=1000), "gear ratio u_р", example["ratio"]),
            Key("rated_torque", _pos("N·m", 1e7), "rated torque on the output shaft", example["rated_torque"]),
            Key("efficiency", EFF, "efficiency η_р", 0.94),
        ))

    def coupling(path: str, example: dict) -> Any:
        return Section(path, "couplings on the motor shaft", "One [[…coupling]] per coupling; each is "
                       "checked by torque, their inertia counts at start.", (
                           Key("designation", NAME, "the catalogue designation", example["designation"]),
                           Key("rated_torque", _pos("N·m", 1e7), "rated torque", example["rated_torque"]),
                           Key("inertia", Number(ge=0, le=1000, unit="kg·m²"), "moment of inertia on the motor "
                               "shaft", example["inertia"]),
                       ), "array")

    def brake(path: str, example: dict) -> Any:
        return Section(path, "the brake chosen from the catalogue", "", (
            Key("designation", NAME, "the catalogue designation", example["designation"]),
            Key("rated_torque", _pos("N·m", 1e6), "rated braking torque", example["rated_torque"]),
            Key("pulley_diameter_mm", _pos("mm", 2000), "diameter of the brake pulley", example["pulley"]),
            Key("count", Int(ge=1, le=2, what="brakes on the mechanism: 1 or 2"), "brakes on the mechanism "
                "(two: each holds with 1,25)", 1, _d(Brake, "count")),
        ))

    return (
        Section("crane", "a bridge crane: hoist and trolley travel (docs/crane.md)",
                "A task with [crane] builds the crane note (course «Грузоподъёмные машины») and two sheets.", (
                    Key("name", Str(), "name of the crane in the note", "Мостовой кран 200 т", ""),
                    Key("group", Word(*GROUPS), "group of the mechanisms, ГОСТ 25835-83 (Cyrillic М)", "3М"),
                    Key("rules", Word(*RULES), "the rules of the coefficients: ПБ 10-382-00 or the 1969 rules",
                        "1969", "PB-10-382-00"),
                    Key("use_class", Word(*USE_CLASSES), "class of use, ГОСТ 25835-83 (informative)", "А4", ""),
                    Key("load_class", Word(*LOAD_CLASSES), "class of loading, ГОСТ 25835-83 (informative)", "В1", ""),
                    Key("span_m", _pos("m", 200), "span of the crane", 25.5),
                    Key("g", Number(gt=9, lt=10.5, unit="m/s²"), "gravity", 9.807, 9.81),
                    Key("hoist", None, "the hoist", None, table="crane.hoist"),
                    Key("trolley", None, "the trolley travel", None, table="crane.trolley"),
                )),
        Section("crane.hoist", "the hoist", "", (
            Key("capacity_t", _pos("t", 2000), "capacity Q", 200),
            Key("hook_mass_kg", Number(ge=0, unit="kg"), "mass of the hook suspension", 10250),
            Key("lifting_height_m", _pos("m", 500), "lifting height H", 14),
            Key("lifting_speed_m_min", _pos("m/min", 300), "lifting speed", 2.22),
            Key("max_acceleration", _pos("m/s²", 5), "largest acceleration at start [a]", 0.2,
                _d(Hoist, "max_acceleration")),
            Key("max_start_time", _pos("s", 60), "longest start [t_п]", 2.0, _d(Hoist, "max_start_time")),
            Key("polyspast", None, "the polyspast", None, table="crane.hoist.polyspast"),
            Key("rope", None, "the rope", None, table="crane.hoist.rope"),
            Key("drum", None, "the drum", None, table="crane.hoist.drum"),
            Key("motor", None, "the motor", None, table="crane.hoist.motor"),
            Key("reducer", None, "the reducer", None, table="crane.hoist.reducer"),
            Key("open_gear", None, "an open gear between the reducer and the drum", None, OPTIONAL,
                "none: the reducer drives the drum", table="crane.hoist.open_gear"),
            Key("coupling", None, "couplings on the motor shaft", None, table="crane.hoist.coupling"),
            Key("brake", None, "the brake", None, table="crane.hoist.brake"),
        )),
        Section("crane.hoist.polyspast", "the polyspast", "", (
            Key("ratio", Int(ge=1, le=20, what="the polyspast ratio: an integer"), "ratio u_п", 8),
            Key("branches", Int(ge=1, le=2, what="rope branches wound on the drum: 1 or 2"),
                "branches wound on the drum (2 = a double polyspast)", 2),
            Key("block_efficiency", Number(gt=0.8, le=1), "efficiency of one block", 0.99,
                _d(Polyspast, "block_efficiency")),
            Key("guide_blocks", Int(ge=0, le=10, what="guide blocks: an integer"), "guide blocks", 0,
                _d(Polyspast, "guide_blocks")),
            Key("hook_block_diameter_mm", _pos("mm", 5000), "hook blocks along the groove bottom", 1100),
            Key("hook_block_spread_mm", Number(ge=0, le=5000, unit="mm"), "axes of the outer hook blocks B",
                620, _d(Polyspast, "hook_block_spread_mm")),
        )),
        Section("crane.hoist.rope", "the rope chosen from its standard", "", (
            Key("designation", NAME, "designation with its standard", "30,5-Г-В-Ж-О-Н-1862 ГОСТ 2688-80"),
            Key("diameter_mm", _pos("mm", 200), "rope diameter d", 30.5),
            Key("breaking_force_kn", _pos("kN", 1e5), "breaking force of the rope as a whole", 782.5),
        )),
        Section("crane.hoist.drum", "the grooved drum", "Single-layer winding.", (
            Key("diameter_mm", _pos("mm", 5000), "diameter along the groove bottom", 900),
            Key("groove_pitch_mm", _pos("mm", 300), "groove pitch t", 36),
            Key("wall_mm", _pos("mm", 300), "wall thickness δ (less than half the diameter)", 40),
            Key("allowable_stress_mpa", _pos("MPa", 2000), "allowable compressive stress of the wall", 110),
            Key("material", Str(), "material of the drum", "сталь 35Л", ""),
            Key("reserve_turns", Number(ge=0, le=10), "turns never unwound", 1.5, _d(Drum, "reserve_turns")),
            Key("clamp_turns", Number(ge=0, le=10), "turns under the clamps", 3, _d(Drum, "clamp_turns")),
            Key("smooth_length_mm", Number(ge=0, le=10000, unit="mm"), "smooth middle part l₀", 800,
                _d(Drum, "smooth_length_mm")),
            Key("end_length_mm", Number(ge=0, le=2000, unit="mm"), "each smooth end l_к", 130,
                _d(Drum, "end_length_mm")),
            Key("ring_width_mm", Number(ge=0, le=2000, unit="mm"), "the open gear's ring on the drum", 332,
                _d(Drum, "ring_width_mm")),
            Key("hook_distance_mm", Number(ge=0, le=50000, unit="mm"), "h_min from the drum axis to the hook "
                "blocks' axes; 0 = 3·D", 0, _d(Drum, "hook_distance_mm")),
            Key("efficiency", EFF, "efficiency of the drum's bearings", 0.99, _d(Drum, "efficiency")),
        )),
        motor("crane.hoist.motor", {"designation": "МТН 612-10", "power_kw": 70, "speed_rpm": 560,
                                    "rotor_inertia": 5.25}),
        reducer("crane.hoist.reducer", {"designation": "Ц2-1000", "ratio": 22.4, "rated_torque": 68384}),
        Section("crane.hoist.open_gear", "the open gear", "Pinion z1 on the reducer, wheel z2 on the drum.", (
            Key("z1", Int(ge=8, le=500, what="a number of teeth: an integer"), "teeth of the pinion", 13),
            Key("z2", Int(ge=8, le=500, what="a number of teeth: an integer"), "teeth of the wheel (> z1)", 52),
            Key("module_mm", _pos("mm", 100), "module", 24),
            Key("efficiency", EFF, "efficiency", 0.97, _d(OpenGear, "efficiency")),
        )),
        coupling("crane.hoist.coupling", {"designation": "Муфта зубчатая 2-16000 ГОСТ 5006-83",
                                          "rated_torque": 16000, "inertia": 0.575}),
        brake("crane.hoist.brake", {"designation": "ТКП-500", "rated_torque": 2500, "pulley": 500}),
        Section("crane.trolley", "the trolley travel (central drive)", "", (
            Key("mass_t", _pos("t", 2000), "mass of the trolley", 60),
            Key("speed_m_min", _pos("m/min", 300), "travel speed", 23),
            Key("wheel_base_m", _pos("m", 50), "wheel base", 4.0),
            Key("gauge_m", _pos("m", 50), "gauge", 4.5),
            Key("wheels", Int(ge=3, le=16, what="trolley wheels: an integer"), "wheels", 8),
            Key("driven_wheels", Int(ge=1, le=16, what="driven wheels: an integer"), "driven wheels "
                "(at most wheels)", 4),
            Key("travel_length_m", Number(ge=0, le=200, unit="m"), "one working travel for the heating check; "
                "0 = half the span", 0, _d(Trolley, "travel_length_m")),
            Key("max_acceleration", _pos("m/s²", 5), "largest acceleration at start [a]", 0.2,
                _d(Trolley, "max_acceleration")),
            Key("max_start_time", _pos("s", 60), "longest start [t_п]", 5.0, _d(Trolley, "max_start_time")),
            Key("brake_deceleration", _pos("m/s²", 5), "design deceleration of the loaded trolley", 0.1,
                _d(Trolley, "brake_deceleration")),
            Key("adhesion", Number(gt=0, lt=1), "adhesion φ of wheel and rail", 0.2, _d(Trolley, "adhesion")),
            Key("adhesion_safety", Number(ge=1, le=5), "least adhesion safety k_сц", 1.2,
                _d(Trolley, "adhesion_safety")),
            Key("wheel", None, "the wheels", None, table="crane.trolley.wheel"),
            Key("rail", None, "the rail", None, table="crane.trolley.rail"),
            Key("motor", None, "the motor", None, table="crane.trolley.motor"),
            Key("reducer", None, "the reducer", None, table="crane.trolley.reducer"),
            Key("coupling", None, "couplings on the motor shaft", None, table="crane.trolley.coupling"),
            Key("brake", None, "the brake", None, table="crane.trolley.brake"),
        )),
        Section("crane.trolley.wheel", "the wheel chosen from the catalogue", "", (
            Key("designation", NAME, "the catalogue designation", "К2РП-800"),
            Key("diameter_mm", _pos("mm", 3000), "wheel diameter D", 800),
            Key("journal_diameter_mm", _pos("mm", 1000), "journal (bearing) diameter d (< D)", 130),
            Key("tread_width_mm", _pos("mm", 500), "tread width B", 115),
            Key("allowable_load_kn", _pos("kN", 1e5), "allowable wheel load [P]", 400),
            Key("rolling_arm_mm", Number(gt=0, le=5, unit="mm"), "rolling friction μ", 0.8,
                _d(Wheel, "rolling_arm_mm")),
            Key("bearing_friction", Number(gt=0, lt=0.5), "bearing friction f reduced to the journal", 0.015,
                _d(Wheel, "bearing_friction")),
            Key("flange_factor", Number(ge=1, le=5), "k_р: flanges and current supply", 2.0,
                _d(Wheel, "flange_factor")),
        )),
        Section("crane.trolley.rail", "the rail", "", (
            Key("designation", NAME, "designation with its standard", "КР-100 ГОСТ 4121-76"),
            Key("head_width_mm", _pos("mm", 500), "head width b", 100),
            Key("slope", Number(ge=0, le=0.05), "slope of the track α", 0.002, _d(Rail, "slope")),
        )),
        motor("crane.trolley.motor", {"designation": "МТF 312-6", "power_kw": 16, "speed_rpm": 935,
                                      "rotor_inertia": 0.3}),
        reducer("crane.trolley.reducer", {"designation": "ВКУ-965М", "ratio": 100, "rated_torque": 25000}),
        coupling("crane.trolley.coupling", {"designation": "Муфта зубчатая 2-4000 ГОСТ 5006-83",
                                            "rated_torque": 4000, "inertia": 0.06}),
        brake("crane.trolley.brake", {"designation": "ТКГ-200", "rated_torque": 245, "pulley": 200}),
    )


__all__ = ["crane_sections", "REQUIRED"]
