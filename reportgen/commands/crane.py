"""``reportgen crane TASK``: the hoist and trolley-travel calculation of a task's [crane] section,
printed as requirements and checks (formula results, pass/fail with the numbers, the next catalogue
step of a failed check); ``--json`` prints the ``crane`` block of results.json. Nothing is written."""
from __future__ import annotations

import argparse
import json
import sys

from ..errors import TaskError
from ..taskfile import load_task


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "crane", help="bridge crane: hoist and trolley travel — requirements and checks",
        description="Compute the hoist (rope, blocks, drum, motor, transmission, couplings, brake) "
                    "and the trolley travel (wheels, resistance, motor, reducer, brake, adhesion) of "
                    "the [crane] section of TASK and print every requirement and check.")
    p.add_argument("task", help="the task file (TOML) with a [crane] section")
    p.add_argument("--json", action="store_true", help="print the crane block of results.json")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from ..crane import crane_calc
    from ..crane.results import crane_block

    task = load_task(args.task)
    if task.crane is None:
        raise TaskError("crane", "the task has no [crane] section", "a [crane] section (docs/crane.md)")
    calc = crane_calc(task.crane)
    if args.json:
        json.dump(crane_block(calc), sys.stdout, ensure_ascii=False, indent=1, allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(format_report(calc))
    return 0


def _num(x: float, digits: int = 4) -> str:
    from ..crane.steps import plain_number
    return plain_number(x, digits)


def _plain(symbol: str) -> str:
    """A LaTeX symbol as plain text: ``S_{\\max}`` → ``S_max``, ``\\eta_{\\text{п}}`` → ``η_п``."""
    import re
    greek = {r"\eta": "η", r"\alpha": "α", r"\sigma": "σ", r"\delta": "δ", r"\psi": "ψ", r"\omega": "ω",
             r"\varphi": "φ", r"\mu": "μ", r"\Delta": "Δ", r"\Sigma": "Σ", r"\max": "max", r"\min": "min"}
    text = re.sub(r"\\text\{([^}]*)\}", r"\1", symbol)
    for k, v in greek.items():
        text = text.replace(k, v)
    return text.replace("{", "").replace("}", "").replace("\\", "")


TITLES = {"hoist": "Hoist", "trolley": "Trolley travel"}


def format_report(calc) -> str:
    r = calc.rules
    lines = [f"Bridge crane {calc.crane.name or ''}".rstrip(),
             f"duty group {r.group} (ISO 4301 {r.iso_class}, regime {r.regime}, ПВ {r.pv_percent:g} %), "
             f"rules {r.rules}: rope factor {r.rope_factor:g}, block ratio {r.block_ratio:g}, "
             f"drum ratio {r.drum_ratio:g}, brake factor {r.brake_factor:g}"]
    for name, mech in calc.mechanisms:
        lines += ["", f"{TITLES[name]}:"]
        for key, rec in mech.records.items():
            unit = f" {rec.unit}" if rec.unit else ""
            shown = _num(rec.value, rec.digits)
            lines.append(f"  {key:<9} {_plain(rec.symbol):<12} = {shown}{unit}")
        lines += ["", f"  Checks of the {TITLES[name].lower()}:"]
        for c in mech.checks:
            unit = f" {c.unit}" if c.unit else ""
            line = (f"  [{'pass' if c.passed else 'FAIL'}] {c.key}: {_num(c.value)}{unit} {c.relation} "
                    f"{_num(c.limit)}{unit}")
            if not c.passed and c.advice:
                line += f"  → next step: {c.advice}"
                if c.advice_value is not None:
                    line += f" ({_num(c.advice_value)} {c.advice_unit})".rstrip()
            lines.append(line)
    lines += ["", "all checks pass" if calc.passed else "some checks FAIL (see above)"]
    return "\n".join(lines) + "\n"
