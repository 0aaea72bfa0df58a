"""The four planetary schemes of the course: Willis' ratio and the coaxiality condition.

Every scheme has a central wheel 1, a planet block (2, or 2 and 2′ on one axle), a fixed central
wheel 3 and the carrier H. Tooth numbers are given as ``z = (z1, z2, z3)`` for ``single-row`` and
``z = (z1, z2, z2′, z3)`` for the two-row schemes.

Willis' formula (Артоболевский И. И., «Теория механизмов и машин», гл. «Планетарные механизмы»):
in the carrier's frame the train is an ordinary one,
    u13^H = (ω1 − ωH)/(ω3 − ωH) = s1·(z2/z1) · s2·(z3/z2′),
with s = −1 for an external mesh and +1 for an internal one; with ω3 = 0
    u1H = ω1/ωH = 1 − u13^H.
Coaxiality (one module for both rows): the planet axis is at the same distance from the central axis
for both rows, z1 ± z2 = z3 ∓ z2′ (+ for an external mesh of wheel 1, − for an internal one, and so on).
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Literal

from ..errors import TaskError

Mesh = Literal["external", "internal"]
Driver = Literal["wheel", "carrier"]
DRIVERS: tuple[str, ...] = ("wheel", "carrier")


@dataclass(frozen=True)
class Scheme:
    """A scheme: the kind of each mesh. ``row1`` is wheel 1 with planet 2, ``row2`` planet 2′ with
    the fixed wheel 3. A mesh is "internal" when its central wheel has internal teeth."""
    name: str
    row1: Mesh
    row2: Mesh
    two_row: bool
    title_ru: str

    @property
    def labels(self) -> tuple[str, ...]:
        """Wheel labels in the order of ``z``."""
        return ("1", "2", "2′", "3") if self.two_row else ("1", "2", "3")

    @property
    def internal_wheels(self) -> tuple[str, ...]:
        """Labels of the wheels with internal teeth (always central wheels)."""
        out = []
        if self.row1 == "internal":
            out.append("1")
        if self.row2 == "internal":
            out.append("3")
        return tuple(out)

    @property
    def sigma(self) -> int:
        """Sign of u13^H = sigma·z2·z3/(z1·z2′): (−1)^(number of external meshes)."""
        s1 = -1 if self.row1 == "external" else 1
        s2 = -1 if self.row2 == "external" else 1
        return s1 * s2


SCHEMES: dict[str, Scheme] = {
    "single-row": Scheme("single-row", "external", "internal", False,
                         "однорядный (солнце 1 – сателлиты 2 – неподвижное колесо 3)"),
    "two-row-ext-int": Scheme("two-row-ext-int", "external", "internal", True,
                              "двухрядный с внешним и внутренним зацеплениями"),
    "two-row-ext-ext": Scheme("two-row-ext-ext", "external", "external", True,
                              "двухрядный с двумя внешними зацеплениями"),
    "two-row-int-int": Scheme("two-row-int-int", "internal", "internal", True,
                              "двухрядный с двумя внутренними зацеплениями"),
}


def get_scheme(name: str) -> Scheme:
    """The scheme called ``name``; a ``TaskError`` on ``planetary.scheme`` otherwise."""
    try:
        return SCHEMES[name]
    except (KeyError, TypeError):
        raise TaskError("planetary.scheme", f"unknown scheme {name!r}",
                        "one of: " + ", ".join(SCHEMES)) from None


def expand(scheme: Scheme, z: tuple[int, ...]) -> tuple[int, int, int, int]:
    """``(z1, z2, z2′, z3)``; for the single-row scheme z2′ = z2 (one planet crown)."""
    n = 4 if scheme.two_row else 3
    if len(z) != n or not all(isinstance(v, int) and not isinstance(v, bool) for v in z):
        raise TaskError("planetary.z", f"{len(z)} tooth numbers {tuple(z)!r} for {scheme.name}",
                        f"{n} integers ({', '.join('z' + s for s in scheme.labels)})")
    if min(z) < 1:
        raise TaskError("planetary.z", f"tooth numbers {tuple(z)!r} must be positive", "integers ≥ 1")
    if scheme.two_row:
        return z[0], z[1], z[2], z[3]
    return z[0], z[1], z[1], z[2]


def willis_u13h(scheme: Scheme, z: tuple[int, ...]) -> Fraction:
    """u13^H = s1·s2·(z2·z3)/(z1·z2′) (Willis), exact."""
    z1, z2, z2p, z3 = expand(scheme, z)
    return scheme.sigma * Fraction(z2 * z3, z1 * z2p)


def willis_u1h(scheme: Scheme, z: tuple[int, ...]) -> Fraction:
    """u1H = 1 − u13^H (wheel 3 fixed, wheel 1 driving, carrier driven), exact."""
    return 1 - willis_u13h(scheme, z)


def reducer_ratio(scheme: Scheme, z: tuple[int, ...], driver: Driver = "wheel") -> Fraction:
    """The reducer's ratio ω_in/ω_out: u1H when wheel 1 drives, uH1 = 1/u1H when the carrier drives."""
    u = willis_u1h(scheme, z)
    if driver == "wheel":
        return u
    if driver == "carrier":
        if u == 0:
            raise TaskError("planetary.z", f"u1H = 0 for z = {tuple(z)}: the carrier cannot drive",
                            "tooth numbers with z2·z3 ≠ z1·z2′")
        return 1 / u
    raise TaskError("planetary.driver", f"unknown driver {driver!r}", "wheel or carrier")


def row_sums(scheme: Scheme, z: tuple[int, ...]) -> tuple[int, int]:
    """Twice the centre distance of each row in modules: (z1 ± z2, z3 ∓ z2′)."""
    z1, z2, z2p, z3 = expand(scheme, z)
    left = z1 + z2 if scheme.row1 == "external" else z1 - z2
    right = z3 + z2p if scheme.row2 == "external" else z3 - z2p
    return left, right


def coaxial_z3(scheme: Scheme, z1: int, z2: int, z2p: int) -> int:
    """z3 from coaxiality: z3 = (z1 ± z2) ∓ z2′ (for single-row pass z2p = z2: z3 = z1 + 2·z2)."""
    a2 = z1 + z2 if scheme.row1 == "external" else z1 - z2
    return a2 - z2p if scheme.row2 == "external" else a2 + z2p


def envelope(scheme: Scheme, z: tuple[int, ...]) -> int:
    """Diameter, in modules, of the smallest circle about the central axis that holds every pitch
    circle: max(z1, z3, 2a/m + max(z2, z2′)). The ranking's measure of overall size."""
    z1, z2, z2p, z3 = expand(scheme, z)
    a2 = row_sums(scheme, z)[0]
    return max(z1, z3, a2 + max(z2, z2p))
