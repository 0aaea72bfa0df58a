"""The conditions a planetary tooth set must meet, each as a record of its numbers.

Every check keeps the values that the note shows as "formula = numbers = result".

* Coaxiality: both rows put the planet axis at the same distance a from the central axis
  (one module): z1 ± z2 = z3 ∓ z2′ (Артоболевский; Кудрявцев В. Н., «Планетарные передачи»).
* No undercut: an external wheel with zero shift and the ГОСТ 13755 rack (ha* = 1, α = 20°) needs
  z ≥ 17; a wheel with internal teeth needs z ≥ 85 (the limit the course note of seed 000 uses);
  an internal mesh needs z_internal − z_planet ≥ 8 (no interference of the tips). The limits are
  a parameter, :class:`UndercutLimits`.
* Adjacency (соседство) of K planets: the tip circles of neighbouring planets must not touch,
  2a·sin(π/K) > d_a = m·(z_p + 2ha*) for the larger planet crown z_p, i.e. in modules
  (2a/m)·sin(π/K) > z_p + 2ha*; the course writes it as K < 180°/arcsin((z_p + 2)/(z1 + z2)).
* Assembly (сборка) with K equally spaced planets, exact for a two-row planet block
  (../shared/NOTES.md): (z1·z2′ ± z3·z2)/(K·gcd(z2, z2′)) is an integer, + for one external and one
  internal mesh, − for two of a kind. For a single-row planet (z2 = z2′) it is (z1 + z3)/K.
  Derivation: a planet at carrier angle θ = 2π/K must mesh with both fixed central wheels; its
  rotation ψ must satisfy z2·ψ ≡ c1·θ and z2′·ψ ≡ c2·θ (mod 2π), which has a solution iff
  θ·(z1·z2′ ± z3·z2)/(2π) is a multiple of gcd(z2, z2′).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from ..errors import TaskError
from .schemes import Scheme, expand, row_sums


@dataclass(frozen=True)
class UndercutLimits:
    """Smallest tooth numbers without undercut or interference (zero shift, ha* = 1, α = 20°).

    ``external_min``: z_min = 2ha*/sin²α = 17.1, taken as 17 in the course (Артоболевский).
    ``internal_min``: the course's limit for a wheel with internal teeth, 85 (seed 000, §4.2).
    ``internal_difference_min``: z_internal − z_planet ≥ 8 for an internal mesh (ТММ course manuals).
    """
    external_min: int = 17
    internal_min: int = 85
    internal_difference_min: int = 8

    def __post_init__(self) -> None:
        for name in ("external_min", "internal_min", "internal_difference_min"):
            v = getattr(self, name)
            if not isinstance(v, int) or v < 1:
                raise TaskError(f"planetary.limits.{name}", f"{v!r}", "an integer ≥ 1")


#: The course's limits (a frozen value: safe as a default argument).
DEFAULT_LIMITS = UndercutLimits()


@dataclass(frozen=True)
class CoaxialCheck:
    """z1 ± z2 (``left``) against z3 ∓ z2′ (``right``): twice the centre distance in modules."""
    formula: str
    left: int
    right: int
    holds: bool


@dataclass(frozen=True)
class UndercutItem:
    """One limit: ``what`` is a wheel label ("1", "2′") or a mesh ("3−2′"), ``value`` its z or z
    difference, ``limit`` the smallest allowed value."""
    what: str
    kind: str          # "external" | "internal" | "internal mesh"
    value: int
    limit: int
    holds: bool


@dataclass(frozen=True)
class UndercutCheck:
    items: tuple[UndercutItem, ...]
    holds: bool


@dataclass(frozen=True)
class AdjacencyCheck:
    """(2a/m)·sin(π/K) = ``left`` > ``right`` = z_p + 2ha*; ``k_limit`` = 180°/arcsin(right/(2a/m))
    (K must be below it; 2.0 if even two planets do not fit), ``k_max`` the largest such integer."""
    satellites: int
    centre_sum: int        # 2a/m
    planet_z: int          # the larger planet crown
    planet_label: str
    ha: float
    sin_term: float        # sin(180°/K)
    left: float
    right: float
    k_limit: float
    k_max: int
    holds: bool


@dataclass(frozen=True)
class AssemblyCheck:
    """(z1·z2′ ± z3·z2)/(K·g) = ``quotient``; ``g`` = gcd(z2, z2′) (for single-row the record is
    (z1 + z3)/K with g = 1)."""
    satellites: int
    formula: str
    sign: str              # "+" or "−"
    numerator: int
    g: int
    divisor: int           # K·g
    quotient: Fraction
    holds: bool


def check_coaxial(scheme: Scheme, z: tuple[int, ...]) -> CoaxialCheck:
    left, right = row_sums(scheme, z)
    a = "z1 + z2" if scheme.row1 == "external" else "z1 − z2"
    p = "z2′" if scheme.two_row else "z2"
    b = f"z3 + {p}" if scheme.row2 == "external" else f"z3 − {p}"
    return CoaxialCheck(f"{a} = {b}", left, right, left == right and left > 0)


def check_undercut(scheme: Scheme, z: tuple[int, ...],
                   limits: UndercutLimits = DEFAULT_LIMITS) -> UndercutCheck:
    z1, z2, z2p, z3 = expand(scheme, z)
    internal = scheme.internal_wheels
    items: list[UndercutItem] = []
    labelled = list(zip(scheme.labels, z))
    for label, value in labelled:
        if label in internal:
            items.append(UndercutItem(label, "internal", value, limits.internal_min,
                                      value >= limits.internal_min))
        else:
            items.append(UndercutItem(label, "external", value, limits.external_min,
                                      value >= limits.external_min))
    p = "2′" if scheme.two_row else "2"
    if scheme.row1 == "internal":
        d = z1 - z2
        items.append(UndercutItem("1−2", "internal mesh", d, limits.internal_difference_min,
                                  d >= limits.internal_difference_min))
    if scheme.row2 == "internal":
        d = z3 - z2p
        items.append(UndercutItem(f"3−{p}", "internal mesh", d, limits.internal_difference_min,
                                  d >= limits.internal_difference_min))
    return UndercutCheck(tuple(items), all(i.holds for i in items))


# sin²(π/K) where it is rational, so that the strict inequality is decided exactly.
_SIN2_RATIONAL = {1: Fraction(0), 2: Fraction(1), 3: Fraction(3, 4), 4: Fraction(1, 2), 6: Fraction(1, 4)}


def adjacent(centre_sum: int, planet_z: int, satellites: int, ha: float = 1.0) -> bool:
    """(2a/m)·sin(π/K) > z_p + 2ha*, decided exactly for K = 1, 2, 3, 4, 6 (integer 2ha*)."""
    if satellites == 1:
        return True
    right = planet_z + 2 * ha
    s2 = _SIN2_RATIONAL.get(satellites)
    if s2 is not None and float(2 * ha).is_integer() and centre_sum > 0:
        return Fraction(centre_sum) ** 2 * s2 > Fraction(int(right)) ** 2
    return centre_sum * math.sin(math.pi / satellites) > right


def adjacency_k_limit(centre_sum: int, planet_z: int, ha: float = 1.0) -> float:
    """180°/arcsin((z_p + 2ha*)/(2a/m)): K must be below it (2.0 when even K = 2 fails)."""
    ratio = (planet_z + 2 * ha) / centre_sum if centre_sum > 0 else math.inf
    if ratio >= 1:
        return 2.0
    return 180.0 / math.degrees(math.asin(ratio))


def check_adjacency(scheme: Scheme, z: tuple[int, ...], satellites: int,
                    ha: float = 1.0) -> AdjacencyCheck:
    z1, z2, z2p, z3 = expand(scheme, z)
    centre_sum = row_sums(scheme, z)[0]
    planet_z, label = (z2, "2") if z2 >= z2p else (z2p, "2′")
    k_limit = adjacency_k_limit(centre_sum, planet_z, ha)
    k_max = max((k for k in range(1, 13) if adjacent(centre_sum, planet_z, k, ha)), default=1)
    sin_term = math.sin(math.pi / satellites)
    return AdjacencyCheck(satellites, centre_sum, planet_z, label, ha, sin_term,
                          centre_sum * sin_term, planet_z + 2 * ha, k_limit, k_max,
                          adjacent(centre_sum, planet_z, satellites, ha))


def assembly_numbers(scheme: Scheme, z1: int, z2: int, z2p: int, z3: int) -> tuple[str, int, int]:
    """(sign, numerator, g) of the exact assembly condition: numerator/(K·g) must be an integer."""
    if not scheme.two_row:
        return "+", z1 + z3, 1
    g = math.gcd(z2, z2p)
    if scheme.row1 != scheme.row2:
        return "+", z1 * z2p + z3 * z2, g
    return "−", abs(z1 * z2p - z3 * z2), g


def check_assembly(scheme: Scheme, z: tuple[int, ...], satellites: int) -> AssemblyCheck:
    z1, z2, z2p, z3 = expand(scheme, z)
    sign, num, g = assembly_numbers(scheme, z1, z2, z2p, z3)
    if scheme.two_row:
        formula = f"|z1·z2′ {sign} z3·z2| / (K·gcd(z2, z2′))"
    else:
        formula = "(z1 + z3) / K"
    divisor = satellites * g
    q = Fraction(num, divisor)
    return AssemblyCheck(satellites, formula, sign, num, g, divisor, q, q.denominator == 1)
