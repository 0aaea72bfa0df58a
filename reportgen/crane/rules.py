"""Coefficients fixed by the rules for the duty of a mechanism: rope safety factor, the ratio of a
block or drum diameter to the rope diameter (e, h), the brake safety factor, the duty factor ПВ.

Two sets of rules are offered, because the course's textbooks use both:

``PB-10-382-00`` — ПБ 10-382-00 «Правила устройства и безопасной эксплуатации грузоподъёмных
    кранов» (Госгортехнадзор России, 2000): mechanism groups M1…M8 of ISO 4301/1; the least safety
    factor Z_p of a running rope (table 11) and the least ratios h₁ (drum), h₂ (block), h₃
    (equalizing block) of the diameter along the rope's centre line to the rope diameter (table 12);
    the hoist brake's safety factor of at least 1,5 with one brake, 1,25 for each of two (п. 4.2.x
    on hoist brakes). These numbers are those of ISO 4308-1 for M1…M8.
``1969`` — the earlier «Правила устройства и безопасной эксплуатации грузоподъёмных кранов»
    (Госгортехнадзор СССР, 1969; as used by Казак С. А. «Курсовое проектирование грузоподъёмных
    машин», 1989, and by the seed note 002): duty regimes Л/С/Т/ВТ; rope safety factor k = 5 / 5,5 / 6
    / 6 for machine-driven hoists; e = 20 / 25 / 30 / 35 for cranes; the drum allowed 15 % smaller
    than the blocks (the seed's «0,85·d·e»); brake safety factor 1,5 / 1,75 / 2 / 2,5.

ГОСТ 25835-83 groups 1М…6М are translated to ISO 4301/1 classes and to the old regimes by the usual
correspondence (Казак 1989, ch. 1): 1М → M1…M3 (M3 taken), 2М → M4, 3М → M5, 4М → M6, 5М → M7,
6М → M8; 1М, 2М, 3М → Л (light), 4М → С, 5М → Т, 6М → ВТ. The ПВ of each regime (15, 25, 40, 60 %)
is Руденко Н. Ф. «Справочник по кранам» (the regime table of crane motors).
"""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import TaskError

GROUPS = ("1М", "2М", "3М", "4М", "5М", "6М")
RULES = ("PB-10-382-00", "1969")

#: ГОСТ 25835-83 group → ISO 4301/1 mechanism class used for ПБ 10-382-00's tables.
ISO_CLASS = {"1М": "M3", "2М": "M4", "3М": "M5", "4М": "M6", "5М": "M7", "6М": "M8"}
#: ГОСТ 25835-83 group → the regime of the 1969 rules (Л, С, Т, ВТ).
REGIME = {"1М": "Л", "2М": "Л", "3М": "Л", "4М": "С", "5М": "Т", "6М": "ВТ"}
#: Duty factor ПВ of a regime, % (Руденко, the regime table of crane motors).
PV_OF_REGIME = {"Л": 15.0, "С": 25.0, "Т": 40.0, "ВТ": 60.0}

#: ПБ 10-382-00, table 11: least safety factor Z_p of a running rope, by ISO class.
PB_ROPE_FACTOR = {"M1": 3.15, "M2": 3.35, "M3": 3.55, "M4": 4.0, "M5": 4.5, "M6": 5.6, "M7": 7.1,
                  "M8": 9.0}
#: ПБ 10-382-00, table 12: (h₁ drum, h₂ block, h₃ equalizing block), by ISO class.
PB_DIAMETER_RATIO = {"M1": (11.2, 12.5, 11.2), "M2": (12.5, 14.0, 12.5), "M3": (14.0, 16.0, 12.5),
                     "M4": (16.0, 18.0, 14.0), "M5": (18.0, 20.0, 14.0), "M6": (20.0, 22.4, 16.0),
                     "M7": (22.4, 25.0, 16.0), "M8": (25.0, 28.0, 18.0)}
#: 1969 rules: rope safety factor, e of blocks, brake safety factor by regime.
OLD_ROPE_FACTOR = {"Л": 5.0, "С": 5.5, "Т": 6.0, "ВТ": 6.0}
OLD_E = {"Л": 20.0, "С": 25.0, "Т": 30.0, "ВТ": 35.0}
OLD_BRAKE_FACTOR = {"Л": 1.5, "С": 1.75, "Т": 2.0, "ВТ": 2.5}
#: The drum may be 15 % smaller than the blocks under the 1969 rules (seed 002: 0,85·d·e).
OLD_DRUM_SHARE = 0.85


@dataclass(frozen=True)
class DutyRules:
    """The coefficients for one mechanism group under one set of rules, with where they come from."""
    group: str
    rules: str
    iso_class: str
    regime: str
    pv_percent: float
    rope_factor: float          # least safety factor of the rope
    block_ratio: float          # least D_block (rope centre) / d
    drum_ratio: float           # least D_drum (rope centre) / d
    brake_factor: float         # hoist brake safety factor (one brake)
    source: str


def duty_rules(group: str, rules: str = "PB-10-382-00", path: str = "crane") -> DutyRules:
    """The coefficients of ``group`` (ГОСТ 25835-83) under ``rules``; a bad name is a TaskError."""
    if group not in GROUPS:
        raise TaskError(f"{path}.group", f"unknown group {group!r}", "one of " + ", ".join(GROUPS)
                        + " (ГОСТ 25835-83; Cyrillic М)")
    if rules not in RULES:
        raise TaskError(f"{path}.rules", f"unknown rules {rules!r}", " or ".join(f'"{r}"' for r in RULES))
    iso = ISO_CLASS[group]
    regime = REGIME[group]
    pv = PV_OF_REGIME[regime]
    if rules == "PB-10-382-00":
        h1, h2, _ = PB_DIAMETER_RATIO[iso]
        return DutyRules(group, rules, iso, regime, pv, PB_ROPE_FACTOR[iso], h2, h1, 1.5,
                         "ПБ 10-382-00, табл. 11 и 12")
    e = OLD_E[regime]
    return DutyRules(group, rules, iso, regime, pv, OLD_ROPE_FACTOR[regime], e, OLD_DRUM_SHARE * e,
                     OLD_BRAKE_FACTOR[regime], "Правила Госгортехнадзора СССР 1969 г.")


def brake_factor_each(rules: DutyRules, count: int) -> float:
    """The safety factor each brake must give: the duty's with one brake; 1,25 each with two or more
    (ПБ 10-382-00 on hoists with two brakes)."""
    return rules.brake_factor if count == 1 else 1.25
