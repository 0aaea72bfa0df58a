"""``reportgen planetary``: synthesise (or check) a planetary reducer and print a summary or the
``planetary`` block of results.json."""
from __future__ import annotations

import argparse
import json
import math
from typing import Literal

from ..errors import OptionError, PlanetarySynthesisError, TaskError
from ..planetary.drive import DEFAULT_INPUT_OMEGA, drive_check, drive_ratio, input_speed
from ..planetary.results import planetary_block
from ..planetary.schemes import SCHEMES, expand
from ..planetary.search import PlanetaryDesign, evaluate, synthesize
from ..planetary.velocity import velocity_triangle

# task key → command-line option, so that an error names what the user typed
_OPTION = {"planetary.scheme": "--scheme", "planetary.ratio": "--ratio", "planetary.tolerance": "--tolerance",
           "planetary.satellites": "--satellites", "planetary.module": "--module", "planetary.driver": "--driver",
           "planetary.z": "--z", "planetary.motor_rpm": "--motor-rpm", "gears.z1": "--open",
           "gears.z2": "--open", "mechanism.drive.omega": "--omega-crank", "planetary.alternatives": "--alternatives"}


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "planetary", help="planetary reducer: tooth numbers, conditions, velocity triangle",
        description="Choose the tooth numbers of a planetary reducer for a ratio (or check a given "
                    "set): coaxiality, undercut, adjacency of K planets, exact assembly condition.")
    p.add_argument("--scheme", required=True, choices=tuple(SCHEMES), help="the reducer scheme")
    p.add_argument("--ratio", required=True,
                   help='target ratio ω_in/ω_out, or "auto" with --motor-rpm, --open and --omega-crank')
    p.add_argument("--satellites", default="auto", help='number of planets K, or "auto" (largest ≤ 6 that fits)')
    p.add_argument("--tolerance", default="0.05", help="allowed relative error of the ratio (default 0.05)")
    p.add_argument("--module", default=None, help="module, mm: adds diameters and the velocity triangle")
    p.add_argument("--driver", default="wheel", choices=("wheel", "carrier"),
                   help="driving member: wheel 1 (ratio u1H, default) or the carrier (uH1)")
    p.add_argument("--z", nargs="+", default=None, metavar="Z",
                   help="check this tooth set (z1 z2 z3 or z1 z2 z2′ z3) instead of searching")
    p.add_argument("--alternatives", default="5", help="how many next candidates to list (default 5)")
    p.add_argument("--motor-rpm", default=None,
                   help="motor speed, rpm: for --ratio auto, and the input speed of the velocity triangle "
                        f"(without it: {DEFAULT_INPUT_OMEGA:g} rad/s, as the build)")
    p.add_argument("--open", nargs=2, default=None, metavar=("Z1", "Z2"),
                   help="tooth numbers of the open pair, z1 driving (for --ratio auto)")
    p.add_argument("--omega-crank", default=None, help="crank speed ω1, rad/s (for --ratio auto)")
    p.add_argument("--json", action="store_true", help="print the planetary block of results.json")
    p.set_defaults(func=run)


def _number(option: str, text: str | None, kind: type = float) -> float | int:
    try:
        value = kind(text)
    except (TypeError, ValueError):
        raise OptionError(option, f"{text!r} is not {'an integer' if kind is int else 'a number'}",
                          "an integer" if kind is int else "a number") from None
    if isinstance(value, float) and not math.isfinite(value):
        raise OptionError(option, f"{text!r}", "a finite number")
    return value


def _int(option: str, text: str | None) -> int:
    """An integer option (``_number`` with ``int``)."""
    return int(_number(option, text, int))


def _design(args: argparse.Namespace):
    drive = None
    if args.ratio == "auto":
        missing = [o for o, v in (("--motor-rpm", args.motor_rpm), ("--open", args.open),
                                  ("--omega-crank", args.omega_crank)) if v is None]
        if missing:
            raise OptionError("--ratio", "auto needs " + ", ".join(missing),
                              'a number, or "auto" with --motor-rpm N --open Z1 Z2 --omega-crank W')
        drive = drive_ratio(_number("--motor-rpm", args.motor_rpm),
                            _int("--open", args.open[0]), _int("--open", args.open[1]),
                            _number("--omega-crank", args.omega_crank))
        target = drive.required
    else:
        target = _number("--ratio", args.ratio)
    k: int | Literal["auto"] = "auto" if args.satellites == "auto" else _int("--satellites", args.satellites)
    tol = _number("--tolerance", args.tolerance)
    module = None if args.module is None else _number("--module", args.module)
    if args.z is not None:
        z = tuple(_int("--z", t) for t in args.z)
        design = evaluate(args.scheme, z, k, target=target, tolerance=tol, driver=args.driver, module=module)
    else:
        design = synthesize(args.scheme, target, tol, k, module, driver=args.driver,
                            alternatives=_int("--alternatives", args.alternatives))
    check = drive_check(drive, design.ratio) if drive is not None else None
    triangle = None
    if module is not None:
        motor = None if args.motor_rpm is None else _number("--motor-rpm", args.motor_rpm)
        if motor is not None and not motor > 0:
            raise OptionError("--motor-rpm", f"{args.motor_rpm!r}", "a motor speed > 0, rpm")
        w_in, _ = input_speed(drive, motor)   # the build's rule: the motor's speed when given
        triangle = velocity_triangle(design, w_in)
    return design, check, triangle


def _ok(flag: bool) -> str:
    return "ok" if flag else "FAILS"


def summary(design: PlanetaryDesign, drive=None, triangle=None) -> str:
    """A readable summary: every condition as formula = numbers = result."""
    sch, rc = design.scheme, design.ratio_check
    z1, z2, z2p, z3 = expand(sch, design.z)
    p = "z2′" if sch.two_row else "z2"
    sgn = "+" if sch.sigma < 0 else "−"
    lines = [f"Planetary reducer: {sch.name} — {sch.title_ru}; wheel 3 fixed, "
             f"{'wheel 1 drives, carrier driven' if design.driver == 'wheel' else 'carrier drives, wheel 1 driven'}",
             "  " + ", ".join(f"z{lab} = {v}" for lab, v in zip(sch.labels, design.z))
             + f"; K = {design.satellites}{' (auto: the largest ≤ 6 that fits)' if design.satellites_auto else ''}"]
    ratio = f"u1H = 1 {sgn} z2·z3/(z1·{p}) = 1 {sgn} {z2}·{z3}/({z1}·{z2p}) = {float(rc.u1h):.4f}"
    if design.driver == "carrier":
        ratio += f"; uH1 = 1/u1H = {float(rc.ratio):.4f}"
    if rc.target is not None and rc.deviation is not None:
        ratio += (f"; target {rc.target:.4f}, deviation {rc.deviation * 100:+.2f} % "
                  f"(allowed ±{rc.tolerance * 100:g} %)  {_ok(rc.holds)}")
    lines.append("  ratio      " + ratio)
    c = design.coaxial
    lines.append(f"  coaxial    {c.formula}: {c.left} = {c.right}  {_ok(c.holds)}")
    lines.append("  undercut   " + ", ".join(
        f"{i.what}: {i.value} ≥ {i.limit}" + ("" if i.holds else " FAILS") for i in design.undercut.items)
        + f"  {_ok(design.undercut.holds)}")
    a = design.adjacency
    lines.append(f"  adjacency  (2a/m)·sin(180°/K) > z{a.planet_label} + 2ha*: {a.centre_sum}·{a.sin_term:.4f} = "
                 f"{a.left:.2f} > {a.right:.2f}; K < 180°/arcsin({a.right:g}/{a.centre_sum}) = {a.k_limit:.2f}"
                 f"  {_ok(a.holds)}")
    s = design.assembly
    q = float(s.quotient)
    lines.append(f"  assembly   {s.formula} = {s.numerator}/({s.satellites}·{s.g}) = "
                 f"{int(q) if s.holds else f'{q:.3f}'}  {_ok(s.holds)}")
    lines.append(f"  size       envelope {design.size}·m (largest pitch diameter across the axis)"
                 + (f" = {design.size * design.module:g} mm, a = {design.centre_distance_mm:g} mm"
                    if design.module else ""))
    if design.alternatives:
        lines.append("  next:      " + "; ".join(
            f"{'/'.join(map(str, c.z))} K={c.satellites} u={c.ratio:.3f} ({c.deviation * 100:+.2f} %) size {c.size}"
            for c in design.alternatives))
    if drive is not None:
        r = drive.required
        lines.append(f"  drive      ω_motor = π·{r.motor_rpm:g}/30 = {r.omega_motor:.2f} 1/s; u = z1·ω_motor/(z2·ω1) = "
                     f"{r.z1_open}·{r.omega_motor:.2f}/({r.z2_open}·{r.omega_crank:g}) = {r.required:.3f}; "
                     f"ω1 achieved {drive.omega_crank_achieved:.4f} 1/s ({drive.deviation * 100:+.2f} %)")
    if triangle is not None:
        t = triangle
        lines.append(f"  triangle   ω1 = {abs(t.omega1):.4g} 1/s; scale {t.scale_label}; v_A = {t.v_a:.4f} m/s as {t.vector_mm:g} mm; "
                     f"v_B read {t.v_b_mm_read:.2f} mm = {t.v_b:.4f} m/s; ω_H = {t.omega_h:.3f} 1/s; "
                     f"u = {t.ratio_graphical:.3f} ({t.difference_percent:+.3f} % from analytic)")
    lines.append("  valid" if design.valid else "  NOT VALID: see the conditions marked FAILS")
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    try:
        design, drive, triangle = _design(args)
    except TaskError as exc:
        if exc.path in _OPTION:
            raise OptionError(_OPTION[exc.path], exc.problem, exc.expected) from exc
        raise
    except PlanetarySynthesisError as exc:   # its message names the task key; here the option was typed
        raise OptionError("--ratio", str(exc).removeprefix("planetary.ratio: ")) from exc
    if args.json:
        print(json.dumps(planetary_block(design, triangle, drive), ensure_ascii=False, indent=2))
    else:
        print(summary(design, drive, triangle))
    return 0 if design.valid else 1
