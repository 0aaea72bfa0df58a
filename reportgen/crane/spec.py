"""The ``[crane]`` section of a task as frozen dataclasses (hoist and trolley travel of a bridge crane).

Units are those of the catalogues a student copies from, and the key names carry them where a slip
is likely (``diameter_mm``, ``power_kw``, ``speed_rpm``); the reader (``reportgen.crane.taskfile``)
documents each key. Every catalogue item here is the *student's choice*: the calculations check it,
they never take it on trust.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Rope:
    """A wire rope as chosen from its standard (e.g. ГОСТ 2688-80 ЛК-Р 6×19)."""
    designation: str
    diameter_mm: float
    breaking_force_kn: float


@dataclass(frozen=True)
class Motor:
    """A crane motor: rated power at its ПВ (duty factor), speed, rotor inertia, torque ratios."""
    designation: str
    power_kw: float
    pv_percent: float
    speed_rpm: float
    rotor_inertia: float          # kg·m²
    max_torque_ratio: float       # ψ_max = M_max / M_nom
    start_torque_ratio: float = 1.5   # ψ_п = mean starting torque / M_nom


@dataclass(frozen=True)
class Reducer:
    designation: str
    ratio: float
    rated_torque: float           # N·m on the output (slow) shaft
    efficiency: float


@dataclass(frozen=True)
class OpenGear:
    """An open spur pair between the reducer and the drum (pinion z1 on the reducer shaft)."""
    z1: int
    z2: int
    module_mm: float
    efficiency: float = 0.96

    @property
    def ratio(self) -> float:
        return self.z2 / self.z1


@dataclass(frozen=True)
class Coupling:
    designation: str
    rated_torque: float           # N·m
    inertia: float                # kg·m², the part on the motor shaft


@dataclass(frozen=True)
class Brake:
    designation: str
    rated_torque: float           # N·m
    pulley_diameter_mm: float
    count: int = 1


@dataclass(frozen=True)
class Polyspast:
    """``ratio`` u_п; ``branches`` the rope branches wound on the drum (2 = a double polyspast)."""
    ratio: int
    branches: int
    block_efficiency: float = 0.98
    guide_blocks: int = 0
    hook_block_diameter_mm: float = 0.0   # along the groove bottom (D_бл.0)
    hook_block_spread_mm: float = 0.0     # axes of the outer hook blocks, B (smooth drum part ≥ B)


@dataclass(frozen=True)
class Drum:
    """A grooved drum with single-layer winding; sizes in mm, ``diameter_mm`` along the groove bottom."""
    diameter_mm: float
    groove_pitch_mm: float
    wall_mm: float
    allowable_stress_mpa: float
    material: str = ""
    reserve_turns: float = 1.5
    clamp_turns: float = 3.0
    smooth_length_mm: float = 0.0     # l₀, the middle smooth part (double polyspast)
    end_length_mm: float = 0.0        # l_к, each smooth end
    ring_width_mm: float = 0.0        # a gear ring on the drum (open gear), 0 if none
    hook_distance_mm: float = 0.0     # h_min, drum axis to the hook block axis at the top; 0 = 3·D
    efficiency: float = 0.99


@dataclass(frozen=True)
class Hoist:
    capacity_t: float
    hook_mass_kg: float
    lifting_height_m: float
    lifting_speed_m_min: float
    polyspast: Polyspast
    rope: Rope
    drum: Drum
    motor: Motor
    reducer: Reducer
    couplings: tuple[Coupling, ...]
    brake: Brake
    open_gear: OpenGear | None = None
    max_acceleration: float = 0.2     # m/s²
    max_start_time: float = 2.0       # s


@dataclass(frozen=True)
class Wheel:
    designation: str
    diameter_mm: float
    journal_diameter_mm: float
    tread_width_mm: float
    allowable_load_kn: float
    rolling_arm_mm: float = 0.6       # μ, coefficient of rolling friction (arm)
    bearing_friction: float = 0.015   # f, reduced to the journal
    flange_factor: float = 2.0        # k_р, flanges and the current supply


@dataclass(frozen=True)
class Rail:
    designation: str
    head_width_mm: float
    slope: float = 0.002


@dataclass(frozen=True)
class Trolley:
    mass_t: float
    speed_m_min: float
    wheel_base_m: float
    gauge_m: float
    wheels: int
    driven_wheels: int
    wheel: Wheel
    rail: Rail
    motor: Motor
    reducer: Reducer
    couplings: tuple[Coupling, ...]
    brake: Brake
    travel_length_m: float = 0.0      # one working travel; 0 = half the span
    max_acceleration: float = 0.2     # m/s²
    max_start_time: float = 5.0       # s
    brake_deceleration: float = 0.1   # m/s², the loaded trolley's design deceleration
    adhesion: float = 0.2             # φ: 0,2 indoors, 0,12 outdoors (Руденко)
    adhesion_safety: float = 1.2      # k_сц


@dataclass(frozen=True)
class Crane:
    """The bridge crane's assignment: duty, rules, the hoist and the trolley travel."""
    group: str                         # ГОСТ 25835-83 group of the mechanism: 1М … 6М
    rules: str                         # "PB-10-382-00" | "1969"
    span_m: float
    hoist: Hoist
    trolley: Trolley
    use_class: str = ""                # ГОСТ 25835-83 class of use А0 … А6 (informative)
    load_class: str = ""               # В1 … В4 (informative)
    g: float = 9.81
    name: str = ""
