"""Bridge crane (course «Грузоподъёмные машины»): the hoist and the trolley travel mechanism.

``crane_calc(crane)`` → :class:`CraneCalc` with the duty's coefficients and, for each mechanism, its
calculation records and checks (:class:`reportgen.crane.hoist.MechanismCalc`). Pure: no presentation.
The bridge girder and the crane travel are a later step: a ``bridge`` stage would sit beside
``hoist`` and ``trolley`` here.
"""
from __future__ import annotations

from dataclasses import dataclass

from .hoist import MechanismCalc, hoist_calc
from .rules import DutyRules, duty_rules
from .spec import Crane
from .trolley import trolley_calc

__all__ = ["CraneCalc", "crane_calc", "crane_code", "CRANE_CODE", "MechanismCalc", "DutyRules"]


@dataclass(frozen=True)
class CraneCalc:
    crane: Crane
    rules: DutyRules
    hoist: MechanismCalc
    trolley: MechanismCalc

    @property
    def mechanisms(self) -> tuple[tuple[str, MechanismCalc], ...]:
        return (("hoist", self.hoist), ("trolley", self.trolley))

    @property
    def passed(self) -> bool:
        return self.hoist.passed and self.trolley.passed


#: The designation of a crane project when [document] code is left at the ТММ default (ГОСТ 2.201).
CRANE_CODE = "ГПМ.КП.00.00"


def crane_code(document, default: str = CRANE_CODE) -> str:
    """[document] code, or ``default`` (the language's letters, ``CRANE_CODE`` in Russian) if the
    task left it at the ТММ default."""
    from ..task import Document
    return default if document.code == Document().code else document.code


def crane_calc(crane: Crane) -> CraneCalc:
    rules = duty_rules(crane.group, crane.rules)
    return CraneCalc(crane, rules, hoist_calc(crane, rules), trolley_calc(crane, rules))
