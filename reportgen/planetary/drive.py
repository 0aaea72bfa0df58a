"""The drive: motor → open gear pair [gears] → planetary reducer → crank (speeds as magnitudes).

The ratio the planetary reducer must give (seed 000, §4.2):
    ω_motor = π·n/30,   u_planetary = z1·ω_motor/(z2·ω1),
where z1/z2 is the open pair (z1 driving) and ω1 the crank's angular speed. The product of the two
ratios is the same in either order; ``order`` only says which member turns at which speed:
"planetary-first" (seed 000: wheel 1 of the reducer on the motor shaft, v_A = ω_motor·r1) or
"open-first" (the open pair on the motor shaft).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from numbers import Real
from typing import Literal

from ..errors import TaskError

Order = Literal["planetary-first", "open-first"]
ORDERS: tuple[str, ...] = ("planetary-first", "open-first")


@dataclass(frozen=True)
class DriveRatio:
    """The required reducer ratio: ω_motor = π·n/30; u_open = z2/z1; u = ω_motor/(u_open·ω1)."""
    motor_rpm: float
    omega_motor: float
    z1_open: int
    z2_open: int
    open_ratio: float
    omega_crank: float
    required: float
    order: str

    @property
    def omega_planetary_in(self) -> float:
        """Speed of the reducer's input member, rad/s."""
        return self.omega_motor if self.order == "planetary-first" else self.omega_motor / self.open_ratio


@dataclass(frozen=True)
class DriveCheck:
    """With the chosen reducer: ω1' = ω_motor/(u_open·|u|), deviation = (ω1' − ω1)/ω1."""
    required: DriveRatio
    planetary_ratio: float
    total_ratio: float
    omega_crank_achieved: float
    deviation: float

DEFAULT_INPUT_OMEGA = 100.0
"""rad/s: the reducer's input speed when neither the drive nor a motor speed gives one (≈ 955 rpm)."""


def input_speed(drive: DriveRatio | None, motor_rpm: float | None) -> tuple[float, str]:
    """The speed of the reducer's input member, rad/s, and where it comes from.

    One rule for ``reportgen planetary`` and ``reportgen build``: the drive's speed when the ratio is
    "auto" (motor → open pair → reducer); else the motor's, ω = π·n/30, when a motor speed is given;
    else :data:`DEFAULT_INPUT_OMEGA`. Returns ``(omega, source)``, ``source`` one of "drive",
    "motor", "default".
    """
    if drive is not None:
        return drive.omega_planetary_in, "drive"
    if motor_rpm:
        return math.pi * float(motor_rpm) / 30.0, "motor"
    return DEFAULT_INPUT_OMEGA, "default"


def _positive(path: str, value: object, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, Real) or not (math.isfinite(float(value)) and float(value) > 0):
        raise TaskError(path, f"{value!r}", what)
    return float(value)


def drive_ratio(motor_rpm: float, z1_open: int, z2_open: int, omega_crank: float,
                order: Order = "planetary-first") -> DriveRatio:
    """u_planetary = z1·ω_motor/(z2·ω1) with ω_motor = π·n/30 (seed 000 §4.2). ``omega_crank`` is
    taken as a magnitude (its sign is the crank's sense of rotation, not a speed)."""
    n = _positive("planetary.motor_rpm", motor_rpm, "a motor speed > 0 in rpm")
    for path, zz in (("gears.z1", z1_open), ("gears.z2", z2_open)):
        if isinstance(zz, bool) or not isinstance(zz, int) or zz < 1:
            raise TaskError(path, f"{zz!r}", "a tooth number ≥ 1")
    if isinstance(omega_crank, bool) or not isinstance(omega_crank, Real) or float(omega_crank) == 0 \
            or not math.isfinite(float(omega_crank)):
        raise TaskError("mechanism.drive.omega", f"{omega_crank!r}", "a crank speed ≠ 0, rad/s")
    if order not in ORDERS:
        raise TaskError("planetary.order", f"{order!r}", " or ".join(ORDERS))
    w1 = abs(float(omega_crank))
    wm = math.pi * n / 30.0
    u_open = z2_open / z1_open
    return DriveRatio(n, wm, z1_open, z2_open, u_open, w1, z1_open * wm / (z2_open * w1), order)


def drive_check(required: DriveRatio, planetary_ratio: float) -> DriveCheck:
    """The crank speed the drive gives with the reducer's ratio, and its relative deviation."""
    u = abs(float(planetary_ratio))
    if u == 0 or not math.isfinite(u):
        raise TaskError("planetary.ratio", f"{planetary_ratio!r}", "a finite ratio ≠ 0")
    total = required.open_ratio * u
    w = required.omega_motor / total
    return DriveCheck(required, float(planetary_ratio), total, w,
                      (w - required.omega_crank) / required.omega_crank)
