"""``reportgen gear``: solve one external involute pair and print a table, or the ``gears`` block
of results.json with ``--json``. Touches nothing but :mod:`reportgen.gears`."""
from __future__ import annotations

import argparse
import json
import math
import sys

from ..errors import OptionError, TaskError

_OPTION_OF_KEY = {"z1": "--z1", "z2": "--z2", "module": "--module", "x1": "--x1", "x2": "--x2",
                  "alpha_deg": "--alpha", "ha": "--ha", "c": "--c", "sa_min_factor": "--sa-min",
                  "eps_min": "--eps-min"}


def _shift(text: str):
    if text.strip().lower() == "auto":
        return "auto"
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is neither a number nor \"auto\"") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"'{text}' is not a finite number")
    return value


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "gear", help="the shifted external involute pair: geometry, checks, auto shifts",
        description="Geometry by ГОСТ 16532-70 of an external spur involute pair, its checks "
                    "(undercut, sharpening, contact ratio, fillet interference) and specific sliding. "
                    "x1 = x2 = auto chooses the shifts on the computed blocking contour.")
    p.add_argument("--z1", type=int, required=True, help="teeth of the pinion")
    p.add_argument("--z2", type=int, required=True, help="teeth of the wheel")
    p.add_argument("--module", type=float, required=True, help="module, mm")
    p.add_argument("--x1", type=_shift, default=0.0, help="profile shift of gear 1, or auto")
    p.add_argument("--x2", type=_shift, default=0.0, help="profile shift of gear 2, or auto")
    p.add_argument("--alpha", type=float, default=20.0, help="profile angle of the rack, deg (20)")
    p.add_argument("--ha", type=float, default=1.0, help="addendum coefficient ha* (1)")
    p.add_argument("--c", type=float, default=0.25, help="clearance coefficient c* (0.25)")
    p.add_argument("--sa-min", type=float, default=0.25, help="least tip thickness as a share of m (0.25)")
    p.add_argument("--eps-min", type=float, default=1.2, help="least transverse contact ratio (1.2)")
    p.add_argument("--json", action="store_true", help="print the gears block of results.json")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from ..gears.pair import solve_gear_pair
    from ..gears.results import gears_block

    try:
        pair = solve_gear_pair(args.z1, args.z2, args.module, args.x1, args.x2, alpha_deg=args.alpha,
                               ha=args.ha, c=args.c, sa_min_factor=args.sa_min, eps_min=args.eps_min)
    except TaskError as exc:
        key = exc.path.split(".", 1)[-1]
        raise OptionError(_OPTION_OF_KEY.get(key, key), exc.problem, exc.expected) from exc
    if args.json:
        json.dump(gears_block(pair), sys.stdout, ensure_ascii=False, indent=2, allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(format_table(pair))
    return 0


def _f(v: float, nd: int = 3) -> str:
    if v == math.inf:
        return "+∞"
    if v == -math.inf:
        return "−∞"
    return f"{v:.{nd}f}"


def format_table(pair) -> str:
    """A plain-text table of the solved pair."""
    g = pair.geometry
    lines = [f"External involute pair z1 = {g.z1}, z2 = {g.z2}, m = {g.m:g} mm, "
             f"α = {g.alpha_deg:g}°, ha* = {g.ha:g}, c* = {g.c:g}"]
    if pair.shift_choice is not None:
        ch = pair.shift_choice
        lines.append(f"shifts chosen automatically: x1 = {g.x1:.2f}, x2 = {g.x2:.2f} "
                     f"(exact {ch.x1_exact:.4f}, {ch.x2_exact:.4f}); rule: {ch.rule}")
    lines += ["",
              f"  x1 + x2 = {g.x_sum:.4f}   inv αw = {g.inv_alpha_w:.8f}   αw = {g.alpha_w_deg:.4f}°",
              f"  a = {g.a:.3f} mm   aw = {g.aw:.3f} mm   y = {g.y:.5f}   Δy = {g.dy:.5f}   u = {g.u:.4f}",
              f"  p = {g.p:.3f} mm   pb = {g.pb:.3f} mm",
              f"  N1N2 = {g.g:.3f} mm   N1a = {g.n1a:.3f}   N1P = {g.n1p:.3f}   N1b = {g.n1b:.3f}   "
              f"ab = {g.ab:.3f} mm",
              f"  εα = ab/pb = {g.eps_alpha:.4f}", "",
              f"  {'quantity':<36}{'gear 1':>12}{'gear 2':>12}"]
    rows = [("shift x", "x1", "x2", 3), ("pitch diameter d, mm", "d1", "d2", 3),
            ("base diameter db, mm", "db1", "db2", 3), ("working pitch diameter dw, mm", "dw1", "dw2", 3),
            ("tip diameter da, mm", "da1", "da2", 3), ("root diameter df, mm", "df1", "df2", 3),
            ("addendum ha, mm", "ha1", "ha2", 3), ("dedendum hf, mm", "hf1", "hf2", 3),
            ("tooth height h, mm", "h1", "h2", 3), ("thickness on pitch circle s, mm", "s1", "s2", 3),
            ("thickness on tip circle sa, mm", "sa1", "sa2", 3),
            ("thickness on working circle sw, mm", "sw1", "sw2", 3),
            ("chordal thickness s̄, mm", "chord_s1", "chord_s2", 3),
            ("chordal height h̄a, mm", "chord_h1", "chord_h2", 3),
            ("teeth spanned zw", "zw1", "zw2", 0), ("base tangent length W, mm", "w1", "w2", 3)]
    for title, k1, k2, nd in rows:
        lines.append(f"  {title:<36}{getattr(g, k1):>12.{nd}f}{getattr(g, k2):>12.{nd}f}")
    lines.append(f"  {'profile angle at tip αa, deg':<36}{math.degrees(g.alpha_a1):>12.3f}"
                 f"{math.degrees(g.alpha_a2):>12.3f}")
    lines += ["", "Checks:"]
    for c in pair.checks:
        unit = f" {c.unit}" if c.unit else ""
        lines.append(f"  [{'pass' if c.passed else 'FAIL'}] {c.title}: {c.symbol} = {c.value:.4f}{unit} "
                     f"{c.relation} {c.limit:.4f}{unit}")
    lines += ["", "Specific sliding along N1N2 (ρ = distance from N1):",
              f"  {'point':<6}{'ρ, mm':>10}{'λ1':>10}{'λ2':>10}"]
    for r in pair.sliding.rows:
        lines.append(f"  {r.label:<6}{r.rho:>10.3f}{_f(r.lambda1):>10}{_f(r.lambda2):>10}")
    return "\n".join(lines) + "\n"
